// The cushion with spin, its energy: the change for any friction impulse, and the sign of each part.
#include "models/shot/steps.hpp"

#include <string>
#include <vector>

namespace billiards::derive::shot {

namespace {

ex ball_kinetic_energy(const Vec& v, const Vec& w) {
  const Symbols& s = symbols();
  return s.m * dot(v, v) / 2 + numeric(2, 5) * s.m * s.R * s.R * dot(w, w) / 2;
}

}  // namespace

void the_cushion_energy(Recorder& record, const Strike& k, const CushionContact& c,
                        const CushionRegimes& regimes) {
  const Symbols& s = symbols();
  const ex e = s.cushion_restitution, Pn = s.normal_impulse, j = s.friction_impulse, sigma = s.slip;
  // Energy: the change for any j, then its parts' signs.
  const ex P_z = -Pn * s.sin_a - j * c.u_t[2] / sigma;
  const ex energy_change =
      (ball_kinetic_energy(c.after[0], c.after[1]) - ball_kinetic_energy(c.v, c.w)).subs(c.with_normal);
  const ex u_n = k.v[0] * s.cos_a;
  const ex table_impulse{GiNaC::realsymbol("P_z", "P_z")};
  const ex energy_form = -numeric(1, 2) * (1 - e * e) * s.m * u_n * u_n - j * sigma +
                         numeric(7, 4) * j * j / s.m - pow(table_impulse, 2) / (2 * s.m);
  record.add({
      .id = "cushion.energy_change",
      .statement =
          "The ball's kinetic energy changes by −½ (1 − e_c²) m (v_x cos θ_a)² − j σ + (7/(4m)) j² − "
          "P_z²/(2m), P_z = −P_n sin θ_a − j u_t,z/σ the vertical impulse the table cancels.",
      .method =
          "½ m v² + ½ I ω² after minus before, P_n of cushion.normal_impulse, j any; identity, σ² = u_t·u_t "
          "and cos²θ_a + sin²θ_a = 1 imposed",
      .comparison = Comparison::identity,
      .paper_expression = energy_form.subs(table_impulse == P_z).subs(c.with_normal),
      .derived_expression = energy_change,
      .constraints = {c.slip, c.unit},
      .depends_on = {"cushion.normal_impulse", "cushion.slip_after_friction", "definition.cushion_table"},
  });
  const ex in_range = s.q / (1 + s.q);
  const ex friction_part = j * sigma - numeric(7, 4) * j * j / s.m;
  struct Part {
    std::string id, statement, method;
    ex loss;
  };
  const std::vector<Part> parts = {
      {"cushion.energy_normal_part", "The normal part of the loss, ½ (1 − e_c²) m (v_x cos θ_a)², is ≥ 0.",
       "sign: at e_c = q/(1 + q), q > 0 (e_c = 0 and 1 by continuity), it factors into positive symbols, "
       "sums "
       "of them and even powers",
       (numeric(1, 2) * (1 - e * e) * s.m * u_n * u_n).subs(e == in_range)},
      {"cushion.energy_table_part", "The table's part, P_z²/(2m), is ≥ 0.", "sign: an even power over m",
       pow(table_impulse, 2) / (2 * s.m)},
      {"cushion.energy_sticking_part",
       "Sticking (j = 2 m σ/7), the friction part j σ − (7/(4m)) j² = m σ²/7 is ≥ 0.",
       "sign: at j = 2 m σ/7 it factors into positive symbols", friction_part.subs(j == regimes.sticking)},
      {"cushion.energy_sliding_part",
       "Sliding (0 < j < 2 m σ/7), the friction part j σ − (7/(4m)) j² is ≥ 0.",
       "sign: at j = (2 m σ/7)/(1 + q), q > 0, it factors into positive symbols and sums of them",
       friction_part.subs(j == regimes.sticking / (1 + s.q))},
  };
  for (const Part& part : parts) {
    record.add({
        .id = part.id,
        .statement = part.statement + " With the others: the cushion never adds energy.",
        .method = part.method,
        .comparison = Comparison::nonnegative,
        .paper_expression = 0,
        .derived_expression = GiNaC::normal(part.loss),
        .depends_on = {"cushion.energy_change", "cushion.regime"},
    });
  }
}

}  // namespace billiards::derive::shot
