// Squirt: the cue ball's deflection from the cue's line when the tip strikes off centre, from the
// lateral impulse that the cue's end mass takes (Alciatore, TP A-31).
#include "models/shot/steps.hpp"

namespace billiards::derive::shot {

void the_squirt(Recorder& record, const Strike& k) {
  const Symbols& s = symbols();
  record.section("squirt", "Squirt",
                 "A level cue (θ = 0) striking a ball at rest with side offset only (b = 0): the tip grips the "
                 "ball across the cue (definition.cue_end_mass), so the ball takes a lateral impulse J_s as well "
                 "as J along the cue, solved from the grip, not typed, and leaves at an angle to the cue's line "
                 "(Alciatore, TP A-31).");
  const GiNaC::exmap level_side_hit{{s.cos_theta, 1}, {s.sin_theta, 0}, {s.b, 0}};
  const auto level = [&](const Vec& vector) {
    Vec out;
    for (const ex& component : vector) out.push_back(component.subs(level_side_hit));
    return out;
  };
  const Vec along = level(k.along), side = level(k.side), contact = level(k.contact);
  const Vec impulse = add(scale(s.impulse, along), scale(s.side_impulse, side));
  const ex inertia = numeric(2, 5) * s.m * s.R * s.R;
  const Vec v = scale(1 / s.m, impulse);
  const Vec w = scale(1 / inertia, cross(contact, impulse));
  // The grip: the ball's contact point and the tip's end leave with the same velocity along s.
  const ex grip = dot(add(v, cross(w, contact)), side) - (-s.side_impulse / s.end_mass);
  const ex side_impulse = GiNaC::lsolve(grip.expand() == 0, s.side_impulse);
  // b = 0: c² = 1 − a², and cos²φ + sin²φ = 1.
  const std::vector<Constraint> level_unit = {k.unit[1], {pow(s.c, 2) == 1 - pow(s.a, 2), "a² + c² = 1 (b = 0)"}};
  const ex denominator = 1 + s.m / s.end_mass + numeric(5, 2) * s.c * s.c;
  record.add({
      .id = "squirt.side_impulse",
      .statement = "The tip's grip gives the ball J_s = −(5/2) a c J/(1 + m/m_e + (5/2) c²) across the cue, c = "
                   "√(1 − a²): against the side the tip is on.",
      .method = "the grip, (v' + ω' × r)·s = −J_s/m_e with v' = (J d + J_s s)/m and ω' = I⁻¹ r × (J d + J_s s), "
                "θ = 0 and b = 0, solved for J_s (lsolve: it is linear in J_s); identity, a² + c² = 1 and "
                "cos²φ + sin²φ = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = -numeric(5, 2) * s.a * s.c * s.impulse / denominator,
      .derived_expression = side_impulse,
      .constraints = level_unit,
      .depends_on = {"definition.cue_end_mass", "definition.cue_impulse", "definition.solid_sphere",
                     "strike.frame"},
  });
  // The deflection: tan α = −(v'·s)/(v'·d), positive when the ball leaves to the left of the cue's line.
  const GiNaC::exmap solved{{s.side_impulse, side_impulse}};
  const ex tangent = (-dot(v, side) / dot(v, along)).subs(solved);
  const ex c_of_a = sqrt(1 - s.a * s.a);
  record.add({
      .id = "squirt.angle",
      .paper = "TP A-31, the squirt angle",
      .paper_tex = "\\tan\\alpha = \\frac{\\frac{5}{2} a \\sqrt{1 - a^2}}{1 + \\frac{m}{m_e} + \\frac{5}{2}(1 - a^2)}",
      .statement = "The ball leaves at α from the cue's line, to the left for a tip right of centre (a > 0), with "
                   "tan α = (5/2) a √(1 − a²)/(1 + m/m_e + (5/2)(1 − a²)).",
      .method = "−(v'·s)/(v'·d) with the J_s of the grip, c = √(1 − a²); identity, cos²φ + sin²φ = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression =
          numeric(5, 2) * s.a * c_of_a / (1 + s.m / s.end_mass + numeric(5, 2) * (1 - s.a * s.a)),
      .derived_expression = tangent.subs(s.c == c_of_a),
      .constraints = {k.unit[1]},
      .depends_on = {"squirt.side_impulse"},
  });
  const ex tangent_as_one_fraction = GiNaC::normal(tangent);
  record.add({
      .id = "squirt.none_without_offset_or_end_mass",
      .paper = "TP A-31: a lighter end mass squirts less",
      .statement = "A centre hit (a = 0) does not squirt, and neither does a cue whose end mass vanishes "
                   "(m_e → 0): tan α is then 0 whatever the offset.",
      .method = "tan α as one fraction, a = 0, and m_e = 0; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{0, 0},
      .derived_expression =
          lst{tangent_as_one_fraction.subs(s.a == 0), tangent_as_one_fraction.subs(s.end_mass == 0)},
      .depends_on = {"squirt.angle"},
  });
}

}  // namespace billiards::derive::shot
