// Every fast path's domain proven safe, and each output's rounding error bounded, by Gappa (a tool made
// for straight-line floating-point code): its input is written from the plain kernel as printed (the
// reader's statements, so the operations round in the order the header performs them), for float and
// double. Generic: it reads a printed function and its kernel, never a model.
#pragma once

#include "core/named_constants.hpp"
#include "prove/cpp_reader.hpp"
#include "emit/kernel.hpp"
#include "emit/validate.hpp"

#include <ginac/ginac.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace billiards::derive {

/// What Gappa proved of one plain kernel in one format and one case of its rounding ranges: every
/// intermediate and every output finite and normal (|x| from the smallest normal number to the largest
/// finite one), and each output's relative error at most `relative[i]`.
struct RoundingBound {
  std::string kernel;
  std::string format;                    ///< "float" or "double"
  std::string hypotheses;                ///< the domain and the case, as Gappa was given them
  std::vector<std::string> outputs;      ///< each output as printed
  std::vector<GiNaC::numeric> relative;  ///< the proven bound on |computed − exact|/|exact|, each output
  std::vector<double> in_epsilons;       ///< the same over ε = 2^(1 − digits), rounded up to 0.01
};

/// Writes Gappa's input for the plain kernel `kernel` (a kernel with a domain) printed as `printed`,
/// runs Gappa on it for float and double and for each of the kernel's rounding cases, and appends
/// what it proved to `bounds`. Returns a problem for every proof that does not hold — an intermediate
/// or output that may overflow or leave the normal range, an output without a finite relative bound, a
/// guard the domain neither rules out nor in, a domain that is not a closed interval of finite
/// constants — and when Gappa cannot be run. Never throws.
/// Intervals by parameter name: [low, high].
using Intervals = std::map<std::string, std::pair<GiNaC::numeric, GiNaC::numeric>>;

/// What the header prints that a proof's script must state, by format type ("float", "double"): the
/// intervals its printed range test admits for a fast path's plain form (empty for any other kernel), and
/// the named constants' values as printed (each constant's symbol → its value).
struct PrintedFacts {
  std::map<std::string, Intervals> guard;
  std::map<std::string, GiNaC::exmap> constants;
};

/// The interval each parameter has under `relationals` (`a <= x`, `x <= b`, `x < c` or `c < x`, `>` and
/// `>=` alike; x < c up to the largest number of the format below c), the bounds' named constants given
/// the values `constants` holds; relationals of other quantities, or whose bound is then no number, are
/// passed over.
Intervals intervals_of(const std::vector<GiNaC::ex>& relationals, const GiNaC::exmap& constants,
                       const BinaryFormat& format);

/// Each script is also held against the printed text before Gappa's answer is taken: its `@rnd` must
/// round as the format's C++ type does (std::numeric_limits), and its hypothesis on each parameter must
/// be the interval the printed guard admits (`printed.guard`) and the interval the case's ranges give with
/// the constants' printed values (`printed.constants`); a mismatch is a problem.
std::vector<KernelProblem> prove_rounding(const CppFunction& printed, const Kernel& kernel,
                                          std::vector<RoundingBound>& bounds, const PrintedFacts& facts = {});

/// prove_rounding in one format alone, every case in this process (the canaries' path).
std::vector<KernelProblem> prove_rounding_in(const CppFunction& printed, const Kernel& kernel,
                                             const BinaryFormat& format, std::vector<RoundingBound>& bounds);

/// The Gappa input for one format and case, for tests: what prove_rounding runs, with `guards_taken`
/// saying, guard by guard in the order printed, which branch it takes, and `hints` (Gappa's `a -> b
/// { condition };`) appended.
std::string gappa_script(const CppFunction& printed, const Kernel& kernel, const BinaryFormat& format,
                         const std::vector<GiNaC::ex>& case_ranges, const std::vector<bool>& guards_taken,
                         const std::vector<std::string>& hints = {});

}  // namespace billiards::derive
