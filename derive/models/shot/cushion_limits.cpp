// The cushion with spin, its limits: frictionless at the equator (the paper's restitution and reflection)
// and the side spin that turns the rebound.
#include "models/shot/steps.hpp"

#include <string>
#include <vector>

namespace billiards::derive::shot {

namespace {

lst expanded_list(const lst& list) {
  lst out;
  for (const ex& e : list) out.append(e.expand());
  return out;
}

}  // namespace

void the_cushion_limits(Recorder& record, const Strike& k, const CushionContact& c,
                        const CushionRegimes& regimes) {
  const Symbols& s = symbols();
  const ex e = s.cushion_restitution, mu = s.cushion_friction, j = s.friction_impulse, sigma = s.slip;
  // μ_c = 0 and h = R (θ_a = 0): the paper's restitution and reflection.
  const GiNaC::exmap level_frictionless{{mu, 0}, {s.cos_a, 1}, {s.sin_a, 0}};
  const Vec x_axis{1, 0, 0};
  const Vec restitution_form = subtract(c.v, scale((1 + e) * dot(c.v, x_axis), x_axis));
  const lst frictionless = expanded_list(GiNaC::ex_to<lst>(regimes.sliding_state.subs(level_frictionless)));
  record.add({
      .id = "cushion.frictionless_at_the_equator",
      .paper = "Parkin (2023), the restitution form",
      .statement =
          "With μ_c = 0 and the nose at the equator (h = R, θ_a = 0) the cushion gives v' = v − (1 + e_c) "
          "(v·n) n and leaves the spin alone.",
      .method = "the sliding state (σ > 0; sticking with μ_c = 0 needs σ = 0, where j = 0 too) with μ_c = 0, "
                "cos θ_a = 1, sin θ_a = 0; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{restitution_form[0], restitution_form[1], k.w[0], k.w[1], k.w[2]},
      .derived_expression = frictionless,
      .depends_on = {"cushion.han_2005_sliding"},
  });
  const Vec reflection = subtract(c.v, scale(2 * dot(c.v, x_axis), x_axis));
  record.add({
      .id = "cushion.frictionless_elastic_is_the_paper",
      .paper = "Parkin (2023), the wall limit v1 − 2 (v1·n) n",
      .statement =
          "With e_c = 1 as well it is the paper's reflection from an immovable wall, v' = v − 2 (v·n) n.",
      .method = "the frictionless state at the equator with e_c = 1; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{reflection[0], reflection[1], k.w[0], k.w[1], k.w[2]},
      .derived_expression = ex(frictionless).subs(e == 1),
      .depends_on = {"cushion.frictionless_at_the_equator"},
  });
  // English: the side spin ω_z.
  const ex along_rail_sliding = add(scale(-c.normal_impulse, c.n), scale(-regimes.sliding / sigma, c.u_t))[1];
  record.add({
      .id = "cushion.english",
      .statement =
          "Side spin turns the rebound. Sticking, ∂v_y'/∂ω_z = −(2/7) R cos θ_a and ∂v_x'/∂ω_z = 0: for "
          "v_y > 0, running English (ω_z < 0, the ball's surface rolling along the cushion) sends the ball "
          "off faster along the cushion, at a wider angle from its normal, and reverse English (ω_z > 0) "
          "narrows it. Sliding, the impulse along the cushion is −μ_c P_n (v_y + R ω_z cos θ_a − R ω_x "
          "sin θ_a)/σ: it speeds the ball along the cushion iff the running English exceeds rolling.",
      .method = "derivatives of the sticking state by ω_z, and the ŷ part of P with j = μ_c P_n; identity",
      .comparison = Comparison::identity,
      .paper_expression =
          lst{-numeric(2, 7) * s.R * s.cos_a, 0,
              -mu * c.normal_impulse * (k.v[1] + s.R * k.w[2] * s.cos_a - s.R * k.w[0] * s.sin_a) / sigma},
      .derived_expression =
          lst{regimes.sticking_state.op(1).diff(GiNaC::ex_to<GiNaC::symbol>(k.w[2])),
              regimes.sticking_state.op(0).diff(GiNaC::ex_to<GiNaC::symbol>(k.w[2])), along_rail_sliding},
      .depends_on = {"cushion.han_2005_sticking", "cushion.han_2005_sliding"},
  });
}

}  // namespace billiards::derive::shot
