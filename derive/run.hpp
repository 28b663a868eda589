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

/// Parses the command line (`--out DIR`, `--model NAME`, `--help`) and runs `models` (all, or the one
/// named). Returns the exit status.
int derive_main(int argc, const char* const* argv, const std::vector<ModelEntry>& models);

}  // namespace billiards::derive
