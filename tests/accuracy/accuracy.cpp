// billiards-accuracy: every emitted kernel, in float and double, on random and adversarial inputs,
// against the same derived expressions evaluated exactly (inputs converted exactly to rationals).
//
// What is measured is what a user gets: each output is a change Δ of a ball's velocity component
// (x·n = v·n + Δ; along a direction d, x·d/(d·d) = v·d/(d·d) + Δ), so its error is scaled by the
// error bound of that sum, ε (|v| + |Δ|):
//
//   scaled ULP = |Δ computed − Δ exact| / (ε · (|v exact| + |Δ exact|)),
//
// with ε the type's machine epsilon and the denominator floored at the smallest subnormal. A change
// that underflows (a subnormal Δ beside a normal v) is then judged against the velocity it changes,
// which it cannot move anyway. Exact values come from the derivation's own kernel expressions with
// every input converted exactly to a rational; an infinite mass is the limit t → 0 of 1/t.
//
// The spinning-ball kernels (billiards::kernels::spin) return quantities of their own (an impulse, a
// time, a velocity change), judged by their relative error, |computed − exact| / (ε |exact|), the
// denominator floored at the smallest subnormal; an exact +∞ (a phase without friction) must come out
// +∞, and where the exact value rounds to ±∞ in the type (it exceeds the largest finite number by half
// an ulp or more) ±∞ is the correctly rounded result, not a failure. Their inputs are drawn by
// parameter name: each positive quantity log-uniform over the whole range, from the smallest subnormal
// to the largest finite number, with zeros (no slip, no friction), restitution 0 and 1, and equal masses
// among them.
//
// Usage: billiards-accuracy [--samples N (1 to 10^7, default 20000)] [--limit ULP] [--proven AUDIT_JSON]...
//   prints a Markdown table (kernel, type, samples, largest error in ULP, the bound Gappa proved where the
//   audits --proven names hold one, non-finite results) and exits 1 when an error exceeds --limit
//   (default 4) or its proven bound, or a valid input gives NaN or infinity.
#include "core/named_constants.hpp"
#include "exact.hpp"
#include "models/parkin2023/paper.hpp"
#include "models/shot/shot.hpp"
#include "models/spinning/spinning.hpp"

#include <billiards/kernel_list.hpp>
#include <billiards/shot_kernel_list.hpp>
#include <billiards/spin_kernel_list.hpp>

#include <CLI/CLI.hpp>
#include <billiards_support/cli_checks.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using billiards::accuracy::exact_rational;
using GiNaC::ex;
using GiNaC::numeric;

// One kernel's inputs by parameter name; an infinite mass is +∞.
template <typename Scalar>
using Inputs = std::map<std::string, Scalar>;

// Calls the compiled kernel `name` in type Scalar, through the derivation's own list of its kernels.
template <typename Scalar>
std::vector<Scalar> call_kernel(const std::string& name, const Inputs<Scalar>& in) {
  return billiards::kernels::list::call<Scalar>(name, [&](const char* key) { return in.at(key); });
}

// An exact output: a number, or +∞ where a piecewise guard says "no contact".
struct Exact {
  numeric value;
  bool infinite = false;
};

bool names_infinity(const ex& e) {
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (it->is_equal(billiards::derive::infinity())) return true;
  }
  return false;
}

// The kernel's outputs evaluated exactly from its derived steps. An infinite mass is the limit
// t → 0 of 1/t, taken after normal(): the steps are rational in t. Piecewise and overridden guards are
// honoured (the last one whose condition holds, exactly, gives the value), as the code takes them;
// same-value guards are alternative forms of the same quantity and are skipped. A step that divides by zero
// (the significands of a duration without friction) is left undefined, and an output that still reads it is
// an error. A square root is evaluated to GiNaC::Digits digits. `normal_throughout`, where given, says
// whether every step and output is exactly 0 or a normal number of Scalar (false with an infinite mass):
// where a proven rounding bound holds.
template <typename Scalar>
std::vector<Exact> exact_outputs(const billiards::derive::Kernel& kernel, const Inputs<Scalar>& in,
                                 bool* normal_throughout = nullptr) {
  const numeric smallest = exact_rational(std::numeric_limits<Scalar>::min());
  bool normal = true;
  const auto note = [&](const ex& value) {
    if (!GiNaC::is_a<numeric>(value)) {
      normal = false;
    } else if (const numeric v = GiNaC::abs(GiNaC::ex_to<numeric>(value)); !v.is_zero() && v < smallest) {
      normal = false;
    }
  };
  const GiNaC::symbol t("t"), undefined("undefined");
  GiNaC::exmap values;
  std::map<ex, bool, GiNaC::ex_is_less> infinite;
  bool has_infinity = false;
  for (const ex& parameter : kernel.parameters) {
    const Scalar x = in.at(GiNaC::ex_to<GiNaC::symbol>(parameter).get_name());
    has_infinity |= std::isinf(x);
    values[parameter] = std::isinf(x) ? ex(1 / t) : ex(exact_rational(x));
  }
  const auto evaluate = [&](const ex& e) {
    const ex value = has_infinity ? GiNaC::normal(e.subs(values)) : e.subs(values);
    return GiNaC::is_a<numeric>(value) ? value : GiNaC::evalf(value);
  };
  for (const billiards::derive::KernelStep& step : kernel.steps) {
    const billiards::derive::Guard* chosen = nullptr;
    for (const billiards::derive::Guard& guard : step.guards) {
      if (guard.kind != billiards::derive::Guard::Kind::piecewise &&
          guard.kind != billiards::derive::Guard::Kind::overridden)
        continue;
      const ex condition = guard.condition.subs(values);
      if (!GiNaC::is_a<GiNaC::relational>(condition) || has_infinity)
        throw std::logic_error("kernel " + kernel.name +
                               ": a piecewise or overridden guard cannot be evaluated exactly");
      if (static_cast<bool>(GiNaC::ex_to<GiNaC::relational>(condition))) chosen = &guard;
    }
    infinite[step.name] = chosen != nullptr && names_infinity(chosen->alternative);
    try {
      values[step.name] =
          infinite[step.name] ? ex(0) : evaluate(chosen ? chosen->alternative : step.expression);
    } catch (const GiNaC::pole_error&) {
      values[step.name] = undefined;  // a division by zero (no friction) that a later guard replaces
    }
    if (!infinite[step.name] && !values[step.name].is_equal(undefined)) note(values[step.name]);
  }
  std::vector<Exact> outputs;
  for (const ex& output : kernel.outputs) {
    if (infinite.count(output) && infinite[output]) {
      outputs.push_back({0, true});
      continue;
    }
    const ex value = has_infinity ? GiNaC::normal(evaluate(output)).subs(t == 0) : evaluate(output);
    if (!GiNaC::is_a<numeric>(value)) {
      std::ostringstream text;
      text << value;
      throw std::logic_error("kernel " + kernel.name +
                             ": an output did not evaluate to a number: " + text.str());
    }
    outputs.push_back({GiNaC::ex_to<numeric>(value)});
    note(value);
  }
  if (normal_throughout != nullptr) *normal_throughout = normal && !has_infinity;
  return outputs;
}

// The exact velocity component (normal or per d·d) that output `index` of `kernel` changes.
template <typename Scalar>
numeric changed_velocity(const billiards::derive::Kernel& kernel, const Inputs<Scalar>& in,
                         std::size_t index) {
  const std::string ball = std::to_string(index + 1);
  if (in.count("vn")) return exact_rational(in.at("vn"));
  if (in.count("v" + ball + "n")) return exact_rational(in.at("v" + ball + "n"));
  if (in.count("v" + ball + "d"))
    return exact_rational(in.at("v" + ball + "d")) / exact_rational(in.at("dd"));
  throw std::invalid_argument("kernel " + kernel.name + ": no velocity for output " + std::to_string(index));
}

// The time of impact is judged by its backward error: the computed t̂ is the exact contact time of
// inputs perturbed by how many ulps? Near a graze the root is ill-conditioned (D = pv² − vv (pp − r²)
// cancels), so a forward error says more about the inputs than the kernel; the residual
// q(t̂) = vv t̂² + 2 pv t̂ + pp − r², against the sum of the magnitudes of its terms, does not:
//
//   scaled ULP = |q(t̂)| / (ε (vv t̂² + 2 |pv| t̂ + pp + r²)).
//
// Both +∞ agree. A finite time where the exact answer is +∞, or the other way round, is judged by the
// perturbation that would flip the decision: |D| / (ε (pv² + vv (pp + r²))) for a graze, and
// |pv| / (ε √(pp vv)) for a contact that is neither approaching nor separating.
template <typename Scalar>
double time_of_impact_error(Scalar computed, const Exact& exact, const Inputs<Scalar>& in) {
  const numeric pp = exact_rational(in.at("pp")), pv = exact_rational(in.at("pv")),
                vv = exact_rational(in.at("vv")), r = exact_rational(in.at("contact_distance"));
  const numeric epsilon = exact_rational(std::numeric_limits<Scalar>::epsilon());
  const auto in_ulps = [](const numeric& error, const numeric& scale) {
    if (scale.is_zero()) return error.is_zero() ? 0.0 : 1e6;
    const numeric ratio = GiNaC::abs(error) / scale;
    return ratio > numeric(1000000) ? 1e6 : ratio.to_double();
  };
  if (exact.infinite && std::isinf(computed)) return 0;
  if (exact.infinite || std::isinf(computed)) {
    const numeric discriminant = pv * pv - vv * (pp - r * r);
    const double graze = in_ulps(discriminant, epsilon * (pv * pv + vv * (pp + r * r)));
    const double still = std::sqrt(in_ulps(pv * pv, epsilon * epsilon * pp * vv));
    return std::min(graze, still);
  }
  const numeric t = exact_rational(computed);
  return in_ulps(vv * t * t + 2 * pv * t + pp - r * r,
                 epsilon * (vv * t * t + 2 * GiNaC::abs(pv) * t + pp + r * r));
}

template <typename Scalar>
double scaled_ulp_error(Scalar computed, const numeric& exact, const numeric& velocity) {
  numeric scale =
      exact_rational(std::numeric_limits<Scalar>::epsilon()) * (GiNaC::abs(velocity) + GiNaC::abs(exact));
  const numeric smallest = exact_rational(std::numeric_limits<Scalar>::denorm_min());
  if (scale < smallest) scale = smallest;
  const numeric ratio = GiNaC::abs(exact_rational(computed) - exact) / scale;
  return ratio > numeric(1000000) ? 1e6 : ratio.to_double();  // anything this large fails anyway
}

namespace accuracy {

// A number log-uniform in [low, high].
template <typename Scalar>
Scalar log_uniform(std::mt19937_64& random, Scalar low, Scalar high) {
  std::uniform_real_distribution<double> exponent(std::log2(static_cast<double>(low)),
                                                  std::log2(static_cast<double>(high)));
  const Scalar x = static_cast<Scalar>(std::exp2(exponent(random)));
  return std::min(std::max(x, low), high);
}

// Throws unless every condition of the kernel's domain reads only m1, m2 and the plain mass range's
// ends: the one domain over masses the accuracy tool knows how to draw from.
void require_plain_mass_range(const billiards::derive::Kernel& kernel) {
  for (const ex& condition : kernel.domain) {
    for (GiNaC::const_preorder_iterator it = condition.preorder_begin(); it != condition.preorder_end();
         ++it) {
      if (!GiNaC::is_a<GiNaC::symbol>(*it)) continue;
      const std::string name = GiNaC::ex_to<GiNaC::symbol>(*it).get_name();
      if (name != "m1" && name != "m2" && !it->is_equal(billiards::derive::plain_mass_low()) &&
          !it->is_equal(billiards::derive::plain_mass_high())) {
        throw std::invalid_argument("kernel " + kernel.name + ": its domain reads " + name +
                                    "; the accuracy tool knows only the plain mass range");
      }
    }
  }
}

// A mass in [plain_mass_low, plain_mass_high]: its ends, powers of two, the whole range log-uniform.
template <typename Scalar>
Scalar plain_range_mass(std::mt19937_64& random, int mode) {
  const Scalar low = billiards::kernels::plain_mass_low<Scalar>(),
               high = billiards::kernels::plain_mass_high<Scalar>();
  switch (mode) {
    case 0: return random() % 2 ? low : high;
    case 1: return log_uniform(random, low, high);
    case 2: return std::ldexp(Scalar(1), static_cast<int>(random() % 40) - 20);
    default: return log_uniform(random, Scalar(1e-3), Scalar(1e3));
  }
}

}  // namespace accuracy

// Inputs in the checked API's domain, random and adversarial.
template <typename Scalar>
class InputGenerator {
 public:
  /// `finite_masses`: no infinite mass (for a kernel that does not take one).
  InputGenerator(std::uint64_t seed, bool finite_masses) : random_(seed), finite_masses_(finite_masses) {}

  Inputs<Scalar> operator()(const billiards::derive::Kernel& kernel, int sample) {
    Inputs<Scalar> in;
    const int mode = sample % 8;  // which adversarial family this sample stresses
    if (kernel.name == "time_of_impact") return contact_geometry(mode);
    // A kernel with a domain (a fast path's form) is measured inside it only: the plain form's mass
    // range, the one domain the derivation gives (checked, so that a new one is not silently ignored).
    const bool within_domain = !kernel.domain.empty();
    if (within_domain) accuracy::require_plain_mass_range(kernel);
    const Scalar limit = std::sqrt(std::numeric_limits<Scalar>::max()) / Scalar(64);
    const Scalar direction_length = log_uniform(std::sqrt(std::numeric_limits<Scalar>::min()), limit);
    for (const ex& parameter : kernel.parameters) {
      const std::string name = GiNaC::ex_to<GiNaC::symbol>(parameter).get_name();
      if (name == "m1" || name == "m2") {
        in[name] = within_domain                 ? accuracy::plain_range_mass<Scalar>(random_, mode)
                   : finite_masses_ && mode == 0 ? mass(1)
                                                 : mass(mode);
      }
      if (name == "restitution") in[name] = mode == 3 ? Scalar(0) : mode == 4 ? Scalar(1) : unit_(random_);
      if (name == "dd") in[name] = direction_length * direction_length;
      if (name == "v1n" || name == "v2n" || name == "vn") in[name] = speed(mode, limit);
      if (name == "v1d" || name == "v2d") in[name] = speed(mode, limit) * direction_length;
    }
    if (in.count("m1") && std::isinf(in["m1"]) && std::isinf(in["m2"])) {
      in["m1"] = Scalar(1);
      if ((sample / 8) % 2 != 0) std::swap(in["m1"], in["m2"]);  // the immovable body on either side
    }
    // Nearly tangent: the second normal speed a few ulps from the first.
    const auto nearly_equal = [&](const char* a, const char* b) {
      if (mode == 5 && in.count(a)) {
        Scalar x = in[a];
        for (int step = 0; step < 1 + static_cast<int>(random_() % 4); ++step) {
          x = std::nextafter(x, std::numeric_limits<Scalar>::infinity());
        }
        in[b] = x;
      }
    };
    nearly_equal("v1n", "v2n");
    nearly_equal("v1d", "v2d");
    // Masses over the whole range with ball 1 at rest: its change is then judged against itself alone,
    // so a heavy ball's tiny (but normal) change cannot hide behind its velocity.
    if (mode == 1 && (sample / 8) % 2 == 0) {
      if (in.count("v1n")) in["v1n"] = Scalar(0);
      if (in.count("v1d")) in["v1d"] = Scalar(0);
    }
    return in;
  }

 private:
  // Two spheres for the time of impact: contact distance r over six decades, the gap from nearly
  // touching (a relative 1e-7, or touching up to rounding) to a hundred radii, aimed at each other,
  // nearly grazing (missing or hitting by 0.1 %) or in any direction (separating or missing).
  Inputs<Scalar> contact_geometry(int mode) {
    std::normal_distribution<double> normal;
    std::array<double, 3> along{}, across{};
    for (double& x : along) x = normal(random_);
    for (double& x : across) x = normal(random_);
    const double along_length = std::sqrt(along[0] * along[0] + along[1] * along[1] + along[2] * along[2]);
    for (double& x : along) x /= along_length;
    const double overlap = across[0] * along[0] + across[1] * along[1] + across[2] * along[2];
    for (int i = 0; i < 3; ++i) across[i] -= overlap * along[i];
    const double across_length =
        std::sqrt(across[0] * across[0] + across[1] * across[1] + across[2] * across[2]);
    for (double& x : across) x /= across_length;
    const double r = log_uniform(Scalar(1e-3), Scalar(1e3));
    const double gap = mode == 1   ? 0.0
                       : mode == 2 ? log_uniform(Scalar(1e-7), Scalar(1))
                                   : log_uniform(Scalar(1e-3), Scalar(100));
    const double distance = r * (1 + gap);
    const double speed = log_uniform(Scalar(1e-3), Scalar(1e3));
    // Aim: the miss distance b (impact parameter) of the relative line, against r.
    double aim = unit_(random_) * r * 0.999;
    if (mode == 3) aim = r * (random_() % 2 ? 0.999 : 1.001);
    std::array<double, 3> w{};
    const double sine = std::min(aim / distance, 1.0), cosine = std::sqrt(1 - sine * sine);
    for (int i = 0; i < 3; ++i) w[i] = speed * (-cosine * along[i] + sine * across[i]);
    if (mode == 4) {
      for (double& x : w) x = speed * normal(random_);
    }
    std::array<Scalar, 3> p{}, v{};
    for (int i = 0; i < 3; ++i) {
      p[i] = static_cast<Scalar>(distance * along[i]);
      v[i] = static_cast<Scalar>(w[i]);
    }
    const auto dot = [](const std::array<Scalar, 3>& a, const std::array<Scalar, 3>& b) {
      return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    };
    const std::array<Scalar, 3> cross = {p[1] * v[2] - p[2] * v[1], p[2] * v[0] - p[0] * v[2],
                                         p[0] * v[1] - p[1] * v[0]};
    return {{"pp", dot(p, p)},
            {"pv", dot(p, v)},
            {"vv", dot(v, v)},
            {"cross_squared", dot(cross, cross)},
            {"contact_distance", static_cast<Scalar>(r)}};
  }

  Scalar log_uniform(Scalar low, Scalar high) { return accuracy::log_uniform(random_, low, high); }
  Scalar mass(int mode) {
    const Scalar smallest = std::numeric_limits<Scalar>::denorm_min(),
                 largest = std::numeric_limits<Scalar>::max();
    switch (mode) {
      case 0:
        return std::numeric_limits<Scalar>::infinity();  // one side immovable (the other is made finite)
      case 1: return log_uniform(smallest, largest);     // the whole range, subnormals included
      case 2: return std::ldexp(Scalar(1), static_cast<int>(random_() % 40) - 20);
      default: return log_uniform(Scalar(1e-3), Scalar(1e3));
    }
  }
  Scalar speed(int mode, Scalar limit) {
    const Scalar sign = random_() % 2 ? Scalar(1) : Scalar(-1);
    if (mode == 6) return sign * log_uniform(std::numeric_limits<Scalar>::denorm_min(), Scalar(1));  // tiny
    if (mode == 7) return sign * log_uniform(Scalar(1), limit);                                      // large
    return sign * log_uniform(Scalar(1e-3), Scalar(1e3));
  }

  std::mt19937_64 random_;
  bool finite_masses_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
};

// The inputs and output `index` of a kernel's largest error, for --verbose.
template <typename Scalar>
std::string describe(const Inputs<Scalar>& in, std::size_t index, Scalar computed, const Exact& exact) {
  std::ostringstream text;
  text.precision(9);
  for (const auto& [name, value] : in) text << name << "=" << static_cast<double>(value) << " ";
  text << "output " << index << " computed " << computed << " exact ";
  if (exact.infinite) {
    text << "inf";
  } else {
    text << exact.value.to_double();
  }
  return text.str();
}

struct Row {
  std::string kernel, type;
  long samples = 0;
  double worst = 0;
  double worst_normal = 0;  ///< the largest where every exact step and output is 0 or normal
  long non_finite = 0;
  std::string worst_input;  ///< the inputs of the largest error, for --verbose
};

template <typename Scalar>
Row measure(const billiards::derive::Kernel& kernel, const char* type, long samples,
            bool finite_masses = false) {
  Row row;
  row.kernel = kernel.name;
  row.type = type;
  InputGenerator<Scalar> generate(0xB111A5D5ULL + kernel.name.size(), finite_masses);
  for (long sample = 0; sample < samples; ++sample) {
    const Inputs<Scalar> in = generate(kernel, static_cast<int>(sample));
    const std::vector<Scalar> computed = call_kernel<Scalar>(kernel.name, in);
    bool normal = false;
    const std::vector<Exact> exact = exact_outputs(kernel, in, &normal);
    const bool is_time = kernel.name == "time_of_impact";
    for (std::size_t i = 0; i < computed.size(); ++i) {
      if (std::isnan(computed[i]) || (!is_time && std::isinf(computed[i]))) {
        ++row.non_finite;
        continue;
      }
      const double error =
          is_time ? time_of_impact_error(computed[i], exact[i], in)
                  : scaled_ulp_error(computed[i], exact[i].value, changed_velocity(kernel, in, i));
      if (error > row.worst) {
        row.worst = error;
        row.worst_input = describe(in, i, computed[i], exact[i]);
      }
      if (normal) row.worst_normal = std::max(row.worst_normal, error);
    }
    ++row.samples;
  }
  return row;
}

// ---- The spinning-ball kernels ---------------------------------------------------------------

// True where an exact value rounds to ±∞ in Scalar: its magnitude at least the largest finite number
// plus half that number's ulp. There ±∞ is the correctly rounded result, not a failure.
template <typename Scalar>
bool rounds_to_infinity(const numeric& value) {
  using limits = std::numeric_limits<Scalar>;
  static const numeric threshold =
      exact_rational(limits::max()) + numeric(2).power(limits::max_exponent - 1 - limits::digits);
  return GiNaC::abs(value) >= threshold;
}

// A spin kernel's output that is NaN, or ∞ where the exact value is finite in Scalar.
template <typename Scalar>
bool wrongly_non_finite(Scalar computed, const Exact& exact) {
  if (std::isnan(computed)) return true;
  if (!std::isinf(computed) || exact.infinite) return false;
  return !rounds_to_infinity<Scalar>(exact.value) || (computed > 0) != (exact.value > 0);
}

template <typename Scalar>
double relative_ulp_error(Scalar computed, const Exact& exact) {
  if (exact.infinite) return std::isinf(computed) && computed > 0 ? 0 : 1e6;
  if (std::isinf(computed)) return wrongly_non_finite(computed, exact) ? 1e6 : 0;
  if (!std::isfinite(computed)) return 1e6;
  numeric scale = exact_rational(std::numeric_limits<Scalar>::epsilon()) * GiNaC::abs(exact.value);
  const numeric smallest = exact_rational(std::numeric_limits<Scalar>::denorm_min());
  if (scale < smallest) scale = smallest;
  const numeric ratio = GiNaC::abs(exact_rational(computed) - exact.value) / scale;
  return ratio > numeric(1000000) ? 1e6 : ratio.to_double();
}

// Inputs of a spin kernel by parameter name (see the top of this file).
template <typename Scalar>
class SpinInputGenerator {
 public:
  explicit SpinInputGenerator(std::uint64_t seed) : random_(seed) {}

  Inputs<Scalar> operator()(const billiards::derive::Kernel& kernel, int sample) {
    const int mode = sample % 8;
    Inputs<Scalar> in;
    // The event polynomials' coefficients are measured where their bound is proven: inside their case
    // (every term of one sign), scaled by one power of two common to every input, which their terms
    // follow exactly; where the terms cancel their relative error has no bound.
    if (kernel.name.find("contact_") != std::string::npos) return in_scaled_case(kernel, true);
    // The strike's and the cushion's kernels mix lengths with ratios (offsets in units of R, restitution,
    // the nose's cos and sin, the friction ratio): measured over the case they are proven over, unscaled.
    if (kernel.name.rfind("strike_", 0) == 0 || kernel.name.rfind("cushion_", 0) == 0)
      return in_scaled_case(kernel, false);
    // A fast path's plain form is measured inside its domain only: the moderate range (every input) or
    // the plain mass range (the masses; checked, so that a new domain is not silently ignored).
    const bool moderate = std::any_of(kernel.domain.begin(), kernel.domain.end(), [](const ex& condition) {
      return condition.has(billiards::derive::moderate_low()) ||
             condition.has(billiards::derive::moderate_high());
    });
    const bool plain_masses = !kernel.domain.empty() && !moderate;
    if (plain_masses) accuracy::require_plain_mass_range(kernel);
    if (moderate) {
      for (const ex& condition : kernel.domain) {
        if (!condition.has(billiards::derive::moderate_low()) &&
            !condition.has(billiards::derive::moderate_high()))
          throw std::logic_error("kernel " + kernel.name + ": a domain other than the moderate range");
      }
      for (const ex& parameter : kernel.parameters) {
        in[GiNaC::ex_to<GiNaC::symbol>(parameter).get_name()] =
            mode == 0   ? billiards::kernels::moderate_low<Scalar>()
            : mode == 1 ? billiards::kernels::moderate_high<Scalar>()
                        : log_uniform(billiards::kernels::moderate_low<Scalar>(),
                                      billiards::kernels::moderate_high<Scalar>());
      }
      return in;
    }
    for (const ex& parameter : kernel.parameters) {
      const std::string name = GiNaC::ex_to<GiNaC::symbol>(parameter).get_name();
      if (name == "restitution") {
        in[name] = mode == 1 ? Scalar(0) : mode == 2 ? Scalar(1) : Scalar(unit_(random_));
      } else if (name == "relative_normal_speed") {
        in[name] = -wide();  // approaching
      } else if (name.find("friction") != std::string::npos) {
        in[name] = mode == 3 ? Scalar(0) : mode == 4 ? wide() : Scalar(unit_(random_));
      } else if (mode == 5 && (name == "tangential_slip" || name.find("speed") != std::string::npos)) {
        in[name] = Scalar(0);  // no slip, at rest, no spin
      } else {
        in[name] = wide();
      }
    }
    if (plain_masses) {
      in["m1"] = accuracy::plain_range_mass<Scalar>(random_, mode);
      in["m2"] = accuracy::plain_range_mass<Scalar>(random_, (mode + sample / 8) % 8);
    }
    if (mode == 6 && in.count("m1")) in["m2"] = in["m1"];
    // Both regimes of the friction kernels: the sliding bound a factor of up to 4 either side of sticking.
    if (mode == 7 && in.count("tangential_slip") && in.count("normal_impulse")) {
      in["tangential_slip"] = in["friction"] * in["normal_impulse"] *
                              in["tangential_inverse_effective_mass"] *
                              static_cast<Scalar>(std::exp2(4 * unit_(random_) - 2));
    }
    if (mode == 7 && in.count("tangential_slip") && in.count("relative_normal_speed")) {
      in["tangential_slip"] = Scalar(3.5) * (1 + in["restitution"]) * in["friction"] *
                              -in["relative_normal_speed"] *
                              static_cast<Scalar>(std::exp2(4 * unit_(random_) - 2));
    }
    // Where those products overflow, a slip of the whole range instead.
    if (in.count("tangential_slip") && !std::isfinite(in["tangential_slip"])) in["tangential_slip"] = wide();
    return in;
  }

 private:
  Scalar wide() {
    return log_uniform(std::numeric_limits<Scalar>::denorm_min(), std::numeric_limits<Scalar>::max());
  }

  // Each parameter uniform within its bounds in the kernel's first rounding case (relationals low <= x
  // and x <= high with numeric bounds), where `scaled`, all times one 2^k, k drawn so that squares and
  // products of the scaled inputs stay normal numbers.
  Inputs<Scalar> in_scaled_case(const billiards::derive::Kernel& kernel, bool scaled) {
    if (kernel.rounding_cases.empty()) throw std::logic_error("kernel " + kernel.name + ": no rounding case");
    std::map<std::string, std::pair<double, double>> bounds;
    for (const ex& relation : kernel.rounding_cases.front()) {
      const ex low = relation.lhs(), high = relation.rhs();
      if (GiNaC::is_a<GiNaC::symbol>(high) && GiNaC::is_a<numeric>(low))
        bounds[GiNaC::ex_to<GiNaC::symbol>(high).get_name()].first = GiNaC::ex_to<numeric>(low).to_double();
      else if (GiNaC::is_a<GiNaC::symbol>(low) && GiNaC::is_a<numeric>(high))
        bounds[GiNaC::ex_to<GiNaC::symbol>(low).get_name()].second = GiNaC::ex_to<numeric>(high).to_double();
      else
        throw std::logic_error("kernel " + kernel.name + ": a case bound other than a number");
    }
    const int reach = std::numeric_limits<Scalar>::max_exponent / 2 - 8;
    const int exponent = scaled ? static_cast<int>(std::floor((2 * unit_(random_) - 1) * reach)) : 0;
    Inputs<Scalar> in;
    for (const ex& parameter : kernel.parameters) {
      const std::string name = GiNaC::ex_to<GiNaC::symbol>(parameter).get_name();
      const std::pair<double, double>& range = bounds.at(name);
      const double value = range.first + (range.second - range.first) * unit_(random_);
      in[name] = static_cast<Scalar>(std::ldexp(value, exponent));
    }
    return in;
  }
  Scalar log_uniform(Scalar low, Scalar high) { return accuracy::log_uniform(random_, low, high); }

  std::mt19937_64 random_;
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
};

// A spinning-ball kernel (prefix "spin::") or a shot kernel ("shot::"), called through its model's list.
template <typename Scalar>
Row measure_spin(const billiards::derive::Kernel& kernel, const char* type, long samples,
                 const std::string& prefix = "spin::") {
  Row row;
  row.kernel = prefix + kernel.name;
  row.type = type;
  SpinInputGenerator<Scalar> generate(0x5B1A5ULL + kernel.name.size());
  for (long sample = 0; sample < samples; ++sample) {
    const Inputs<Scalar> in = generate(kernel, static_cast<int>(sample));
    const auto at = [&](const char* key) { return in.at(key); };
    const std::vector<Scalar> computed = prefix == "shot::"
                                             ? billiards::kernels::shot::list::call<Scalar>(kernel.name, at)
                                             : billiards::kernels::spin::list::call<Scalar>(kernel.name, at);
    bool normal = false;
    const std::vector<Exact> exact = exact_outputs(kernel, in, &normal);
    for (std::size_t i = 0; i < computed.size(); ++i) {
      if (wrongly_non_finite(computed[i], exact[i])) ++row.non_finite;
      const double error = relative_ulp_error(computed[i], exact[i]);
      if (error > row.worst) {
        row.worst = error;
        row.worst_input = describe(in, i, computed[i], exact[i]);
      }
      if (normal) row.worst_normal = std::max(row.worst_normal, error);
    }
    ++row.samples;
  }
  return row;
}

// The bounds Gappa proved, from audits billiards-derive wrote: kernel and type → the largest bound, in ε,
// over its cases and outputs. Throws std::runtime_error naming the file when one cannot be read.
std::map<std::pair<std::string, std::string>, double> proven_bounds(const std::vector<std::string>& files) {
  std::map<std::pair<std::string, std::string>, double> bounds;
  for (const std::string& file : files) {
    std::ifstream in(file);
    try {
      const nlohmann::json audit = nlohmann::json::parse(in);
      for (const auto& kernel : audit.at("kernels")) {
        for (const auto& proof : kernel.at("rounding")) {
          double& bound = bounds[{kernel.at("name").get<std::string>(), proof.at("type").get<std::string>()}];
          for (const auto& output : proof.at("outputs"))
            bound = std::max(bound, output.at("epsilons").get<double>());
        }
      }
    } catch (const std::exception& error) {
      throw std::runtime_error("--proven: " + file + ": not an audit.json with proven bounds (" +
                               error.what() + ")");
    }
  }
  return bounds;
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Measures every emitted kernel against exact rational arithmetic.", "billiards-accuracy"};
  long samples = 20000;
  double limit = 4;
  bool verbose = false;
  app.add_flag("--verbose", verbose, "Also print the inputs of each kernel's largest error");
  // At most 10^7 inputs a kernel and type (10^5 take minutes): any count ends, and fits a long.
  app.add_option("--samples", samples, "Inputs per kernel and type (1 to 10^7)")
      ->check(billiards_support::count_at_least(1, 10'000'000));
  app.add_option("--limit", limit, "Largest error allowed, in scaled ULP")
      ->check(billiards_support::finite_number(true));
  std::vector<std::string> proven_files;
  app.add_option("--proven", proven_files,
                 "An audit.json whose proven bounds (Gappa's, for the fast paths' plain forms) the measured "
                 "errors must stay within; may be given more than once")
      ->type_name("FILE");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "billiards-accuracy: " << error.what() << " (run with --help for usage)\n";
    return 2;
  }

  std::map<std::pair<std::string, std::string>, double> proven;
  try {
    proven = proven_bounds(proven_files);
  } catch (const std::exception& error) {
    std::cerr << "billiards-accuracy: " << error.what() << "\n";
    return 2;
  }
  GiNaC::Digits = 60;  // square roots, far beyond double precision
  const billiards::derive::Derivation derivation = billiards::derive::parkin2023::derive();
  std::vector<Row> rows, reference_rows;
  for (const billiards::derive::Kernel& kernel : derivation.kernels) {
    rows.push_back(measure<float>(kernel, "float", samples));
    rows.push_back(measure<double>(kernel, "double", samples));
  }
  for (const billiards::derive::Kernel& kernel : billiards::derive::spinning::derive().kernels) {
    rows.push_back(measure_spin<float>(kernel, "float", samples));
    rows.push_back(measure_spin<double>(kernel, "double", samples));
  }
  for (const billiards::derive::Kernel& kernel : billiards::derive::shot::derive().kernels) {
    rows.push_back(measure_spin<float>(kernel, "float", samples, "shot::"));
    rows.push_back(measure_spin<double>(kernel, "double", samples, "shot::"));
  }
  // The benchmark's reference kernel (finite masses only) for comparison, not held to the limit.
  for (const billiards::derive::Kernel& kernel : derivation.reference_kernels) {
    reference_rows.push_back(measure<float>(kernel, "float", samples, true));
    reference_rows.push_back(measure<double>(kernel, "double", samples, true));
  }
  bool ok = true;
  std::cout << "| kernel | type | inputs | largest error (scaled ULP) | largest where normal | proven bound (ε) "
               "| NaN or ∞ |\n"
               "|---|---|---:|---:|---:|---:|---:|\n";
  for (const Row& row : rows) {
    // The spinning kernels are listed as spin::name; the audit names them without the namespace.
    const std::string name =
        row.kernel.substr(row.kernel.find(':') == std::string::npos ? 0 : row.kernel.rfind(':') + 1);
    const auto bound = proven.find({name, row.type});
    std::cout << "| `" << row.kernel << "` | " << row.type << " | " << row.samples << " | " << row.worst
              << " | " << row.worst_normal << " | "
              << (bound == proven.end() ? std::string("—") : std::to_string(bound->second).substr(0, 4))
              << " | " << row.non_finite << " |\n";
    ok = ok && row.worst <= limit && row.non_finite == 0;
    // A proven bound holds where the intermediates and outputs are normal numbers (each is proven over
    // ranges where they are, and the kernels scale exactly): measured there.
    if (bound != proven.end() && row.worst_normal > bound->second) {
      std::cerr << "billiards-accuracy: " << row.kernel << " (" << row.type << ") measured "
                << row.worst_normal << " ε where every intermediate is normal, above its proven bound "
                << bound->second << " ε\n";
      ok = false;
    }
    if (verbose) std::cerr << row.kernel << " (" << row.type << "): " << row.worst_input << "\n";
  }
  std::cout
      << "\nReference kernels (the raw derivation, for the benchmark only; not held to the limit):\n\n"
      << "| kernel | type | inputs | largest error (scaled ULP) | NaN or ∞ |\n|---|---|---:|---:|---:|\n";
  for (const Row& row : reference_rows) {
    std::cout << "| `" << row.kernel << "` | " << row.type << " | " << row.samples << " | " << row.worst
              << " | " << row.non_finite << " |\n";
  }
  if (!ok)
    std::cerr << "billiards-accuracy: an error exceeds " << limit
              << " ULP or its proven bound, or a valid input gave NaN or ∞\n";
  return ok ? 0 : 1;
}
