// A worked example of a model (docs/adding_a_model.md): a ball rolling to rest on the cloth. Its symbols
// and its steps, one function a step; model.cpp strings them together.
#pragma once

#include "core/record.hpp"
#include "emit/kernel.hpp"
#include "model.hpp"

#include <ginac/ginac.h>

#include <vector>

namespace rolling {

using GiNaC::ex;

/// The model's symbols: the name is the C++ name a kernel's parameter takes, the second the audit's TeX.
struct Symbols {
  GiNaC::possymbol speed{"speed", "v_0"};                    ///< the rolling speed at t = 0
  GiNaC::possymbol resistance{"rolling_resistance", "\\mu_r"};  ///< the rolling-resistance coefficient
  GiNaC::possymbol gravity{"gravity", "g"};
  GiNaC::possymbol time{"t", "t"};
};
const Symbols& symbols();

// The steps, each a section of the audit.
void record_premises(billiards::derive::Recorder& record);
struct Stopping {
  ex speed_at;       ///< v(t) = v_0 − μ_r g t
  ex stop_time;      ///< T, where v(T) = 0
  ex stop_distance;  ///< ∫₀ᵀ v dt
};
Stopping the_stopping(billiards::derive::Recorder& record);
std::vector<billiards::derive::Kernel> rolling_kernels(const Stopping& stopping);

/// The model: what billiards-derive runs.
billiards::derive::Derivation derive();

}  // namespace rolling
