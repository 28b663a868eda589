// The shot model: its symbols, the cue and the ball in 3-D components, and the step functions, one per
// audit section. model.cpp strings them together.
#pragma once

#include "core/algebra.hpp"
#include "core/record.hpp"
#include "emit/kernel.hpp"

#include <ginac/ginac.h>

#include <vector>

namespace billiards::derive::shot {

using GiNaC::ex;
using GiNaC::lst;
using GiNaC::numeric;

// The scalar names of the derivation. Static: GiNaC tells symbols apart by identity.
struct Symbols {
  GiNaC::possymbol m{"m", "m"};              ///< the ball's mass
  GiNaC::possymbol M{"M", "M"};              ///< the cue's mass
  GiNaC::possymbol R{"R", "R"};              ///< the ball's radius
  GiNaC::possymbol V{"V", "V"};              ///< the cue's speed along its axis before the strike
  GiNaC::realsymbol a{"a", "a"};             ///< the side offset of the tip, in units of R, right positive
  GiNaC::realsymbol b{"b", "b"};             ///< the offset up, perpendicular to the cue, in units of R
  GiNaC::possymbol c{"c", "c"};              ///< √(1 − a² − b²): the contact point's depth along the cue
  GiNaC::realsymbol restitution{"e_tip", "e_{\\text{tip}}"};
  GiNaC::possymbol q{"q", "q"};              ///< a positive parameter: e_tip = 1/(1 + q) < 1
  GiNaC::realsymbol impulse{"J", "J"};       ///< the impulse on the ball, along the cue
  GiNaC::possymbol K{"K", "K"};              ///< the inverse effective mass of cue and ball at the tip
  GiNaC::possymbol cos_theta{"cos_theta", "\\cos\\theta"};  ///< the cue's elevation, 0 ≤ θ < 90°
  GiNaC::realsymbol sin_theta{"sin_theta", "\\sin\\theta"};
  GiNaC::realsymbol cos_phi{"cos_phi", "\\cos\\varphi"};    ///< the azimuth of the aim
  GiNaC::realsymbol sin_phi{"sin_phi", "\\sin\\varphi"};
  GiNaC::realsymbol b_vertical{"b_v", "b_v"};  ///< TP A-30's offset: vertical, in units of R
  GiNaC::realsymbol c_horizontal{"c_h", "c_h"};  ///< TP A-30's depth: horizontal, along the aim
  GiNaC::possymbol end_mass{"m_e", "m_e"};   ///< the cue's end mass: what moves across the cue with the tip
  GiNaC::realsymbol side_impulse{"J_s", "J_s"};  ///< the impulse on the ball across the cue, along s
  // The cushion, in its own frame: x̂ its normal into the cushion, ŷ along it, ẑ up.
  GiNaC::possymbol cos_a{"cos_theta_a", "\\cos\\theta_a"};  ///< the nose's angle above the equator, |θ_a| < 90°
  GiNaC::realsymbol sin_a{"sin_theta_a", "\\sin\\theta_a"};  ///< sin θ_a = h/R − 1
  GiNaC::possymbol nose_height{"h", "h"};  ///< the cushion's nose above the table, 0 < h < 2R
  GiNaC::realsymbol cushion_restitution{"e_c", "e_c"};
  GiNaC::possymbol cushion_friction{"mu_c", "\\mu_c"};
  GiNaC::possymbol normal_impulse{"P_n", "P_n"};  ///< the cushion's impulse on the ball along −n
  GiNaC::possymbol friction_impulse{"j", "j"};    ///< its size across n, against the slip
  GiNaC::possymbol slip{"sigma", "\\sigma"};    ///< |u_t|, the contact point's slip across n
};

const Symbols& symbols();

/// The cue and the ball at the strike, in the table's frame (x, y on the cloth, z up).
struct Strike {
  Vec along;  ///< d = (cos θ cos φ, cos θ sin φ, −sin θ): the cue's axis, from the tip into the ball
  Vec side;   ///< s = (sin φ, −cos φ, 0): to the right of the cue, horizontal
  Vec up;     ///< u = s × d = (sin θ cos φ, sin θ sin φ, cos θ): up, perpendicular to the cue
  Vec contact;  ///< r = R (a s + b u − c d): the tip's contact point from the ball's centre
  Vec v, w;     ///< the ball's velocity and spin before the strike
  std::vector<Constraint> unit;  ///< cos² + sin² = 1 for θ and φ, a² + b² + c² = 1

  Strike();
  /// The ball's velocity and spin after the impulse J along d at r: v + (J/m) d, ω + (5/(2 m R²)) r × J d.
  std::vector<Vec> after(const ex& impulse) const;
  /// The velocity of the ball's contact point along d.
  ex contact_speed(const Vec& v_, const Vec& w_) const;
};

// ---- The steps ------------------------------------------------------------------------------------

void record_premises(Recorder& record);

/// What the strike's later steps read of its impulse.
struct CueStrike {
  ex impulse;               ///< J, solved from the tip's restitution
  ex inverse_mass;          ///< 1/M + 1/m + (5/2)(a² + b²)/m, of cue and ball at the tip along d
  ex approach;              ///< V − (v + ω × r)·d, the tip's approach speed
  GiNaC::exmap at_rest;     ///< v = ω = 0
  ex impulse_at_rest;       ///< J on a ball at rest
};
CueStrike the_cue_strike(Recorder& record, const Strike& strike);
void the_strike_spin(Recorder& record, const Strike& strike, const CueStrike& impulse);
void the_strike_energy(Recorder& record, const Strike& strike, const CueStrike& impulse);
void the_strike_in_tp_a30_frame(Recorder& record, const Strike& strike);
void the_squirt(Recorder& record, const Strike& strike);

/// The ball at the cushion's nose, in the cushion's frame (x̂ its normal into the cushion, ŷ along it, ẑ
/// up), and the impulse's parts, as the cushion's later steps read them.
struct CushionContact {
  Vec n, r;                  ///< the contact normal (cos θ_a, 0, sin θ_a) and point R n
  Vec v, w;                  ///< the ball's velocity (on the cloth, v_z = 0) and spin before
  Vec u;                     ///< the contact point's velocity v + ω × r
  Vec u_t;                   ///< its part across n
  ex u_n;                    ///< its part along n
  Constraint unit;           ///< cos²θ_a + sin²θ_a = 1
  Constraint slip;           ///< σ² = u_t·u_t
  ex normal_impulse;         ///< P_n = (1 + e_c) m v_x cos θ_a, solved
  Vec friction;              ///< the friction impulse −j u_t/σ
  std::vector<Vec> after;    ///< v', ω' for P = −P_n n − j u_t/σ (P_n and j symbols), v_z' = 0
  GiNaC::exmap with_normal;  ///< P_n → its solution
};
CushionContact the_cushion_contact(Recorder& record, const Strike& strike);

/// The friction impulse in each regime and the outgoing state (v_x', v_y', ω_x', ω_y', ω_z') in each.
struct CushionRegimes {
  ex sticking;  ///< j = 2 m σ/7
  ex sliding;   ///< j = μ_c P_n
  lst sticking_state, sliding_state;
};
CushionRegimes the_cushion_regimes(Recorder& record, const Strike& strike, const CushionContact& contact);
void the_cushion_energy(Recorder& record, const Strike& strike, const CushionContact& contact,
                        const CushionRegimes& regimes);
void the_cushion_limits(Recorder& record, const Strike& strike, const CushionContact& contact,
                        const CushionRegimes& regimes);
void the_cushion_in_its_frame(Recorder& record, const Strike& strike, const CushionContact& contact);

/// The strike's kernels (the velocity change J/m, the spin change in the cue's frame) and the cushion's.
std::vector<Kernel> shot_kernels(const Strike& strike);

}  // namespace billiards::derive::shot
