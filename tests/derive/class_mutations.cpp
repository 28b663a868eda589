// The mutation suite by class: for each kind of slip — in the printer, the emitter, the support code it
// prints, a parameter's meaning, a claim no kernel cites — mutations that must fail the run, naming what
// they broke; and a comment, which must not.
#include "core/claim.hpp"
#include "core/named_constants.hpp"
#include "mutations.hpp"

#include <stdexcept>

namespace billiards::derive::testing {

using GiNaC::ex;

namespace {

// A mutation of the header `header`'s text: `from` replaced by `to` in the body of `function`.
Mutation printed(const std::string& name, const std::string& culprit, const std::string& header,
                 const std::string& function, const std::string& from, const std::string& to) {
  return {.name = name,
          .kernel = culprit,
          .header = header,
          .edit_printed = [function, from, to](const std::string& text) {
            return edit_function(text, function, from, to);
          }};
}

const std::string kernels_header = "billiards/kernels.hpp";
const std::string support_header = "billiards/kernel_support.hpp";
const std::string spin_header = "billiards/spin_kernels.hpp";
const std::string list_header = "billiards/kernel_list.hpp";
const std::string spin_list_header = "billiards/spin_kernel_list.hpp";

// The claim `id` with its paper side changed, checked again: a slip in a claim that no kernel cites.
Mutation uncited_claim_wrong(const std::string& name, const std::string& id) {
  return claim_retyped(name, id, [](const GiNaC::ex& typed) { return typed + GiNaC::symbol("slip"); });
}

// Every kernel named `kernel` or `plain_<kernel>` with the meanings of parameters `a` and `b` swapped.
Mutation meanings_swapped(const std::string& name, const std::string& kernel, const std::string& a,
                          const std::string& b) {
  return {.name = name, .kernel = kernel, .edit_derivation = [kernel, a, b](Derivation& derivation) {
            for (Kernel& k : derivation.kernels) {
              if (k.name != kernel && k.name != "plain_" + kernel) continue;
              ex first, second;
              for (const auto& [parameter, meaning] : k.in_claim_terms) {
                const std::string n = GiNaC::ex_to<GiNaC::symbol>(parameter).get_name();
                if (n == a) first = parameter;
                if (n == b) second = parameter;
              }
              if (first.is_zero() || second.is_zero())
                throw std::invalid_argument(kernel + " has no meaning of " + a);
              std::swap(k.in_claim_terms[first], k.in_claim_terms[second]);
            }
          }};
}

// Every fast path's domain widened, the plain forms' domains and the predicates' conditions alike (both
// come from one place in a model): the named constant `from` replaced by `to`.
Mutation domain_widened(const std::string& name, const std::string& culprit, const ex& from, const ex& to) {
  return {.name = name, .kernel = culprit, .edit_derivation = [from, to](Derivation& derivation) {
            for (Kernel& k : derivation.kernels) {
              for (ex& condition : k.domain) condition = condition.subs(from == to);
              if (k.fast_path) {
                for (ex& condition : k.fast_path->conditions) condition = condition.subs(from == to);
              }
            }
          }};
}

}  // namespace

const std::vector<Mutation>& paper_class_mutations() {
  static const std::vector<Mutation> mutations = {
      // The bit comparison's helpers, one off.
      printed("support_bits_above_off_by_one", "bits_above", support_header, "bits_above",
              "std::bit_cast<Bits>(low))", "std::bit_cast<Bits>(low) + 1)"),
      printed("support_larger_takes_the_smaller", "larger", support_header, "larger", "a > b ? a : b",
              "a < b ? a : b"),
      // The printer: each relational and arithmetic operator, literals and their suffixes.
      printed("printer_less_as_less_or_equal", "full_normal_velocity_change", kernels_header,
              "full_normal_velocity_change", " < smallest_normal", " <= smallest_normal"),
      printed("printer_less_or_equal_as_less", "time_of_impact", kernels_header, "time_of_impact",
              "discriminant <= Scalar(0)", "discriminant < Scalar(0)"),
      printed("printer_greater_or_equal_as_greater", "time_of_impact", kernels_header, "time_of_impact",
              "pv >= Scalar(0)", "pv > Scalar(0)"),
      printed("printer_plus_as_minus", "plain_normal_velocity_change", kernels_header,
              "plain_normal_velocity_change", "Scalar(1) + restitution", "Scalar(1) - restitution"),
      printed("printer_minus_as_plus", "plain_elastic_normal_velocity_change", kernels_header,
              "plain_elastic_normal_velocity_change", "v2n - v1n", "v2n + v1n"),
      printed("printer_times_as_divided", "plain_elastic_normal_velocity_change", kernels_header,
              "plain_elastic_normal_velocity_change", "first_impulse_coefficient * relative_normal_speed",
              "first_impulse_coefficient / relative_normal_speed"),
      printed("printer_divided_as_times", "time_of_impact", kernels_header, "time_of_impact", "gap / (",
              "gap * ("),
      printed("printer_negation_dropped", "cushion_normal_velocity_change", kernels_header,
              "cushion_normal_velocity_change", "return -(Scalar(2) * vn);", "return (Scalar(2) * vn);"),
      printed("printer_bare_double_literal", "plain_elastic_normal_velocity_change", kernels_header,
              "plain_elastic_normal_velocity_change", "Scalar(2) * m2", "2.0 * m2"),
      printed("printer_float_suffix_dropped", "plain_mass_low", support_header, "plain_mass_low<float>",
              "0x1p-61f", "0x1p-61"),
      printed("printer_float_suffix_on_double", "plain_mass_low", support_header, "plain_mass_low<double>",
              "0x1p-509", "0x1p-509f"),
      // The emitter: the arguments of every call a fast path prints, and which plain form it takes.
      printed("emitter_fast_call_masses_swapped", "normal_velocity_change", kernels_header,
              "normal_velocity_change", "plain_normal_velocity_change(m1, m2,",
              "plain_normal_velocity_change(m2, m1,"),
      printed("emitter_full_call_speeds_swapped", "elastic_normal_velocity_change", kernels_header,
              "elastic_normal_velocity_change", "full_elastic_normal_velocity_change(m1, m2, v1n, v2n)",
              "full_elastic_normal_velocity_change(m1, m2, v2n, v1n)"),
      printed("emitter_predicate_arguments_swapped", "direction_velocity_change", kernels_header,
              "direction_velocity_change", "within_plain_mass_range(m1, m2)",
              "within_plain_mass_range(m2, m1)"),
      printed("emitter_fast_path_takes_another_plain_form", "direction_velocity_change", kernels_header,
              "direction_velocity_change", "return plain_direction_velocity_change(",
              "return plain_approaching_direction_velocity_change("),
      // Printed support code: a wrong constant, an off-by-one exponent, a wrong range end, |x|.
      printed("support_constant_off_by_one", "plain_mass_low", support_header, "plain_mass_low<double>",
              "0x1p-509", "0x1p-508"),
      printed("support_generic_loop_off_by_one", "plain_mass_low", support_header, "plain_mass_low",
              "min_exponent) / 2;", "min_exponent) / 2 + 1;"),
      printed("support_smallest_normal_off_by_one", "smallest_normal", support_header,
              "smallest_normal<float>", "0x1p-126f", "0x1p-125f"),
      printed("support_predicate_range_end", "within_plain_mass_range", kernels_header,
              "within_plain_mass_range", "m2 <= plain_mass_high<Scalar>()", "m2 <= infinity<Scalar>()"),
      printed("support_predicate_bits_range_end", "within_plain_mass_range", kernels_header,
              "within_plain_mass_range", "bits_above(plain_mass_high<Scalar>(), low)",
              "bits_above(infinity<Scalar>(), low)"),
      printed("support_absolute_value_sign", "absolute_value", support_header, "absolute_value", "? -x : x",
              "? x : -x"),
      // Parameter meanings, written from the definitions: D with its operands swapped (−D), a meaning
      // negated or two swapped.
      {"meaning_discriminant_operands_swapped", "time_of_impact",
       [](Kernel& k) {
         for (KernelStep& step : k.steps) {
           if (step.name.get_name() == "discriminant") step.expression = -step.expression;
         }
       }},
      {.name = "meaning_pv_negated",
       .kernel = "time_of_impact",
       .edit =
           [](Kernel& k) {
             for (auto& [parameter, meaning] : k.in_claim_terms) {
               if (GiNaC::ex_to<GiNaC::symbol>(parameter).get_name() == "pv") meaning = -meaning;
             }
           }},
      meanings_swapped("meaning_direction_speeds_swapped", "direction_velocity_change", "v1d", "v2d"),
      // A domain widened past what is safe: to +∞ (a NaN for an immovable body), or down to the smallest
      // normal number (the impulse coefficients then underflow).
      domain_widened("domain_mass_range_to_infinity", "plain_elastic_normal_velocity_change",
                     plain_mass_high(), infinity()),
      domain_widened("domain_mass_range_down_to_the_smallest_normal", "plain_normal_velocity_change",
                     plain_mass_low(), smallest_normal()),
      // A kernel's stated rounding range widened through zero: v·n = 0 gives a change of 0, no normal
      // number, and no relative bound.
      {"rounding_range_through_zero", "cushion_normal_velocity_change",
       [](Kernel& k) { k.rounding_cases.at(0).at(0) = 0 <= k.parameters.at(0); }},
      // A full form's small-mass case with the light mass down to 1/4: m_heavy/m_light then overflows.
      {"rounding_case_where_a_mass_ratio_overflows", "elastic_normal_velocity_change",
       [](Kernel& k) { k.rounding_cases.at(2).at(0) = GiNaC::numeric(1, 4) <= k.parameters.at(0); }},
      // time_of_impact's case down to p·p = 1, where the balls may already touch (p·p − r² of either
      // sign): the guard is no longer decided.
      {"rounding_case_through_a_touch", "time_of_impact",
       [](Kernel& k) { k.rounding_cases.at(0).at(0) = 1 <= k.parameters.at(0); }},
      // The kernel list, which the tests call the kernels through: a branch's arguments swapped, and the
      // sum of every kernel passing a[1] for a[0].
      printed("list_call_arguments_swapped", "call", list_header, "call",
              "elastic_normal_velocity_change(at(\"m1\"), at(\"m2\"), at(\"v1n\"), at(\"v2n\"))",
              "elastic_normal_velocity_change(at(\"m1\"), at(\"m2\"), at(\"v2n\"), at(\"v1n\"))"),
      printed("list_sum_argument_shifted", "sum_of_every_kernel", list_header, "sum_of_every_kernel",
              "cushion_normal_velocity_change(a[0])", "cushion_normal_velocity_change(a[1])"),
      // A claim that no kernel cites.
      uncited_claim_wrong("uncited_claim_momentum_along_n", "along_n.momentum"),
      // A comment changes nothing that is proven.
      {.name = "comment_only",
       .kernel = "plain_elastic_normal_velocity_change",
       .header = kernels_header,
       .edit_printed =
           [](const std::string& text) {
             return edit_function(text, "plain_elastic_normal_velocity_change", "  const Scalar total_mass",
                                  "  // the sum of the masses\n  const Scalar total_mass");
           },
       .harmless = true},
  };
  return mutations;
}

const std::vector<Mutation>& spin_class_mutations() {
  static const std::vector<Mutation> mutations = {
      printed("printer_literal_not_exact_in_float", "tangential_inverse_effective_mass", spin_header,
              "tangential_inverse_effective_mass", "Scalar(3.5) / m1", "Scalar(3.4) / m1"),
      printed("printer_literal_misspelled", "spin_change", spin_header, "spin_change", "Scalar(2.5)",
              "Scalar(2.25)"),
      // A fused multiply-add read back as its value: its addend's sign slipped is a different c0.
      printed("printer_fused_addend_sign", "contact_constant_term", spin_header, "contact_constant_term",
              "std::fma(distance, distance, -dd)", "std::fma(distance, distance, dd)"),
      // Split into a product and a sum, it rounds twice: the same value, but the kept error is lost, which
      // only the proof of the promised bound sees.
      printed("printer_fused_as_two_roundings", "contact_constant_term", spin_header, "contact_constant_term",
              "std::fma(dx, dx, -xx)", "dx * dx - xx"),
      printed("emitter_fast_call_arguments_swapped", "slide_time", spin_header, "slide_time",
              "plain_slide_time(slip_speed, sliding_friction, gravity)",
              "plain_slide_time(slip_speed, gravity, sliding_friction)"),
      printed("support_moderate_loop_off_by_one", "moderate_low", support_header, "moderate_low",
              "max_exponent / 4 - 2", "max_exponent / 4 - 1"),
      // The bit helpers, one off: run from their text over every exponent, each answers wrongly somewhere.
      printed("support_binary_exponent_bias_off_by_one", "binary_exponent", support_header, "binary_exponent",
              "static_cast<int>(field) - bias", "static_cast<int>(field) - bias + 1"),
      printed("support_binary_exponent_device_path_off_by_one", "binary_exponent", support_header,
              "binary_exponent", "return Scalar(std::ilogb(x));", "return Scalar(std::ilogb(x) - 1);"),
      printed("support_times_power_of_two_bias_off_by_one", "times_power_of_two", support_header,
              "times_power_of_two", "static_cast<Bits>(exponent + bias)", "static_cast<Bits>(exponent + bias + 1)"),
      printed("support_times_power_of_two_clamp_off_by_one", "times_power_of_two", support_header,
              "times_power_of_two", "exponent >= 1 - bias", "exponent >= -bias"),
      meanings_swapped("meaning_roll_time_speed_and_gravity_swapped", "roll_time", "speed", "gravity"),
      uncited_claim_wrong("uncited_claim_linear_momentum", "conservation.linear_momentum"),
      // A scaled kernel's range beyond one binade, where its exponents are no longer 0.
      {"rounding_range_beyond_one_binade", "spin_change_per_impulse",
       [](Kernel& k) { k.rounding_cases.at(0).at(1) = k.parameters.at(0) < 4; }},
      // The spin kernel list returning a kernel's two outputs swapped.
      printed("list_call_outputs_swapped", "call", spin_list_header, "call", "return {r.first, r.second};",
              "return {r.second, r.first};"),
      // A kernel that states no rounding cases has no proven error bound.
      {"rounding_cases_dropped", "spin_change", [](Kernel& k) { k.rounding_cases.clear(); }},
      // The full tangential form's sticking case with the slip down to 7/4: the bound 2|u_t|/7 then spans
      // two binades, and its binary exponent is no longer fixed.
      {"rounding_case_exponent_not_fixed", "tangential_velocity_change",
       [](Kernel& k) { k.rounding_cases.at(0).at(4) = GiNaC::numeric(7, 4) <= k.parameters.at(5); }},
      // The phase times' moderate range widened up to 2^509 (double) from 2^254: a quotient of three
      // inputs then overflows.
      domain_widened("domain_moderate_range_to_the_plain_mass_range", "plain_slide_time", moderate_high(),
                     plain_mass_high()),
      domain_widened("domain_tangential_mass_range_to_infinity", "plain_tangential_velocity_change",
                     plain_mass_high(), infinity()),
  };
  return mutations;
}

Mutation claim_retyped(const std::string& name, const std::string& id,
                       const std::function<GiNaC::ex(const GiNaC::ex&)>& retype) {
  return {.name = name, .kernel = id, .edit_derivation = [id, retype](Derivation& derivation) {
            for (Claim& claim : derivation.claims) {
              if (claim.id != id) continue;
              claim.paper_expression = retype(claim.paper_expression);
              check(claim);
              return;
            }
            throw std::invalid_argument("no claim " + id);
          }};
}

}  // namespace billiards::derive::testing
