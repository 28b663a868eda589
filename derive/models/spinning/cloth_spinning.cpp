#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

// The audit section "Spinning on the cloth": the spin about ẑ under the spinning friction; returns the
// stop time.
ex spinning_on_the_cloth(Recorder& record, const ClothStart& start) {
  const Symbols& s = symbols();
  const ex t = s.t, g = s.g, m = s.m, R = s.R;
  const ex inertia = start.inertia;
  const GiNaC::symbol& tau = start.tau;
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
  return spin_time;
}

}  // namespace billiards::derive::spinning
