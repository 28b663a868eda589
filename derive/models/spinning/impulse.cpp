#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

namespace {

// The change of slip caused by the impulse `impulse` on ball 2, expanded.
Vec slip_change(const Contact& c, const Vec& impulse) {
  const std::vector<Vec> after = c.after(impulse);
  Vec change = subtract(c.slip(after[0], after[1], after[2], after[3]), c.slip(c.v1, c.w1, c.v2, c.w2));
  for (ex& component : change) component = component.expand();
  return change;
}

// `numerator_component / along_component`, the numerator first reduced modulo n·n = 1: the factor by
// which a vector along `along` is scaled, read off one component.
ex factor_along(const Contact& c, const ex& numerator_component, const ex& along_component) {
  return GiNaC::normal(reduce_modulo(numerator_component, c.unit_normal.relation) / along_component);
}

}  // namespace

Impulse the_impulse(Recorder& record, const Contact& c) {
  const Symbols& s = symbols();
  record.section("impulse", "The impulse and the slip",
                 "The impulse equations (definition.impulse) applied to a general impulse J: how the slip at "
                 "the contact changes. The change is linear in J and splits into a normal part that only the "
                 "normal impulse moves and a tangential part that only the tangential impulse moves; the "
                 "tangential inverse effective mass k is read off, not typed.");
  const Vec general = slip_change(c, c.J);
  const ex rotational = s.R1 * s.R1 / s.I1 + s.R2 * s.R2 / s.I2;
  const Vec printed = add(scale(1 / s.m1 + 1 / s.m2, c.J), scale(rotational, perpendicular_part(c.J, c.n)));
  record.add({
      .id = "impulse.slip_change_linear",
      .statement = "Δu = (1/m1 + 1/m2) J + (R1²/I1 + R2²/I2) J_t, J_t = J − (J·n) n: the change of slip is "
                   "linear in the impulse and independent of the velocities and spins.",
      .method = std::string("u after minus u before, the impulse equations in components; identity") +
                unit_normal_method,
      .comparison = Comparison::identity,
      .paper_expression = to_lst(printed),
      .derived_expression = to_lst(general),
      .constraints = {c.unit_normal},
      .depends_on = {"definition.slip", "definition.impulse", "definition.contact"},
  });
  const Vec along_n = slip_change(c, c.n);
  const ex normal_inverse = factor_along(c, along_n[0], c.n[0]);
  record.add({
      .id = "impulse.normal_inverse_effective_mass",
      .statement = "A unit impulse along n changes the slip by (1/m1 + 1/m2) n: it turns neither ball's spin "
                   "into slip (r × n = 0).",
      .method = "Δu for J = n, its x component reduced modulo n·n = 1 and divided by n_x; identity",
      .comparison = Comparison::identity,
      .paper_expression = 1 / s.m1 + 1 / s.m2,
      .derived_expression = normal_inverse,
      .depends_on = {"impulse.slip_change_linear"},
  });
  const Vec tangent = c.tangent();
  const Vec along_t = slip_change(c, tangent);
  const ex k_general = factor_along(c, along_t[0], tangent[0]);
  record.add({
      .id = "impulse.tangential_inverse_effective_mass",
      .statement = "A unit tangential impulse changes the slip by k along itself, k = 1/m1 + 1/m2 + R1²/I1 + "
                   "R2²/I2: the tangential inverse effective mass of the contact.",
      .method = "Δu for J = t = n × a (tangent for any a), its x component reduced modulo n·n = 1 and "
                "divided by t_x; identity",
      .comparison = Comparison::identity,
      .paper_expression = 1 / s.m1 + 1 / s.m2 + rotational,
      .derived_expression = k_general,
      .depends_on = {"impulse.slip_change_linear"},
  });
  const GiNaC::exmap solid{{s.I1, numeric(2, 5) * s.m1 * s.R1 * s.R1},
                           {s.I2, numeric(2, 5) * s.m2 * s.R2 * s.R2}};
  const ex k_solid = GiNaC::normal(k_general.subs(solid));
  record.add({
      .id = "impulse.tangential_inverse_effective_mass_solid_spheres",
      .statement = "For two solid spheres k = (7/2)(1/m1 + 1/m2): the radii cancel.",
      .method = "I = (2/5) m R² substituted in the derived k; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = numeric(7, 2) * (1 / s.m1 + 1 / s.m2),
      .derived_expression = k_solid,
      .depends_on = {"impulse.tangential_inverse_effective_mass", "definition.solid_sphere"},
  });
  const Vec split_impulse = add(scale(s.normal_impulse, c.n), tangent);
  const Vec split_change = slip_change(c, split_impulse);
  record.add({
      .id = "impulse.decoupled",
      .statement = "For J = J_n n + J_t (J_t ⊥ n) the slip changes by (1/m1 + 1/m2) J_n n + k J_t: the "
                   "normal impulse moves only the normal slip, the tangential impulse only the tangential "
                   "slip.",
      .method = std::string("Δu for J = J_n n + n × a against the derived coefficients; identity") +
                unit_normal_method,
      .comparison = Comparison::identity,
      .paper_expression =
          to_lst(add(scale(normal_inverse * s.normal_impulse, c.n), scale(k_general, tangent))),
      .derived_expression = to_lst(split_change),
      .constraints = {c.unit_normal},
      .depends_on = {"impulse.normal_inverse_effective_mass", "impulse.tangential_inverse_effective_mass"},
  });
  return {k_general, normal_inverse};
}

}  // namespace billiards::derive::spinning
