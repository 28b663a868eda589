// A model: what a source (a paper, or physics beyond it) is re-derived into — its record of claims
// and the kernels built from it — with the words the audit and the headers print about it. The
// generic layers (audit/, emit/) read these fields and never name a model.
#pragma once

#include "core/record.hpp"
#include "emit/kernel.hpp"
#include "prove/canaries.hpp"
#include "prove/rounding.hpp"

#include <functional>
#include <string>
#include <vector>

namespace billiards::derive {

/// What the audit and the headers say about a model, and where its outputs go.
struct ModelInfo {
  std::string name;                  ///< registry name, e.g. "parkin2023"
  std::string title;                 ///< the audit's heading, e.g. "Billiard Ball Physics"
  std::string citation;              ///< e.g. S. T. Parkin, "Billiard Ball Physics", 2023
  std::string scope;                 ///< what the model covers, one phrase
  std::string notation;              ///< how the audit writes symbols, a paragraph of Markdown
  std::vector<std::string> remarks;  ///< where the source is imprecise, one Markdown bullet each
  /// The struct a kernel with two outputs returns where the kernel names none of its own.
  PairResult pair_result;
  std::string kernels_namespace = "billiards::kernels";
  std::string reference_namespace = "billiards::reference_kernels";
  /// Output paths relative to the output folder; an empty header path writes no header.
  std::string markdown_path = "AUDIT.md";
  std::string json_path = "audit.json";
  std::string kernels_path = "billiards/kernels.hpp";
  std::string reference_path;
  /// A test-only header listing every kernel (billiards/kernel_list.hpp for the paper), so that tests
  /// call, measure and compile each kernel without a list kept by hand; empty for none.
  std::string kernel_list_path;
};

/// A model's record (premises, sections, claims) and the kernels built from it.
struct Derivation : Record {
  ModelInfo model;
  std::vector<Kernel> kernels;  ///< what the emitter prints, each validated against the claims
  /// Kernels for the benchmark only (the raw derivation before simplification), validated the same
  /// way and printed into the reference header, never part of the runtime.
  std::vector<Kernel> reference_kernels;
  /// What Gappa proved of each fast path's plain form, filled in when the printed kernels are read back
  /// (billiards-derive), before the audit is written.
  std::vector<RoundingBound> rounding;
  /// What the prover's canaries (prove/canaries.hpp) answered at the start of the run.
  std::vector<CanaryOutcome> canaries;
};

/// One line of the registry: a model's name and the function that derives it.
struct ModelEntry {
  std::string name;
  std::function<Derivation()> derive;
  /// For the mutation suite only: an edit of each header's printed text (its path relative to the
  /// output folder, its text) before it is read back and proven, as a slip in the printer would make.
  std::function<std::string(const std::string&, const std::string&)> edit_printed = {};
  /// For the mutation suite only: the kernels whose rounding Gappa proves (every kernel when empty).
  std::function<bool(const std::string&)> proves_rounding_of = {};
};

/// Every registered model, in the order billiards-derive runs them (models/registry.cpp).
const std::vector<ModelEntry>& registered_models();

}  // namespace billiards::derive
