// The cue strike: the impulse solved from the tip's restitution, and the ball's velocity and speed.
#include "models/shot/steps.hpp"

namespace billiards::derive::shot {

CueStrike the_cue_strike(Recorder& record, const Strike& k) {
  const Symbols& s = symbols();
  const ex e = s.restitution;
  record.section(
      "strike", "The cue strike",
      "The impulse equations of the cue and the ball (definition.cue_impulse) and the tip's "
      "restitution (definition.tip_restitution), in 3-D components: the impulse is solved, not "
      "typed, and the ball's speed and spin read off it (Alciatore, TP A-30, with e_tip).");
  record.add({
      .id = "strike.frame",
      .statement =
          "d, s and u are unit vectors, each perpendicular to the others, u = s × d, and the contact "
          "point lies on the ball: |r| = R.",
      .method = "dot products of the components; identity, cos² + sin² = 1 and a² + b² + c² = 1 imposed by "
                "substitution",
      .comparison = Comparison::identity,
      .paper_expression = lst{1, 1, 1, 0, 0, 0, 0, 0, 0, s.R * s.R},
      .derived_expression = concatenate({{dot(k.along, k.along), dot(k.side, k.side), dot(k.up, k.up),
                                          dot(k.side, k.along), dot(k.up, k.along), dot(k.side, k.up)},
                                         subtract(cross(k.side, k.along), k.up),
                                         {dot(k.contact, k.contact)}}),
      .constraints = k.unit,
      .depends_on = {"definition.cue", "definition.tip_offset"},
  });
  // The restitution equation, linear in J: solved for J.
  const std::vector<Vec> after = k.after(s.impulse);
  const ex before_speed = k.contact_speed(k.v, k.w);
  const ex cue_after = s.V - s.impulse / s.M;
  const ex restitution_law = k.contact_speed(after[0], after[1]) - cue_after - e * (s.V - before_speed);
  CueStrike out;
  out.impulse = GiNaC::lsolve(restitution_law.expand() == 0, s.impulse);
  out.inverse_mass = 1 / s.M + 1 / s.m + numeric(5, 2) * (s.a * s.a + s.b * s.b) / s.m;
  record.add({
      .id = "strike.impulse",
      .paper = "TP A-30 (for e_tip = 1 and a ball at rest)",
      .statement = "J = (1 + e_tip)(V − (v + ω × r)·d)/(1/M + 1/m + (5/2)(a² + b²)/m): the tip's approach "
                   "speed over the inverse effective mass of cue and ball at the tip, along d.",
      .method = "the restitution law with the impulse equations substituted, solved for J (lsolve: it is "
                "linear in J); identity, the unit relations imposed",
      .comparison = Comparison::identity,
      .paper_expression = (1 + e) * (s.V - before_speed) / out.inverse_mass,
      .derived_expression = out.impulse,
      .constraints = k.unit,
      .depends_on = {"definition.cue_impulse", "definition.tip_restitution", "definition.solid_sphere",
                     "strike.frame"},
  });
  record.add({
      .id = "strike.velocity_change",
      .statement = "The ball's velocity changes by (J/m) d, J/m = (1 + e_tip)(V − (v + ω × r)·d)/(1 + m/M + "
                   "(5/2)(a² + b²)): for a ball at rest, its speed.",
      .method = "J of strike.impulse over m; identity, the unit relations imposed",
      .comparison = Comparison::identity,
      .paper_expression =
          (1 + e) * (s.V - before_speed) / (1 + s.m / s.M + numeric(5, 2) * (s.a * s.a + s.b * s.b)),
      .derived_expression = out.impulse / s.m,
      .constraints = k.unit,
      .depends_on = {"strike.impulse"},
  });
  out.at_rest = [&] {
    GiNaC::exmap rest;
    for (std::size_t i = 0; i < 3; ++i) {
      rest[k.v[i]] = 0;
      rest[k.w[i]] = 0;
    }
    return rest;
  }();
  out.impulse_at_rest = out.impulse.subs(out.at_rest);
  record.add({
      .id = "strike.speed",
      .paper = "TP A-30, the ball's speed",
      .statement =
          "A ball at rest leaves along the cue at V_ball = (1 + e_tip) V/(1 + m/M + (5/2)(a² + b²)).",
      .method = "|v'| = J/m (|d| = 1) with v = ω = 0; identity, the unit relations imposed",
      .comparison = Comparison::identity,
      .paper_expression = (1 + e) * s.V / (1 + s.m / s.M + numeric(5, 2) * (s.a * s.a + s.b * s.b)),
      .derived_expression = out.impulse_at_rest / s.m,
      .constraints = k.unit,
      .depends_on = {"strike.impulse"},
  });
  out.approach = s.V - before_speed;
  return out;
}

}  // namespace billiards::derive::shot
