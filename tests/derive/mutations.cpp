#include "mutations.hpp"

#include "core/named_constants.hpp"
#include "models/shot/steps.hpp"
#include "core/powers_of_two.hpp"

#include <stdexcept>

namespace billiards::derive::testing {

using GiNaC::ex;

namespace {

KernelStep& step(Kernel& kernel, const std::string& name) {
  for (KernelStep& s : kernel.steps) {
    if (s.name.get_name() == name) return s;
  }
  throw std::invalid_argument("kernel " + kernel.name + " has no step " + name);
}

// A symbol of the kernel by its name: a parameter or a step.
ex symbol(const Kernel& kernel, const std::string& name) {
  for (const ex& parameter : kernel.parameters) {
    if (GiNaC::ex_to<GiNaC::symbol>(parameter).get_name() == name) return parameter;
  }
  for (const KernelStep& s : kernel.steps) {
    if (s.name.get_name() == name) return s.name;
  }
  throw std::invalid_argument("kernel " + kernel.name + " has no symbol " + name);
}

}  // namespace

const std::vector<Mutation>& paper_mutations() {
  static const std::vector<Mutation> mutations = {
      {"relative_speed_sign_flipped", "elastic_normal_velocity_change",
       [](Kernel& k) { step(k, "relative_normal_speed").expression = symbol(k, "v1n") - symbol(k, "v2n"); }},
      {"mass_ratio_swapped", "elastic_normal_velocity_change",
       [](Kernel& k) { step(k, "first_mass_ratio").expression = symbol(k, "m2") / symbol(k, "m1"); }},
      {"approach_clamp_sign_flipped", "approaching_direction_velocity_change",
       [](Kernel& k) {
         const ex s = symbol(k, "direction_speed");
         step(k, "approach_speed").expression = (s + GiNaC::abs(s)) / 2;
       }},
      {"division_by_dd_dropped", "direction_velocity_change",
       [](Kernel& k) { step(k, "direction_speed").expression = symbol(k, "v2d") - symbol(k, "v1d"); }},
      {"division_by_dd_squared", "direction_velocity_change",
       [](Kernel& k) {
         step(k, "direction_speed").expression =
             (symbol(k, "v2d") - symbol(k, "v1d")) / GiNaC::pow(symbol(k, "dd"), 2);
       }},
      {"guard_alternative_m1_for_m2", "normal_velocity_change",
       [](Kernel& k) { step(k, "first_multiplier").guards.at(0).alternative = symbol(k, "m1"); }},
      {"guard_alternative_difference_of_masses", "normal_velocity_change",
       [](Kernel& k) {
         step(k, "impulse_per_total_mass").expression = (1 + symbol(k, "restitution")) *
                                                        symbol(k, "relative_normal_speed") /
                                                        (symbol(k, "m1") - symbol(k, "m2"));
       }},
      {"reference_root_sign_flipped", "raw_normal_velocity_change",
       [](Kernel& k) {
         step(k, "x1n").expression =
             (-symbol(k, "quadratic_b") - symbol(k, "signed_root")) / (2 * symbol(k, "quadratic_a"));
       }},
      {"reference_factor_two_dropped", "raw_normal_velocity_change",
       [](Kernel& k) {
         step(k, "x1n").expression =
             (-symbol(k, "quadratic_b") + symbol(k, "signed_root")) / symbol(k, "quadratic_a");
       }},
      {"time_of_impact_approach_test_reversed", "time_of_impact",
       [](Kernel& k) { step(k, "contact_time").guards.at(2).condition = symbol(k, "pv") <= 0; }},
      {"cushion_output_negated", "cushion_normal_velocity_change",
       [](Kernel& k) { k.outputs.at(0) = -k.outputs.at(0); }},
      // Beyond the first eleven.
      {"time_of_impact_touching_value", "time_of_impact",
       [](Kernel& k) { step(k, "contact_time").guards.at(0).alternative = 1; }},
      // √ of 0 where D ≤ 0: only where the time is +∞ anyway, and never passed off as the
      // same value.
      {"time_of_impact_root_clamped_under_another_condition", "time_of_impact",
       [](Kernel& k) {
         step(k, "root_argument").guards.at(0).condition = symbol(k, "discriminant") <= symbol(k, "gap");
       }},
      {"time_of_impact_root_clamp_as_the_same_value", "time_of_impact",
       [](Kernel& k) { step(k, "root_argument").guards.at(0).kind = Guard::Kind::same_value; }},
      {"reference_discriminant_guard_not_a_sign", "raw_normal_velocity_change",
       [](Kernel& k) { step(k, "discriminant").guards.at(0).condition = symbol(k, "quadratic_b") < 0; }},
      {"step_reads_an_unknown_symbol", "elastic_normal_velocity_change",
       [](Kernel& k) { step(k, "first_mass_ratio").expression = symbol(k, "m1") / GiNaC::symbol("m3"); }},
      {"cites_an_unknown_claim", "cushion_normal_velocity_change",
       [](Kernel& k) { k.claims.push_back("cushion.no_such_claim"); }},
      {"equals_an_unverified_claim", "elastic_normal_velocity_change",
       [](Kernel& k) { k.equals = "assumption.tangential_velocity_unchanged"; }},
      // The fast path: its plain kernels and the way the full kernels take them.
      {"plain_coefficient_mass_swapped", "plain_elastic_normal_velocity_change",
       [](Kernel& k) {
         step(k, "first_impulse_coefficient").expression =
             2 * symbol(k, "m1") / (symbol(k, "m1") + symbol(k, "m2"));
       }},
      {"plain_restitution_dropped", "plain_normal_velocity_change",
       [](Kernel& k) {
         step(k, "second_impulse_coefficient").expression =
             2 * symbol(k, "m1") / (symbol(k, "m1") + symbol(k, "m2"));
       }},
      {"fast_path_takes_another_claims_kernel", "normal_velocity_change",
       [](Kernel& k) { k.fast_path->kernel = "plain_elastic_normal_velocity_change"; }},
      {"fast_path_range_wider_than_the_plain_form", "direction_velocity_change",
       [](Kernel& k) { k.fast_path->conditions.at(1) = symbol(k, "m1") <= infinity(); }},
      {"fast_path_condition_reads_an_unknown_symbol", "approaching_direction_velocity_change",
       [](Kernel& k) { k.fast_path->conditions.at(0) = plain_mass_low() <= GiNaC::symbol("m3"); }},
  };
  return mutations;
}

const std::vector<Mutation>& spin_mutations() {
  using GiNaC::numeric;
  static const std::vector<Mutation> mutations = {
      // The classic: 5/2 (the rotational part alone) for 7/2.
      {"tangential_mass_five_halves", "tangential_inverse_effective_mass",
       [](Kernel& k) { k.outputs.at(0) = numeric(5, 2) * (1 / symbol(k, "m1") + 1 / symbol(k, "m2")); }},
      {"tangential_mass_one_ball", "tangential_inverse_effective_mass",
       [](Kernel& k) { k.outputs.at(0) = numeric(7, 2) / symbol(k, "m1"); }},
      {"normal_impulse_restitution_dropped", "normal_impulse",
       [](Kernel& k) {
         k.outputs.at(0) =
             -2 * times_power_of_two(symbol(k, "scaled_impulse"), symbol(k, "impulse_exponent"));
       }},
      {"heavier_mass_guard_keeps_the_lighter", "normal_impulse",
       [](Kernel& k) { step(k, "heavier_mass").guards.at(0).alternative = symbol(k, "m2"); }},
      // The scaling by powers of two: a significand not scaled back, an exponent's sign.
      {"normal_impulse_not_scaled_back", "normal_impulse",
       [](Kernel& k) { k.outputs.at(0) = -(1 + symbol(k, "restitution")) * symbol(k, "scaled_impulse"); }},
      {"normal_impulse_speed_exponent_subtracted", "normal_impulse",
       [](Kernel& k) {
         step(k, "impulse_exponent").expression =
             symbol(k, "lighter_mass_exponent") - symbol(k, "relative_normal_speed_exponent");
       }},
      {"friction_bound_reversed", "friction_impulse",
       [](Kernel& k) {
         Guard& guard = step(k, "impulse").guards.at(0);
         guard.condition = guard.condition.lhs() > guard.condition.rhs();
       }},
      {"friction_sliding_value_without_normal_impulse", "friction_impulse",
       [](Kernel& k) { step(k, "impulse").guards.at(0).alternative = symbol(k, "friction"); }},
      // The mass-ratio form of the tangential change: each ball's fraction, the 2/7, the sliding bound.
      {"tangential_change_fractions_swapped", "tangential_velocity_change",
       [](Kernel& k) { step(k, "first").expression = symbol(k, "second_fraction") * symbol(k, "bound"); }},
      {"tangential_change_two_fifths", "tangential_velocity_change",
       [](Kernel& k) {
         step(k, "sticking_change").expression = numeric(2, 5) * symbol(k, "tangential_slip");
       }},
      {"tangential_change_sliding_without_restitution", "tangential_velocity_change",
       [](Kernel& k) {
         step(k, "sliding_change").expression = -symbol(k, "friction") * symbol(k, "relative_normal_speed");
       }},
      {"tangential_change_small_mass_form_wrong_mass", "tangential_velocity_change",
       [](Kernel& k) {
         // Ball 1's small-mass form for ball 2's.
         step(k, "second").guards.at(0).alternative = times_power_of_two(
             symbol(k, "scaled_first_small_mass_change"), symbol(k, "first_small_mass_change_exponent"));
       }},
      {"tangential_change_small_mass_exponent_sign", "tangential_velocity_change",
       [](Kernel& k) {
         step(k, "second_small_mass_change_exponent").expression =
             symbol(k, "bound_exponent") - symbol(k, "m1_exponent") - symbol(k, "m2_exponent");
       }},
      {"tangential_change_bound_reversed", "tangential_velocity_change",
       [](Kernel& k) {
         Guard& guard = step(k, "bound").guards.at(0);
         guard.condition = guard.condition.lhs() > guard.condition.rhs();
       }},
      // The plain form over one sum where both masses lie in the plain range.
      {"plain_tangential_change_shares_swapped", "plain_tangential_velocity_change",
       [](Kernel& k) { step(k, "first").expression = symbol(k, "bound") * symbol(k, "second_share"); }},
      {"plain_tangential_change_share_of_the_lighter_sum", "plain_tangential_velocity_change",
       [](Kernel& k) { step(k, "second_share").expression = symbol(k, "m1") / symbol(k, "m2"); }},
      {"tangential_change_fast_path_range_wider_than_its_plain_form", "tangential_velocity_change",
       [](Kernel& k) { k.fast_path->conditions.at(3) = symbol(k, "m2") <= infinity(); }},
      // A hollow sphere's R/I = 3/(2 m R) for the solid sphere's 5/(2 m R).
      {"spin_change_hollow_sphere", "spin_change",
       [](Kernel& k) { k.outputs.at(0) = numeric(3, 2) * symbol(k, "change_per_radius"); }},
      {"spin_change_without_the_half", "spin_change",
       [](Kernel& k) { k.outputs.at(0) = 5 * symbol(k, "change_per_radius"); }},
      {"spin_change_inverted_inertia", "spin_change_per_impulse",
       [](Kernel& k) {
         step(k, "scaled_per_impulse").expression =
             numeric(2, 5) / (symbol(k, "scaled_mass") * symbol(k, "scaled_radius"));
       }},
      {"spin_change_per_impulse_radius_not_scaled", "spin_change_per_impulse",
       [](Kernel& k) { step(k, "scaled_radius").expression = symbol(k, "radius"); }},
      {"tangential_mass_term_seven", "tangential_inverse_effective_mass",
       [](Kernel& k) { step(k, "first_term").expression = 7 / symbol(k, "m1"); }},
      {"slide_time_five_for_seven", "slide_time",
       [](Kernel& k) {
         step(k, "scaled_duration").expression =
             2 * symbol(k, "scaled_slip_speed") /
             (5 * symbol(k, "scaled_sliding_friction") * symbol(k, "scaled_gravity"));
       }},
      {"slide_time_fast_path_range_wider_than_its_plain_form", "slide_time",
       [](Kernel& k) { k.fast_path->conditions.at(1) = symbol(k, "slip_speed") <= infinity(); }},
      {"slide_time_frictionless_zero", "slide_time",
       [](Kernel& k) { step(k, "duration").guards.at(0).alternative = 0; }},
      {"slide_time_gravity_exponent_added", "slide_time",
       [](Kernel& k) {
         step(k, "duration_exponent").expression = symbol(k, "slip_speed_exponent") +
                                                   symbol(k, "gravity_exponent") -
                                                   symbol(k, "sliding_friction_exponent");
       }},
      {"roll_time_gravity_dropped", "roll_time",
       [](Kernel& k) {
         step(k, "scaled_duration").expression =
             symbol(k, "scaled_speed") / symbol(k, "scaled_rolling_friction");
       }},
      {"spin_time_factor_inverted", "spin_time",
       [](Kernel& k) {
         step(k, "scaled_duration").expression =
             5 * symbol(k, "scaled_radius") * symbol(k, "scaled_spin_speed") /
             (2 * symbol(k, "scaled_spinning_friction") * symbol(k, "scaled_gravity"));
       }},
      // The event polynomials' kernels, each with a slip of its own.
      {"contact_constant_term_distance_added", "contact_constant_term",
       [](Kernel& k) {
         const auto x = [&](const char* name) { return symbol(k, name); };
         k.outputs.at(0) = x("dx") * x("dx") + x("dy") * x("dy") + x("distance") * x("distance");
       }},
      // c0 without cancellation: each part of it is what keeps its promised bound near a contact (8 ε,
      // which only Gappa's proof can hold it to: every edit below is the same value in exact arithmetic).
      {"contact_constant_term_kept_errors_dropped", "contact_constant_term",
       [](Kernel& k) { step(k, "constant_term").expression = symbol(k, "nearest"); }},
      {"contact_constant_term_product_error_rounded_twice", "contact_constant_term",
       [](Kernel& k) {
         step(k, "dd_error").expression = symbol(k, "distance") * symbol(k, "distance") - symbol(k, "dd");
       }},
      {"contact_constant_term_larger_square_unguarded", "contact_constant_term",
       [](Kernel& k) {
         step(k, "larger").guards.clear();
         step(k, "smaller").guards.clear();
       }},
      {"contact_constant_term_smaller_square_first", "contact_constant_term",
       [](Kernel& k) {
         step(k, "difference").expression = symbol(k, "larger") + symbol(k, "smaller");
         step(k, "nearest").expression = symbol(k, "difference") - symbol(k, "dd");
       }},
      {"contact_linear_term_without_its_two", "contact_linear_term",
       [](Kernel& k) {
         const auto x = [&](const char* name) { return symbol(k, name); };
         k.outputs.at(0) = x("dx") * x("dvx") + x("dy") * x("dvy");
       }},
      {"contact_quadratic_term_acceleration_halved", "contact_quadratic_term",
       [](Kernel& k) {
         const auto x = [&](const char* name) { return symbol(k, name); };
         k.outputs.at(0) = x("dvx") * x("dvx") + x("dvy") * x("dvy") + (x("dx") * x("dax") + x("dy") * x("day")) / 2;
       }},
      {"contact_cubic_term_components_crossed", "contact_cubic_term",
       [](Kernel& k) {
         const auto x = [&](const char* name) { return symbol(k, name); };
         k.outputs.at(0) = x("dvx") * x("day") + x("dvy") * x("dax");
       }},
      {"contact_quartic_term_half_for_quarter", "contact_quartic_term",
       [](Kernel& k) {
         const auto x = [&](const char* name) { return symbol(k, name); };
         k.outputs.at(0) = (x("dax") * x("dax") + x("day") * x("day")) / 2;
       }},
      {"cushion_contact_constant_term_radius_added", "cushion_contact_constant_term",
       [](Kernel& k) { k.outputs.at(0) = symbol(k, "gap") + symbol(k, "radius"); }},
      {"cushion_contact_quadratic_term_not_halved", "cushion_contact_quadratic_term",
       [](Kernel& k) { k.outputs.at(0) = symbol(k, "normal_acceleration"); }},
      // The event polynomials' claims as hands type them: c1 without its 2, and the cushion's ½ a_n as a_n.
      claim_retyped("events_contact_linear_term_halved", "events.contact_linear_term",
                    [](const GiNaC::ex& typed) { return typed / 2; }),
      claim_retyped("events_cushion_acceleration_not_halved", "events.cushion_quadratic_term",
                    [](const GiNaC::ex& typed) { return 2 * typed; }),
  };
  return mutations;
}

void apply(const Mutation& mutation, Derivation& derivation) {
  if (mutation.edit_derivation) mutation.edit_derivation(derivation);
  if (!mutation.edit) return;
  for (std::vector<Kernel>* list : {&derivation.kernels, &derivation.reference_kernels}) {
    for (Kernel& kernel : *list) {
      if (kernel.name == mutation.kernel) {
        mutation.edit(kernel);
        return;
      }
    }
  }
  throw std::invalid_argument("mutation " + mutation.name + ": no kernel " + mutation.kernel);
}

std::string edit_function(const std::string& text, const std::string& name, const std::string& from,
                          const std::string& to) {
  // The definition: " name(" on a line that ends its signature with ") noexcept {" or ") {", the body up
  // to the "}" that starts a line.
  for (std::size_t at = text.find(" " + name + "("); at != std::string::npos;
       at = text.find(" " + name + "(", at + 1)) {
    const std::size_t open = std::min(text.find(") noexcept {\n", at), text.find(") {\n", at));
    if (open == std::string::npos || text.find(';', at) < open) continue;
    const std::size_t end = text.find("\n}\n", open);
    std::string body = text.substr(open, end - open);
    if (body.find(from) == std::string::npos)
      throw std::invalid_argument("the function " + name + " has no " + from);
    for (std::size_t i = body.find(from); i != std::string::npos; i = body.find(from, i + to.size()))
      body.replace(i, from.size(), to);
    return text.substr(0, open) + body + text.substr(end);
  }
  throw std::invalid_argument("no function " + name + " in the header");
}

}  // namespace billiards::derive::testing

namespace billiards::derive::testing {

const std::vector<Mutation>& shot_mutations() {
  const shot::Symbols& s = shot::symbols();
  static const std::vector<Mutation> mutations = {
      // The strike's kernels: the cue's mass ratio inverted, and the spin's 5/2 as 5/7.
      {"strike_velocity_change_mass_ratio_inverted", "strike_velocity_change",
       [](Kernel& k) { step(k, "mass_ratio").expression = symbol(k, "cue_mass") / symbol(k, "ball_mass"); }},
      {"strike_spin_five_sevenths", "strike_spin",
       [](Kernel& k) {
         step(k, "spin_factor").expression = GiNaC::numeric(5, 7) * symbol(k, "velocity_change") / symbol(k, "radius");
       }},
      // The cushion's kernels: the spin about the normal with its sign turned in the slip along the
      // cushion, restitution dropped from the normal impulse, the nose's cos and sin swapped in Δv_x, and
      // the spin change's 5/2 as 5/7.
      {"cushion_slip_normal_spin_sign_turned", "cushion_slip",
       [](Kernel& k) {
         k.outputs.at(1) = symbol(k, "along_speed") + symbol(k, "radius") * symbol(k, "spin_up") * symbol(k, "cos_nose") +
                           symbol(k, "radius") * symbol(k, "spin_normal") * symbol(k, "sin_nose");
       }},
      {"cushion_normal_impulse_restitution_dropped", "cushion_normal_impulse",
       [](Kernel& k) { k.outputs.at(0) = 2 * symbol(k, "approach_speed") * symbol(k, "cos_nose"); }},
      {"cushion_velocity_change_cos_for_sin", "cushion_velocity_change",
       [](Kernel& k) {
         k.outputs.at(0) = -symbol(k, "normal_impulse") * symbol(k, "sin_nose") -
                           symbol(k, "friction_ratio") * symbol(k, "slip_tangent") * symbol(k, "cos_nose");
       }},
      {"cushion_spin_change_five_sevenths", "cushion_spin_change",
       [](Kernel& k) {
         step(k, "spin_factor").expression = GiNaC::numeric(5, 7) * symbol(k, "friction_ratio") / symbol(k, "radius");
       }},
      // Han's s_y taken for the slip along the cushion: his eq. 14 has it turned round.
      claim_retyped("shot_han_slip_along_sign_kept", "cushion.slip_in_cushion_frame",
                    [](const GiNaC::ex& typed) { return GiNaC::lst{typed.op(0), -typed.op(1)}; }),
      // The cue's mass where the ball's belongs (an impulse of 2 M V over the denominator, not 2 m V).
      claim_retyped("shot_speed_cue_mass_for_ball_mass", "strike.speed",
                    [&s](const GiNaC::ex& typed) { return typed * s.M / s.m; }),
      // A cos for a sin in TP A-30's offset terms: (c cos θ)² for (c sin θ)².
      claim_retyped("shot_offset_terms_cos_for_sin", "strike.tp_a30_offset_terms",
                    [&s](const GiNaC::ex& typed) {
                      return typed - GiNaC::pow(s.c_horizontal * s.sin_theta, 2) +
                             GiNaC::pow(s.c_horizontal * s.cos_theta, 2);
                    }),
      // The spin typed with the wrong sense: r × J d turned round.
      claim_retyped("shot_spin_sign_turned", "strike.spin", [](const GiNaC::ex& typed) { return -typed; }),
      // The end mass and the ball's mass swapped in TP A-31's ratio: m_e/m for m/m_e.
      claim_retyped("shot_squirt_mass_ratio_inverted", "squirt.angle",
                    [&s](const GiNaC::ex& typed) {
                      return typed.subs(GiNaC::exmap{{s.m, s.end_mass}, {s.end_mass, s.m}});
                    }),
      // Han (2005)'s stick/slip test as printed, without μ.
      claim_retyped("shot_han_stick_test_without_mu", "cushion.regime",
                    [&s](const GiNaC::ex& typed) { return typed.subs(s.cushion_friction == 1); }),
      // The nose's angle misread: θ_a measured from the vertical, cos and sin swapped in Han's equations.
      claim_retyped("shot_han_angle_misread", "cushion.han_2005_sticking",
                    [&s](const GiNaC::ex& typed) {
                      return typed.subs(GiNaC::exmap{{s.cos_a, s.sin_a}, {s.sin_a, s.cos_a}});
                    }),
  };
  return mutations;
}

}  // namespace billiards::derive::testing
