// The premises: what the derivation starts from, shown at the head of the audit.
#include "rolling.hpp"

namespace rolling {

const Symbols& symbols() {
  static const Symbols s;  // one instance: GiNaC tells symbols apart by identity
  return s;
}

void record_premises(billiards::derive::Recorder& record) {
  const Symbols& s = symbols();
  record.premise({"definition.rolling_resistance",
                  "A ball rolling on the cloth slows at μ_r g: dv/dt = −μ_r g, while v > 0.",
                  -s.resistance * s.gravity});
  record.premise({"definition.start", "At t = 0 the ball rolls at v_0 > 0.", s.speed});
}

}  // namespace rolling
