#include "models/parkin2023/steps.hpp"

#include "core/named_constants.hpp"

namespace billiards::derive::parkin2023 {

TimeOfImpact time_of_impact_quadratic(Recorder& record) {
  const Symbols& s = symbols();
  // Two spheres with centres p1 + t v1 and p2 + t v2 and radii r1, r2 touch when |p + t w| = r, with
  // p = p2 − p1, w = v2 − v1 and r = r1 + r2 (3-D components): another quadratic, in t.
  const Vec p = component_symbols("p", "p", "", 3);  // the relative position p2 − p1
  const Vec w = component_symbols("w", "w", "", 3);  // the relative velocity v2 − v1
  const GiNaC::possymbol contact_distance("contact_distance", "r");
  const GiNaC::realsymbol time("t", "t");
  const Vec separation_at_time = add(p, scale(time, w));
  const ex touching =
      (dot(separation_at_time, separation_at_time) - contact_distance * contact_distance).expand();
  // Read off as a t² + 2 b t + c.
  const ex coefficient_a = touching.coeff(time, 2), coefficient_b = touching.coeff(time, 1) / 2,
           coefficient_c = touching.coeff(time, 0);
  const GiNaC::possymbol qa("a", "a"), root_of_d("s", "\\sqrt{D}");
  const GiNaC::realsymbol qb("b", "b"), qc("c", "c"), qd("D", "D");
  const std::vector<std::string> time_premises = {"definition.time_of_impact"};
  record.add({
      .id = "beyond.time_of_impact.quadratic",
      .statement = "|p + t w|² − r² = a t² + 2 b t + c with a = w·w, b = p·w, c = p·p − r²: the spheres "
                   "touch at the roots t of a quadratic.",
      .method = "|p + t w|² − r² expanded in 3-D components; coeff() in t; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{dot(w, w), dot(p, w), dot(p, p) - contact_distance * contact_distance},
      .derived_expression = lst{coefficient_a, coefficient_b, coefficient_c},
      .paper_label = lst{qa, qb, qc},
      .derived_label = lst{qa, qb, qc},
      .depends_on = time_premises,
  });
  // D/4 = b² − a c from the coefficients read off; in 3-D it is a r² − |p × w|² (Lagrange's identity).
  const ex quarter_discriminant = (coefficient_b * coefficient_b - coefficient_a * coefficient_c).expand();
  const Vec cross = {p[1] * w[2] - p[2] * w[1], p[2] * w[0] - p[0] * w[2], p[0] * w[1] - p[1] * w[0]};
  const ex lagrange = dot(w, w) * contact_distance * contact_distance - dot(cross, cross);
  record.add({
      .id = "beyond.time_of_impact.discriminant",
      .statement = "D = b² − a c = (w·w) r² − |p × w|²: real roots exist iff the line of relative motion "
                   "passes within r, |p × w|/|w| ≤ r. D < 0 is a miss, D = 0 a graze.",
      .method = "b² − a c of the coefficients read off, 3-D components; identity after expand()",
      .comparison = Comparison::identity,
      .paper_expression = lagrange,
      .derived_expression = quarter_discriminant,
      .paper_display = qa * contact_distance * contact_distance - s.cross_product_squared,
      .derived_display = qb * qb - qa * qc,
      .display_definitions = {{qa, dot(w, w)},
                              {qb, dot(p, w)},
                              {qc, dot(p, p) - contact_distance * contact_distance},
                              {s.cross_product_squared, dot(cross, cross)}},
      .note = "D here is a quarter of the usual B² − 4AC with B = 2b.",
      .depends_on = {"beyond.time_of_impact.quadratic"},
  });
  // The roots by the quadratic formula, A = a, B = 2b, C = c, with √(B² − 4AC) = 2√D = 2 s.
  const ex quadratic_in_t = qa * GiNaC::pow(time, 2) + 2 * qb * time + qc;
  const ex big_a = quadratic_in_t.coeff(time, 2), big_b = quadratic_in_t.coeff(time, 1),
           big_c = quadratic_in_t.coeff(time, 0);
  const ex d_of_coefficients = ((big_b * big_b - 4 * big_a * big_c) / 4).expand();
  const ex root_relation = GiNaC::pow(root_of_d, 2) == d_of_coefficients;
  const ex earlier_root = GiNaC::normal((-big_b - 2 * root_of_d) / (2 * big_a));
  const ex later_root = GiNaC::normal((-big_b + 2 * root_of_d) / (2 * big_a));
  const lst printed_roots{(-qb - root_of_d) / qa, (-qb + root_of_d) / qa};
  record.add({
      .id = "beyond.time_of_impact.roots",
      .statement = "t∓ = (−b ∓ √D)/a, D = b² − a c, and both solve a t² + 2 b t + c = 0.",
      .method = "quadratic formula with A, B, C read off by coeff(); each root substituted back, the "
                "numerator reduced modulo s² = b² − a c (s = √D); identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{printed_roots.op(0), printed_roots.op(1), 0, 0},
      .derived_expression = lst{earlier_root, later_root, quadratic_in_t.subs(time == earlier_root),
                                quadratic_in_t.subs(time == later_root)},
      .constraints = {{root_relation, "s² = b² − a c (s = √D)"}},
      .depends_on = {"beyond.time_of_impact.discriminant"},
  });
  // (p + t w)·w is the rate of change of |p + t w|²/2: negative while the gap closes.
  const ex closing_rate = dot(separation_at_time, w);
  record.add({
      .id = "beyond.time_of_impact.first_contact_approaches",
      .statement = "At t− the spheres approach, (p + t w)·w = −√D ≤ 0, and at t+ they separate (+√D): t− "
                   "is the physical contact, t+ the moment they would part after passing through "
                   "each other.",
      .method = "(p + t w)·w − (b + a t) in 3-D components (zero), then b + a t at t∓; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{0, -root_of_d, root_of_d},
      .derived_expression = lst{(closing_rate - (coefficient_b + coefficient_a * time)).expand(),
                                qb + qa * earlier_root, qb + qa * later_root},
      .depends_on = {"beyond.time_of_impact.roots"},
  });
  // The earlier root without cancellation: multiply by (s − b)/(s − b) and reduce s² = b² − a c.
  const ex rationalized_numerator =
      reduce_modulo(((-qb - root_of_d) * (root_of_d - qb)).expand(), root_relation);
  const ex stable_root = GiNaC::normal(rationalized_numerator / (qa * (root_of_d - qb)));
  return {p,
          w,
          contact_distance,
          coefficient_a,
          coefficient_b,
          coefficient_c,
          quarter_discriminant,
          cross,
          qa,
          root_of_d,
          qb,
          qc,
          qd,
          root_relation,
          earlier_root,
          later_root,
          stable_root};
}

void time_of_impact_cases(Recorder& record, const TimeOfImpact& toi) {
  const GiNaC::possymbol& qa = toi.qa;
  const GiNaC::possymbol& root_of_d = toi.root_of_d;
  const GiNaC::realsymbol &qb = toi.qb, &qc = toi.qc, &qd = toi.qd;
  const ex &root_relation = toi.root_relation, &earlier_root = toi.earlier_root, &later_root = toi.later_root;
  const ex& stable_root = toi.stable_root;
  const lst printed_roots{(-qb - root_of_d) / qa, (-qb + root_of_d) / qa};
  record.add({
      .id = "beyond.time_of_impact.stable_form",
      .statement = "t− = c/(√D − b): for approaching spheres (b < 0) no cancellation (√D ≥ 0 and −b > 0 are "
                   "added) and no division by a, so no division by zero.",
      .method = "t− multiplied by (s − b)/(s − b), the numerator reduced modulo s² = b² − a c; identity",
      .comparison = Comparison::identity,
      .paper_expression = qc / (root_of_d - qb),
      .derived_expression = stable_root,
      .constraints = {{root_relation, "s² = b² − a c (s = √D)"}},
      .paper_display = qc / (root_of_d - qb),
      .derived_display = printed_roots.op(0),
      .note = "(−b − √D)/a loses every digit when a c is small beside b² (spheres nearly touching); "
              "c/(√D − b) does not.",
      .depends_on = {"beyond.time_of_impact.roots"},
  });
  {
    // The runtime scales lengths and speeds by powers of two before calling the kernel, so that no
    // square it forms underflows or overflows: the same contact, at a scaled time.
    const GiNaC::possymbol lambda("lambda", "\\lambda"), mu("mu", "\\mu");
    const GiNaC::realsymbol time("t", "t");
    const auto touching = [](const Vec& p, const Vec& w, const ex& r, const ex& t) {
      const Vec separation = add(p, scale(t, w));
      return dot(separation, separation) - r * r;
    };
    const ex scaled_touching =
        touching(scale(lambda, toi.p), scale(mu, toi.w), lambda * toi.r, lambda / mu * time).expand();
    const ex scaled_stable_root = stable_root.subs(
        lst{qb == lambda * mu * qb, qc == lambda * lambda * qc, root_of_d == lambda * mu * root_of_d});
    record.add({
        .id = "beyond.time_of_impact.scale_invariant",
        .statement = "Lengths scaled by λ > 0 and speeds by μ > 0 (p → λ p, r → λ r, w → μ w) give the same "
                     "contact at the time (λ/μ) t: |λ p + (λ/μ) t μ w|² − (λ r)² = λ² (|p + t w|² − r²), and "
                     "b → λμ b, c → λ² c, √D → λμ √D turn c/(√D − b) into (λ/μ) c/(√D − b). The runtime "
                     "scales both by powers of two (exactly) so that no square the kernel forms underflows "
                     "or overflows, and scales the time back.",
        .method = "substitution in |p + t w|² − r² (3-D components) and in the stable form; identity after "
                  "expand() and normal()",
        .comparison = Comparison::identity,
        .paper_expression =
            lst{lambda * lambda * touching(toi.p, toi.w, toi.r, time), lambda / mu * stable_root},
        .derived_expression = lst{scaled_touching, scaled_stable_root},
        .depends_on = {"beyond.time_of_impact.stable_form"},
    });
  }
  record.add({
      .id = "beyond.time_of_impact.no_contact",
      .statement = "t− t+ = c/a and t− + t+ = −2b/a: spheres apart (c > 0) that are not approaching (b ≥ 0) "
                   "have no root t > 0, and neither have spheres that miss (D < 0). There is no contact: "
                   "the kernel returns +∞.",
      .method = "product and sum of the roots, reduced modulo s² = b² − a c; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{qc / qa, -2 * qb / qa},
      .derived_expression = lst{earlier_root * later_root, earlier_root + later_root},
      .constraints = {{root_relation, "s² = b² − a c (s = √D)"}},
      .paper_display = lst{qc / qa, -2 * qb / qa},
      .derived_display = lst{earlier_root * later_root, earlier_root + later_root},
      .depends_on = {"beyond.time_of_impact.roots"},
      .cases = {{lst{qb >= 0}, infinity()}},
  });
  record.add({
      .id = "beyond.time_of_impact.grazing",
      .statement =
          "D = 0 (a graze): the roots coincide and at the contact (p + t w)·w = 0, no closing speed, "
          "so resolving only approaching contacts changes nothing. The kernel treats D ≤ 0 as no "
          "contact (+∞).",
      .method = "√D = 0 substituted; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{0, 0},
      .derived_expression = lst{(earlier_root - later_root).subs(root_of_d == 0),
                                GiNaC::normal(qb + qa * earlier_root).subs(root_of_d == 0)},
      .paper_display = lst{0, 0},
      .depends_on = {"beyond.time_of_impact.first_contact_approaches", "beyond.approaching.kernel_form"},
      .cases = {{lst{qd <= 0, qb < 0}, infinity()}},
  });
  {
    const GiNaC::possymbol overlap("gamma", "\\gamma"), approach("beta", "\\beta");
    const ex negated_time = GiNaC::normal(-stable_root.subs(lst{qc == -overlap, qb == -approach}));
    record.add({
        .id = "beyond.time_of_impact.touching_now",
        .statement = "Spheres already touching or overlapping by rounding (c ≤ 0) and approaching (b < 0) "
                     "give t− ≤ 0: the contact is now, and the kernel returns 0.",
        .method = "sign: c = −γ, b = −β (γ, β > 0) in the stable form; −t− factors into positive "
                  "symbols (√D ≥ 0)",
        .comparison = Comparison::nonnegative,
        .paper_expression = 0,
        .derived_expression = negated_time,
        .paper_display = 0,
        .derived_display = negated_time,
        .depends_on = {"beyond.time_of_impact.stable_form"},
        .cases = {{lst{qc<0, qd> 0, qb < 0}, 0}},
    });
  }
}

}  // namespace billiards::derive::parkin2023
