// The cue strike's spin: its change in the table's and the cue's frame, none from a centre hit, and natural
// roll at b = 2/5.
#include "models/shot/steps.hpp"

namespace billiards::derive::shot {

namespace {

Vec expanded_vector(Vec a) {
  for (ex& component : a) component = component.expand();
  return a;
}

}  // namespace

void the_strike_spin(Recorder& record, const Strike& k, const CueStrike& strike) {
  const Symbols& s = symbols();
  const Vec spin_change = expanded_vector(subtract(k.after(s.impulse)[1], k.w));
  record.add({
      .id = "strike.spin",
      .paper = "TP A-30, the ball's spin",
      .statement = "The spin changes by Δω = I⁻¹ (r × J d) = (5 J/(2 m R)) (a u − b s): side offset turns it "
                   "about u, up offset about −s, and the depth c along the cue not at all.",
      .method = "r × d in components; identity, the unit relations imposed",
      .comparison = Comparison::identity,
      .paper_expression =
          to_lst(scale(5 * s.impulse / (2 * s.m * s.R), subtract(scale(s.a, k.up), scale(s.b, k.side)))),
      .derived_expression = to_lst(spin_change),
      .constraints = k.unit,
      .depends_on = {"definition.cue_impulse", "strike.frame"},
  });
  record.add({
      .id = "strike.spin_in_cue_frame",
      .statement =
          "In the cue's frame the spin changes by (5 a/(2R)) (J/m) about u and −(5 b/(2R)) (J/m) about s "
          "(and, by strike.spin, not at all about d).",
      .method = "Δω dotted with u and s; identity, the unit relations imposed",
      .comparison = Comparison::identity,
      .paper_expression = lst{5 * s.a * s.impulse / (2 * s.m * s.R), -5 * s.b * s.impulse / (2 * s.m * s.R)},
      .derived_expression = lst{dot(spin_change, k.up), dot(spin_change, k.side)},
      .constraints = k.unit,
      .depends_on = {"strike.spin"},
  });
  const GiNaC::exmap centre{{s.a, 0}, {s.b, 0}, {s.c, 1}};
  record.add({
      .id = "strike.centre_no_spin",
      .statement = "A hit at the centre (a = b = 0) gives no spin, whatever the elevation.",
      .method = "Δω with a = b = 0, c = 1; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{0, 0, 0},
      .derived_expression = to_lst(expanded_vector(subtract(k.after(s.impulse)[1], k.w))).subs(centre),
      .depends_on = {"strike.spin"},
  });
  // Natural roll: a level cue (θ = 0) at b = 2/5 on a ball at rest; the slip at the cloth, v + ω × (−R ẑ).
  const GiNaC::exmap level{{s.cos_theta, 1}, {s.sin_theta, 0}, {s.a, 0}, {s.b, numeric(2, 5)}};
  const std::vector<Vec> struck = k.after(strike.impulse_at_rest);
  const Vec cloth_slip = add(struck[0], cross(struck[1], Vec{0, 0, -s.R}));
  Vec rolling_slip;
  for (const ex& component : cloth_slip) rolling_slip.push_back(component.subs(strike.at_rest).subs(level));
  record.add({
      .id = "strike.natural_roll",
      .paper = "TP A-30: b = 2R/5 gives natural roll",
      .statement = "A level cue (θ = 0) striking a ball at rest at b = 2/5 (2R/5 above the centre) and a = 0 "
                   "gives natural roll at once: the slip at the cloth, v' + ω' × (−R ẑ), is zero.",
      .method = "the ball's velocity and spin after the strike, θ = 0, a = 0, b = 2/5; identity, the unit "
                "relations imposed",
      .comparison = Comparison::identity,
      .paper_expression = lst{0, 0, 0},
      .derived_expression = to_lst(rolling_slip),
      .constraints = k.unit,
      .depends_on = {"strike.speed", "strike.spin"},
  });
}

}  // namespace billiards::derive::shot
