// The spinning-ball model as a pipeline: the contact impulse, what it conserves, friction, the throw,
// the cloth, then the kernels built from what the steps returned.
#include "models/spinning/spinning.hpp"

#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

ModelInfo info() {
  ModelInfo model;
  model.name = "spinning";
  model.title = "Spinning balls: ball–ball friction and the cloth";
  model.citation =
      "spinning balls with friction, from Newton's and Euler's laws (throw after Alciatore, TP A-14)";
  model.scope =
      "rigid solid spheres: instantaneous contacts with Coulomb friction, and a ball sliding, "
      "rolling and spinning on the cloth";
  model.notation =
      "Vectors are 3-D, in symbolic components: $v_{1,x}$ is `v1_x`, $\\omega_{1,x}$ is `w1_x`. Where "
      "$n \\cdot n = 1$ is needed it is imposed by substituting $n_z^2 \\to 1 - n_x^2 - n_y^2$, and the "
      "claim "
      "says so (\"Under: n·n = 1\"); lengths such as $|u_t|$ are positive symbols tied to their vectors the "
      "same way. A tangent vector is written $n \\times a$ for an arbitrary $a$.";
  model.remarks = {
      "The balls are rigid and the impulses instantaneous; the slip direction is held during the contact "
      "(Alciatore's TP A-14 and common simulators), so the tangential impulse is one vector against the "
      "initial slip.",
      "The table's own friction during a ball–ball impact is neglected: the contact with the cloth acts only "
      "between impacts (\"Sliding on the cloth\" and after).",
      "Rolling resistance is a modelling assumption (`assumption.rolling_resistance`), the only unchecked "
      "claim.",
  };
  model.pair_result = {"TangentialVelocityChange",
                       "The changes of the two balls' velocities along the slip direction û_t that a "
                       "tangential impulse j against the slip makes: ball 1's by +j/m1, ball 2's by −j/m2.",
                       "j/m1, ball 1's change along û_t", "j/m2, ball 2's change against û_t"};
  model.kernels_namespace = "billiards::kernels::spin";
  model.markdown_path = "spinning/AUDIT.md";
  model.json_path = "spinning/audit.json";
  model.kernels_path = "billiards/spin_kernels.hpp";
  model.kernel_list_path = "billiards/spin_kernel_list.hpp";
  return model;
}

Derivation derive() {
  Derivation derivation;
  derivation.model = info();
  record_steps(derivation, [&](Recorder& record) {
    const Contact contact;
    record_premises(record);
    const Impulse impulse = the_impulse(record, contact);
    conservation(record, contact, impulse);
    const Friction friction = the_friction(record, contact, impulse);
    the_throw(record, contact, friction);
    const Cloth cloth = the_cloth(record);
    event_times(record);
    pressed_contacts(record);
    kernel_claims(record, contact, impulse, friction);
    derivation.kernels = spin_kernels(cloth);
  });
  return derivation;
}

}  // namespace billiards::derive::spinning
