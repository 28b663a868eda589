// The record of a derivation: its premises, its sections (the steps, in the source's order) and its
// claims, each checked as it is recorded. Generic: it never names a model.
#pragma once

#include "core/claim.hpp"

#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <vector>

namespace billiards::derive {

/// A definition or an input the derivation starts from, shown at the head of the audit.
struct Premise {
  std::string id;
  std::string statement;
  GiNaC::ex display = 0;  ///< the definition as used, shown when not 0
};

struct Section {
  std::string id;
  std::string title;
  std::string text;  ///< what the step does, in the source's terms
};

struct Record {
  std::vector<Premise> premises;
  std::vector<Section> sections;
  std::vector<Claim> claims;  ///< in the source's order, every verdict decided
};

/// Records sections and claims into a Record: each claim is checked as it is added, placed in the
/// current section, and must rest only on premises and claims recorded before it.
class Recorder {
 public:
  explicit Recorder(Record& record) : record_(record) {}

  void premise(Premise premise);
  void section(std::string id, std::string title, std::string text);
  /// Checks `claim` (check() never throws) and appends it. Throws std::logic_error when it depends on
  /// an id not recorded before it, or repeats an id: a mistake in the model, not in the algebra.
  const Claim& add(Claim claim);
  /// The id of the section (step) claims are placed in now; empty before the first.
  const std::string& current_section() const { return current_section_; }

 private:
  bool known(const std::string& id) const;
  Record& record_;
  std::string current_section_;
};

/// Runs a model's steps on `record` through one Recorder. An exception thrown anywhere in them (a slip
/// such as GiNaC's "power::eval(): division by zero", outside any check) does not escape: it is recorded
/// as the failed claim `derivation.stopped`, whose failure names the step it stopped in and the claim
/// being built, so the audit of what was derived is still written and the model's headers are not.
void record_steps(Record& record, const std::function<void(Recorder&)>& steps);

struct Summary {
  int verified = 0;
  int failed = 0;
  int assumption = 0;
};
Summary summarize(const std::vector<Claim>& claims);

/// The claim with id `id`, or nullptr.
const Claim* find_claim(const std::vector<Claim>& claims, const std::string& id);

/// The ids of `claims` that rest, directly or through other claims, on the premise or claim `id`.
std::vector<std::string> downstream_of(const std::vector<Claim>& claims, const std::string& id);

}  // namespace billiards::derive
