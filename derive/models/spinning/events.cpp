// Event times on the cloth: the polynomials in t whose roots are contacts — ball with ball, with a
// straight cushion, with a circle (a pocket's capture circle, a cushion's rounded jaw) — while each ball
// moves as its phase's solution, r(t) = r0 + v0 t + ½ a t².
#include "models/spinning/steps.hpp"

namespace billiards::derive::spinning {

EventSymbols::EventSymbols()
    : dx("dx", "\\Delta r_x"),
      dy("dy", "\\Delta r_y"),
      dvx("dvx", "\\Delta v_x"),
      dvy("dvy", "\\Delta v_y"),
      dax("dax", "\\Delta a_x"),
      day("day", "\\Delta a_y"),
      distance("distance", "D"),
      gap("gap", "s_0"),
      normal_speed("normal_speed", "v_n"),
      normal_acceleration("normal_acceleration", "a_n"),
      radius("radius", "R"),
      separation("rho", "|\\Delta r|") {}

const EventSymbols& event_symbols() {
  static const EventSymbols instance;
  return instance;
}

EventPolynomials event_times(Recorder& record) {
  const Symbols& s = symbols();
  const EventSymbols& p = event_symbols();
  const ex t = s.t;
  record.section("events", "Event times on the cloth",
                 "In every phase a ball's centre moves as r(t) = r0 + v0 t + ½ a t² (sliding.position, "
                 "rolling.position; a = 0 while it only spins or rests), so the contacts of the next phase are "
                 "roots of polynomials in t. Their coefficients are derived here and emitted as kernels; the "
                 "runtime's root finder takes the earliest root in which the bodies approach.");
  // Two balls, each r_i(t) = r_i + v_i t + ½ a_i t².
  const Vec r1 = component_symbols("p1", "r", "1", 2), r2 = component_symbols("p2", "r", "2", 2);
  const Vec v1 = component_symbols("u1", "v", "1", 2), v2 = component_symbols("u2", "v", "2", 2);
  const Vec a1 = component_symbols("b1", "a", "1", 2), a2 = component_symbols("b2", "a", "2", 2);
  const auto motion = [&](const Vec& r, const Vec& v, const Vec& a) {
    return add(add(r, scale(t, v)), scale(t * t / 2, a));
  };
  const Vec dr{p.dx, p.dy}, dv{p.dvx, p.dvy}, da{p.dax, p.day};
  const GiNaC::exmap relative{{p.dx, r2[0] - r1[0]}, {p.dy, r2[1] - r1[1]}, {p.dvx, v2[0] - v1[0]},
                              {p.dvy, v2[1] - v1[1]}, {p.dax, a2[0] - a1[0]}, {p.day, a2[1] - a1[1]}};
  record.add({
      .id = "events.relative_motion",
      .statement = "Between two balls in any phases, r2(t) − r1(t) = Δr + Δv t + ½ Δa t² with Δr = r2 − r1, "
                   "Δv = v2 − v1, Δa = a2 − a1: the same form, in the differences.",
      .method = "the two motions subtracted, the differences substituted; identity",
      .comparison = Comparison::identity,
      .paper_expression = to_lst(motion(dr, dv, da)).subs(relative),
      .derived_expression = to_lst(subtract(motion(r2, v2, a2), motion(r1, v1, a1))),
      .depends_on = {"sliding.position", "rolling.position"},
  });
  // The squared distance less the contact distance squared, and its coefficients.
  const Vec gap_vector = motion(dr, dv, da);
  const ex contact = (dot(gap_vector, gap_vector) - p.distance * p.distance).expand();
  EventPolynomials out;
  out.contact = {dot(dr, dr) - p.distance * p.distance, 2 * dot(dr, dv), dot(dv, dv) + dot(dr, da),
                 dot(dv, da), dot(da, da) / 4};
  ex typed_polynomial = 0;
  for (std::size_t k = 0; k < out.contact.size(); ++k) typed_polynomial += out.contact[k] * pow(t, static_cast<int>(k));
  record.add({
      .id = "events.contact_polynomial",
      .statement = "|Δr + Δv t + ½ Δa t²|² − D² = c0 + c1 t + c2 t² + c3 t³ + c4 t⁴ with c0 = Δr·Δr − D², c1 = "
                   "2 Δr·Δv, c2 = Δv·Δv + Δr·Δa, c3 = Δv·Δa, c4 = ¼ Δa·Δa: two balls touch (D = R1 + R2) where it "
                   "vanishes; with Δr, Δv, Δa a ball's state less a fixed point c, and D = R + ρ or ρ, it is the "
                   "contact with a circle of radius ρ about c (a cushion's rounded jaw) or the centre's entry "
                   "into it (a pocket's capture circle).",
      .method = "the squared distance expanded in t against the polynomial; identity",
      .comparison = Comparison::identity,
      .paper_expression = typed_polynomial,
      .derived_expression = contact,
      .depends_on = {"events.relative_motion"},
  });
  // Each coefficient read off the squared distance: the kernels' claims.
  const std::vector<std::pair<std::string, std::string>> terms = {
      {"events.contact_constant_term", "c0 = Δr·Δr − D², the coefficient of t⁰."},
      {"events.contact_linear_term", "c1 = 2 Δr·Δv, the coefficient of t."},
      {"events.contact_quadratic_term", "c2 = Δv·Δv + Δr·Δa, the coefficient of t²."},
      {"events.contact_cubic_term", "c3 = Δv·Δa, the coefficient of t³."},
      {"events.contact_quartic_term", "c4 = ¼ Δa·Δa, the coefficient of t⁴."},
  };
  for (std::size_t k = 0; k < terms.size(); ++k) {
    record.add({
        .id = terms[k].first,
        .statement = terms[k].second,
        .method = "coeff() of the expanded squared distance; identity",
        .comparison = Comparison::identity,
        .paper_expression = out.contact[k],
        .derived_expression = contact.coeff(t, static_cast<int>(k)),
        .depends_on = {"events.contact_polynomial"},
    });
  }
  record.add({
      .id = "events.contact_degree",
      .statement = "The degree drops exactly where the motion says: c4 = ¼ |Δa|² vanishes iff Δa = 0 (equal "
                   "accelerations), and then c3 = 0 too and the polynomial is the quadratic |Δv|² t² + 2 Δr·Δv t "
                   "+ c0; with Δv = 0 as well c2 = 0 and the distance is constant. No root is sought by dividing "
                   "by a leading coefficient that the phases make zero.",
      .method = "c4, c3 at Δa = 0 and c2 at Δa = Δv = 0; identity",
      .comparison = Comparison::identity,
      .paper_expression = lst{0, 0, 0},
      .derived_expression = lst{out.contact[4].subs(lst{p.dax == 0, p.day == 0}),
                                out.contact[3].subs(lst{p.dax == 0, p.day == 0}),
                                out.contact[2].subs(lst{p.dax == 0, p.day == 0, p.dvx == 0, p.dvy == 0})},
      .depends_on = {"events.contact_polynomial"},
  });
  const Constraint separation{pow(p.separation, 2) == dot(dr, dr), "|Δr|² = Δr·Δr"};
  // |Δr(t)|, written so that its value at t = 0 is |Δr| itself.
  const ex distance_now = sqrt(pow(p.separation, 2) + (dot(gap_vector, gap_vector) - dot(dr, dr)).expand());
  record.add({
      .id = "events.contact_now_and_approach",
      .statement = "At t = 0 the polynomial is (|Δr| − D)(|Δr| + D): its sign is the gap's. Its slope there, c1 = "
                   "2 Δr·Δv, is 2 |Δr| d|Δr|/dt: the bodies approach iff c1 < 0, so a root at t = 0 with c1 ≥ 0 "
                   "(touching while separating, or at exact tangency) is no contact.",
      .method = "the polynomial at t = 0, and d|Δr(t)|/dt at t = 0 times 2 |Δr|; identity, |Δr|² = Δr·Δr "
                "imposed",
      .comparison = Comparison::identity,
      .paper_expression = lst{(p.separation - p.distance) * (p.separation + p.distance), out.contact[1]},
      .derived_expression = lst{contact.subs(t == 0),
                                2 * p.separation * distance_now.diff(GiNaC::ex_to<GiNaC::symbol>(t)).subs(t == 0)},
      .constraints = {separation},
      .depends_on = {"events.contact_polynomial"},
  });
  // A straight cushion: the line n·x = d, n its unit normal into the table; the ball touches it where its
  // centre is R from the line.
  const Vec n = component_symbols("cushion_normal", "n", "", 2);
  const Vec r0 = component_symbols("rc", "r", "", 2), v0 = component_symbols("vc", "v", "", 2),
            a0 = component_symbols("ac", "a", "", 2);
  const GiNaC::realsymbol line("line_offset", "d");
  out.cushion = {p.gap - p.radius, p.normal_speed, p.normal_acceleration / 2};
  record.add({
      .id = "events.cushion_motion",
      .statement = "Along a straight cushion's unit normal n (into the table), the line n·x = d, a ball's centre "
                   "is at n·r(t) − d = s0 + v_n t + ½ a_n t² from the line, s0 = n·r0 − d, v_n = n·v0, a_n = n·a.",
      .method = "n·r(t) − d in components, expanded; identity",
      .comparison = Comparison::identity,
      .paper_expression = (dot(n, r0) - line) + dot(n, v0) * t + dot(n, a0) * t * t / 2,
      .derived_expression = (dot(n, motion(r0, v0, a0)) - line).expand(),
      .depends_on = {"sliding.position", "rolling.position"},
  });
  const ex cushion_gap =
      (p.gap + p.normal_speed * t + p.normal_acceleration * t * t / 2 - p.radius).expand();
  const std::vector<std::pair<std::string, std::string>> cushion_terms = {
      {"events.cushion_constant_term",
       "The ball touches the cushion where s0 − R + v_n t + ½ a_n t² = 0, a quadratic (linear where a_n = 0): "
       "its c0 = s0 − R is the gap at t = 0."},
      {"events.cushion_linear_term", "Its c1 = v_n, its slope at t = 0: the ball approaches iff v_n < 0."},
      {"events.cushion_quadratic_term", "Its c2 = ½ a_n."},
  };
  for (std::size_t k = 0; k < cushion_terms.size(); ++k) {
    record.add({
        .id = cushion_terms[k].first,
        .statement = cushion_terms[k].second,
        .method = "coeff() of s0 + v_n t + ½ a_n t² − R; identity",
        .comparison = Comparison::identity,
        .paper_expression = out.cushion[k],
        .derived_expression = cushion_gap.coeff(t, static_cast<int>(k)),
        .depends_on = {"events.cushion_motion"},
    });
  }
  return out;
}

}  // namespace billiards::derive::spinning
