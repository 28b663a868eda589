// The cushion with spin, its contact: the immovable limit of the frictional contact at the cushion's nose,
// the table holding the ball down; the normal impulse and the slip after friction.
#include "models/shot/steps.hpp"

#include <string>
#include <vector>

namespace billiards::derive::shot {

namespace {

// The ball's velocity and spin after the impulse P at r, the table cancelling the vertical velocity.
std::vector<Vec> after(const CushionContact& c, const Vec& impulse) {
  const Symbols& s = symbols();
  const ex inertia = numeric(2, 5) * s.m * s.R * s.R;
  Vec v = add(c.v, scale(1 / s.m, impulse));
  v[2] = c.v[2];
  return {v, add(c.w, scale(1 / inertia, cross(c.r, impulse)))};
}

}  // namespace

CushionContact the_cushion_contact(Recorder& record, const Strike& k) {
  const Symbols& s = symbols();
  const ex e = s.cushion_restitution, Pn = s.normal_impulse, j = s.friction_impulse, sigma = s.slip;
  record.section(
      "cushion", "The cushion with spin",
      "The ball meets a straight cushion at its nose, height h above the table: the frictional contact "
      "in its immovable limit (definition.cushion_impact), with restitution e_c and friction μ_c, the "
      "table holding the ball on the cloth. The impulse, the sticking and sliding regimes and the "
      "outgoing state are derived, then compared with Han (2005)'s equations 14–23.");
  CushionContact c;
  c.n = {s.cos_a, 0, s.sin_a};
  c.r = scale(s.R, c.n);
  c.v = {k.v[0], k.v[1], 0};
  c.w = k.w;
  c.u = add(c.v, cross(c.w, c.r));
  c.unit = {pow(s.sin_a, 2) == 1 - pow(s.cos_a, 2), "cos²θ_a + sin²θ_a = 1"};
  c.u_n = dot(c.u, c.n).expand();
  for (const ex& component : subtract(c.u, scale(c.u_n, c.n))) c.u_t.push_back(component.expand());
  c.slip = {pow(sigma, 2) == dot(c.u_t, c.u_t).expand(), "σ² = u_t·u_t"};
  record.add({
      .id = "cushion.normal_slip",
      .statement =
          "The contact point meets the cushion at u·n = v_x cos θ_a: the spin adds nothing along n, and "
          "the ball approaches iff v_x > 0.",
      .method = "u = v + ω × r in components dotted with n; identity",
      .comparison = Comparison::identity,
      .paper_expression = k.v[0] * s.cos_a,
      .derived_expression = c.u_n,
      .depends_on = {"definition.cushion", "definition.cushion_table"},
  });
  // The contact point's response to an impulse along −n and to one across n, t = n × g.
  const Vec g = component_symbols("g", "g", "", 3);
  const Vec t = cross(c.n, g);
  const auto response = [&](const Vec& impulse) {
    const ex inertia = numeric(2, 5) * s.m * s.R * s.R;
    return add(scale(1 / s.m, impulse), cross(scale(1 / inertia, cross(c.r, impulse)), c.r));
  };
  record.add({
      .id = "cushion.inverse_effective_masses",
      .paper = "Han (2005), eq. 16: B = 1/m, A = 7/(2m)",
      .statement =
          "The contact point responds to an impulse −P_n n by −(P_n/m) n and to one across n, j t, by "
          "(7/(2m)) j t: the frictional contact's 1/m1 + 1/m2 and 1/m1 + 1/m2 + R1²/I1 + R2²/I2 with the "
          "cushion's inverse mass and inertia zero, and the two directions decoupled.",
      .method = "Δv + Δω × r for the impulse at r (the ball's free response; the table's reaction is applied "
                "after), t = n × g for any g; identity, cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = concatenate({scale(-Pn / s.m, c.n), scale(numeric(7, 2) * j / s.m, t)}),
      .derived_expression = concatenate({response(scale(-Pn, c.n)), response(scale(j, t))}),
      .constraints = {c.unit},
      .depends_on = {"definition.cushion_impact", "definition.solid_sphere"},
  });
  c.normal_impulse = GiNaC::lsolve(c.u_n - Pn / s.m == -e * c.u_n, Pn);
  record.add({
      .id = "cushion.normal_impulse",
      .paper = "Han (2005), eq. 17",
      .statement = "P_n = (1 + e_c) m v_x cos θ_a.",
      .method =
          "restitution along n, u_n − P_n/m = −e_c u_n (cushion.inverse_effective_masses), solved for P_n "
          "with lsolve(); identity",
      .comparison = Comparison::identity,
      .paper_expression = (1 + e) * s.m * k.v[0] * s.cos_a,
      .derived_expression = c.normal_impulse,
      .depends_on = {"cushion.normal_slip", "cushion.inverse_effective_masses",
                     "definition.cushion_restitution_friction"},
  });
  // The slip after a tangential impulse j against it.
  c.friction = scale(-j / sigma, c.u_t);
  const Vec u_after = add(c.u, response(c.friction));
  Vec u_t_after;
  for (const ex& component : subtract(u_after, scale(dot(u_after, c.n), c.n)))
    u_t_after.push_back(component.expand());
  record.add({
      .id = "cushion.slip_after_friction",
      .statement =
          "A friction impulse j against the slip leaves u_t' = (1 − 7 j/(2 m σ)) u_t, σ = |u_t|: the slip "
          "keeps its direction, and j = 2 m σ/7 stops it.",
      .method = "u' = u + Δu for P = −j u_t/σ, its part across n, in components; identity, σ² = u_t·u_t and "
                "cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(scale(1 - numeric(7, 2) * j / (s.m * sigma), c.u_t)),
      .derived_expression = to_lst(u_t_after),
      .constraints = {c.slip, c.unit},
      .depends_on = {"cushion.inverse_effective_masses", "definition.cushion_restitution_friction"},
  });
  // The state after the impulse, P_n and j still symbols, and P_n's solution to put in.
  c.after = after(c, add(scale(-Pn, c.n), c.friction));
  c.with_normal = {{Pn, c.normal_impulse}};
  return c;
}

}  // namespace billiards::derive::shot
