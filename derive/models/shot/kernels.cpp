// The shot model's kernels: what the runtime's strike computes.
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
  return kernels;
}

}  // namespace billiards::derive::shot
