#include "models/shot/steps.hpp"

namespace billiards::derive::shot {

void record_premises(Recorder& record) {
  const std::vector<Premise> premises = {
      {"definition.solid_sphere",
       "The ball is a rigid, uniform solid sphere of mass m > 0 and radius R > 0: I = (2/5) m R².", ex(0)},
      {"definition.cue",
       "The table is the plane z = 0, ẑ up. The cue, of mass M > 0, moves at speed V > 0 along its axis d = "
       "(cos θ cos φ, cos θ sin φ, −sin θ): aimed at azimuth φ, elevated by θ (0 ≤ θ < 90°) above the "
       "table, pointing down into the ball. s = (sin φ, −cos φ, 0) is to its right and u = s × d up, both "
       "perpendicular to it.",
       ex(0)},
      {"definition.tip_offset",
       "The tip meets the ball at r = R (a s + b u − c d) from its centre: a to the right and b up, "
       "measured in the plane perpendicular to the cue in units of R, c = √(1 − a² − b²) (a² + b² < 1).",
       ex(0)},
      {"definition.cue_impulse",
       "The strike is instantaneous and the tip frictionless on the ball (Alciatore's instantaneous point "
       "model, TP A-30): an impulse J along d acts on the ball at r and −J d on the cue, so Δv = (J/m) d, "
       "Δω = I⁻¹ (r × J d) and ΔV = −J/M.",
       ex(0)},
      {"definition.tip_restitution",
       "Newton's law of restitution at the tip, along d: the ball's contact point leaves the tip at e_tip "
       "times the speed they met with, 0 ≤ e_tip ≤ 1 ((v + ω × r)·d − V' = e_tip (V − (v + ω × r)·d) "
       "with the ball's state after on the left, before on the right).",
       ex(0)},
  };
  for (const Premise& premise : premises) record.premise(premise);
}

}  // namespace billiards::derive::shot
