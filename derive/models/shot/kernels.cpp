// The shot model's kernels: what the runtime's strike and cushion compute.
#include "models/shot/steps.hpp"

namespace billiards::derive::shot {

std::vector<Kernel> shot_kernels(const Strike& k) {
  const Symbols& s = symbols();
  std::vector<Kernel> kernels;
  const GiNaC::possymbol ball_mass("ball_mass"), cue_mass("cue_mass"), approach("approach_speed"),
      change("velocity_change"), radius("radius");
  const GiNaC::realsymbol side("side_offset"), up("up_offset"), restitution("tip_restitution");
  const GiNaC::symbol ratio("mass_ratio"), offsets("offset_terms"), inverse("inverse_mass"), factor("spin_factor");
  const ex before_speed = k.contact_speed(k.v, k.w);
  kernels.push_back({
      .name = "strike_velocity_change",
      .brief = "J/m = (1 + e_tip) w/(1 + m/M + (5/2)(a² + b²)): the struck ball's velocity change along the cue "
               "(its speed, for a ball at rest), from the ball's and the cue's masses, the tip's approach speed "
               "w = V − (v + ω × r)·d, the tip's offsets a (right) and b (up) in units of R, and its restitution.",
      .parameters = {ball_mass, cue_mass, approach, side, up, restitution},
      .steps = {{ratio, ball_mass / cue_mass},
                {offsets, side * side + up * up},
                {inverse, 1 + ratio + numeric(5, 2) * offsets}},
      .outputs = {(1 + restitution) * approach / inverse},
      .equals = "strike.velocity_change",
      .in_claim_terms = {{ball_mass, s.m}, {cue_mass, s.M}, {approach, s.V - before_speed}, {side, s.a},
                         {up, s.b}, {restitution, s.restitution}},
      .claims = {"strike.speed"},
      // Every term positive: the masses in neighbouring binades, offsets and restitution as a strike has them.
      .rounding_cases = {{1 <= ball_mass, ball_mass <= 2, 2 <= cue_mass, cue_mass <= 4, 1 <= approach,
                          approach <= 2, ex(1) / 4 <= side, side <= ex(1) / 2, ex(1) / 4 <= up, up <= ex(1) / 2,
                          ex(1) / 2 <= restitution, restitution <= 1}},
  });
  kernels.push_back({
      .name = "strike_spin",
      .brief = "The struck ball's spin change in the cue's frame, (5 a/(2R)) (J/m) about u and −(5 b/(2R)) (J/m) "
               "about s, from the velocity change J/m (strike_velocity_change), the radius R and the tip's "
               "offsets a and b.",
      .parameters = {change, radius, side, up},
      .steps = {{factor, numeric(5, 2) * change / radius}},
      .outputs = {factor * side, -factor * up},
      .equals = "strike.spin_in_cue_frame",
      .in_claim_terms = {{change, s.impulse / s.m}, {radius, s.R}, {side, s.a}, {up, s.b}},
      .rounding_cases = {{1 <= change, change <= 2, 1 <= radius, radius <= 2, ex(1) / 4 <= side,
                          side <= ex(1) / 2, ex(1) / 4 <= up, up <= ex(1) / 2}},
  });
  // The cushion, in its frame: x̂ its normal into the cushion, ŷ along it, ẑ up.
  const GiNaC::realsymbol along_speed("along_speed"), spin_normal("spin_normal"), spin_along("spin_along"),
      spin_up("spin_up"), sin_nose("sin_nose"), slip_tangent("slip_tangent"), slip_along("slip_along"),
      cushion_restitution("restitution");
  const GiNaC::possymbol cos_nose("cos_nose"), normal_impulse("normal_impulse"), friction_ratio("friction_ratio");
  // The slip in the claims' terms (cushion.slip_in_cushion_frame), and the friction ratio k = j/(m σ).
  const ex slip_tangent_terms = k.v[0] * s.sin_a + s.R * k.w[1];
  const ex slip_along_terms = k.v[1] + s.R * k.w[2] * s.cos_a - s.R * k.w[0] * s.sin_a;
  const ex ratio_terms = s.friction_impulse / (s.m * s.slip);
  const PairResult slip_pair{"CushionSlip", "The contact point's slip across the cushion's normal, in the cushion's frame.",
                             "s_t, along t = (sin θ_a, 0, −cos θ_a): down the nose, into the cushion",
                             "s_y, along ŷ: along the cushion"};
  const PairResult velocity_pair{"CushionVelocityChange", "The change of a ball's velocity at the cushion, in its frame.",
                                 "Δv_x, along x̂: the cushion's normal into it", "Δv_y, along ŷ: along the cushion"};
  const PairResult spin_pair{"CushionSpinChange", "The change of a ball's spin at the cushion, in its frame.",
                             "Δω·t, t = (sin θ_a, 0, −cos θ_a)", "Δω·ŷ, along the cushion"};
  kernels.push_back({
      .name = "cushion_slip",
      .brief = "The slip of a ball's contact point with the cushion's nose across its normal: s_t = v_x sin θ_a + "
               "R ω_y and s_y = v_y + R ω_z cos θ_a − R ω_x sin θ_a, from the ball's velocity (v_x = approach_speed "
               "into the cushion, v_y = along_speed), its spin (ω_x, ω_y, ω_z) in the cushion's frame, its radius and "
               "the nose's angle θ_a above the equator.",
      .parameters = {approach, along_speed, spin_normal, spin_along, spin_up, radius, cos_nose, sin_nose},
      .outputs = {approach * sin_nose + radius * spin_along,
                  along_speed + radius * spin_up * cos_nose - radius * spin_normal * sin_nose},
      .pair = slip_pair,
      .equals = "cushion.slip_in_cushion_frame",
      .in_claim_terms = {{approach, k.v[0]}, {along_speed, k.v[1]}, {spin_normal, k.w[0]}, {spin_along, k.w[1]},
                         {spin_up, k.w[2]}, {radius, s.R}, {cos_nose, s.cos_a}, {sin_nose, s.sin_a}},
      // Every term of one sign: the spin about the normal against the others.
      .rounding_cases = {{1 <= approach, approach <= 2, 1 <= along_speed, along_speed <= 2, -2 <= spin_normal,
                          spin_normal <= -1, 1 <= spin_along, spin_along <= 2, 1 <= spin_up, spin_up <= 2,
                          1 <= radius, radius <= 2, ex(1) / 2 <= cos_nose, cos_nose <= 1, ex(1) / 8 <= sin_nose,
                          sin_nose <= ex(1) / 2}},
  });
  kernels.push_back({
      .name = "cushion_normal_impulse",
      .brief = "P_n/m = (1 + e_c) v_x cos θ_a: the cushion's normal impulse per unit mass, from the ball's speed "
               "into the cushion, the cosine of the nose's angle and the cushion's restitution.",
      .parameters = {approach, cos_nose, cushion_restitution},
      .outputs = {(1 + cushion_restitution) * approach * cos_nose},
      .equals = "cushion.normal_impulse_per_unit_mass",
      .in_claim_terms = {{approach, k.v[0]}, {cos_nose, s.cos_a}, {cushion_restitution, s.cushion_restitution}},
      .rounding_cases = {{1 <= approach, approach <= 2, ex(1) / 2 <= cos_nose, cos_nose <= 1,
                          0 <= cushion_restitution, cushion_restitution <= 1}},
  });
  kernels.push_back({
      .name = "cushion_velocity_change",
      .brief = "The velocity change at the cushion, Δv_x = −(P_n/m) cos θ_a − k s_t sin θ_a and Δv_y = −k s_y, "
               "from the normal impulse per unit mass (cushion_normal_impulse), the friction ratio k = j/(m σ) "
               "(2/7 sticking, μ_c (P_n/m)/σ sliding), the slip (cushion_slip) and the nose's angle.",
      .parameters = {normal_impulse, friction_ratio, slip_tangent, slip_along, cos_nose, sin_nose},
      .outputs = {-normal_impulse * cos_nose - friction_ratio * slip_tangent * sin_nose,
                  -friction_ratio * slip_along},
      .pair = velocity_pair,
      .equals = "cushion.velocity_change",
      .in_claim_terms = {{normal_impulse, s.normal_impulse / s.m},
                         {friction_ratio, ratio_terms},
                         {slip_tangent, slip_tangent_terms},
                         {slip_along, slip_along_terms},
                         {cos_nose, s.cos_a},
                         {sin_nose, s.sin_a}},
      .rounding_cases = {{1 <= normal_impulse, normal_impulse <= 2, ex(1) / 16 <= friction_ratio,
                          friction_ratio <= ex(1) / 2, 1 <= slip_tangent, slip_tangent <= 2, 1 <= slip_along,
                          slip_along <= 2, ex(1) / 2 <= cos_nose, cos_nose <= 1, ex(1) / 8 <= sin_nose,
                          sin_nose <= ex(1) / 2}},
  });
  kernels.push_back({
      .name = "cushion_spin_change",
      .brief = "The spin change at the cushion, (5 k/(2R)) s_y about t = (sin θ_a, 0, −cos θ_a) and −(5 k/(2R)) "
               "s_t about ŷ (none about the normal), from the friction ratio k, the slip (cushion_slip) and the "
               "radius.",
      .parameters = {friction_ratio, slip_tangent, slip_along, radius},
      .steps = {{factor, numeric(5, 2) * friction_ratio / radius}},
      .outputs = {factor * slip_along, -factor * slip_tangent},
      .pair = spin_pair,
      .equals = "cushion.spin_change",
      .in_claim_terms = {{friction_ratio, ratio_terms},
                         {slip_tangent, slip_tangent_terms},
                         {slip_along, slip_along_terms},
                         {radius, s.R}},
      .claims = {"cushion.no_spin_change_about_the_normal"},
      .rounding_cases = {{ex(1) / 16 <= friction_ratio, friction_ratio <= ex(1) / 2, 1 <= slip_tangent,
                          slip_tangent <= 2, 1 <= slip_along, slip_along <= 2, 1 <= radius, radius <= 2}},
  });
  return kernels;
}

}  // namespace billiards::derive::shot
