#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void conservation_along_n(Recorder& record, const Setting& setting) {
  const Symbols& s = symbols();
  const Definitions& d = setting.definitions;
  const Space& space = setting.space;
  record.section("along_n", "Conservation reduces to the parts along n",
                 "With the tangential parts unchanged, x_i = v_i⊥ + (x_i·n) n, and the conservation "
                 "laws become P(v1∥, v2∥) = P(x1∥, x2∥) and K(v1∥, v2∥) = K(x1∥, x2∥).");
  {
    const Vec x1 = space.after_collision(space.v1, s.x1n), x2 = space.after_collision(space.v2, s.x2n);
    const Vec v1_par = parallel_part(space.v1, space.n), v2_par = parallel_part(space.v2, space.n);
    const Vec x1_par = parallel_part(x1, space.n), x2_par = parallel_part(x2, space.n);
    record.add({
        .id = "along_n.momentum",
        .paper = "\"our preservation equations become\" (momentum)",
        .paper_tex = R"tex(P(v_1^\parallel, v_2^\parallel) = P(x_1^\parallel, x_2^\parallel))tex",
        .statement = "P(v1, v2) − P(x1, x2) = P(v1∥, v2∥) − P(x1∥, x2∥) when x_i⊥ = v_i⊥ (3-D).",
        .method = std::string("identity after expand(), componentwise") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = to_lst(subtract(momentum(d, v1_par, v2_par), momentum(d, x1_par, x2_par))),
        .derived_expression = to_lst(subtract(momentum(d, space.v1, space.v2), momentum(d, x1, x2))),
        .constraints = {space.unit_normal},
        .paper_label = s.P_v_par_minus_x_par,
        .derived_label = s.P_v_minus_x,
        .depends_on = {"definition.conservation", "split.momentum.3d",
                       "assumption.tangential_velocity_unchanged"},
    });
    record.add({
        .id = "along_n.kinetic_energy",
        .paper = "\"our preservation equations become\" (kinetic energy)",
        .paper_tex = R"tex(K(v_1^\parallel, v_2^\parallel) = K(x_1^\parallel, x_2^\parallel))tex",
        .statement = "K(v1, v2) − K(x1, x2) = K(v1∥, v2∥) − K(x1∥, x2∥) when x_i⊥ = v_i⊥ (3-D).",
        .method = std::string("identity after expand()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = kinetic(d, v1_par, v2_par) - kinetic(d, x1_par, x2_par),
        .derived_expression = kinetic(d, space.v1, space.v2) - kinetic(d, x1, x2),
        .constraints = {space.unit_normal},
        .paper_label = s.K_v_par_minus_x_par,
        .derived_label = s.K_v_minus_x,
        .depends_on = {"definition.conservation", "split.kinetic.3d",
                       "assumption.tangential_velocity_unchanged"},
    });
    record.add({
        .id = "along_n.momentum_is_along_n",
        .paper = "the notation P·n",
        .paper_tex = R"tex(P^\parallel = P(v_1^\parallel, v_2^\parallel))tex",
        .statement = "P∥ = P(v1∥, v2∥) = (P·n) n with P·n = m1 (v1·n) + m2 (v2·n): momentum along n "
                     "is one scalar equation.",
        .method = "identity after expand(), componentwise",
        .comparison = Comparison::identity,
        .paper_expression = to_lst(scale(dot(momentum(d, space.v1, space.v2), space.n), space.n)),
        .derived_expression = to_lst(momentum(d, v1_par, v2_par)),
        .paper_display = s.Pn * s.n,
        .derived_label = s.P_of_v_parallel,
        .display_definitions = merged({shorthand(d), space.normal_components()}),
        .display_components = space.vector_components(),
        .note = "The paper writes P·n for P(v1, v2)·n, the total momentum along n.",
        .depends_on = {"definition.momentum", "definition.split"},
    });
    record.add({
        .id = "along_n.kinetic_energy_in_normal_components",
        .paper = "K∥ = K(v1∥, v2∥)",
        .paper_tex = R"tex(K^\parallel = K(v_1^\parallel, v_2^\parallel))tex",
        .statement = "K∥ = K(v1∥, v2∥) = ½ m1 (v1·n)² + ½ m2 (v2·n)² given n·n = 1.",
        .method = std::string("identity after expand()") + unit_normal_method,
        .comparison = Comparison::identity,
        .paper_expression = space.components_of(scalar_kinetic(d, s.v1n, s.v2n)),
        .derived_expression = kinetic(d, v1_par, v2_par),
        .constraints = {space.unit_normal},
        .paper_display = scalar_kinetic(d, s.v1n, s.v2n),
        .derived_label = s.K_of_v_parallel,
        .display_definitions = space.normal_components(),
        .depends_on = {"definition.kinetic_energy", "definition.split"},
    });
  }
}

}  // namespace billiards::derive::parkin2023
