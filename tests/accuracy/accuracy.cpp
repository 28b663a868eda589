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
// Usage: billiards-accuracy [--samples N] [--limit ULP]
//   prints a Markdown table (kernel, type, samples, largest error in ULP, non-finite results) and
//   exits 1 when an error exceeds --limit (default 4) or a valid input gives NaN or infinity.
#include "derivation.hpp"
#include "exact.hpp"

#include <billiards/kernels.hpp>

#include <CLI/CLI.hpp>

#include <cmath>
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

// Calls the compiled kernel `name` in type Scalar.
template <typename Scalar>
std::vector<Scalar> call_kernel(const std::string& name, const Inputs<Scalar>& in) {
  using namespace billiards::kernels;
  const auto at = [&](const char* key) { return in.at(key); };
  if (name == "elastic_normal_velocity_change") {
    const auto r = elastic_normal_velocity_change(at("m1"), at("m2"), at("v1n"), at("v2n"));
    return {r.first, r.second};
  }
  if (name == "normal_velocity_change") {
    const auto r = normal_velocity_change(at("m1"), at("m2"), at("v1n"), at("v2n"), at("restitution"));
    return {r.first, r.second};
  }
  if (name == "direction_velocity_change") {
    const auto r =
        direction_velocity_change(at("m1"), at("m2"), at("v1d"), at("v2d"), at("dd"), at("restitution"));
    return {r.first, r.second};
  }
  if (name == "approaching_direction_velocity_change") {
    const auto r = approaching_direction_velocity_change(at("m1"), at("m2"), at("v1d"), at("v2d"), at("dd"),
                                                         at("restitution"));
    return {r.first, r.second};
  }
  if (name == "cushion_normal_velocity_change") return {cushion_normal_velocity_change(at("vn"))};
  throw std::invalid_argument("kernel " + name + " has no caller in billiards-accuracy: add one");
}

// The kernel's outputs evaluated exactly from its derived steps. An infinite mass is the limit
// t → 0 of 1/t, taken after normal(): the steps are rational in t.
template <typename Scalar>
std::vector<numeric> exact_outputs(const billiards::derive::Kernel& kernel, const Inputs<Scalar>& in) {
  const GiNaC::symbol t("t");
  GiNaC::exmap values;
  bool has_infinity = false;
  for (const ex& parameter : kernel.parameters) {
    const Scalar x = in.at(GiNaC::ex_to<GiNaC::symbol>(parameter).get_name());
    has_infinity |= std::isinf(x);
    values[parameter] = std::isinf(x) ? ex(1 / t) : ex(exact_rational(x));
  }
  const auto evaluate = [&](const ex& e) {
    return has_infinity ? GiNaC::normal(e.subs(values)) : e.subs(values);
  };
  for (const billiards::derive::KernelStep& step : kernel.steps)
    values[step.name] = evaluate(step.expression);
  std::vector<numeric> outputs;
  for (const ex& output : kernel.outputs) {
    const ex value = has_infinity ? GiNaC::normal(evaluate(output)).subs(t == 0) : evaluate(output);
    if (!GiNaC::is_a<numeric>(value)) {
      std::ostringstream text;
      text << value;
      throw std::logic_error("kernel " + kernel.name +
                             ": an output did not evaluate to a number: " + text.str());
    }
    outputs.push_back(GiNaC::ex_to<numeric>(value));
  }
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

template <typename Scalar>
double scaled_ulp_error(Scalar computed, const numeric& exact, const numeric& velocity) {
  numeric scale =
      exact_rational(std::numeric_limits<Scalar>::epsilon()) * (GiNaC::abs(velocity) + GiNaC::abs(exact));
  const numeric smallest = exact_rational(std::numeric_limits<Scalar>::denorm_min());
  if (scale < smallest) scale = smallest;
  const numeric ratio = GiNaC::abs(exact_rational(computed) - exact) / scale;
  return ratio > numeric(1000000) ? 1e6 : ratio.to_double();  // anything this large fails anyway
}

// Inputs in the checked API's domain, random and adversarial.
template <typename Scalar>
class InputGenerator {
 public:
  explicit InputGenerator(std::uint64_t seed) : random_(seed) {}

  Inputs<Scalar> operator()(const billiards::derive::Kernel& kernel, int sample) {
    Inputs<Scalar> in;
    const int mode = sample % 8;  // which adversarial family this sample stresses
    const Scalar limit = std::sqrt(std::numeric_limits<Scalar>::max()) / Scalar(64);
    const Scalar direction_length = log_uniform(std::sqrt(std::numeric_limits<Scalar>::min()), limit);
    for (const ex& parameter : kernel.parameters) {
      const std::string name = GiNaC::ex_to<GiNaC::symbol>(parameter).get_name();
      if (name == "m1" || name == "m2") in[name] = mass(mode);
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
  Scalar log_uniform(Scalar low, Scalar high) {
    std::uniform_real_distribution<double> exponent(std::log2(static_cast<double>(low)),
                                                    std::log2(static_cast<double>(high)));
    const Scalar x = static_cast<Scalar>(std::exp2(exponent(random_)));
    return std::min(std::max(x, low), high);
  }
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
  std::uniform_real_distribution<double> unit_{0.0, 1.0};
};

struct Row {
  std::string kernel, type;
  long samples = 0;
  double worst = 0;
  long non_finite = 0;
  std::string worst_input;  ///< the inputs of the largest error, for --verbose
};

template <typename Scalar>
Row measure(const billiards::derive::Kernel& kernel, const char* type, long samples) {
  Row row;
  row.kernel = kernel.name;
  row.type = type;
  InputGenerator<Scalar> generate(0xB111A5D5ULL + kernel.name.size());
  for (long sample = 0; sample < samples; ++sample) {
    const Inputs<Scalar> in = generate(kernel, static_cast<int>(sample));
    const std::vector<Scalar> computed = call_kernel<Scalar>(kernel.name, in);
    const std::vector<numeric> exact = exact_outputs(kernel, in);
    for (std::size_t i = 0; i < computed.size(); ++i) {
      if (!std::isfinite(computed[i])) {
        ++row.non_finite;
        continue;
      }
      const double error = scaled_ulp_error(computed[i], exact[i], changed_velocity(kernel, in, i));
      if (error > row.worst) {
        row.worst = error;
        row.worst_input.clear();
        for (const auto& [name, value] : in)
          row.worst_input += name + "=" + std::to_string(static_cast<double>(value)) + " ";
        std::ostringstream text;
        text << "output " << i << " computed " << computed[i] << " exact " << exact[i].to_double();
        row.worst_input += text.str();
      }
    }
    ++row.samples;
  }
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Measures every emitted kernel against exact rational arithmetic.", "billiards-accuracy"};
  long samples = 20000;
  double limit = 4;
  bool verbose = false;
  app.add_flag("--verbose", verbose, "Also print the inputs of each kernel's largest error");
  app.add_option("--samples", samples, "Inputs per kernel and type")->check(CLI::PositiveNumber);
  app.add_option("--limit", limit, "Largest error allowed, in scaled ULP")->check(CLI::PositiveNumber);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    std::cerr << "billiards-accuracy: " << error.what() << " (run with --help for usage)\n";
    return 2;
  }

  const billiards::derive::Derivation derivation = billiards::derive::derive_paper();
  std::vector<Row> rows;
  for (const billiards::derive::Kernel& kernel : derivation.kernels) {
    rows.push_back(measure<float>(kernel, "float", samples));
    rows.push_back(measure<double>(kernel, "double", samples));
  }
  bool ok = true;
  std::cout
      << "| kernel | type | inputs | largest error (scaled ULP) | NaN or ∞ |\n|---|---|---:|---:|---:|\n";
  for (const Row& row : rows) {
    std::cout << "| `" << row.kernel << "` | " << row.type << " | " << row.samples << " | " << row.worst
              << " | " << row.non_finite << " |\n";
    ok = ok && row.worst <= limit && row.non_finite == 0;
    if (verbose) std::cerr << row.kernel << " (" << row.type << "): " << row.worst_input << "\n";
  }
  if (!ok)
    std::cerr << "billiards-accuracy: an error exceeds " << limit << " ULP, or a valid input gave NaN or ∞\n";
  return ok ? 0 : 1;
}
