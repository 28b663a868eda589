#include "models/parkin2023/steps.hpp"

namespace billiards::derive::parkin2023 {

void record_premises(Recorder& record, const Definitions& d) {
  {
    const ex a = GiNaC::symbol("a"), b = GiNaC::symbol("b");
    const std::vector<Premise> premises = {
        {"definition.momentum", "P(a, b) = m1 a + m2 b: the total momentum of the two balls.",
         scalar_momentum(d, a, b)},
        {"definition.kinetic_energy", "K(a, b) = ½ m1 a² + ½ m2 b²: their total kinetic energy (a² = a·a).",
         scalar_kinetic(d, a, b)},
        {"definition.masses",
         "m1 > 0 and m2 > 0 (the paper takes m1, m2 ∈ ℝ; a mass is positive): GiNaC's positive symbols "
         "carry it, so √(m1²) = m1 and the sign claims rest on it.",
         ex(0)},
        {"definition.split",
         "a∥ = (a·n) n and a⊥ = a − a∥ for a unit contact normal n (n·n = 1); vectors are kept in "
         "symbolic components in 2-D and 3-D, never a chosen numeric n.",
         ex(0)},
        {"definition.restitution",
         "Newton's law of restitution (beyond the paper): (x2 − x1)·n = −e (v2 − v1)·n with 0 ≤ e ≤ 1; "
         "e = 1 is the paper's perfectly elastic collision.",
         ex(0)},
        {"definition.time_of_impact",
         "Balls move in straight lines between collisions (beyond the paper): centres p1 + t v1 and "
         "p2 + t v2; spheres of radii r1, r2 touch when |(p2 − p1) + t (v2 − v1)| = r1 + r2.",
         ex(0)},
        {"definition.conservation",
         "Momentum is conserved, P(v1, v2) = P(x1, x2); for a perfectly elastic collision so is the "
         "kinetic energy, K(v1, v2) = K(x1, x2).",
         ex(0)},
    };
    for (const Premise& premise : premises) record.premise(premise);
  }
}

}  // namespace billiards::derive::parkin2023
