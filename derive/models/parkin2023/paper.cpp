// The paper's model as a pipeline: the steps in the order of the paper's table of contents (one file
// each), then beyond the paper, then the kernels built from what the steps returned.
#include "models/parkin2023/paper.hpp"

#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

ModelInfo info() {
  ModelInfo model;
  model.name = "parkin2023";
  model.title = "Billiard Ball Physics";
  model.citation = "S. T. Parkin, \"Billiard Ball Physics\", 2023";
  model.scope = "frictionless, spinless balls in instantaneous contact (perfectly elastic)";
  model.notation =
      "Vectors in components are written $v_{1,x}$ as `v1_x`; $(v_1 \\cdot n)$ is the scalar $v_1 \\cdot n$; "
      "$\\mathbf{v}_1$ names the vector itself. Where $n \\cdot n = 1$ is needed it is imposed by "
      "substituting "
      "$n_\\text{last}^2 \\to 1 - \\sum n_i^2$, never by choosing a numeric normal, and the claim says so "
      "(\"Under: n·n = 1\").";
  model.remarks = {
      "Footnote 1 calls P and K \"bilinear\". P is linear and K is a quadratic form; K splits into parts "
      "along and across n because the cross terms a∥·b⊥ vanish for a unit n (`split.kinetic_cross_term.2d`, "
      "`split.kinetic_cross_term.3d`).",
      "\"A physics-based argument that we must have v1⊥ = x1⊥\" is an assumption (frictionless, spinless "
      "contact), not a consequence of conservation: `assumption.tangential_velocity_unchanged` is the only "
      "unchecked claim.",
      "P·n and (x1∥)² are shorthand for P(v1, v2)·n and x1∥·x1∥.",
      "The paper rejects the \"−\" root because it does not depend on v2. The stronger reason is that it is "
      "x1 = v1, x2 = v2: the state before the collision (`selection.minus_root_is_no_collision`); the \"+\" "
      "root reverses the relative normal velocity (`selection.plus_root_reverses_relative_normal_velocity`).",
      "The cushion limit asks for v2 = 0 but needs only v2·n = 0 (`cushion.limit`): the limit for a wall "
      "moving with v2 is v1 + 2((v2 − v1)·n) n (`cushion.moving_wall_limit`). −n v1 n is a reflection only "
      "when n² = 1.",
      "The masses are taken in ℝ; they must be positive (`definition.masses`): √D = m1 |(v2 − v1)·n| and "
      "D ≥ 0 rest on it.",
      "The \"+\" root is chosen whatever the sign of (v2 − v1)·n, and the paper says the direction of n does "
      "not matter. That is true of the formula, not of the choice: with n from ball 1 to ball 2 the \"+\" "
      "root is the collision only when the balls approach "
      "(`selection.plus_root_separates_only_approaching_balls`); for separating balls nothing happens "
      "(`beyond.approaching.resolve_only_approaching`).",
  };
  model.pair_result = {
      "NormalVelocityChange",
      "The changes x1·n − v1·n and x2·n − v2·n of the two balls' velocities along the contact "
      "normal n.",
      "x1·n − v1·n", "x2·n − v2·n"};
  model.reference_path = "billiards/reference_kernels.hpp";
  model.kernel_list_path = "billiards/kernel_list.hpp";
  return model;
}

Derivation derive(const Definitions& definitions) {
  const Setting setting{definitions};
  Derivation derivation;
  derivation.model = info();
  record_steps(derivation, [&](Recorder& record) {
    // The paper.
    record_premises(record, definitions);
    split_along_and_across(record, setting);
    frictionless_contact(record);
    conservation_along_n(record, setting);
    const Quadratic quadratic = the_quadratic(record, setting);
    const Discriminant discriminant = the_discriminant(record, definitions, quadratic);
    const Roots roots = the_roots(record, quadratic, discriminant);
    putting_it_together(record, setting, quadratic, discriminant, roots);
    const Selection selection = choosing_the_root(record, quadratic, discriminant, roots);
    the_collision_formula(record, setting, discriminant, selection);
    sanity_checks(record, setting, selection);
    the_cushion(record, setting, selection);
    end_to_end(record, setting, selection);
    const KernelPieces pieces = what_the_emitter_prints(record, selection);

    // Beyond the paper.
    record.section("beyond", "Beyond the paper",
                   "What engines need and the paper does not cover: a coefficient of restitution, "
                   "immovable bodies, directions that are not unit vectors, contacts that are "
                   "already separating, and the time at which two moving balls first touch. Derived "
                   "and checked like the paper's claims; the paper states none of them.");
    const Restitution with_restitution = restitution(record, definitions);
    const MassRatios ratios = immovable_bodies(record, with_restitution);
    const PlainRange plain = plain_range(record, with_restitution, ratios);
    const Direction direction = any_direction(record, setting, with_restitution);
    const Approaching approaching = approaching_contacts(record, definitions, selection, with_restitution);
    const TimeOfImpact toi = time_of_impact_quadratic(record);
    time_of_impact_cases(record, toi);

    // What each kernel returns, then the kernels themselves.
    record.section(
        "kernel_outputs", "What each emitted kernel computes",
        "One claim per emitted quantity: what the kernel returns, derived from the steps above and "
        "compared with the formula the source prints. Every kernel is proven equal to the derived "
        "side of its claim before it is printed (see \"The emitted kernels\" below).");
    kernel_outputs(record, setting, selection, with_restitution, direction, approaching);
    derivation.kernels = collision_kernels(setting, pieces, ratios, plain, direction);
    derivation.kernels.push_back(time_of_impact_kernel(toi));
    derivation.reference_kernels = reference_kernels(quadratic);
  });
  return derivation;
}

}  // namespace billiards::derive::parkin2023
