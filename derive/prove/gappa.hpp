// Gappa as every proof of the run calls it: the rounding a script states for a format, the run itself
// (each script answered once, and from the proof cache where one is kept), and Gappa's verdict, read
// exactly. The canaries (canaries.hpp) check these same functions at the start of every run.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>

namespace billiards::derive {

/// Gappa's rounding operator for an IEEE binary format of `digits` significand digits whose normal
/// numbers start at 2^(min_exponent − 1): "float<ieee_32, ne>" for float, "float<ieee_64, ne>" for
/// double, "float<digits, e>" (e the smallest subnormal's exponent) for any other; rounding to nearest,
/// ties to even.
std::string gappa_rounding(int digits, int min_exponent);

/// What Gappa answered for a script: its exit status, everything it printed, and the verdict.
struct GappaAnswer {
  int status = -1;
  std::string output;
  bool proven = false;  ///< gappa_proved(status, output)
};

/// Gappa's own success: exit status 0, no property reported unsatisfied and no error. Anything else
/// (an unproven property, a syntax error, a signal) is no proof.
bool gappa_proved(int status, const std::string& output);

/// The first property Gappa names as not satisfied, or its first error, or all of `output`.
std::string gappa_failure(const std::string& output);

/// `script` without the definitions its proposition and hints do not read, directly or through other
/// definitions: Gappa takes time over every definition it is given. The lines kept are unchanged.
std::string only_what_is_read(const std::string& script);

/// Runs Gappa on `only_what_is_read(script)`: the same script is answered once a run, and from the proof
/// cache (ProofCache::instance) where one is kept. Throws std::runtime_error when Gappa cannot be run.
GappaAnswer run_gappa(const std::string& script);

/// The proof cache (BILLIARDS_PROOF_CACHE, docs/code_generation.md): Gappa's exit status and output for a
/// script, in a file named by a hash of Gappa's version and the whole script, which holds both in full.
/// An answer is taken only from a file whose version and script equal the ones asked for, byte for
/// byte (a hash collision, a truncated or foreign file is a miss), and only a proven (0) or unproven (1)
/// answer is kept. Written atomically; an unwritable cache is left alone: the run goes on without it.
class ProofCache {
 public:
  /// A cache in `folder` (none when empty) for answers of Gappa `version` (its `--version` text).
  ProofCache(std::filesystem::path folder, std::string version);
  /// The run's cache: BILLIARDS_PROOF_CACHE's folder, keyed by the installed Gappa's version; none when
  /// the variable is unset or empty or Gappa cannot tell its version.
  static ProofCache& instance();

  /// The answer kept for exactly `script`: its exit status and output.
  [[nodiscard]] std::optional<std::pair<int, std::string>> find(const std::string& script) const;
  /// Keeps the answer (status 0 or 1 only) for `script`.
  void keep(const std::string& script, int status, const std::string& output) const;
  /// The file an answer for `script` is kept in.
  [[nodiscard]] std::filesystem::path path(const std::string& script) const;

 private:
  [[nodiscard]] std::string entry(const std::string& script, int status, const std::string& output) const;
  std::filesystem::path folder_;
  std::string version_;
};

}  // namespace billiards::derive
