#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

// The audit section "Rolling on the cloth": the rolling condition, the rolling resistance and the
// motion it gives; returns the stop time.
ex rolling_on_the_cloth(Recorder& record, const ClothStart& start) {
  const Symbols& s = symbols();
  const ex t = s.t, g = s.g, m = s.m, R = s.R;
  const Vec z{0, 0, 1}, contact{0, 0, -R};
  const Vec &v0 = start.v0, &r0 = start.r0;
  const GiNaC::symbol& tau = start.tau;
  record.section("rolling", "Rolling on the cloth",
                 "Once the slip is zero the ball rolls: its horizontal spin follows its velocity. Rolling "
                 "resistance is modelled as a deceleration μ_r g against v that keeps the ball rolling (an "
                 "assumption, as in common simulators); the motion, the stop time and the energy follow.");
  const ex mu_r = s.rolling_friction, nu0 = s.ball_speed;
  const GiNaC::realsymbol wx("w_x", "\\omega_x"), wy("w_y", "\\omega_y");
  const Vec w_free{wx, wy, 0};
  const Vec u_free = add(v0, cross(w_free, contact));
  const ex rolling_spin = GiNaC::lsolve(lst{u_free[0] == 0, u_free[1] == 0}, lst{wx, wy});
  record.add({
      .id = "rolling.condition",
      .statement = "The ball rolls (u = 0) iff its horizontal spin is ω = ẑ × v/R.",
      .method = "lsolve() of u = v + ω × (−R ẑ) = 0 for ω_x, ω_y; identity",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(scale(1 / R, cross(z, v0))),
      .derived_expression = lst{ex(wx).subs(rolling_spin), ex(wy).subs(rolling_spin), 0},
      .depends_on = {"definition.cloth"},
  });
  record.add({
      .id = "assumption.rolling_resistance",
      .statement = "While rolling, the cloth slows the centre at μ_r g against v and the ball keeps rolling "
                   "(ω = ẑ × v/R); the spin about ẑ decays apart.",
      .method = "not checked: the model of rolling resistance (the cloth's deformation), stated with its "
                "reason",
      .comparison = Comparison::assumption,
      .note = "Rolling resistance comes from the cloth's deformation ahead of the ball, not from a force at "
              "the contact point that the rigid-body equations could derive; simulators model it as this "
              "deceleration.",
      .depends_on = {"rolling.condition"},
  });
  const Vec unit_velocity = scale(1 / nu0, v0);
  const Constraint speed_length{GiNaC::pow(nu0, 2) == dot(v0, v0).expand(), "|v0|² = v0·v0"};
  const Vec v_roll = add(v0, integrate(scale(-mu_r * g, unit_velocity), tau, tau));
  const Vec v_roll_t = at_time(v_roll, tau, t);
  record.add({
      .id = "rolling.velocity",
      .statement = "While rolling, v(t) = v0 − μ_r g t v̂ (v̂ = v0/|v0|) and ω(t) = ẑ × v(t)/R.",
      .method = "dv/dt = −μ_r g v̂ integrated from 0 to t; identity",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(subtract(v0, scale(mu_r * g * t, unit_velocity))),
      .derived_expression = to_lst(v_roll_t),
      .depends_on = {"assumption.rolling_resistance"},
  });
  record.add({
      .id = "rolling.position",
      .statement = "While rolling, r(t) = r0 + v0 t − ½ μ_r g t² v̂.",
      .method = "v(t) integrated from 0 to t; identity",
      .comparison = Comparison::identity,
      .paper_expression =
          to_lst(add(add(r0, scale(t, v0)), scale(-numeric(1, 2) * mu_r * g * t * t, unit_velocity))),
      .derived_expression = to_lst(add(r0, integrate(v_roll, tau, t))),
      .depends_on = {"rolling.velocity"},
  });
  const ex roll_factor = 1 - mu_r * g * t / nu0;
  const ex roll_time = GiNaC::lsolve(roll_factor == 0, s.t);
  record.add({
      .id = "rolling.stop_time",
      .statement = "The rolling ball stops at t_r = |v0|/(μ_r g): v(t) = (1 − μ_r g t/|v0|) v0.",
      .method = "lsolve() of 1 − μ_r g t/|v0| = 0 for t, the factor read off v(t)/v0; identity",
      .comparison = Comparison::identity,
      .paper_expression = nu0 / (mu_r * g),
      .derived_expression = roll_time,
      .depends_on = {"rolling.velocity"},
  });
  record.add({
      .id = "rolling.frictionless_rolls_on",
      .statement = "With μ_r = 0 the rolling ball keeps its velocity forever (the stop time is +∞).",
      .method = "μ_r = 0 in v(t); identity",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(v0),
      .derived_expression = ex(to_lst(v_roll_t)).subs(mu_r == 0),
      .depends_on = {"rolling.velocity"},
      .cases = {{lst{mu_r <= 0}, infinity()}},
  });
  const Vec w_roll = scale(1 / R, cross(z, v_roll_t));
  record.add({
      .id = "rolling.energy_rate",
      .statement =
          "While rolling E = (7/10) m v² and dE/dt = −(7/5) m μ_r g |v(t)|, |v(t)| = |v0| − μ_r g t.",
      .method = "d/dt of ½ m v² + ½ I ω² with ω = ẑ × v/R, with diff(); identity, |v0|² → v0·v0 imposed",
      .comparison = Comparison::identity,
      .paper_expression = -numeric(7, 5) * m * mu_r * g * (nu0 - mu_r * g * t),
      .derived_expression = GiNaC::diff(start.kinetic_energy(v_roll_t, w_roll), s.t).expand(),
      .constraints = {speed_length},
      .depends_on = {"rolling.velocity", "rolling.condition"},
  });
  record.add({
      .id = "rolling.energy_nonincreasing",
      .statement = "While rolling (0 ≤ t < t_r) the energy never increases.",
      .method = "sign: minus the rate at t = t_r/(1 + q), q > 0",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = GiNaC::normal(
          (numeric(7, 5) * m * mu_r * g * (nu0 - mu_r * g * t)).subs(s.t == roll_time / (1 + s.q))),
      .depends_on = {"rolling.energy_rate"},
  });

  return roll_time;
}

}  // namespace billiards::derive::spinning
