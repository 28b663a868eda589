#include "models/spinning/steps.hpp"

#include "core/named_constants.hpp"

namespace billiards::derive::spinning {

namespace {

// ∫₀ᵗ f dτ for each component, f in τ (GiNaC integrates the polynomial).
Vec integrate(const Vec& f, const GiNaC::symbol& tau, const ex& t) {
  Vec out;
  for (const ex& component : f) out.push_back(GiNaC::integral(tau, 0, t, component).eval_integ().expand());
  return out;
}

Vec at_time(const Vec& f, const GiNaC::symbol& tau, const ex& t) {
  Vec out;
  for (const ex& component : f) out.push_back(component.subs(tau == t));
  return out;
}

}  // namespace

Cloth the_cloth(Recorder& record) {
  const Symbols& s = symbols();
  const ex t = s.t, g = s.g, m = s.m, R = s.R;
  const ex inertia = numeric(2, 5) * m * R * R;
  const Vec z{0, 0, 1}, contact{0, 0, -R};
  const Vec v0{GiNaC::realsymbol("v0_x", "v_{0,x}"), GiNaC::realsymbol("v0_y", "v_{0,y}"), 0};
  const Vec w0{GiNaC::realsymbol("w0_x", "\\omega_{0,x}"), GiNaC::realsymbol("w0_y", "\\omega_{0,y}"), 0};
  const Vec r0{GiNaC::realsymbol("r0_x", "r_{0,x}"), GiNaC::realsymbol("r0_y", "r_{0,y}"), R};
  const GiNaC::symbol tau("tau", "\\tau");
  const auto energy = [&](const Vec& v, const Vec& w) {
    return numeric(1, 2) * m * dot(v, v) + numeric(1, 2) * inertia * dot(w, w);
  };

  // ---- Sliding --------------------------------------------------------------------------------------
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
  const Vec w_slide = add(w0, integrate(scale(1 / inertia, cross(contact, force)), tau, tau));
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
  const ex slide_rate = GiNaC::diff(energy(v_t, w_t), s.t).expand();
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

  // ---- Rolling --------------------------------------------------------------------------------------
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
      .derived_expression = GiNaC::diff(energy(v_roll_t, w_roll), s.t).expand(),
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

  // ---- Spinning -------------------------------------------------------------------------------------
  record.section(
      "cloth_spinning", "Spinning on the cloth",
      "The spin about ẑ meets the spinning friction's torque −μ_sp m g R sgn(ω_z) ẑ in every phase "
      "until it stops; integrated for ω_z0 > 0 (the other sign is its mirror image).");
  const ex mu_sp = s.spinning_friction, omega0 = s.spin;
  const ex spin_rate = GiNaC::integral(tau, 0, t, -mu_sp * m * g * R / inertia).eval_integ();
  const ex omega_t = GiNaC::normal(omega0 + spin_rate);
  record.add({
      .id = "spinning.angular_velocity",
      .statement = "ω_z(t) = ω_z0 − (5 μ_sp g/(2R)) t: the spin decays at 5 μ_sp g/(2R).",
      .method = "I dω_z/dt = −μ_sp m g R integrated from 0 to t; identity",
      .comparison = Comparison::identity,
      .paper_expression = omega0 - 5 * mu_sp * g * t / (2 * R),
      .derived_expression = omega_t,
      .depends_on = {"definition.cloth", "definition.solid_sphere"},
  });
  const ex spin_time = GiNaC::lsolve(omega_t == 0, s.t);
  record.add({
      .id = "spinning.stop_time",
      .statement = "The spin stops at t_z = 2 R |ω_z0|/(5 μ_sp g).",
      .method = "lsolve() of ω_z(t) = 0 for t; identity",
      .comparison = Comparison::identity,
      .paper_expression = 2 * R * omega0 / (5 * mu_sp * g),
      .derived_expression = spin_time,
      .depends_on = {"spinning.angular_velocity"},
  });
  record.add({
      .id = "spinning.frictionless_spins_on",
      .statement = "With μ_sp = 0 the spin about ẑ never changes (the stop time is +∞).",
      .method = "μ_sp = 0 in ω_z(t); identity",
      .comparison = Comparison::identity,
      .paper_expression = omega0,
      .derived_expression = omega_t.subs(mu_sp == 0),
      .depends_on = {"spinning.angular_velocity"},
      .cases = {{lst{mu_sp <= 0}, infinity()}},
  });
  const ex spin_energy_rate = GiNaC::diff(numeric(1, 2) * inertia * omega_t * omega_t, s.t).expand();
  record.add({
      .id = "spinning.energy_rate",
      .statement = "The spin's energy ½ I ω_z² changes at −μ_sp m g R ω_z(t).",
      .method = "d/dt of ½ I ω_z(t)² with diff(); identity",
      .comparison = Comparison::identity,
      .paper_expression = -mu_sp * m * g * R * (omega0 - 5 * mu_sp * g * t / (2 * R)),
      .derived_expression = spin_energy_rate,
      .depends_on = {"spinning.angular_velocity"},
  });
  record.add({
      .id = "spinning.energy_nonincreasing",
      .statement = "Until the spin stops (0 ≤ t < t_z) its energy never increases.",
      .method = "sign: minus the rate at t = t_z/(1 + q), q > 0",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = GiNaC::normal(-spin_energy_rate.subs(s.t == spin_time / (1 + s.q))),
      .depends_on = {"spinning.energy_rate"},
  });
  return {slide_time, roll_time, spin_time};
}

}  // namespace billiards::derive::spinning
