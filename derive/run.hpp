// The billiards-derive pipeline, as a function over a registry of models: derive each model, validate
// its kernels, write its audit and (when every kernel is proven) its headers, report. main.cpp calls it
// with the registered models; tests call it with models of their own.
#pragma once

#include "model.hpp"

#include <vector>

namespace billiards::derive {

inline constexpr int exit_claims_failed = 1;  ///< a claim failed or a kernel is not proven
inline constexpr int exit_usage = 2;
inline constexpr int exit_io = 3;

/// Parses the command line (`--out DIR`, `--model NAME`, `--help`), asks `canaries` (the prover's own
/// checks, prove/canaries.hpp) and runs `models` (all, or the one named). Where a canary answers wrongly,
/// each model is still derived and its audit written, showing the canaries' answers, but nothing is
/// proven by the prover that failed and no header is written: exit status 1. Returns the exit status.
int derive_main(int argc, const char* const* argv, const std::vector<ModelEntry>& models,
                const std::vector<Canary>& canaries = prover_canaries());

}  // namespace billiards::derive
