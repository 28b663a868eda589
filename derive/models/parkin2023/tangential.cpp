#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void frictionless_contact(Recorder& record) {
  const Symbols& s = symbols();
  record.section("tangential", "Frictionless contact: the tangential parts are unchanged",
                 "The paper makes \"a physics-based argument that we must have v1⊥ = x1⊥ and "
                 "v2⊥ = x2⊥\". This is a modelling assumption, not a consequence of the "
                 "conservation laws.");
  record.add({
      .id = "assumption.tangential_velocity_unchanged",
      .paper = "\"after making a physics-based argument\"",
      .paper_tex = R"tex(v_1^\perp = x_1^\perp, \quad v_2^\perp = x_2^\perp)tex",
      .statement = "x1⊥ = v1⊥ and x2⊥ = v2⊥: the contact exerts no force across n.",
      .method = "assumption",
      .comparison = Comparison::assumption,
      .paper_expression = lst{s.x1_perp == s.v1_perp, s.x2_perp == s.v2_perp},
      .derived_expression = lst{s.x1_perp == s.v1_perp, s.x2_perp == s.v2_perp},
      .paper_display = lst{s.x1_perp == s.v1_perp, s.x2_perp == s.v2_perp},
      .derived_display = lst{s.x1_perp == s.v1_perp, s.x2_perp == s.v2_perp},
      .note = "Physical reason: smooth (frictionless), spinless balls in instantaneous contact push "
              "on each other only along the contact normal, so no impulse acts across n. Momentum "
              "and energy conservation alone do not force it: they are four scalar equations in 3-D "
              "for six unknown components. With friction or spin the tangential parts change.",
      .depends_on = {},
  });
}

}  // namespace billiards::derive::parkin2023
