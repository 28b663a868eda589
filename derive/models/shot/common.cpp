#include "models/shot/steps.hpp"

namespace billiards::derive::shot {

const Symbols& symbols() {
  static const Symbols instance;
  return instance;
}

Strike::Strike() {
  const Symbols& s = symbols();
  along = {s.cos_theta * s.cos_phi, s.cos_theta * s.sin_phi, -s.sin_theta};
  side = {s.sin_phi, -s.cos_phi, 0};
  up = {s.sin_theta * s.cos_phi, s.sin_theta * s.sin_phi, s.cos_theta};
  contact = scale(s.R, add(add(scale(s.a, side), scale(s.b, up)), scale(-s.c, along)));
  v = component_symbols("v", "v", "", 3);
  w = component_symbols("w", "\\omega", "", 3);
  unit = {{pow(s.sin_theta, 2) == 1 - pow(s.cos_theta, 2), "cos²θ + sin²θ = 1"},
          {pow(s.sin_phi, 2) == 1 - pow(s.cos_phi, 2), "cos²φ + sin²φ = 1"},
          {pow(s.c, 2) == 1 - pow(s.a, 2) - pow(s.b, 2), "a² + b² + c² = 1"}};
}

std::vector<Vec> Strike::after(const ex& impulse) const {
  const Symbols& s = symbols();
  const ex inertia = numeric(2, 5) * s.m * s.R * s.R;
  return {add(v, scale(impulse / s.m, along)), add(w, scale(impulse / inertia, cross(contact, along)))};
}

ex Strike::contact_speed(const Vec& v_, const Vec& w_) const { return dot(add(v_, cross(w_, contact)), along); }

}  // namespace billiards::derive::shot
