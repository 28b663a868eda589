// The cue strike: the impulse solved from the tip's restitution, the ball's speed and spin, and what
// the strike conserves.
#include "models/shot/steps.hpp"

namespace billiards::derive::shot {

namespace {

Vec expanded(Vec a) {
  for (ex& component : a) component = component.expand();
  return a;
}

// The kinetic energy of the cue and the ball.
ex kinetic_energy(const ex& cue_speed, const Vec& v, const Vec& w) {
  const Symbols& s = symbols();
  return s.M * cue_speed * cue_speed / 2 + s.m * dot(v, v) / 2 +
         numeric(2, 5) * s.m * s.R * s.R * dot(w, w) / 2;
}

}  // namespace

CueStrike the_cue_strike(Recorder& record, const Strike& k) {
  const Symbols& s = symbols();
  const ex e = s.restitution;
  record.section("strike", "The cue strike",
                 "The impulse equations of the cue and the ball (definition.cue_impulse) and the tip's "
                 "restitution (definition.tip_restitution), in 3-D components: the impulse is solved, not "
                 "typed, and the ball's speed and spin read off it (Alciatore, TP A-30, with e_tip).");
  record.add({
      .id = "strike.frame",
      .statement = "d, s and u are unit vectors, each perpendicular to the others, u = s × d, and the contact "
                   "point lies on the ball: |r| = R.",
      .method = "dot products of the components; identity, cos² + sin² = 1 and a² + b² + c² = 1 imposed by "
                "substitution",
      .comparison = Comparison::identity,
      .paper_expression = lst{1, 1, 1, 0, 0, 0, 0, 0, 0, s.R * s.R},
      .derived_expression =
          concatenate({{dot(k.along, k.along), dot(k.side, k.side), dot(k.up, k.up), dot(k.side, k.along),
                        dot(k.up, k.along), dot(k.side, k.up)},
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
  const ex impulse = GiNaC::lsolve(restitution_law.expand() == 0, s.impulse);
  const ex inverse_mass = 1 / s.M + 1 / s.m + numeric(5, 2) * (s.a * s.a + s.b * s.b) / s.m;
  record.add({
      .id = "strike.impulse",
      .paper = "TP A-30 (for e_tip = 1 and a ball at rest)",
      .statement = "J = (1 + e_tip)(V − (v + ω × r)·d)/(1/M + 1/m + (5/2)(a² + b²)/m): the tip's approach "
                   "speed over the inverse effective mass of cue and ball at the tip, along d.",
      .method = "the restitution law with the impulse equations substituted, solved for J (lsolve: it is "
                "linear in J); identity, the unit relations imposed",
      .comparison = Comparison::identity,
      .paper_expression = (1 + e) * (s.V - before_speed) / inverse_mass,
      .derived_expression = impulse,
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
      .paper_expression = (1 + e) * (s.V - before_speed) / (1 + s.m / s.M + numeric(5, 2) * (s.a * s.a + s.b * s.b)),
      .derived_expression = impulse / s.m,
      .constraints = k.unit,
      .depends_on = {"strike.impulse"},
  });
  const GiNaC::exmap at_rest = [&] {
    GiNaC::exmap rest;
    for (std::size_t i = 0; i < 3; ++i) {
      rest[k.v[i]] = 0;
      rest[k.w[i]] = 0;
    }
    return rest;
  }();
  const ex impulse_at_rest = impulse.subs(at_rest);
  record.add({
      .id = "strike.speed",
      .paper = "TP A-30, the ball's speed",
      .statement = "A ball at rest leaves along the cue at V_ball = (1 + e_tip) V/(1 + m/M + (5/2)(a² + b²)).",
      .method = "|v'| = J/m (|d| = 1) with v = ω = 0; identity, the unit relations imposed",
      .comparison = Comparison::identity,
      .paper_expression = (1 + e) * s.V / (1 + s.m / s.M + numeric(5, 2) * (s.a * s.a + s.b * s.b)),
      .derived_expression = impulse_at_rest / s.m,
      .constraints = k.unit,
      .depends_on = {"strike.impulse"},
  });
  const Vec spin_change = expanded(subtract(k.after(s.impulse)[1], k.w));
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
      .statement = "In the cue's frame the spin changes by (5 a/(2R)) (J/m) about u and −(5 b/(2R)) (J/m) about s "
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
      .derived_expression = to_lst(expanded(subtract(k.after(s.impulse)[1], k.w))).subs(centre),
      .depends_on = {"strike.spin"},
  });
  // Natural roll: a level cue (θ = 0) at b = 2/5 on a ball at rest; the slip at the cloth, v + ω × (−R ẑ).
  const GiNaC::exmap level{{s.cos_theta, 1}, {s.sin_theta, 0}, {s.a, 0}, {s.b, numeric(2, 5)}};
  const std::vector<Vec> struck = k.after(impulse_at_rest);
  const Vec cloth_slip = add(struck[0], cross(struck[1], Vec{0, 0, -s.R}));
  Vec rolling_slip;
  for (const ex& component : cloth_slip) rolling_slip.push_back(component.subs(at_rest).subs(level));
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
  // The energy change is a quadratic in J: written so, with J a symbol, it is a polynomial identity; the
  // impulse of strike.impulse then enters a small rational expression.
  const std::vector<Vec> struck_any = k.after(s.impulse);
  const ex energy_in_impulse =
      kinetic_energy(s.V - s.impulse / s.M, struck_any[0], struck_any[1]) - kinetic_energy(s.V, k.v, k.w);
  const ex approach = s.V - before_speed;
  record.add({
      .id = "strike.energy_in_impulse",
      .statement = "An impulse J along d changes the kinetic energy of cue and ball by −J (V − (v + ω × r)·d) + "
                   "(J²/2)(1/M + 1/m + (5/2)(a² + b²)/m): the work on the tip's approach plus J² over twice the "
                   "effective mass.",
      .method = "½ M V² + ½ m v² + ½ I ω² after minus before, J a symbol; identity, the unit relations imposed",
      .comparison = Comparison::identity,
      .paper_expression = -s.impulse * approach + s.impulse * s.impulse * inverse_mass / 2,
      .derived_expression = energy_in_impulse,
      .constraints = k.unit,
      .depends_on = {"definition.cue_impulse", "definition.solid_sphere", "strike.frame"},
  });
  const ex energy_change = (-s.impulse * approach + s.impulse * s.impulse * inverse_mass / 2)
                               .subs(s.impulse == (1 + e) * approach / inverse_mass);
  record.add({
      .id = "strike.energy",
      .statement = "The strike changes the kinetic energy of cue and ball by −(1 − e_tip²) (V − (v + ω × r)·d)² "
                   "/ (2 (1/M + 1/m + (5/2)(a² + b²)/m)).",
      .method = "strike.energy_in_impulse with the J of strike.impulse substituted; identity",
      .comparison = Comparison::identity,
      .paper_expression = -(1 - e * e) * approach * approach / (2 * inverse_mass),
      .derived_expression = energy_change,
      .depends_on = {"strike.impulse", "strike.energy_in_impulse"},
  });
  record.add({
      .id = "strike.energy_conserved_elastic",
      .paper = "TP A-30 (e_tip = 1)",
      .statement = "For e_tip = 1 the kinetic energy of cue and ball is conserved.",
      .method = "the energy change with e_tip = 1; identity",
      .comparison = Comparison::identity,
      .paper_expression = 0,
      .derived_expression = energy_change.subs(e == 1),
      .depends_on = {"strike.energy"},
  });
  record.add({
      .id = "strike.energy_decreases",
      .statement = "For e_tip < 1 it decreases: the loss (1 − e_tip²)(V − (v + ω × r)·d)²/(2 K) is ≥ 0, with "
                   "K = 1/M + 1/m + (5/2)(a² + b²)/m > 0 (a sum of positive terms) and e_tip = 1/(1 + q), q > 0.",
      .method = "minus the energy change in the form strike.energy verified, K a positive symbol, e_tip = "
                "1/(1 + q); its factors are positive or even powers",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = ((1 - e * e) * approach * approach / (2 * s.K)).subs(e == 1 / (1 + s.q)),
      .depends_on = {"strike.energy"},
  });
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
      .statement = "With b and c measured vertically and horizontally (TP A-30's frame) the offset terms are "
                   "a² + b² cos²θ + c² sin²θ − 2 b c cos θ sin θ = |r × d|²/R², which is a² + b² in the cue's "
                   "frame: the same strike.",
      .method = "|r × d|²/R² for r = R (a s + b_v ẑ − c_h h) in components; identity, cos² + sin² = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = s.a * s.a + pow(s.b_vertical * s.cos_theta, 2) + pow(s.c_horizontal * s.sin_theta, 2) -
                          2 * s.b_vertical * s.c_horizontal * s.cos_theta * s.sin_theta,
      .derived_expression = dot(tp_lever, tp_lever),
      .constraints = {k.unit[0], k.unit[1]},
      .note = "pooltool's cue_strike once typed (c cos θ)² for (c sin θ)² here, and 2 M V for 2 m V in the "
              "impulse: both are where a typed formula goes wrong and a derived one cannot.",
      .depends_on = {"strike.speed"},
  });
  return {impulse};
}

}  // namespace billiards::derive::shot
