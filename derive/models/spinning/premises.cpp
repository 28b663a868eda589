#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

void record_premises(Recorder& record) {
  const std::vector<Premise> premises = {
      {"definition.solid_sphere",
       "Each ball is a rigid, uniform solid sphere of mass m > 0 and radius R > 0: its moment of inertia "
       "about any axis through its centre is I = (2/5) m R².",
       ex(0)},
      {"definition.contact",
       "n is the unit normal (n·n = 1) from ball 1's centre to ball 2's; the contact point is R1 n from "
       "ball 1's centre and −R2 n from ball 2's. Vectors are 3-D, in symbolic components.",
       ex(0)},
      {"definition.slip",
       "The slip is the velocity of ball 2's contact point relative to ball 1's: u = (v2 + ω2 × (−R2 n)) − "
       "(v1 + ω1 × (R1 n)); u_t = u − (u·n) n is its tangential part.",
       ex(0)},
      {"definition.impulse",
       "An impulse J acts on ball 2 at its contact point and −J on ball 1 at its own, instantaneously: "
       "Δv1 = −J/m1, Δv2 = J/m2, Δω1 = I1⁻¹ (R1 n × (−J)), Δω2 = I2⁻¹ (−R2 n × J) (Newton's and Euler's "
       "laws integrated over the contact).",
       ex(0)},
      {"definition.restitution",
       "Newton's law of restitution for the normal slip: u'·n = −e u·n with 0 ≤ e ≤ 1; the balls approach "
       "iff (v2 − v1)·n < 0.",
       ex(0)},
      {"definition.coulomb_friction",
       "Coulomb friction with coefficient μ ≥ 0: the tangential impulse opposes the slip, J_t = −j û_t, "
       "û_t = u_t/|u_t|, with j the least of μ J_n (sliding throughout) and the j that stops the slip "
       "(sticking); the slip direction is held during the contact.",
       ex(0)},
      {"definition.cloth",
       "The table is the plane z = 0, ẑ up, gravity −g ẑ; a ball on it has its centre at height R and "
       "touches it at −R ẑ from the centre, where its slip is u = v + ω × (−R ẑ). While u ≠ 0 the cloth "
       "pushes −μ_s m g û at the contact (sliding friction); the spin about ẑ meets the torque "
       "−μ_sp m g R ẑ sgn(ω_z) (spinning friction).",
       ex(0)},
  };
  for (const Premise& premise : premises) record.premise(premise);
}

}  // namespace billiards::derive::spinning
