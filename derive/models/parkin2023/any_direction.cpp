#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

Direction any_direction(Recorder& record, const Setting& setting, const Restitution& restitution) {
  const Symbols& s = symbols();
  const ex& first_coefficient_e = restitution.first_coefficient;
  const Space& space = setting.space;
  // Any direction: d not necessarily unit, n = d/√(d·d) substituted into the unit form (3-D).
  const Vec direction = component_symbols("d", "d", "", 3);
  const ex dd = dot(direction, direction);
  const Vec n_of_d = scale(1 / GiNaC::sqrt(dd), direction);
  const ex c1 = first_coefficient_e;
  const auto unit_form = [&](const Vec& n) {
    return add(space.v1, scale(c1 * dot(subtract(space.v2, space.v1), n), n));
  };
  lst from_unit_form;
  for (const ex& component : unit_form(n_of_d)) from_unit_form.append(GiNaC::normal(component));
  const auto direction_form = [&](const Vec& dir) {
    return add(space.v1, scale(c1 * dot(subtract(space.v2, space.v1), dir) / dot(dir, dir), dir));
  };
  // The displays v1 + c1 ((v2 − v1)·d)/(d·d) d and v1 + c1 ((v2 − v1)·d̂) d̂ in components, d̂ = `unit`.
  const ex relative_along_d = dot(subtract(space.v2, space.v1), direction);
  const auto displayed_with = [&](const Vec& unit) {
    std::vector<GiNaC::exmap> components;
    for (std::size_t i = 0; i < 3; ++i) {
      components.push_back({{s.v1, space.v1[i]}, {s.direction, direction[i]}, {s.unit_direction, unit[i]}});
    }
    return components;
  };
  const GiNaC::exmap direction_definitions{
      {s.c1, c1},
      {s.relative_direction_speed, relative_along_d / dd},
      {s.relative_unit_speed, dot(subtract(space.v2, space.v1), n_of_d)}};
  record.add({
      .id = "beyond.any_normal.direction_form",
      .statement = "For a non-zero direction d (not necessarily unit), x1 = v1 + c1 ((v2 − v1)·d)/(d·d) d: "
                   "no square root is needed.",
      .method = "n = d/√(d·d) substituted into the unit form, componentwise (3-D); identity after normal()",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(direction_form(direction)),
      .derived_expression = from_unit_form,
      .paper_display = s.v1 + s.c1 * s.relative_direction_speed * s.direction,
      .derived_display = s.v1 + s.c1 * s.relative_unit_speed * s.unit_direction,
      .display_definitions = direction_definitions,
      .display_components = displayed_with(n_of_d),
      .depends_on = {"beyond.restitution.impulse_coefficients"},
  });
  const GiNaC::realsymbol lambda("lambda", "\\lambda");
  record.add({
      .id = "beyond.any_normal.scale_invariant",
      .statement = "Scaling d by any λ ≠ 0 leaves the result unchanged.",
      .method = "d → λ d substituted; identity after normal(), componentwise (3-D)",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(direction_form(direction)),
      .derived_expression = to_lst(direction_form(scale(lambda, direction))),
      .paper_label = s.x1,
      .derived_label = s.x1_scaled_direction,
      .depends_on = {"beyond.any_normal.direction_form"},
  });
  record.add({
      .id = "beyond.any_normal.unit_direction",
      .statement = "For |d| = 1 the direction form is the unit form x1 = v1 + c1 ((v2 − v1)·d) d.",
      .method = std::string("identity after normal()") +
                " ; d·d = 1 imposed by substituting d_z² → 1 − d_x² − d_y²",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(unit_form(direction)),
      .derived_expression = to_lst(direction_form(direction)),
      .constraints = {{unit_normal_relation(direction), "d·d = 1"}},
      .paper_display = s.v1 + s.c1 * s.relative_unit_speed * s.unit_direction,
      .derived_display = s.v1 + s.c1 * s.relative_direction_speed * s.direction,
      .display_definitions = {{s.c1, c1},
                              {s.relative_direction_speed, relative_along_d / dd},
                              {s.relative_unit_speed, relative_along_d}},
      .display_components = displayed_with(direction),
      .depends_on = {"beyond.any_normal.direction_form"},
  });
  return {direction, dd, n_of_d, from_unit_form};
}

}  // namespace billiards::derive::parkin2023
