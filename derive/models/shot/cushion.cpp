// The cushion with spin: the immovable limit of the frictional contact, at the cushion's nose, the
// table holding the ball down; the result against Han (2005)'s equations 14–23.
#include "models/shot/steps.hpp"

#include <string>
#include <vector>

namespace billiards::derive::shot {

namespace {

struct Cushion {
  Vec n, r;     ///< the contact normal (cos θ_a, 0, sin θ_a) and point R n
  Vec v, w;     ///< the ball's velocity (on the cloth, v_z = 0) and spin before
  Vec u;        ///< the contact point's velocity v + ω × r
  Vec u_t;      ///< its part across n
  ex u_n;       ///< its part along n
  Constraint unit;   ///< cos²θ_a + sin²θ_a = 1
  Constraint slip;   ///< σ² = u_t·u_t
};

// The ball's velocity and spin after the impulse P at r, the table cancelling the vertical velocity.
std::vector<Vec> after(const Cushion& c, const Vec& impulse) {
  const Symbols& s = symbols();
  const ex inertia = numeric(2, 5) * s.m * s.R * s.R;
  Vec v = add(c.v, scale(1 / s.m, impulse));
  v[2] = c.v[2];
  return {v, add(c.w, scale(1 / inertia, cross(c.r, impulse)))};
}

ex kinetic_energy(const Vec& v, const Vec& w) {
  const Symbols& s = symbols();
  return s.m * dot(v, v) / 2 + numeric(2, 5) * s.m * s.R * s.R * dot(w, w) / 2;
}

lst outgoing(const std::vector<Vec>& state) {
  return lst{state[0][0], state[0][1], state[1][0], state[1][1], state[1][2]};
}

lst expanded(const lst& list) {
  lst out;
  for (const ex& e : list) out.append(e.expand());
  return out;
}

}  // namespace

void the_cushion(Recorder& record, const Strike& k) {
  const Symbols& s = symbols();
  const ex e = s.cushion_restitution, mu = s.cushion_friction, Pn = s.normal_impulse, j = s.friction_impulse;
  const ex sigma = s.slip;
  record.section("cushion", "The cushion with spin",
                 "The ball meets a straight cushion at its nose, height h above the table: the frictional contact "
                 "in its immovable limit (definition.cushion_impact), with restitution e_c and friction μ_c, the "
                 "table holding the ball on the cloth. The impulse, the sticking and sliding regimes and the "
                 "outgoing state are derived, then compared with Han (2005)'s equations 14–23.");
  Cushion c;
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
      .statement = "The contact point meets the cushion at u·n = v_x cos θ_a: the spin adds nothing along n, and "
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
      .statement = "The contact point responds to an impulse −P_n n by −(P_n/m) n and to one across n, j t, by "
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
  const ex normal_impulse = GiNaC::lsolve(c.u_n - Pn / s.m == -e * c.u_n, Pn);
  record.add({
      .id = "cushion.normal_impulse",
      .paper = "Han (2005), eq. 17",
      .statement = "P_n = (1 + e_c) m v_x cos θ_a.",
      .method = "restitution along n, u_n − P_n/m = −e_c u_n (cushion.inverse_effective_masses), solved for P_n "
                "with lsolve(); identity",
      .comparison = Comparison::identity,
      .paper_expression = (1 + e) * s.m * k.v[0] * s.cos_a,
      .derived_expression = normal_impulse,
      .depends_on = {"cushion.normal_slip", "cushion.inverse_effective_masses",
                     "definition.cushion_restitution_friction"},
  });
  // The slip after a tangential impulse j against it.
  const Vec friction = scale(-j / sigma, c.u_t);
  const Vec u_after = add(c.u, response(friction));
  Vec u_t_after;
  for (const ex& component : subtract(u_after, scale(dot(u_after, c.n), c.n))) u_t_after.push_back(component.expand());
  record.add({
      .id = "cushion.slip_after_friction",
      .statement = "A friction impulse j against the slip leaves u_t' = (1 − 7 j/(2 m σ)) u_t, σ = |u_t|: the slip "
                   "keeps its direction, and j = 2 m σ/7 stops it.",
      .method = "u' = u + Δu for P = −j u_t/σ, its part across n, in components; identity, σ² = u_t·u_t and "
                "cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(scale(1 - numeric(7, 2) * j / (s.m * sigma), c.u_t)),
      .derived_expression = to_lst(u_t_after),
      .constraints = {c.slip, c.unit},
      .depends_on = {"cushion.inverse_effective_masses", "definition.cushion_restitution_friction"},
  });
  const ex sticking = numeric(2, 7) * s.m * sigma;
  const ex sliding = mu * normal_impulse;
  // Han's quantities, typed as published (eqs 14, 16, 17, 20), with v_z = 0.
  const ex sx = k.v[0] * s.sin_a + s.R * k.w[1];
  const ex sy = -k.v[1] - s.R * k.w[2] * s.cos_a + s.R * k.w[0] * s.sin_a;
  const ex han_c = -k.v[0] * s.cos_a;
  const ex A = numeric(7, 2) / s.m, B = 1 / s.m;
  const ex PzE = -(1 + e) * han_c / B;
  const ex PzS = sigma / A;
  record.add({
      .id = "cushion.regime",
      .paper = "Han (2005), eq. 20, with μ restored",
      .paper_tex = "\\mu P_{zE} - P_{zS} \\ge 0",
      .statement = "The impulse sticks iff 2 m σ/7 ≤ μ_c P_n (the slip stops before the impact ends); it slides "
                   "at j = μ_c P_n otherwise. As Han's P_zS ≤ μ P_zE: μ_c P_n − 2 m σ/7 ≥ 0.",
      .method = "μ_c P_n − 2 m σ/7 against Han's μ P_zE − P_zS, P_zE = −(1 + e) c/B, P_zS = |s|/A, |s| = σ; "
                "identity",
      .comparison = Comparison::identity,
      .paper_expression = mu * PzE - PzS,
      .derived_expression = sliding - sticking,
      .note = "Han (2005) prints the test as P_zS ≤ P_zE, without μ: it compares the normal impulse that would "
              "stop the slip at unit friction with the whole normal impulse, so it calls an impact sticking "
              "that slides for every μ < 1. pooltool's han2005 carried the printed form until it was corrected.",
      .depends_on = {"cushion.normal_impulse", "cushion.slip_after_friction"},
  });
  // The outgoing state in each regime, and Han's, typed as published (eqs 18, 19, 21–23).
  const std::vector<Vec> general = after(c, add(scale(-Pn, c.n), friction));
  const GiNaC::exmap with_normal{{Pn, normal_impulse}};
  const auto regime = [&](const ex& friction_impulse) {
    lst out;
    for (const ex& component : outgoing(general)) out.append(component.subs(j == friction_impulse).subs(with_normal));
    return out;
  };
  const auto han = [&](const ex& PxE, const ex& PyE) {
    const ex PX = -PxE * s.sin_a - PzE * s.cos_a, PY = PyE, PZ = PxE * s.cos_a - PzE * s.sin_a;
    const ex II = numeric(2, 5) * s.m * s.R * s.R;
    return lst{k.v[0] + PX / s.m, k.v[1] + PY / s.m, k.w[0] - s.R / II * PY * s.sin_a,
               k.w[1] + s.R / II * (PX * s.sin_a - PZ * s.cos_a), k.w[2] + s.R / II * PY * s.cos_a};
  };
  const lst sticking_state = regime(sticking), sliding_state = regime(sliding);
  record.add({
      .id = "cushion.han_2005_sticking",
      .paper = "Han (2005), eqs 14–18, 21–23 (sticking)",
      .statement = "Sticking, the ball leaves with (v_x', v_y', ω_x', ω_y', ω_z') as Han's equations give them with "
                   "P_xE = s_x/A, P_yE = s_y/A.",
      .method = "v' = v + P/m with v_z' = 0 (the table), ω' = ω + I⁻¹ r × P, P = −P_n n − j u_t/σ, j = 2 m σ/7, "
                "against Han's eqs 14–18 and 21–23 typed as printed; identity, σ² = u_t·u_t and cos²θ_a + "
                "sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = han(sx / A, sy / A),
      .derived_expression = sticking_state,
      .constraints = {c.slip, c.unit},
      .depends_on = {"cushion.regime", "definition.cushion_table"},
  });
  record.add({
      .id = "cushion.han_2005_sliding",
      .paper = "Han (2005), eqs 14–17, 19, 21–23 (sliding)",
      .statement = "Sliding, the ball leaves with (v_x', v_y', ω_x', ω_y', ω_z') as Han's equations give them with "
                   "P_xE = μ P_zE s_x/|s|, P_yE = μ P_zE s_y/|s|.",
      .method = "as for sticking with j = μ_c P_n, against Han's eqs 19 and 21–23, |s| = σ; identity, σ² = u_t·u_t "
                "and cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = han(mu * PzE * sx / sigma, mu * PzE * sy / sigma),
      .derived_expression = sliding_state,
      .constraints = {c.slip, c.unit},
      .depends_on = {"cushion.regime", "definition.cushion_table"},
  });
  // Energy: the change for any j, then its parts' signs.
  const ex P_z = -Pn * s.sin_a - j * c.u_t[2] / sigma;
  const ex energy_change =
      (kinetic_energy(general[0], general[1]) - kinetic_energy(c.v, c.w)).subs(with_normal);
  const ex u_n = k.v[0] * s.cos_a;
  const ex table_impulse{GiNaC::realsymbol("P_z", "P_z")};
  const ex energy_form = -numeric(1, 2) * (1 - e * e) * s.m * u_n * u_n - j * sigma +
                         numeric(7, 4) * j * j / s.m - pow(table_impulse, 2) / (2 * s.m);
  record.add({
      .id = "cushion.energy_change",
      .statement = "The ball's kinetic energy changes by −½ (1 − e_c²) m (v_x cos θ_a)² − j σ + (7/(4m)) j² − "
                   "P_z²/(2m), P_z = −P_n sin θ_a − j u_t,z/σ the vertical impulse the table cancels.",
      .method = "½ m v² + ½ I ω² after minus before, P_n of cushion.normal_impulse, j any; identity, σ² = u_t·u_t "
                "and cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = energy_form.subs(table_impulse == P_z).subs(with_normal),
      .derived_expression = energy_change,
      .constraints = {c.slip, c.unit},
      .depends_on = {"cushion.normal_impulse", "cushion.slip_after_friction", "definition.cushion_table"},
  });
  const ex in_range = s.q / (1 + s.q);
  const ex friction_part = j * sigma - numeric(7, 4) * j * j / s.m;
  struct Part {
    std::string id, statement, method;
    ex loss;
  };
  const std::vector<Part> parts = {
      {"cushion.energy_normal_part", "The normal part of the loss, ½ (1 − e_c²) m (v_x cos θ_a)², is ≥ 0.",
       "sign: at e_c = q/(1 + q), q > 0 (e_c = 0 and 1 by continuity), it factors into positive symbols, sums "
       "of them and even powers",
       (numeric(1, 2) * (1 - e * e) * s.m * u_n * u_n).subs(e == in_range)},
      {"cushion.energy_table_part", "The table's part, P_z²/(2m), is ≥ 0.", "sign: an even power over m",
       pow(table_impulse, 2) / (2 * s.m)},
      {"cushion.energy_sticking_part", "Sticking (j = 2 m σ/7), the friction part j σ − (7/(4m)) j² = m σ²/7 is ≥ 0.",
       "sign: at j = 2 m σ/7 it factors into positive symbols", friction_part.subs(j == sticking)},
      {"cushion.energy_sliding_part", "Sliding (0 < j < 2 m σ/7), the friction part j σ − (7/(4m)) j² is ≥ 0.",
       "sign: at j = (2 m σ/7)/(1 + q), q > 0, it factors into positive symbols and sums of them",
       friction_part.subs(j == sticking / (1 + s.q))},
  };
  for (const Part& part : parts) {
    record.add({
        .id = part.id,
        .statement = part.statement + " With the others: the cushion never adds energy.",
        .method = part.method,
        .comparison = Comparison::nonnegative,
        .paper_expression = 0,
        .derived_expression = GiNaC::normal(part.loss),
        .depends_on = {"cushion.energy_change", "cushion.regime"},
    });
  }
  // μ_c = 0 and h = R (θ_a = 0): the paper's restitution and reflection.
  const GiNaC::exmap level_frictionless{{mu, 0}, {s.cos_a, 1}, {s.sin_a, 0}};
  const Vec x_axis{1, 0, 0};
  const Vec restitution_form = subtract(c.v, scale((1 + e) * dot(c.v, x_axis), x_axis));
  const lst frictionless = expanded(GiNaC::ex_to<lst>(sliding_state.subs(level_frictionless)));
  record.add({
      .id = "cushion.frictionless_at_the_equator",
      .paper = "Parkin (2023), the restitution form",
      .statement = "With μ_c = 0 and the nose at the equator (h = R, θ_a = 0) the cushion gives v' = v − (1 + e_c) "
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
      .statement = "With e_c = 1 as well it is the paper's reflection from an immovable wall, v' = v − 2 (v·n) n.",
      .method = "the frictionless state at the equator with e_c = 1; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{reflection[0], reflection[1], k.w[0], k.w[1], k.w[2]},
      .derived_expression = ex(frictionless).subs(e == 1),
      .depends_on = {"cushion.frictionless_at_the_equator"},
  });
  // English: the side spin ω_z.
  const ex along_rail_sliding = add(scale(-normal_impulse, c.n), scale(-sliding / sigma, c.u_t))[1];
  record.add({
      .id = "cushion.english",
      .statement = "Side spin turns the rebound. Sticking, ∂v_y'/∂ω_z = −(2/7) R cos θ_a and ∂v_x'/∂ω_z = 0: for "
                   "v_y > 0, running English (ω_z < 0, the ball's surface rolling along the cushion) sends the ball "
                   "off faster along the cushion, at a wider angle from its normal, and reverse English (ω_z > 0) "
                   "narrows it. Sliding, the impulse along the cushion is −μ_c P_n (v_y + R ω_z cos θ_a − R ω_x "
                   "sin θ_a)/σ: it speeds the ball along the cushion iff the running English exceeds rolling.",
      .method = "derivatives of the sticking state by ω_z, and the ŷ part of P with j = μ_c P_n; identity",
      .comparison = Comparison::identity,
      .paper_expression =
          lst{-numeric(2, 7) * s.R * s.cos_a, 0,
              -mu * normal_impulse * (k.v[1] + s.R * k.w[2] * s.cos_a - s.R * k.w[0] * s.sin_a) / sigma},
      .derived_expression = lst{sticking_state.op(1).diff(GiNaC::ex_to<GiNaC::symbol>(k.w[2])),
                                sticking_state.op(0).diff(GiNaC::ex_to<GiNaC::symbol>(k.w[2])), along_rail_sliding},
      .depends_on = {"cushion.han_2005_sticking", "cushion.han_2005_sliding"},
  });
  // The outgoing state as the runtime computes it: the slip in the cushion's frame, the impulse per unit
  // mass and the friction ratio k = j/(m σ) (2/7 sticking, μ_c P_n/(m σ) sliding).
  const Vec tangent{s.sin_a, 0, -s.cos_a};
  const Vec along_rail{0, 1, 0};
  const ex slip_tangent = k.v[0] * s.sin_a + s.R * k.w[1];
  const ex slip_along = k.v[1] + s.R * k.w[2] * s.cos_a - s.R * k.w[0] * s.sin_a;
  record.add({
      .id = "cushion.slip_in_cushion_frame",
      .statement = "Across n the contact point slips by u_t = s_t t + s_y ŷ, t = (sin θ_a, 0, −cos θ_a) (down the "
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
      .derived_expression = normal_impulse / s.m,
      .depends_on = {"cushion.normal_impulse"},
  });
  const ex ratio = j / (s.m * sigma);
  const Vec velocity_change = subtract(general[0], c.v), spin_change = subtract(general[1], c.w);
  record.add({
      .id = "cushion.velocity_change",
      .statement = "For any friction impulse j, with k = j/(m σ) (2/7 sticking, μ_c P_n/(m σ) sliding), the "
                   "velocity changes by Δv_x = −(P_n/m) cos θ_a − k s_t sin θ_a and Δv_y = −k s_y (v_z stays 0).",
      .method = "v' − v with P = −P_n n − j u_t/σ, the table's reaction cancelling v_z'; identity, cos²θ_a + "
                "sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = lst{-Pn / s.m * s.cos_a - ratio * slip_tangent * s.sin_a, -ratio * slip_along},
      .derived_expression = lst{velocity_change[0], velocity_change[1]},
      .constraints = {c.unit},
      .depends_on = {"cushion.slip_in_cushion_frame", "cushion.slip_after_friction", "definition.cushion_table"},
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
      .statement = "About n the spin does not change: r is along n. With cushion.spin_change, ω' = ω + (5 k/(2R)) "
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
