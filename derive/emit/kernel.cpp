#include "emit/kernel.hpp"

#include "core/powers_of_two.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace billiards::derive {

std::string full_form_name(const Kernel& kernel) { return "full_" + kernel.name; }

std::vector<std::string> cited_claims(const Kernel& kernel) {
  std::vector<std::string> ids;
  const auto cite = [&](const std::string& id) {
    if (!id.empty() && std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
  };
  cite(kernel.equals);
  for (const std::string& id : kernel.claims) cite(id);
  for (const KernelStep& step : kernel.steps) {
    for (const Guard& guard : step.guards) cite(guard.claim);
  }
  if (kernel.fast_path) cite(kernel.fast_path->claim);
  return ids;
}

using GiNaC::ex;
using GiNaC::numeric;

ScaledMonomial scaled_monomial(const std::string& name, const ex& monomial,
                               const std::vector<ex>& parameters) {
  ScaledMonomial out;
  ex exponent = 0;
  for (const ex& parameter : parameters) {
    if (!monomial.has(parameter)) continue;
    // The degree a of x in c Π x_i^(a_i): the monomial at 2x over the monomial at x is 2^a.
    const ex ratio = GiNaC::normal(monomial.subs(parameter == 2 * parameter) / monomial);
    const std::string base = GiNaC::ex_to<GiNaC::symbol>(parameter).get_name();
    const auto not_a_monomial = [&] {
      return std::invalid_argument("scaled_monomial " + name +
                                   ": the form is not a monomial of integer degree in " + base);
    };
    const std::optional<int> degree =
        GiNaC::is_a<numeric>(ratio) ? exact_binary_logarithm(GiNaC::ex_to<numeric>(ratio)) : std::nullopt;
    if (!degree) throw not_a_monomial();
    const GiNaC::symbol exponent_step(base + "_exponent"), significand_step("scaled_" + base);
    out.steps.push_back({exponent_step, binary_exponent(parameter)});
    out.steps.push_back({significand_step, times_power_of_two(parameter, -exponent_step)});
    out.scaled[parameter] = significand_step;
    out.exponent[parameter] = exponent_step;
    exponent += *degree * exponent_step;
  }
  const GiNaC::symbol significand("scaled_" + name), exponent_sum(name + "_exponent");
  out.steps.push_back({significand, monomial.subs(out.scaled)});
  out.steps.push_back({exponent_sum, exponent});
  out.value = times_power_of_two(significand, exponent_sum);
  return out;
}

}  // namespace billiards::derive
