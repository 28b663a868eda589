// The cushion with spin in its own frame, as the runtime computes it: the slip's parts, the impulse per
// unit mass and the friction ratio, the velocity and spin changes.
#include "models/shot/steps.hpp"

#include <string>
#include <vector>

namespace billiards::derive::shot {

void the_cushion_in_its_frame(Recorder& record, const Strike& k, const CushionContact& c) {
  const Symbols& s = symbols();
  const ex e = s.cushion_restitution, Pn = s.normal_impulse, j = s.friction_impulse, sigma = s.slip;
  // The outgoing state as the runtime computes it: the slip in the cushion's frame, the impulse per unit
  // mass and the friction ratio k = j/(m σ) (2/7 sticking, μ_c P_n/(m σ) sliding).
  const Vec tangent{s.sin_a, 0, -s.cos_a};
  const Vec along_rail{0, 1, 0};
  const ex slip_tangent = k.v[0] * s.sin_a + s.R * k.w[1];
  const ex slip_along = k.v[1] + s.R * k.w[2] * s.cos_a - s.R * k.w[0] * s.sin_a;
  record.add({
      .id = "cushion.slip_in_cushion_frame",
      .statement =
          "Across n the contact point slips by u_t = s_t t + s_y ŷ, t = (sin θ_a, 0, −cos θ_a) (down the "
          "nose, into the cushion), s_t = v_x sin θ_a + R ω_y, s_y = v_y + R ω_z cos θ_a − R ω_x sin θ_a: "
          "Han's s_x and −s_y (eq. 14).",
      .method = "u_t dotted with t and ŷ; identity, cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = lst{slip_tangent, slip_along},
      .derived_expression = lst{dot(c.u_t, tangent), dot(c.u_t, along_rail)},
      .constraints = {c.unit},
      .depends_on = {"cushion.normal_slip"},
  });
  record.add({
      .id = "cushion.slip_size",
      .statement = "σ² = s_t² + s_y²: t and ŷ span the plane across n.",
      .method = "u_t·u_t against s_t² + s_y²; identity, cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = pow(slip_tangent, 2) + pow(slip_along, 2),
      .derived_expression = dot(c.u_t, c.u_t),
      .constraints = {c.unit},
      .depends_on = {"cushion.slip_in_cushion_frame"},
  });
  record.add({
      .id = "cushion.normal_impulse_per_unit_mass",
      .statement = "Per unit mass the normal impulse is P_n/m = (1 + e_c) v_x cos θ_a.",
      .method = "cushion.normal_impulse over m; identity",
      .comparison = Comparison::identity,
      .paper_expression = (1 + e) * k.v[0] * s.cos_a,
      .derived_expression = c.normal_impulse / s.m,
      .depends_on = {"cushion.normal_impulse"},
  });
  const ex ratio = j / (s.m * sigma);
  const Vec velocity_change = subtract(c.after[0], c.v), spin_change = subtract(c.after[1], c.w);
  record.add({
      .id = "cushion.velocity_change",
      .statement =
          "For any friction impulse j, with k = j/(m σ) (2/7 sticking, μ_c P_n/(m σ) sliding), the "
          "velocity changes by Δv_x = −(P_n/m) cos θ_a − k s_t sin θ_a and Δv_y = −k s_y (v_z stays 0).",
      .method = "v' − v with P = −P_n n − j u_t/σ, the table's reaction cancelling v_z'; identity, cos²θ_a + "
                "sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = lst{-Pn / s.m * s.cos_a - ratio * slip_tangent * s.sin_a, -ratio * slip_along},
      .derived_expression = lst{velocity_change[0], velocity_change[1]},
      .constraints = {c.unit},
      .depends_on = {"cushion.slip_in_cushion_frame", "cushion.slip_after_friction",
                     "definition.cushion_table"},
  });
  record.add({
      .id = "cushion.spin_change",
      .statement = "The spin changes by (5 k/(2R)) s_y about t and −(5 k/(2R)) s_t about ŷ.",
      .method = "ω' − ω = (5/(2 m R²)) r × P dotted with t and ŷ; identity, cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = lst{5 * ratio * slip_along / (2 * s.R), -5 * ratio * slip_tangent / (2 * s.R)},
      .derived_expression = lst{dot(spin_change, tangent), dot(spin_change, along_rail)},
      .constraints = {c.unit},
      .depends_on = {"cushion.slip_in_cushion_frame", "cushion.slip_after_friction"},
  });
  record.add({
      .id = "cushion.no_spin_change_about_the_normal",
      .statement =
          "About n the spin does not change: r is along n. With cushion.spin_change, ω' = ω + (5 k/(2R)) "
          "(s_y t − s_t ŷ).",
      .method = "(ω' − ω)·n; identity, cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = 0,
      .derived_expression = dot(spin_change, c.n),
      .constraints = {c.unit},
      .depends_on = {"cushion.spin_change"},
  });
}

}  // namespace billiards::derive::shot
