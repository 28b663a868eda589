// The shot model as a pipeline: the cue strike, squirt and the cushion, one step a file.
#include "models/shot/shot.hpp"

#include "models/shot/steps.hpp"

namespace billiards::derive::shot {

ModelInfo info() {
  ModelInfo model;
  model.name = "shot";
  model.title = "The shot: the cue strike, squirt and the cushion";
  model.citation =
      "the cue strike, squirt and the cushion with spin, from the impulse equations (after Alciatore, TP A-30 "
      "and A-31, and Han 2005)";
  model.scope =
      "a rigid cue tip striking a rigid solid sphere, and the sphere meeting a rigid cushion: each one "
      "instantaneous impulse";
  model.notation =
      "Vectors are 3-D, in symbolic components: $v_x$ is `v_x`, $\\omega_x$ is `w_x`. The cue's direction "
      "is written with $\\cos\\theta$, $\\sin\\theta$, $\\cos\\varphi$, $\\sin\\varphi$ as symbols, and "
      "$\\cos^2 + \\sin^2 = 1$ and $a^2 + b^2 + c^2 = 1$ are imposed by substitution where a claim says so.";
  model.remarks = {
      "For the strike the tip is frictionless on the ball and the impulse acts along the cue (the "
      "instantaneous point model of TP A-30, as common simulators use it); squirt is derived apart, from a "
      "tip that grips the ball across the cue (TP A-31).",
      "At the cushion the ball's own impulse equations hold with the cushion immovable, and the table keeps "
      "the ball on the cloth by a vertical impulse through its centre that takes no part in the contact at "
      "the nose (Han 2005's convention): no hop, no friction with the cloth during the impact.",
      "TP A-30 is the case e_tip = 1 with the ball at rest; the derivation keeps e_tip and the ball's state "
      "before the strike.",
  };
  model.markdown_path = "shot/AUDIT.md";
  model.json_path = "shot/audit.json";
  model.pair_result = {"StrikeSpin", "The change of a struck ball's spin in the cue's frame.",
                       "ω·u, about u: up, perpendicular to the cue", "ω·s, about s: to the cue's right"};
  model.kernels_namespace = "billiards::kernels::shot";
  model.kernels_path = "billiards/shot_kernels.hpp";
  model.kernel_list_path = "billiards/shot_kernel_list.hpp";
  return model;
}

Derivation derive() {
  Derivation derivation;
  derivation.model = info();
  record_steps(derivation, [&](Recorder& record) {
    const Strike strike;
    record_premises(record);
    const CueStrike impulse = the_cue_strike(record, strike);
    the_strike_spin(record, strike, impulse);
    the_strike_energy(record, strike, impulse);
    the_strike_in_tp_a30_frame(record, strike);
    the_squirt(record, strike);
    const CushionContact cushion = the_cushion_contact(record, strike);
    const CushionRegimes regimes = the_cushion_regimes(record, strike, cushion);
    the_cushion_energy(record, strike, cushion, regimes);
    the_cushion_limits(record, strike, cushion, regimes);
    the_cushion_in_its_frame(record, strike, cushion);
    derivation.kernels = shot_kernels(strike);
  });
  return derivation;
}

}  // namespace billiards::derive::shot
