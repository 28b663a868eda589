#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

const Symbols& symbols() {
  static const Symbols instance;
  return instance;
}

// P and K applied to vectors (a scalar is a one-component vector), with the definitions' coefficients.
Vec momentum(const Definitions& d, const Vec& a, const Vec& b) {
  const Symbols& s = symbols();
  return add(scale(d.momentum_coefficient_1 * s.m1, a), scale(d.momentum_coefficient_2 * s.m2, b));
}

ex kinetic(const Definitions& d, const Vec& a, const Vec& b) {
  const Symbols& s = symbols();
  return d.kinetic_coefficient_1 * s.m1 * dot(a, a) + d.kinetic_coefficient_2 * s.m2 * dot(b, b);
}

ex scalar_momentum(const Definitions& d, const ex& a, const ex& b) { return momentum(d, {a}, {b})[0]; }
ex scalar_kinetic(const Definitions& d, const ex& a, const ex& b) { return kinetic(d, {a}, {b}); }

Space::Space(std::size_t d)
    : dimension(d),
      v1(component_symbols("v1", "v", "1", d)),
      v2(component_symbols("v2", "v", "2", d)),
      n(component_symbols("n", "n", "", d)),
      x1(component_symbols("x1", "x", "1", d)),
      x2(component_symbols("x2", "x", "2", d)),
      unit_normal{unit_normal_relation(n), "n·n = 1"},
      suffix(std::string(".").append(std::to_string(d)).append("d")) {}

ex Space::components_of(const ex& scalar) const {
  const Symbols& s = symbols();
  return scalar.subs(lst{s.v1n == dot(v1, n), s.v2n == dot(v2, n)});
}

Vec Space::after_collision(const Vec& v, const ex& normal) const {
  return add(perpendicular_part(v, n), scale(components_of(normal), n));
}

GiNaC::exmap Space::normal_components() const {
  const Symbols& s = symbols();
  return {{s.v1n, dot(v1, n)}, {s.v2n, dot(v2, n)}};
}

std::vector<GiNaC::exmap> Space::vector_components() const {
  const Symbols& s = symbols();
  std::vector<GiNaC::exmap> components;
  for (std::size_t i = 0; i < dimension; ++i) {
    components.push_back({{s.v1, v1[i]}, {s.v2, v2[i]}, {s.n, n[i]}, {s.x1, x1[i]}, {s.x2, x2[i]}});
  }
  return components;
}

GiNaC::exmap shorthand(const Definitions& d) {
  const Symbols& s = symbols();
  return {{s.Pn, scalar_momentum(d, s.v1n, s.v2n)}, {s.K_parallel, scalar_kinetic(d, s.v1n, s.v2n)}};
}

GiNaC::exmap merged(std::initializer_list<GiNaC::exmap> maps) {
  GiNaC::exmap all;
  for (const GiNaC::exmap& map : maps) {
    for (const auto& [from, to] : map) all[from] = to;
  }
  return all;
}

lst concatenate(const Vec& a, const Vec& b) {
  lst all = to_lst(a);
  for (const ex& component : b) all.append(component);
  return all;
}

}  // namespace billiards::derive::parkin2023
