#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

// The audit section "Sliding on the cloth": the slipping ball under the cloth's friction, integrated;
// returns the slide time.
ex sliding_on_the_cloth(Recorder& record, const ClothStart& start) {
  const Symbols& s = symbols();
  const ex t = s.t, g = s.g, m = s.m, R = s.R;
  const Vec z{0, 0, 1}, contact{0, 0, -R};
  const Vec &v0 = start.v0, &w0 = start.w0, &r0 = start.r0;
  const GiNaC::symbol& tau = start.tau;
  record.section("sliding", "Sliding on the cloth",
                 "While the contact point slips (u ≠ 0) the cloth's friction −μ_s m g û acts at −R ẑ. The "
                 "equations of motion m dv/dt = F, I dω/dt = (−R ẑ) × F are integrated with û held, and the "
                 "result shows û is indeed constant until the slip vanishes. The spin about ẑ is untouched "
                 "by this force (its torque is horizontal) and decays apart (\"Spinning on the cloth\").");
  const ex mu_s = s.sliding_friction, sigma0 = s.slip_speed;
  const Vec u0 = add(v0, cross(w0, contact));
  const Constraint slip_length{GiNaC::pow(sigma0, 2) == dot(u0, u0).expand(), "|u0|² = u0·u0"};
  const Vec unit_slip = scale(1 / sigma0, u0);
  const Vec force = scale(-mu_s * m * g, unit_slip);
  const Vec v_slide = add(v0, integrate(scale(1 / m, force), tau, tau));
  const Vec w_slide = add(w0, integrate(scale(1 / start.inertia, cross(contact, force)), tau, tau));
  const Vec r_slide = add(r0, integrate(v_slide, tau, t));
  const Vec v_t = at_time(v_slide, tau, t), w_t = at_time(w_slide, tau, t);
  const std::vector<std::string> sliding_rests_on = {"definition.cloth", "definition.solid_sphere"};
  record.add({
      .id = "sliding.velocity",
      .statement = "While sliding, v(t) = v0 − μ_s g t û.",
      .method = "m dv/dt = −μ_s m g û integrated from 0 to t; identity",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(subtract(v0, scale(mu_s * g * t, unit_slip))),
      .derived_expression = to_lst(v_t),
      .depends_on = sliding_rests_on,
  });
  record.add({
      .id = "sliding.angular_velocity",
      .statement =
          "While sliding, ω(t) = ω0 + (5 μ_s g/(2R)) t (ẑ × û): the friction's torque is horizontal.",
      .method = "I dω/dt = (−R ẑ) × (−μ_s m g û), I = (2/5) m R², integrated from 0 to t; identity",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(add(w0, scale(5 * mu_s * g * t / (2 * R), cross(z, unit_slip)))),
      .derived_expression = to_lst(w_t),
      .depends_on = sliding_rests_on,
  });
  record.add({
      .id = "sliding.position",
      .statement = "While sliding, r(t) = r0 + v0 t − ½ μ_s g t² û.",
      .method = "v(t) integrated from 0 to t; identity",
      .comparison = Comparison::identity,
      .paper_expression =
          to_lst(add(add(r0, scale(t, v0)), scale(-numeric(1, 2) * mu_s * g * t * t, unit_slip))),
      .derived_expression = to_lst(r_slide),
      .depends_on = {"sliding.velocity"},
  });
  const Vec u_t = add(v_t, cross(w_t, contact));
  const ex shrink = 1 - numeric(7, 2) * mu_s * g * t / sigma0;
  record.add({
      .id = "sliding.slip_direction_constant",
      .statement = "While sliding, u(t) = (1 − 7 μ_s g t/(2 |u0|)) u0: the slip keeps its direction (û is "
                   "constant, as assumed) and shrinks at (7/2) μ_s g.",
      .method = "u = v + ω × (−R ẑ) of the integrated motion; identity",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(scale(shrink, u0)),
      .derived_expression = to_lst(u_t),
      .depends_on = {"sliding.velocity", "sliding.angular_velocity"},
  });
  const ex slide_time = GiNaC::lsolve(shrink == 0, s.t);
  record.add({
      .id = "sliding.slide_time",
      .statement = "The slip vanishes, and the ball starts rolling, at t_s = 2 |u0|/(7 μ_s g).",
      .method = "lsolve() of 1 − 7 μ_s g t/(2 |u0|) = 0 for t; identity",
      .comparison = Comparison::identity,
      .paper_expression = 2 * sigma0 / (7 * mu_s * g),
      .derived_expression = slide_time,
      .depends_on = {"sliding.slip_direction_constant"},
  });
  record.add({
      .id = "sliding.frictionless_slides_on",
      .statement = "With μ_s = 0 the slip never changes, u(t) = u0: the ball slides on forever (the slide "
                   "time is +∞).",
      .method = "μ_s = 0 in u(t); identity",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(u0),
      .derived_expression = ex(to_lst(u_t)).subs(mu_s == 0),
      .depends_on = {"sliding.slip_direction_constant"},
      .cases = {{lst{mu_s <= 0}, infinity()}},
  });
  record.add({
      .id = "sliding.rolling_velocity",
      .statement = "The velocity when rolling starts is v0 − (2/7) u0 (the 5/7 rule: a stun shot, ω0 = 0, "
                   "rolls on at 5/7 of its speed).",
      .method = "v(t_s); identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(subtract(v0, scale(numeric(2, 7), u0))),
      .derived_expression = ex(to_lst(v_t)).subs(s.t == slide_time),
      .depends_on = {"sliding.slide_time", "sliding.velocity"},
  });
  record.add({
      .id = "sliding.rolls_at_slide_time",
      .statement = "At t_s the rolling condition holds: u(t_s) = 0, i.e. v = ω × (R ẑ).",
      .method = "u(t_s) of the integrated motion; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = lst{0, 0, 0},
      .derived_expression = ex(to_lst(u_t)).subs(s.t == slide_time),
      .depends_on = {"sliding.slide_time"},
  });
  const ex slide_rate = GiNaC::diff(start.kinetic_energy(v_t, w_t), s.t).expand();
  record.add({
      .id = "sliding.energy_rate",
      .statement = "While sliding the kinetic energy changes at dE/dt = −μ_s m g |u(t)|, |u(t)| = |u0| − "
                   "(7/2) μ_s g t.",
      .method = "d/dt of ½ m v² + ½ I ω² (the horizontal spin) with diff(); identity, |u0|² → u0·u0 imposed",
      .comparison = Comparison::identity,
      .paper_expression = -mu_s * m * g * (sigma0 - numeric(7, 2) * mu_s * g * t),
      .derived_expression = slide_rate,
      .constraints = {slip_length},
      .depends_on = {"sliding.slip_direction_constant"},
  });
  record.add({
      .id = "sliding.energy_nonincreasing",
      .statement = "While sliding (0 ≤ t < t_s) the energy never increases.",
      .method = "sign: minus the rate at t = t_s/(1 + q), q > 0, is μ_s m g |u0| q/(1 + q)",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = GiNaC::normal(mu_s * m * g * (sigma0 - numeric(7, 2) * mu_s * g * t))
                                .subs(s.t == slide_time / (1 + s.q)),
      .depends_on = {"sliding.energy_rate"},
  });

  return slide_time;
}

}  // namespace billiards::derive::spinning
