#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

void the_throw(Recorder& record, const Contact& c, const Friction& friction) {
  const Symbols& s = symbols();
  const ex e = s.restitution;
  record.section("throw", "No friction, and the throw of a stun shot",
                 "With μ = 0 the tangential impulse is min(0, |u_t|/k) = 0 and the model is the restitution "
                 "collision of the first model, spins untouched. With friction a stun shot throws the object "
                 "ball off the line of centres by atan(min(μ, 2 tan φ/(7(1 + e)))) (Alciatore, TP A-14, for "
                 "e = 1).");
  const ex relative_normal_speed = dot(subtract(c.v2, c.v1), c.n);
  const ex normal_impulse = friction.normal_impulse.subs(s.normal_slip == relative_normal_speed);
  const std::vector<Vec> frictionless = c.after(scale(normal_impulse, c.n));
  const ex first_coefficient = (1 + e) * s.m2 / (s.m1 + s.m2),
           second_coefficient = (1 + e) * s.m1 / (s.m1 + s.m2);
  const std::vector<Vec> restitution = {
      add(c.v1, scale(first_coefficient * relative_normal_speed, c.n)), c.w1,
      add(c.v2, scale(-second_coefficient * relative_normal_speed, c.n)), c.w2};
  record.add({
      .id = "throw.frictionless_is_restitution",
      .statement = "With μ = 0 (j = 0) the balls leave with x1 = v1 + (1 + e) m2/(m1 + m2) ((v2 − v1)·n) n, "
                   "x2 = v2 − (1 + e) m1/(m1 + m2) ((v2 − v1)·n) n and their spins unchanged: the "
                   "restitution collision (the first model's beyond.restitution.impulse_coefficients).",
      .method = "the impulse equations with J = J_n n, J_n from friction.normal_impulse, in components "
                "(v1, ω1, v2, ω2); identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = concatenate(restitution),
      .derived_expression = concatenate(frictionless),
      .depends_on = {"friction.normal_impulse", "definition.coulomb_friction"},
  });
  std::vector<Vec> paper = restitution;
  for (Vec& v : paper) {
    for (ex& component : v) component = component.subs(e == 1);
  }
  record.add({
      .id = "throw.frictionless_elastic_is_the_paper",
      .statement = "With μ = 0 and e = 1: x1 = v1 + (2 m2/(m1 + m2)) ((v2 − v1)·n) n, the paper's result "
                   "(the first model's result.x1_simplified_form), and likewise x2.",
      .method = "e = 1 in throw.frictionless_is_restitution; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = concatenate(paper),
      .derived_expression = ex(concatenate(frictionless)).subs(e == 1),
      .depends_on = {"throw.frictionless_is_restitution"},
  });
  // The stun shot: n = x̂, the cue ball (1) at speed V at cut angle φ to n, no spin; the object ball (2)
  // at rest; equal solid spheres.
  const Vec v1{s.speed * s.cos_cut, s.speed * s.sin_cut, 0}, at_rest{0, 0, 0}, x_axis{1, 0, 0};
  GiNaC::exmap stun{{s.m1, s.m},
                    {s.m2, s.m},
                    {s.R1, s.R},
                    {s.R2, s.R},
                    {s.I1, numeric(2, 5) * s.m * s.R * s.R},
                    {s.I2, numeric(2, 5) * s.m * s.R * s.R}};
  for (std::size_t i = 0; i < 3; ++i) {
    stun[c.v1[i]] = v1[i];
    stun[c.w1[i]] = stun[c.v2[i]] = stun[c.w2[i]] = 0;
    stun[c.n[i]] = x_axis[i];
  }
  const Vec slip = c.slip(c.v1, c.w1, c.v2, c.w2);
  Vec stun_slip;
  for (const ex& component : slip) stun_slip.push_back(component.subs(stun));
  const Vec tangential_slip = perpendicular_part(stun_slip, x_axis);
  const ex slip_length = s.speed * s.sin_cut;  // |u_t| for φ in (0°, 90°)
  const ex stun_normal_impulse =
      friction.normal_impulse.subs(s.normal_slip == dot(stun_slip, x_axis)).subs(stun);
  const auto throw_tangent = [&](const ex& j) {
    const Vec impulse = add(scale(stun_normal_impulse, x_axis), scale(-j / slip_length, tangential_slip));
    const Vec object_ball = c.after(impulse)[2];
    return GiNaC::normal(object_ball[1].subs(stun) / object_ball[0].subs(stun));
  };
  const ex sticking = friction.sticking_impulse.subs(s.tangential_slip == slip_length).subs(stun);
  const ex sticking_throw = throw_tangent(sticking);
  const ex printed_sticking = 2 * (s.sin_cut / s.cos_cut) / (7 * (1 + e));
  const std::vector<std::string> stun_rests_on = {"friction.normal_impulse", "friction.sticking_impulse",
                                                  "impulse.tangential_inverse_effective_mass_solid_spheres"};
  record.add({
      .id = "throw.stun_shot_sticking",
      .statement =
          "A stun shot (object ball at rest, no spin, equal solid spheres) at cut angle φ that sticks "
          "throws the object ball at tan θ = 2 tan φ/(7(1 + e)) off the line of centres.",
      .method = "the impulse equations with n = x̂, v1 = V (cos φ, sin φ, 0), J = J_n n − (|u_t|/k) û_t; "
                "the object ball's velocity across n over along n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = printed_sticking,
      .derived_expression = sticking_throw,
      .depends_on = stun_rests_on,
  });
  record.add({
      .id = "throw.stun_shot_tp_a14",
      .statement = "For e = 1 the sticking throw is tan θ = tan φ/7, the formula of Alciatore's TP A-14.",
      .method = "e = 1 in throw.stun_shot_sticking; identity",
      .comparison = Comparison::identity,
      .paper_expression = (s.sin_cut / s.cos_cut) / 7,
      .derived_expression = sticking_throw.subs(e == 1),
      .depends_on = {"throw.stun_shot_sticking"},
  });
  record.add({
      .id = "throw.stun_shot_sliding",
      .statement = "A stun shot that slides throughout (j = μ J_n) throws at tan θ = μ, so that in all "
                   "θ = atan(min(μ, 2 tan φ/(7(1 + e)))).",
      .method = "as throw.stun_shot_sticking with j = μ J_n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = s.friction,
      .derived_expression = throw_tangent(s.friction * stun_normal_impulse),
      .depends_on = stun_rests_on,
  });
}

}  // namespace billiards::derive::spinning
