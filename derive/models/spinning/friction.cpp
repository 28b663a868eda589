#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

namespace {

// The section's energy claims: the work of the impulse, the change of kinetic energy, and its sign for
// the normal part and in both regimes of friction.
void friction_energy(Recorder& record, const Contact& c, const Impulse& impulse, const Friction& friction) {
  const Symbols& s = symbols();
  const ex e = s.restitution, un = s.normal_slip, Jn = s.normal_impulse, j = s.tangential_impulse;
  const ex sigma = s.tangential_slip, k = impulse.k_general;
  const ex reduced_mass = s.m1 * s.m2 / (s.m1 + s.m2);
  const ex below_sticking = friction.sticking_impulse / (1 + s.q);  // 0 < j < |u_t|/k, q > 0
  const Vec tau = c.tangent();
  const Constraint tangent_length{GiNaC::pow(sigma, 2) == dot(tau, tau).expand(), "|u_t|² = u_t·u_t"};
  // J·u for J = J_n n − j û_t and u = (u·n) n + u_t.
  const Vec impulse_vector = add(scale(Jn, c.n), scale(-j / sigma, tau));
  const Vec slip_split = add(scale(un, c.n), tau);
  record.add({
      .id = "friction.impulse_work",
      .statement = "J·u = J_n u·n − j |u_t| for J = J_n n − j û_t.",
      .method = std::string("u = (u·n) n + u_t with u_t = n × a; identity, |u_t|² → u_t·u_t imposed") +
                unit_normal_method,
      .comparison = Comparison::identity,
      .paper_expression = Jn * un - j * sigma,
      .derived_expression = dot(impulse_vector, slip_split).expand(),
      .constraints = {tangent_length, c.unit_normal},
      .depends_on = {"definition.coulomb_friction"},
  });
  const ex energy_change = GiNaC::normal(
      (Jn * un - j * sigma + numeric(1, 2) * impulse.normal_inverse * Jn * Jn + numeric(1, 2) * k * j * j)
          .subs(Jn == friction.normal_impulse));
  record.add({
      .id = "friction.energy_change",
      .statement = "The kinetic energy changes by −½ (1 − e²) μ_red ((v2 − v1)·n)² − j |u_t| + ½ k j².",
      .method = "conservation.energy_change with J·u from friction.impulse_work and J_n from "
                "friction.normal_impulse; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression =
          -numeric(1, 2) * (1 - e * e) * reduced_mass * un * un - j * sigma + numeric(1, 2) * k * j * j,
      .derived_expression = energy_change,
      .depends_on = {"conservation.energy_change", "friction.impulse_work", "friction.normal_impulse"},
  });
  const ex in_range = s.q / (1 + s.q);  // e ∈ (0, 1)
  const ex normal_part = energy_change.subs(lst{j == 0});
  record.add({
      .id = "friction.normal_energy_loss_nonnegative",
      .statement =
          "The normal impulse creates no energy: −½ (1 − e²) μ_red ((v2 − v1)·n)² ≤ 0 for 0 ≤ e ≤ 1.",
      .method = "sign: minus the change at j = 0 and e = q/(1 + q), q > 0 (e in (0, 1); e = 0 and 1 by "
                "continuity), factors into positive symbols and even powers",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = GiNaC::normal(-normal_part.subs(e == in_range)),
      .depends_on = {"friction.energy_change"},
  });
  const ex friction_part = GiNaC::normal(energy_change - normal_part);
  record.add({
      .id = "friction.energy_nonincreasing_sticking",
      .statement = "Sticking (j = |u_t|/k) takes energy out: −j |u_t| + ½ k j² = −|u_t|²/(2k) ≤ 0, so with "
                   "the normal part the change is ≤ 0.",
      .method = "sign: minus the friction part of the change at j = |u_t|/k factors into positive symbols",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = GiNaC::normal(-friction_part.subs(j == friction.sticking_impulse)),
      .depends_on = {"friction.energy_change", "friction.sticking_impulse",
                     "friction.normal_energy_loss_nonnegative"},
  });
  record.add({
      .id = "friction.energy_nonincreasing_sliding",
      .statement = "Sliding (0 < j < |u_t|/k) takes energy out: −j |u_t| + ½ k j² ≤ 0, so with the normal "
                   "part the change is ≤ 0.",
      .method = "sign: minus the friction part at j = (|u_t|/k)/(1 + q), q > 0, factors into positive "
                "symbols and sums of them",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = GiNaC::normal(-friction_part.subs(j == below_sticking)),
      .depends_on = {"friction.energy_change", "friction.sliding_never_reverses",
                     "friction.normal_energy_loss_nonnegative"},
  });
}

}  // namespace

Friction the_friction(Recorder& record, const Contact& c, const Impulse& impulse) {
  const Symbols& s = symbols();
  const ex e = s.restitution, un = s.normal_slip, Jn = s.normal_impulse, j = s.tangential_impulse;
  const ex sigma = s.tangential_slip, k = impulse.k_general;
  record.section("friction", "The normal impulse and Coulomb friction",
                 "Restitution fixes the normal impulse; Coulomb friction bounds the tangential one by μ J_n. "
                 "Either it stops the slip within the bound (sticking) or it acts at the bound throughout "
                 "(sliding); in both the slip keeps its direction, and no energy is created.");
  const Vec slip = c.slip(c.v1, c.w1, c.v2, c.w2);
  record.add({
      .id = "friction.normal_slip_is_relative_normal_velocity",
      .statement = "u·n = (v2 − v1)·n: the spins add nothing to the normal slip, so the balls approach iff "
                   "u·n < 0.",
      .method = "the slip in components dotted with n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = dot(subtract(c.v2, c.v1), c.n),
      .derived_expression = dot(slip, c.n).expand(),
      .depends_on = {"definition.slip"},
  });
  const ex normal_after = un + impulse.normal_inverse * Jn;
  const ex normal_impulse = GiNaC::normal(GiNaC::lsolve(normal_after == -e * un, Jn));
  const ex reduced_mass = s.m1 * s.m2 / (s.m1 + s.m2);
  record.add({
      .id = "friction.normal_impulse",
      .statement = "J_n = −(1 + e) μ_red u·n, μ_red = m1 m2/(m1 + m2): for approaching balls (1 + e) μ_red "
                   "|(v2 − v1)·n|, the restitution result, whatever the spins.",
      .method = "lsolve() of u·n + (1/m1 + 1/m2) J_n = −e u·n (impulse.decoupled, definition.restitution) "
                "for J_n; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = -(1 + e) * reduced_mass * un,
      .derived_expression = normal_impulse,
      .depends_on = {"impulse.decoupled", "definition.restitution",
                     "friction.normal_slip_is_relative_normal_velocity"},
  });
  // The tangential slip is a tangent vector τ = n × a of length σ; J_t = −j τ/σ.
  const Vec tau = c.tangent();
  const std::vector<Vec> after = c.after(scale(-j / sigma, tau));
  const Vec slip_after = c.slip(after[0], after[1], after[2], after[3]);
  // τ' = τ + Δu, Δu in components: the tangential slip after the impulse.
  Vec tangential_after;
  for (std::size_t i = 0; i < 3; ++i) tangential_after.push_back((tau[i] + slip_after[i] - slip[i]).expand());
  const Constraint tangent_length{GiNaC::pow(sigma, 2) == dot(tau, tau).expand(), "|u_t|² = u_t·u_t"};
  const ex sticking = GiNaC::normal(GiNaC::lsolve(
      GiNaC::normal(reduce_modulo(tangential_after[0], c.unit_normal.relation) / tau[0]) == 0, j));
  record.add({
      .id = "friction.sticking_impulse",
      .statement = "The tangential impulse that stops the slip is j = |u_t|/k.",
      .method = "u_t' = u_t + Δu for J_t = −j u_t/|u_t| (u_t = n × a, the impulse equations in components), "
                "its x component divided by u_t,x and solved for j with lsolve(); identity",
      .comparison = Comparison::identity,
      .paper_expression = sigma / k,
      .derived_expression = sticking,
      .depends_on = {"impulse.decoupled", "definition.coulomb_friction"},
  });
  record.add({
      .id = "friction.sliding_scales_slip",
      .statement =
          "A tangential impulse j against the slip leaves u_t' = (1 − k j/|u_t|) u_t: the slip keeps "
          "its direction and only its length changes; at j = |u_t|/k it is zero (sticking).",
      .method = std::string("u_t' in components against (1 − k j/σ) u_t; identity") + unit_normal_method,
      .comparison = Comparison::identity,
      .paper_expression = to_lst(scale(1 - k * j / sigma, tau)),
      .derived_expression = to_lst(tangential_after),
      .constraints = {c.unit_normal},
      .depends_on = {"friction.sticking_impulse"},
  });
  const ex factor = 1 - k * j / sigma;
  const ex below_sticking = sticking / (1 + s.q);  // 0 < j < |u_t|/k, q > 0
  record.add({
      .id = "friction.sliding_never_reverses",
      .statement = "Sliding (μ J_n < |u_t|/k, so j = μ J_n) never reverses the slip: 1 − k j/|u_t| ≥ 0.",
      .method = "sign: j = (|u_t|/k)/(1 + q), q > 0, covers 0 < j < |u_t|/k; the factor is then q/(1 + q)",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = GiNaC::normal(factor.subs(j == below_sticking)),
      .depends_on = {"friction.sliding_scales_slip"},
  });
  record.add({
      .id = "friction.sliding_reduces_slip",
      .statement = "Friction reduces the slip: 1 minus the factor, k j/|u_t|, is ≥ 0.",
      .method = "sign: k j/|u_t| is a product of positive symbols",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = GiNaC::normal(1 - factor),
      .depends_on = {"friction.sliding_scales_slip"},
  });
  const Friction friction{normal_impulse, sticking};
  friction_energy(record, c, impulse, friction);
  return friction;
}

}  // namespace billiards::derive::spinning
