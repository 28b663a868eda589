#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void kernel_outputs(Recorder& record, const Setting& setting, const Selection& selection,
                    const Restitution& restitution, const Direction& direction,
                    const Approaching& approaching) {
  const Symbols& s = symbols();
  const ex e = s.restitution;
  const ex speed = s.relative_normal_speed;
  const ex &plus_root = selection.x1n, &x2n_selected = selection.x2n;
  const ex &x1n_e = restitution.x1n, &x2n_e = restitution.x2n;
  const ex& second_coefficient_e = restitution.second_coefficient;
  const ex relative = s.v2n - s.v1n;
  const ex& dd = direction.dd;
  const lst& from_unit_form = direction.from_unit_form;
  const Vec& n_of_d = direction.unit;
  const ex& approach_speed = approaching.approach_speed;
  // The two changes as printed: (1 + r) m2/(m1 + m2) times the speed for ball 1, −(1 + r) m1/(m1 + m2) for
  // ball 2, with restitution r.
  const auto printed_pair = [&](const ex& r, const ex& by) {
    return lst{(1 + r) * s.m2 / (s.m1 + s.m2) * by, -(1 + r) * s.m1 / (s.m1 + s.m2) * by};
  };
  const Space& space = setting.space;
  const ex direction_speed_in_components =
      (dot(space.v2, direction.d) - dot(space.v1, direction.d)) / dd;  // ((v2 − v1)·d)/(d·d)
  {
    const lst changes{GiNaC::normal(plus_root - s.v1n), GiNaC::normal(x2n_selected - s.v2n)};
    const lst printed = printed_pair(1, relative);
    record.add({
        .id = "kernel.elastic_normal_velocity_change",
        .paper = "\"This form makes it easier to see the impulse magnitude\"",
        .statement =
            "x1·n − v1·n = (2 m2/(m1 + m2)) (v2 − v1)·n and x2·n − v2·n = −(2 m1/(m1 + m2)) (v2 − v1)·n: "
            "the selected root, and x2·n from momentum, along n.",
        .method = "the \"+\" root minus v1·n, x2·n from momentum minus v2·n; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = printed,
        .derived_expression = changes,
        .paper_display = printed,
        .derived_display = factored_form(changes),
        .depends_on = {"selection.plus_root_reverses_relative_normal_velocity", "result.x1_simplified_form",
                       "result.x2_by_symmetry"},
    });
    const lst changes_e{GiNaC::normal(x1n_e - s.v1n), GiNaC::normal(x2n_e - s.v2n)};
    const lst printed_e = printed_pair(e, relative);
    record.add({
        .id = "kernel.normal_velocity_change",
        .statement = "With restitution e: x1·n − v1·n = (1 + e) m2/(m1 + m2) (v2 − v1)·n and x2·n − v2·n = "
                     "−(1 + e) m1/(m1 + m2) (v2 − v1)·n.",
        .method = "the normal components solved with lsolve() minus v1·n, v2·n; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = printed_e,
        .derived_expression = changes_e,
        .paper_display = printed_e,
        .derived_display = factored_form(changes_e),
        .depends_on = {"beyond.restitution.impulse_coefficients"},
    });
    // The multiples of d: (x1 − v1) = λ1 d in the direction form derived from the unit form, λ1 read off
    // the first component (beyond.any_normal.direction_form checks every component).
    const Vec x2_unit =
        add(space.v2, scale(second_coefficient_e * dot(subtract(space.v2, space.v1), n_of_d), n_of_d));
    const lst multiples{GiNaC::normal((from_unit_form.op(0) - space.v1[0]) / direction.d[0]),
                        GiNaC::normal((x2_unit[0] - space.v2[0]) / direction.d[0])};
    const lst printed_multiples = printed_pair(e, direction_speed_in_components);
    record.add({
        .id = "kernel.direction_velocity_change",
        .statement = "Along a direction d (not necessarily unit) the velocities change by λ1 d and λ2 d with "
                     "λ1 = (1 + e) m2/(m1 + m2) ((v2 − v1)·d)/(d·d) and λ2 = −(1 + e) m1/(m1 + m2) ((v2 − "
                     "v1)·d)/(d·d).",
        .method =
            "n = d/√(d·d) substituted into the unit form (3-D components); (x_i − v_i)/d read off the first "
            "component; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = printed_multiples,
        .derived_expression = multiples,
        .paper_display = printed_pair(e, s.relative_direction_speed),
        .display_definitions = {{s.relative_direction_speed, direction_speed_in_components}},
        .depends_on = {"beyond.any_normal.direction_form", "beyond.restitution.impulse_coefficients"},
    });
    // The changes see the velocities only through their difference: moving both balls by the same
    // velocity along the line of centres changes nothing. So the runtime passes the kernels 0 and one
    // dot product (v2 − v1)·n in place of v1·n and v2·n.
    {
      const GiNaC::realsymbol shift("u");
      const GiNaC::exmap along_n{{s.v1n, s.v1n + shift}, {s.v2n, s.v2n + shift}};
      GiNaC::exmap along_d;
      for (std::size_t i = 0; i < space.v1.size(); ++i) {
        along_d[space.v1[i]] = space.v1[i] + shift * direction.d[i];
        along_d[space.v2[i]] = space.v2[i] + shift * direction.d[i];
      }
      lst shifted, unchanged;
      for (const ex& change : changes_e) shifted.append(GiNaC::normal(change.subs(along_n) - change));
      for (const ex& multiple : multiples) shifted.append(GiNaC::normal(multiple.subs(along_d) - multiple));
      for (std::size_t i = 0; i < shifted.nops(); ++i) unchanged.append(0);
      record.add({
          .id = "kernel.relative_speed_only",
          .statement = "The collision kernels depend on v1·n and v2·n (v1·d and v2·d) only through their "
                       "difference: adding the same u to both (u d to v1 and v2) leaves every change "
                       "unchanged, so the kernels may be given 0 and (v2 − v1)·n.",
          .method = "v1·n → v1·n + u, v2·n → v2·n + u in kernel.normal_velocity_change, v_i → v_i + u d in "
                    "kernel.direction_velocity_change (3-D components); each change minus the original, "
                    "zero after normal()",
          .comparison = Comparison::identity,
          .paper_expression = unchanged,
          .derived_expression = shifted,
          .note = "The runtime's calls and collide_batch compute (v2 − v1)·n as one dot product of the "
                  "difference (detail::difference_dot) and pass v1·n = 0: three subtractions in place of "
                  "a second dot product, and no cancellation between two large dot products. e = 1 "
                  "covers the elastic kernel, the clamped speed the approaching one.",
          .depends_on = {"kernel.normal_velocity_change", "kernel.direction_velocity_change"},
      });
    }
    // Only approaching balls: the relative speed along d clamped as beyond.approaching.kernel_form proves.
    const ex clamped = approach_speed.subs(speed == direction_speed_in_components);
    const lst approaching{GiNaC::normal(multiples.op(0) / direction_speed_in_components) * clamped,
                          GiNaC::normal(multiples.op(1) / direction_speed_in_components) * clamped};
    const ex printed_clamp = (direction_speed_in_components - GiNaC::abs(direction_speed_in_components)) / 2;
    const lst printed_approaching = printed_pair(e, printed_clamp);
    record.add({
        .id = "kernel.approaching_direction_velocity_change",
        .statement =
            "Resolving only approaching balls along d: λ1 and λ2 with ((v2 − v1)·d)/(d·d) replaced by "
            "σ = (s − |s|)/2 of it, which is the collision when (v2 − v1)·d < 0 and no change otherwise.",
        .method =
            "the multiples of kernel.direction_velocity_change divided by their speed, times the clamped "
            "speed of beyond.approaching.kernel_form; identity after normal()",
        .comparison = Comparison::identity,
        .paper_expression = printed_approaching,
        .derived_expression = approaching,
        .paper_display = printed_pair(e, s.approach_direction_speed),
        .display_definitions = {{s.approach_direction_speed, printed_clamp}},
        .depends_on = {"kernel.direction_velocity_change", "beyond.approaching.kernel_form"},
    });
  }
}

}  // namespace billiards::derive::parkin2023
