#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

// The audit section "Pressed contacts": the forces that keep two balls, or a ball and a cushion's nose,
// together while the cloth presses them, on the line of the contact (n = x̂, the spins about ŷ = ẑ × n),
// from Newton's and Euler's laws.
void pressed_contacts(Recorder& record) {
  const Symbols& s = symbols();
  const ex g = s.g, m = s.m, R = s.R, mu_s = s.sliding_friction;
  const ex inertia = numeric(2, 5) * m * R * R;
  const Vec x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  static const GiNaC::possymbol N("N", "N"), T("T", "T"), P("P", "P"), mu_b("mu_b", "\\mu_b"),
      mu_c("mu_c", "\\mu_c"), sigma("sigma_c", "\\sigma"), cos_nose("cos_theta", "\\cos\\theta_a"),
      sin_nose("sin_theta", "\\sin\\theta_a");
  static const GiNaC::realsymbol f("f", "f"), side("s", "s"), wa("w_A", "\\omega_A"), wb("w_B", "\\omega_B");
  record.section("pressed", "Pressed contacts",
                 "Where the cloth presses two balls together (A behind, B in front along n) or a ball into a "
                 "cushion's nose, with everything on the line of the contact (n = x̂, spins about ŷ = ẑ × n), "
                 "the limit of the repeated contacts is a force: the normal force m N on B (−m N on A), the "
                 "balls' friction m T vertical at their contact, the cloth's m f at −R ẑ. Per unit mass each "
                 "ball has v̇ = s N + f (s = −1 for A, +1 for B) and R ω̇_y = −(5/2)(f + T); the engine's "
                 "pieces of sustained contact solve these for N with v̇_A = v̇_B.");
  const std::vector<std::string> laws = {"definition.cloth", "definition.solid_sphere"};
  // The torques' parts along ŷ, times R/I: R ω̇_y.
  const auto spin_rate = [&](const Vec& torque) { return (R * dot(torque, y) / inertia).normal(); };
  record.add({
      .id = "pressed.contact_friction_torque",
      .statement = "The balls' vertical friction, m T ẑ on A at R n and −m T ẑ on B at −R n, turns both the same "
                   "way: R ω̇_y = −(5/2) T for each.",
      .method = "R (r × F)·ŷ / I with I = (2/5) m R², for each ball; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{-numeric(5, 2) * T, -numeric(5, 2) * T},
      .derived_expression = lst{spin_rate(cross(scale(R, x), scale(m * T, z))),
                                spin_rate(cross(scale(-R, x), scale(-m * T, z)))},
      .depends_on = laws,
  });
  record.add({
      .id = "pressed.cloth_torque",
      .statement = "The cloth's friction m f x̂ at −R ẑ: R ω̇_y = −(5/2) f.",
      .method = "R ((−R ẑ) × m f x̂)·ŷ / I; identity",
      .comparison = Comparison::identity,
      .paper_expression = -numeric(5, 2) * f,
      .derived_expression = spin_rate(cross(scale(-R, z), scale(m * f, x))),
      .depends_on = laws,
  });
  const ex rolling_friction = GiNaC::lsolve(side * N + f - (-numeric(5, 2) * (f + T)) == 0, f);
  record.add({
      .id = "pressed.rolling_friction",
      .statement = "A pressed ball keeps rolling (u̇ = v̇ − R ω̇_y = 0) under the cloth's friction "
                   "f = −(2 s N + 5 T)/7, while |f| ≤ μ_s g.",
      .method = "lsolve() of (s N + f) − (−(5/2)(f + T)) = 0 for f; identity",
      .comparison = Comparison::identity,
      .paper_expression = -(2 * side * N + 5 * T) / 7,
      .derived_expression = rolling_friction,
      .depends_on = {"pressed.contact_friction_torque", "pressed.cloth_torque"},
  });
  // The share of the time a rolling ball's cloth contact slips in the contacts' limit: the cloth's
  // sliding friction μ_s g, acting that share of the time, gives the mean friction |f|.
  static const GiNaC::possymbol share("phi", "\\varphi"), size("f_abs", "|f|");
  record.add({
      .id = "pressed.rolling_share",
      .statement = "In the limit of the contacts, a pressed rolling ball slips the share φ = |f|/(μ_s g) of "
                   "the time (where the sliding friction supplies the mean |f|) and rolls the rest, 1 − φ, "
                   "under the rolling resistance.",
      .method = "lsolve() of φ μ_s g = |f| for φ; identity",
      .comparison = Comparison::identity,
      .paper_expression = size / (mu_s * g),
      .derived_expression = GiNaC::lsolve(share * mu_s * g == size, share),
      .depends_on = {"pressed.rolling_friction"},
  });
  // The friction between the balls dissipates: its torques' power on the pair, with σ = R(ω_A + ω_B) > 0
  // (the other sign by symmetry) and T = μ_b N.
  const Vec torque = cross(scale(R, x), scale(m * mu_b * N, z));  // the same on both balls
  const ex power = (dot(torque, scale(wa, y)) + dot(torque, scale(wb, y))).subs(wb == sigma / R - wa);
  record.add({
      .id = "pressed.contact_friction_dissipates",
      .statement = "While the balls' contact points slip (σ = R(ω_A + ω_B) > 0), the friction μ_b N between them "
                   "takes energy at the rate m μ_b N σ ≥ 0; the normal force does no work on balls moving as "
                   "one.",
      .method = "−Σ τ·ω over both balls with T = μ_b N, ω_B = σ/R − ω_A substituted; nonnegative",
      .comparison = Comparison::nonnegative,
      .paper_expression = m * mu_b * N * sigma,
      .derived_expression = (-power).normal(),
      .depends_on = {"pressed.contact_friction_torque"},
  });
  // A ball against a cushion's nose θ_a above its equator: the contact at R(cos θ_a, 0, sin θ_a).
  const Vec contact{R * cos_nose, 0, R * sin_nose}, nose_normal{-cos_nose, 0, -sin_nose},
      down_the_nose{sin_nose, 0, -cos_nose};
  const Vec nose_friction = scale(-mu_c * m * P, down_the_nose);
  const Vec horizontal = add(add(scale(m * P, nose_normal), nose_friction), scale(m * mu_s * g, x));
  const ex nose_force = GiNaC::lsolve(dot(horizontal, x) == 0, P);
  record.add({
      .id = "pressed.cushion_force",
      .statement = "A ball at rest against a cushion while its spin drives it in (the cloth's friction μ_s m g "
                   "into the cushion): the nose pushes with m P, P = μ_s g/(cos θ_a + μ_c sin θ_a).",
      .method = "lsolve() of the horizontal balance of m P along −(cos θ_a, 0, sin θ_a), the nose's friction "
                "μ_c m P against the slip down it and the cloth's μ_s m g for P; identity",
      .comparison = Comparison::identity,
      .paper_expression = mu_s * g / (cos_nose + mu_c * sin_nose),
      .derived_expression = nose_force,
      .depends_on = laws,
  });
  const ex cushion_rate =
      spin_rate(add(cross(contact, nose_friction), cross(scale(-R, z), scale(m * mu_s * g, x)))).subs(P == nose_force);
  record.add({
      .id = "pressed.cushion_spin_rate",
      .statement = "Its spin runs down at R ω̇_y = −(5/2)(μ_s g + μ_c P): the nose's friction and the cloth's "
                   "turn it; the nose's push passes through the centre.",
      .method = "R (Σ r × F)·ŷ / I over the nose's friction and the cloth's, P substituted; identity; "
                "cos²θ_a + sin²θ_a = 1 imposed by substituting sin²θ_a → 1 − cos²θ_a",
      .comparison = Comparison::identity,
      .paper_expression = (-numeric(5, 2) * (mu_s * g + mu_c * P)).subs(P == nose_force),
      .derived_expression = cushion_rate.normal(),
      .constraints = {{GiNaC::pow(sin_nose, 2) == 1 - GiNaC::pow(cos_nose, 2), "cos²θ_a + sin²θ_a = 1"}},
      .depends_on = {"pressed.cushion_force"},
  });
}

}  // namespace billiards::derive::spinning
