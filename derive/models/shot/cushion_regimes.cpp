// The cushion with spin, its regimes: sticking or sliding, and the outgoing state in each against Han
// (2005)'s equations 14–23.
#include "models/shot/steps.hpp"

#include <string>
#include <vector>

namespace billiards::derive::shot {

namespace {

lst outgoing_state(const std::vector<Vec>& state) {
  return lst{state[0][0], state[0][1], state[1][0], state[1][1], state[1][2]};
}

}  // namespace

CushionRegimes the_cushion_regimes(Recorder& record, const Strike& k, const CushionContact& c) {
  const Symbols& s = symbols();
  const ex e = s.cushion_restitution, mu = s.cushion_friction, j = s.friction_impulse, sigma = s.slip;
  CushionRegimes out;
  out.sticking = numeric(2, 7) * s.m * sigma;
  out.sliding = mu * c.normal_impulse;
  const ex &sticking = out.sticking, &sliding = out.sliding;
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
      .statement =
          "The impulse sticks iff 2 m σ/7 ≤ μ_c P_n (the slip stops before the impact ends); it slides "
          "at j = μ_c P_n otherwise. As Han's P_zS ≤ μ P_zE: μ_c P_n − 2 m σ/7 ≥ 0.",
      .method = "μ_c P_n − 2 m σ/7 against Han's μ P_zE − P_zS, P_zE = −(1 + e) c/B, P_zS = |s|/A, |s| = σ; "
                "identity",
      .comparison = Comparison::identity,
      .paper_expression = mu * PzE - PzS,
      .derived_expression = sliding - sticking,
      .note =
          "Han (2005) prints the test as P_zS ≤ P_zE, without μ: it compares the normal impulse that would "
          "stop the slip at unit friction with the whole normal impulse, so it calls an impact sticking "
          "that slides for every μ < 1. pooltool's han2005 carried the printed form until it was corrected.",
      .depends_on = {"cushion.normal_impulse", "cushion.slip_after_friction"},
  });
  // The outgoing state in each regime, and Han's, typed as published (eqs 18, 19, 21–23).
  const auto regime = [&](const ex& friction_impulse) {
    lst state;
    for (const ex& component : outgoing_state(c.after))
      state.append(component.subs(j == friction_impulse).subs(c.with_normal));
    return state;
  };
  const auto han = [&](const ex& PxE, const ex& PyE) {
    const ex PX = -PxE * s.sin_a - PzE * s.cos_a, PY = PyE, PZ = PxE * s.cos_a - PzE * s.sin_a;
    const ex II = numeric(2, 5) * s.m * s.R * s.R;
    return lst{k.v[0] + PX / s.m, k.v[1] + PY / s.m, k.w[0] - s.R / II * PY * s.sin_a,
               k.w[1] + s.R / II * (PX * s.sin_a - PZ * s.cos_a), k.w[2] + s.R / II * PY * s.cos_a};
  };
  out.sticking_state = regime(sticking);
  out.sliding_state = regime(sliding);
  record.add({
      .id = "cushion.han_2005_sticking",
      .paper = "Han (2005), eqs 14–18, 21–23 (sticking)",
      .statement =
          "Sticking, the ball leaves with (v_x', v_y', ω_x', ω_y', ω_z') as Han's equations give them with "
          "P_xE = s_x/A, P_yE = s_y/A.",
      .method =
          "v' = v + P/m with v_z' = 0 (the table), ω' = ω + I⁻¹ r × P, P = −P_n n − j u_t/σ, j = 2 m σ/7, "
          "against Han's eqs 14–18 and 21–23 typed as printed; identity, σ² = u_t·u_t and cos²θ_a + "
          "sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = han(sx / A, sy / A),
      .derived_expression = out.sticking_state,
      .constraints = {c.slip, c.unit},
      .depends_on = {"cushion.regime", "definition.cushion_table"},
  });
  record.add({
      .id = "cushion.han_2005_sliding",
      .paper = "Han (2005), eqs 14–17, 19, 21–23 (sliding)",
      .statement =
          "Sliding, the ball leaves with (v_x', v_y', ω_x', ω_y', ω_z') as Han's equations give them with "
          "P_xE = μ P_zE s_x/|s|, P_yE = μ P_zE s_y/|s|.",
      .method =
          "as for sticking with j = μ_c P_n, against Han's eqs 19 and 21–23, |s| = σ; identity, σ² = u_t·u_t "
          "and cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = han(mu * PzE * sx / sigma, mu * PzE * sy / sigma),
      .derived_expression = out.sliding_state,
      .constraints = {c.slip, c.unit},
      .depends_on = {"cushion.regime", "definition.cushion_table"},
  });
  return out;
}

}  // namespace billiards::derive::shot
