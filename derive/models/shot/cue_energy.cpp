// The cue strike's energy: its change for any impulse along the cue, conserved for e_tip = 1 and lost for
// e_tip < 1.
#include "models/shot/steps.hpp"

namespace billiards::derive::shot {

namespace {

// The kinetic energy of the cue and the ball.
ex cue_and_ball_energy(const ex& cue_speed, const Vec& v, const Vec& w) {
  const Symbols& s = symbols();
  return s.M * cue_speed * cue_speed / 2 + s.m * dot(v, v) / 2 +
         numeric(2, 5) * s.m * s.R * s.R * dot(w, w) / 2;
}

}  // namespace

void the_strike_energy(Recorder& record, const Strike& k, const CueStrike& strike) {
  const Symbols& s = symbols();
  const ex e = s.restitution;
  // The energy change is a quadratic in J: written so, with J a symbol, it is a polynomial identity; the
  // impulse of strike.impulse then enters a small rational expression.
  const std::vector<Vec> struck_any = k.after(s.impulse);
  const ex energy_in_impulse = cue_and_ball_energy(s.V - s.impulse / s.M, struck_any[0], struck_any[1]) -
                               cue_and_ball_energy(s.V, k.v, k.w);
  const ex& approach = strike.approach;
  record.add({
      .id = "strike.energy_in_impulse",
      .statement =
          "An impulse J along d changes the kinetic energy of cue and ball by −J (V − (v + ω × r)·d) + "
          "(J²/2)(1/M + 1/m + (5/2)(a² + b²)/m): the work on the tip's approach plus J² over twice the "
          "effective mass.",
      .method =
          "½ M V² + ½ m v² + ½ I ω² after minus before, J a symbol; identity, the unit relations imposed",
      .comparison = Comparison::identity,
      .paper_expression = -s.impulse * approach + s.impulse * s.impulse * strike.inverse_mass / 2,
      .derived_expression = energy_in_impulse,
      .constraints = k.unit,
      .depends_on = {"definition.cue_impulse", "definition.solid_sphere", "strike.frame"},
  });
  const ex energy_change = (-s.impulse * approach + s.impulse * s.impulse * strike.inverse_mass / 2)
                               .subs(s.impulse == (1 + e) * approach / strike.inverse_mass);
  record.add({
      .id = "strike.energy",
      .statement =
          "The strike changes the kinetic energy of cue and ball by −(1 − e_tip²) (V − (v + ω × r)·d)² "
          "/ (2 (1/M + 1/m + (5/2)(a² + b²)/m)).",
      .method = "strike.energy_in_impulse with the J of strike.impulse substituted; identity",
      .comparison = Comparison::identity,
      .paper_expression = -(1 - e * e) * approach * approach / (2 * strike.inverse_mass),
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
      .statement =
          "For e_tip < 1 it decreases: the loss (1 − e_tip²)(V − (v + ω × r)·d)²/(2 K) is ≥ 0, with "
          "K = 1/M + 1/m + (5/2)(a² + b²)/m > 0 (a sum of positive terms) and e_tip = 1/(1 + q), q > 0.",
      .method = "minus the energy change in the form strike.energy verified, K a positive symbol, e_tip = "
                "1/(1 + q); its factors are positive or even powers",
      .comparison = Comparison::nonnegative,
      .paper_expression = 0,
      .derived_expression = ((1 - e * e) * approach * approach / (2 * s.K)).subs(e == 1 / (1 + s.q)),
      .depends_on = {"strike.energy"},
  });
}

}  // namespace billiards::derive::shot
