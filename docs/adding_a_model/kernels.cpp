// The kernels: what the emitter prints, each proven equal to a verified claim and its rounding bounded.
#include "rolling.hpp"

namespace rolling {

std::vector<billiards::derive::Kernel> rolling_kernels(const Stopping& stopping) {
  const Symbols& s = symbols();
  return {{
      .name = "stop_distance",
      .brief = "The distance a ball rolling at `speed` covers before it stops, v_0²/(2 μ_r g).",
      .parameters = {s.speed, s.resistance, s.gravity},
      .steps = {},
      .outputs = {stopping.stop_distance},
      .equals = "stopping.distance",
      // Gappa bounds its rounding over one binade of each input (the output scales exactly with each).
      .rounding_cases = {{1 <= s.speed, s.speed <= 2, GiNaC::numeric(1, 128) <= s.resistance,
                          s.resistance <= GiNaC::numeric(1, 64), 8 <= s.gravity, s.gravity <= 16}},
  }};
}

}  // namespace rolling
