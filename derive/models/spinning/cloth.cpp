#include "models/spinning/steps.hpp"

#include "core/named_constants.hpp"

namespace billiards::derive::spinning {

Vec integrate(const Vec& f, const GiNaC::symbol& tau, const ex& t) {
  Vec out;
  for (const ex& component : f) out.push_back(GiNaC::integral(tau, 0, t, component).eval_integ().expand());
  return out;
}

Vec at_time(const Vec& f, const GiNaC::symbol& tau, const ex& t) {
  Vec out;
  for (const ex& component : f) out.push_back(component.subs(tau == t));
  return out;
}

ex ClothStart::kinetic_energy(const Vec& v, const Vec& w) const {
  const ex m = symbols().m;
  return numeric(1, 2) * m * dot(v, v) + numeric(1, 2) * inertia * dot(w, w);
}

ClothStart cloth_start() {
  const Symbols& s = symbols();
  return {
      .v0 = {GiNaC::realsymbol("v0_x", "v_{0,x}"), GiNaC::realsymbol("v0_y", "v_{0,y}"), 0},
      .w0 = {GiNaC::realsymbol("w0_x", "\\omega_{0,x}"), GiNaC::realsymbol("w0_y", "\\omega_{0,y}"), 0},
      .r0 = {GiNaC::realsymbol("r0_x", "r_{0,x}"), GiNaC::realsymbol("r0_y", "r_{0,y}"), s.R},
      .tau = GiNaC::symbol("tau", "\\tau"),
      .inertia = numeric(2, 5) * s.m * s.R * s.R,
  };
}

Cloth the_cloth(Recorder& record) {
  const ClothStart start = cloth_start();
  const ex slide_time = sliding_on_the_cloth(record, start);
  const ex roll_time = rolling_on_the_cloth(record, start);
  const ex spin_time = spinning_on_the_cloth(record, start);
  return {slide_time, roll_time, spin_time};
}

}  // namespace billiards::derive::spinning
