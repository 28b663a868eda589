#include "core/record.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace billiards::derive {

void Recorder::premise(Premise premise) {
  if (known(premise.id)) throw std::logic_error("premise " + premise.id + " is recorded twice");
  record_.premises.push_back(std::move(premise));
}

void Recorder::section(std::string id, std::string title, std::string text) {
  current_section_ = id;
  record_.sections.push_back({std::move(id), std::move(title), std::move(text)});
}

const Claim& Recorder::add(Claim claim) {
  claim.section = current_section_;
  if (known(claim.id)) throw std::logic_error("claim " + claim.id + " is recorded twice");
  for (const std::string& upstream : claim.depends_on) {
    if (!known(upstream)) throw std::logic_error("claim " + claim.id + " depends on unknown " + upstream);
  }
  check(claim);
  record_.claims.push_back(std::move(claim));
  clear_claim_being_built();
  return record_.claims.back();
}

void record_steps(Record& record, const std::function<void(Recorder&)>& steps) {
  Recorder recorder(record);
  clear_claim_being_built();
  try {
    steps(recorder);
  } catch (const std::exception& error) {
    const std::string step = recorder.current_section().empty() ? "(before the first step)"
                                                                : "`" + recorder.current_section() + "`";
    const std::string& building = claim_being_built();
    std::string where = "the step " + step + " stopped ";
    if (!building.empty()) {
      where += "while building the claim `" + building + "`";
    } else if (!record.claims.empty()) {
      where += "after the claim `" + record.claims.back().id + "`, outside any claim";
    } else {
      where += "before its first claim";
    }
    clear_claim_being_built();
    Claim stopped;
    stopped.id = "derivation.stopped";
    stopped.section = recorder.current_section();
    stopped.statement = "Every step of the derivation runs to its end.";
    stopped.method = "The derivation's steps were run in order; one threw an exception.";
    stopped.verdict = Verdict::failed;
    stopped.failure = where + ": " + error.what();
    record.claims.push_back(std::move(stopped));
  }
}

bool Recorder::known(const std::string& id) const {
  const auto& premises = record_.premises;
  return find_claim(record_.claims, id) != nullptr ||
         std::any_of(premises.begin(), premises.end(), [&](const Premise& p) { return p.id == id; });
}

Summary summarize(const std::vector<Claim>& claims) {
  Summary summary;
  for (const Claim& claim : claims) {
    switch (claim.verdict) {
      case Verdict::verified: ++summary.verified; break;
      case Verdict::failed: ++summary.failed; break;
      case Verdict::assumption: ++summary.assumption; break;
    }
  }
  return summary;
}

const Claim* find_claim(const std::vector<Claim>& claims, const std::string& id) {
  const auto found = std::find_if(claims.begin(), claims.end(), [&](const Claim& c) { return c.id == id; });
  return found == claims.end() ? nullptr : &*found;
}

std::vector<std::string> downstream_of(const std::vector<Claim>& claims, const std::string& id) {
  std::set<std::string> reached{id};
  std::vector<std::string> downstream;
  // Claims are recorded after everything they depend on, so one pass in order suffices.
  for (const Claim& claim : claims) {
    const bool rests_on_reached = std::any_of(claim.depends_on.begin(), claim.depends_on.end(),
                                              [&](const std::string& d) { return reached.count(d) > 0; });
    if (rests_on_reached) {
      reached.insert(claim.id);
      downstream.push_back(claim.id);
    }
  }
  return downstream;
}

}  // namespace billiards::derive
