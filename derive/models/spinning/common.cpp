#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

const Symbols& symbols() {
  static const Symbols instance;
  return instance;
}

Contact::Contact()
    : v1(component_symbols("v1", "v", "1", 3)),
      w1(component_symbols("w1", "\\omega", "1", 3)),
      v2(component_symbols("v2", "v", "2", 3)),
      w2(component_symbols("w2", "\\omega", "2", 3)),
      n(component_symbols("n", "n", "", 3)),
      a(component_symbols("a", "a", "", 3)),
      J(component_symbols("J", "J", "", 3)),
      unit_normal{unit_normal_relation(n), "n·n = 1"} {}

Vec Contact::r1() const { return scale(symbols().R1, n); }
Vec Contact::r2() const { return scale(-symbols().R2, n); }

Vec Contact::slip(const Vec& v1_, const Vec& w1_, const Vec& v2_, const Vec& w2_) const {
  return subtract(add(v2_, cross(w2_, r2())), add(v1_, cross(w1_, r1())));
}

std::vector<Vec> Contact::after(const Vec& impulse) const {
  const Symbols& s = symbols();
  const Vec on_first = scale(-1, impulse);
  return {add(v1, scale(1 / s.m1, on_first)), add(w1, scale(1 / s.I1, cross(r1(), on_first))),
          add(v2, scale(1 / s.m2, impulse)), add(w2, scale(1 / s.I2, cross(r2(), impulse)))};
}

ex Contact::kinetic_energy(const std::vector<Vec>& state) const {
  const Symbols& s = symbols();
  return numeric(1, 2) * (s.m1 * dot(state[0], state[0]) + s.I1 * dot(state[1], state[1]) +
                          s.m2 * dot(state[2], state[2]) + s.I2 * dot(state[3], state[3]));
}

Vec Contact::tangent() const { return cross(n, a); }

}  // namespace billiards::derive::spinning
