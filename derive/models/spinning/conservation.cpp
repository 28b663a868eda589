#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

void conservation(Recorder& record, const Contact& c, const Impulse& impulse) {
  const Symbols& s = symbols();
  record.section("conservation", "What the impulse conserves",
                 "Linear momentum, each ball's angular momentum about its contact point, and the change of "
                 "kinetic energy (translational and rotational) in terms of the impulse and the slip.");
  const std::vector<Vec> after = c.after(c.J);
  const auto momentum = [&](const Vec& v1, const Vec& v2) { return add(scale(s.m1, v1), scale(s.m2, v2)); };
  record.add({
      .id = "conservation.linear_momentum",
      .statement = "m1 v1' + m2 v2' = m1 v1 + m2 v2 for any impulse J.",
      .method = "the impulse equations in components; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(momentum(c.v1, c.v2)),
      .derived_expression = to_lst(momentum(after[0], after[2])),
      .depends_on = {"definition.impulse"},
  });
  // About its contact point a ball's centre sits at −R1 n (ball 1) and R2 n (ball 2).
  const auto about_contact = [&](const Vec& w, const Vec& v, const ex& inertia, const ex& mass,
                                 const Vec& centre) {
    return add(scale(inertia, w), scale(mass, cross(centre, v)));
  };
  const Vec centre1 = scale(-1, c.r1()), centre2 = scale(-1, c.r2());
  record.add({
      .id = "conservation.angular_momentum_about_contact_first",
      .statement =
          "Ball 1's angular momentum about its contact point, I1 ω1 + (−R1 n) × m1 v1, is unchanged: "
          "the impulse acts at that point.",
      .method = "the impulse equations in components; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(about_contact(c.w1, c.v1, s.I1, s.m1, centre1)),
      .derived_expression = to_lst(about_contact(after[1], after[0], s.I1, s.m1, centre1)),
      .depends_on = {"definition.impulse", "definition.contact"},
  });
  record.add({
      .id = "conservation.angular_momentum_about_contact_second",
      .statement = "Ball 2's angular momentum about its contact point, I2 ω2 + (R2 n) × m2 v2, is unchanged.",
      .method = "the impulse equations in components; identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(about_contact(c.w2, c.v2, s.I2, s.m2, centre2)),
      .derived_expression = to_lst(about_contact(after[3], after[2], s.I2, s.m2, centre2)),
      .depends_on = {"definition.impulse", "definition.contact"},
  });
  const Vec tangent = c.tangent();
  const Vec split_impulse = add(scale(s.normal_impulse, c.n), tangent);
  const std::vector<Vec> split_after = c.after(split_impulse);
  const ex change = (c.kinetic_energy(split_after) - c.kinetic_energy({c.v1, c.w1, c.v2, c.w2})).expand();
  const Vec slip = c.slip(c.v1, c.w1, c.v2, c.w2);
  const ex printed = dot(split_impulse, slip) +
                     numeric(1, 2) * impulse.normal_inverse * s.normal_impulse * s.normal_impulse +
                     numeric(1, 2) * impulse.k_general * dot(tangent, tangent);
  record.add({
      .id = "conservation.energy_change",
      .statement =
          "For J = J_n n + J_t the kinetic energy changes by J·u + ½ (1/m1 + 1/m2) J_n² + ½ k |J_t|², "
          "u the slip before the impulse.",
      .method = std::string("½ m v² + ½ I ω² of both balls after minus before, J_t = n × a; identity") +
                unit_normal_method,
      .comparison = Comparison::identity,
      .paper_expression = printed,
      .derived_expression = change,
      .constraints = {c.unit_normal},
      .depends_on = {"impulse.decoupled", "definition.slip"},
  });
}

}  // namespace billiards::derive::spinning
