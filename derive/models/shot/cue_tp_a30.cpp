// The cue strike in TP A-30's frame: its offset terms, with b measured vertically and c horizontally.
#include "models/shot/steps.hpp"

namespace billiards::derive::shot {

void the_strike_in_tp_a30_frame(Recorder& record, const Strike& k) {
  const Symbols& s = symbols();
  // TP A-30 writes the tip's contact point with b measured vertically and c horizontally, along the aim:
  // r = R (a s + b_v ẑ − c_h h), h = (cos φ, sin φ, 0); its offset terms are |r × d|²/R² in that frame.
  const Vec aim{s.cos_phi, s.sin_phi, 0};
  const Vec tp_contact =
      add(add(scale(s.a, k.side), scale(s.b_vertical, Vec{0, 0, 1})), scale(-s.c_horizontal, aim));
  const Vec tp_lever = cross(tp_contact, k.along);
  record.add({
      .id = "strike.tp_a30_offset_terms",
      .paper = "TP A-30, the denominator's offset terms",
      .paper_tex = "a^2 + b^2\\cos^2\\theta + c^2\\sin^2\\theta - 2bc\\cos\\theta\\sin\\theta",
      .statement =
          "With b and c measured vertically and horizontally (TP A-30's frame) the offset terms are "
          "a² + b² cos²θ + c² sin²θ − 2 b c cos θ sin θ = |r × d|²/R², which is a² + b² in the cue's "
          "frame: the same strike.",
      .method =
          "|r × d|²/R² for r = R (a s + b_v ẑ − c_h h) in components; identity, cos² + sin² = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = s.a * s.a + pow(s.b_vertical * s.cos_theta, 2) +
                          pow(s.c_horizontal * s.sin_theta, 2) -
                          2 * s.b_vertical * s.c_horizontal * s.cos_theta * s.sin_theta,
      .derived_expression = dot(tp_lever, tp_lever),
      .constraints = {k.unit[0], k.unit[1]},
      .note = "pooltool's cue_strike once typed (c cos θ)² for (c sin θ)² here, and 2 M V for 2 m V in the "
              "impulse: both are where a typed formula goes wrong and a derived one cannot.",
      .depends_on = {"strike.speed"},
  });
}

}  // namespace billiards::derive::shot
