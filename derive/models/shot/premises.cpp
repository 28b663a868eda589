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
      {"definition.cue_end_mass",
       "For squirt (TP A-31) the tip grips the ball across the cue: the cue's end mass m_e > 0, the part of "
       "the shaft near the tip that moves with it, starts with no speed across the cue and takes an impulse "
       "−J_s s while the ball takes J d + J_s s, and the tip and the ball's contact point leave with the "
       "same velocity along s.",
       ex(0)},
      {"definition.cushion",
       "The cushion is immovable and straight; its nose meets the ball at height h above the table (0 < h "
       "< 2R). In the cushion's frame, x̂ its normal from the table into the cushion, ŷ along it and ẑ up, "
       "the contact point is r = R n from the ball's centre, n = (cos θ_a, 0, sin θ_a), sin θ_a = h/R − 1: "
       "θ_a above the ball's equator.",
       ex(0)},
      {"definition.cushion_impact",
       "The impact is instantaneous: the cushion's impulse P acts on the ball at r, so Δv = P/m and Δω = "
       "I⁻¹ (r × P). The cushion is the second ball of the frictional contact (spinning model) in the limit "
       "of infinite mass and moment of inertia, at rest: it takes −P and does not move.",
       ex(0)},
      {"definition.cushion_restitution_friction",
       "At the nose, restitution e_c (0 ≤ e_c ≤ 1) along n, u_n' = −e_c u_n for the contact point's velocity "
       "u = v + ω × r, and Coulomb friction μ_c > 0 across n: the impulse P = −P_n n − j û_t, j ≤ μ_c P_n, "
       "stops the slip u_t = u − (u·n) n if it can (sticking) and is j = μ_c P_n against it otherwise "
       "(sliding).",
       ex(0)},
      {"definition.cushion_table",
       "The ball is on the cloth before the impact (v_z = 0) and stays on it: the table's reaction is an "
       "impulse along ẑ through the ball's centre (frictionless during the impact) that cancels the vertical "
       "velocity the cushion's impulse would give, and takes no part in the contact at the nose (the "
       "convention of Han 2005).",
       ex(0)},
  };
  for (const Premise& premise : premises) record.premise(premise);
}

}  // namespace billiards::derive::shot
