#include "core/algebra.hpp"

#include <map>
#include <stdexcept>

namespace billiards::derive {

using GiNaC::ex;

namespace {

const char* const component_names[] = {"x", "y", "z"};

}  // namespace

Vec component_symbols(const std::string& name, const std::string& tex_letter,
                      const std::string& tex_subscript, std::size_t dimension) {
  if (dimension < 2 || dimension > 3) {
    throw std::invalid_argument("component_symbols: dimension is " + std::to_string(dimension) +
                                ", expected 2 or 3");
  }
  // GiNaC tells symbols apart by identity, not by name: cache them so that every step that asks for
  // "v1" in 3-D gets the same three symbols.
  static std::map<std::string, GiNaC::realsymbol> cache;
  Vec components;
  for (std::size_t i = 0; i < dimension; ++i) {
    const std::string key = name + "_" + component_names[i];
    auto found = cache.find(key);
    if (found == cache.end()) {
      const std::string tex =
          tex_letter + "_{" + tex_subscript + (tex_subscript.empty() ? "" : ",") + component_names[i] + "}";
      found = cache.emplace(key, GiNaC::realsymbol(key, tex)).first;
    }
    components.push_back(found->second);
  }
  return components;
}

namespace {

void require_same_dimension(const Vec& a, const Vec& b, const char* operation) {
  if (a.size() != b.size()) {
    throw std::invalid_argument(std::string(operation) + ": dimensions " + std::to_string(a.size()) +
                                " and " + std::to_string(b.size()) + " differ");
  }
}

}  // namespace

Vec add(const Vec& a, const Vec& b) {
  require_same_dimension(a, b, "add");
  Vec sum;
  for (std::size_t i = 0; i < a.size(); ++i) sum.push_back(a[i] + b[i]);
  return sum;
}

Vec cross(const Vec& a, const Vec& b) {
  require_same_dimension(a, b, "cross");
  if (a.size() != 3)
    throw std::invalid_argument("cross: dimension is " + std::to_string(a.size()) + ", expected 3");
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Vec subtract(const Vec& a, const Vec& b) { return add(a, scale(-1, b)); }

Vec scale(const ex& factor, const Vec& a) {
  Vec scaled;
  for (const ex& component : a) scaled.push_back(factor * component);
  return scaled;
}

ex dot(const Vec& a, const Vec& b) {
  require_same_dimension(a, b, "dot");
  ex sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

GiNaC::lst to_lst(const Vec& a) {
  GiNaC::lst components;
  for (const ex& component : a) components.append(component);
  return components;
}

GiNaC::lst concatenate(const std::vector<Vec>& vectors) {
  GiNaC::lst all;
  for (const Vec& v : vectors) {
    for (const GiNaC::ex& component : v) all.append(component);
  }
  return all;
}

Vec parallel_part(const Vec& a, const Vec& n) { return scale(dot(a, n), n); }

Vec perpendicular_part(const Vec& a, const Vec& n) { return subtract(a, parallel_part(a, n)); }

ex unit_normal_relation(const Vec& n) {
  ex rest = 1;
  for (std::size_t i = 0; i + 1 < n.size(); ++i) rest -= GiNaC::pow(n[i], 2);
  return GiNaC::pow(n.back(), 2) == rest;
}

ex reduce_modulo(const ex& e, const ex& relation) {
  const ex variable = relation.lhs().op(0);
  ex current = e.expand();
  // Each pass lowers the degree in `variable` by at least one; a polynomial has finite degree.
  while (current.degree(variable) > 1) {
    current = current.subs(relation, GiNaC::subs_options::algebraic).expand();
  }
  return current;
}

namespace {

// Calls `visit(base, exponent)` for each factor of a factored expression.
template <typename Visit>
void for_each_factor(const ex& factored, Visit visit) {
  if (GiNaC::is_a<GiNaC::mul>(factored)) {
    for (const ex& factor : factored) visit(factor);
  } else {
    visit(factored);
  }
}

bool is_positive_constant_or_symbol(const ex& e) { return e.info(GiNaC::info_flags::positive); }

}  // namespace

ex square_root_of_perfect_square(const ex& e) {
  const ex factored = GiNaC::factor(GiNaC::normal(e));
  ex root = 1;
  bool perfect = true;
  for_each_factor(factored, [&](const ex& factor) {
    if (GiNaC::is_a<GiNaC::power>(factor) && GiNaC::is_a<GiNaC::numeric>(factor.op(1)) &&
        GiNaC::ex_to<GiNaC::numeric>(factor.op(1)).is_even()) {
      root *= GiNaC::pow(GiNaC::abs(factor.op(0)), factor.op(1) / 2);
    } else if (GiNaC::is_a<GiNaC::numeric>(factor) && is_positive_constant_or_symbol(factor)) {
      root *= GiNaC::sqrt(factor);
    } else {
      perfect = false;
    }
  });
  return perfect ? root : GiNaC::sqrt(e);
}

bool is_manifestly_nonnegative(const ex& e) {
  const ex factored = GiNaC::factor(GiNaC::normal(e));
  bool nonnegative = true;
  for_each_factor(factored, [&](const ex& factor) {
    const bool even_power = GiNaC::is_a<GiNaC::power>(factor) && GiNaC::is_a<GiNaC::numeric>(factor.op(1)) &&
                            GiNaC::ex_to<GiNaC::numeric>(factor.op(1)).is_even();
    if (!even_power && !is_positive_constant_or_symbol(factor)) nonnegative = false;
  });
  return nonnegative;
}

ex resolve_absolute_values(const ex& e, const ex& s, int sign) {
  if (GiNaC::is_a<GiNaC::function>(e) && GiNaC::ex_to<GiNaC::function>(e).get_name() == "abs") {
    const ex argument = resolve_absolute_values(e.op(0), s, sign);
    const ex ratio = GiNaC::normal(argument / s);
    if (!ratio.has(s) && ratio.info(GiNaC::info_flags::positive)) return sign * argument;
    if (!ratio.has(s) && (-ratio).info(GiNaC::info_flags::positive)) return -sign * argument;
    return GiNaC::abs(argument);
  }
  struct resolve_operands : GiNaC::map_function {
    const ex& s;
    int sign;
    resolve_operands(const ex& s_, int sign_) : s(s_), sign(sign_) {}
    ex operator()(const ex& operand) override { return resolve_absolute_values(operand, s, sign); }
  } resolve{s, sign};
  return e.map(resolve);
}

#if !defined(__clang__)
GiNaC::lst clifford_components(const ex& e, const ex& c, bool algebraic) {
  return GiNaC::clifford_to_lst(e, c, algebraic);
}
#endif

}  // namespace billiards::derive
