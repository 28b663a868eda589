// The step: the speed at any time, the time to rest and the distance rolled, each derived from the
// premises and compared with the formula as a textbook prints it.
#include "rolling.hpp"

namespace rolling {

using billiards::derive::Comparison;

Stopping the_stopping(billiards::derive::Recorder& record) {
  const Symbols& s = symbols();
  const GiNaC::possymbol tau("tau", "\\tau");
  record.section("stopping", "Rolling to rest",
                 "The deceleration integrated once for the speed and again for the distance; the time to rest "
                 "solved from v(T) = 0.");
  Stopping out;
  out.speed_at = s.speed + GiNaC::integral(tau, 0, s.time, -s.resistance * s.gravity).eval_integ();
  record.add({
      .id = "stopping.speed",
      .statement = "The speed falls linearly: v(t) = v_0 − μ_r g t.",
      .method = "v_0 + ∫₀ᵗ (−μ_r g) dτ; identity",
      .comparison = Comparison::identity,
      .paper_expression = s.speed - s.resistance * s.gravity * s.time,
      .derived_expression = out.speed_at,
      .depends_on = {"definition.rolling_resistance", "definition.start"},
  });
  out.stop_time = GiNaC::lsolve(out.speed_at == 0, s.time);
  record.add({
      .id = "stopping.time",
      .statement = "The ball comes to rest at T = v_0/(μ_r g).",
      .method = "v(T) = 0 solved for T (lsolve); identity",
      .comparison = Comparison::identity,
      .paper_expression = s.speed / (s.resistance * s.gravity),
      .derived_expression = out.stop_time,
      .depends_on = {"stopping.speed"},
  });
  out.stop_distance =
      GiNaC::integral(tau, 0, out.stop_time, out.speed_at.subs(s.time == tau)).eval_integ().normal();
  record.add({
      .id = "stopping.distance",
      .statement = "It rolls d = v_0²/(2 μ_r g) before it stops.",
      .method = "∫₀ᵀ v(τ) dτ; identity",
      .comparison = Comparison::identity,
      .paper_expression = s.speed * s.speed / (2 * s.resistance * s.gravity),
      .derived_expression = out.stop_distance,
      .depends_on = {"stopping.speed", "stopping.time"},
  });
  return out;
}

}  // namespace rolling
