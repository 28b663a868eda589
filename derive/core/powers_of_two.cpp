#include "core/powers_of_two.hpp"

#include <map>
#include <string>

namespace billiards::derive {

using GiNaC::ex;
using GiNaC::numeric;

namespace {

ex binary_exponent_eval(const ex& x) {
  if (GiNaC::is_a<numeric>(x) && GiNaC::ex_to<numeric>(x).is_rational()) {
    numeric magnitude = GiNaC::abs(GiNaC::ex_to<numeric>(x));
    if (magnitude.is_zero()) return 0;
    int exponent = 0;
    while (magnitude >= 2) {
      magnitude /= 2;
      ++exponent;
    }
    while (magnitude < 1) {
      magnitude *= 2;
      --exponent;
    }
    return exponent;
  }
  return binary_exponent(x).hold();
}

// The symbol standing for 2^a, the same for equal a on every call.
const GiNaC::possymbol& power_symbol(const ex& a) {
  static std::map<ex, GiNaC::possymbol, GiNaC::ex_is_less> symbols;
  const auto found = symbols.find(a);
  if (found != symbols.end()) return found->second;
  return symbols.emplace(a, GiNaC::possymbol("two_to_" + std::to_string(symbols.size()))).first->second;
}

}  // namespace

REGISTER_FUNCTION(binary_exponent, eval_func(binary_exponent_eval))

namespace {
ex fused_multiply_add_eval(const ex& a, const ex& b, const ex& c) { return a * b + c; }
}  // namespace

REGISTER_FUNCTION(fused_multiply_add, eval_func(fused_multiply_add_eval))

ex fused_multiply_add_held(const ex& a, const ex& b, const ex& c) { return fused_multiply_add(a, b, c).hold(); }

std::optional<int> exact_binary_logarithm(const numeric& n) {
  if (!n.is_rational() || !n.is_positive()) return std::nullopt;
  // 2^|k| is an integer: as many halvings of it as bring it to 1.
  numeric power = n >= 1 ? n : numeric(1) / n;
  int k = 0;
  while (power.is_integer() && power > 1 && (power / 2).is_integer()) {
    power /= 2;
    ++k;
  }
  if (power != 1) return std::nullopt;
  return n >= 1 ? k : -k;
}

bool is_power_of_two_with_symbolic_exponent(const ex& e) {
  return GiNaC::is_a<GiNaC::power>(e) && e.op(0).is_equal(2) && !GiNaC::is_a<numeric>(e.op(1));
}

ex times_power_of_two(const ex& x, const ex& k) { return x * GiNaC::pow(2, k); }

bool uses_power_of_two_scaling(const ex& e) {
  for (GiNaC::const_preorder_iterator it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (is_power_of_two_with_symbolic_exponent(*it)) return true;
    if (GiNaC::is_a<GiNaC::function>(*it) &&
        GiNaC::ex_to<GiNaC::function>(*it).get_name() == "binary_exponent")
      return true;
  }
  return false;
}

ex resolve_powers_of_two(const ex& e) {
  struct resolve : GiNaC::map_function {
    ex operator()(const ex& operand) override {
      if (!is_power_of_two_with_symbolic_exponent(operand)) return operand.map(*this);
      const ex exponent = operand.op(1).map(*this).expand();
      ex product = 1;
      for (const ex& term : GiNaC::is_a<GiNaC::add>(exponent) ? exponent : ex(GiNaC::lst{exponent})) {
        if (GiNaC::is_a<numeric>(term)) {
          product *= GiNaC::pow(2, term);
          continue;
        }
        // term = c · a, c the numeric coefficient of a product (1 otherwise)
        numeric c = 1;
        ex a = term;
        if (GiNaC::is_a<GiNaC::mul>(term)) {
          a = 1;
          for (const ex& factor : term) {
            if (GiNaC::is_a<numeric>(factor)) {
              c *= GiNaC::ex_to<numeric>(factor);
            } else {
              a *= factor;
            }
          }
        }
        product *= GiNaC::pow(power_symbol(a), c);
      }
      return product;
    }
  } rewrite;
  return rewrite(e);
}

}  // namespace billiards::derive
