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

struct CueStrike {
  ex impulse;  ///< J, solved from the tip's restitution
};
CueStrike the_cue_strike(Recorder& record, const Strike& strike);
void the_squirt(Recorder& record, const Strike& strike);
void the_cushion(Recorder& record, const Strike& strike);

/// The strike's kernels (the velocity change J/m, the spin change in the cue's frame) and the cushion's.
std::vector<Kernel> shot_kernels(const Strike& strike);

}  // namespace billiards::derive::shot
