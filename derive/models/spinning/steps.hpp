// The spinning-ball model: what every step shares — its symbols, the two balls in 3-D components, the
// impulse equations — and the step functions, one per audit section, each taking what it reads and
// returning what later steps use. model.cpp strings them together.
#pragma once

#include "core/algebra.hpp"
#include "core/record.hpp"
#include "emit/kernel.hpp"
#include "model.hpp"

#include <ginac/ginac.h>

#include <string>
#include <vector>

namespace billiards::derive::spinning {

using GiNaC::ex;
using GiNaC::lst;
using GiNaC::numeric;

// The scalar names of the derivation. Static: GiNaC tells symbols apart by identity.
struct Symbols {
  GiNaC::possymbol m1{"m1", "m_1"};
  GiNaC::possymbol m2{"m2", "m_2"};
  GiNaC::possymbol R1{"R1", "R_1"};
  GiNaC::possymbol R2{"R2", "R_2"};
  GiNaC::possymbol I1{"I1", "I_1"};
  GiNaC::possymbol I2{"I2", "I_2"};
  GiNaC::realsymbol restitution{"restitution", "e"};
  GiNaC::possymbol friction{"friction", "\\mu"};
  GiNaC::realsymbol normal_impulse{"Jn", "J_n"};
  GiNaC::possymbol tangential_impulse{"j", "j"};        ///< |J_t|
  GiNaC::possymbol tangential_slip{"sigma", "|u_t|"};   ///< |u_t| > 0
  GiNaC::realsymbol normal_slip{"un", "(u \\cdot n)"};  ///< u·n = (v2 − v1)·n
  GiNaC::possymbol k{"k", "k"};                         ///< the tangential inverse effective mass
  GiNaC::possymbol q{"q", "q"};                         ///< a positive parameter for sign claims
  GiNaC::possymbol velocity_change{"dv", "\\Delta v"};  ///< a ball's velocity change along û_t
  // The stun shot: cos φ and sin φ of the cut angle, the cue ball's speed.
  GiNaC::possymbol cos_cut{"cos_phi", "\\cos\\varphi"};
  GiNaC::possymbol sin_cut{"sin_phi", "\\sin\\varphi"};
  GiNaC::possymbol speed{"V", "V"};
  // The cloth.
  GiNaC::possymbol m{"m", "m"};
  GiNaC::possymbol R{"R", "R"};
  GiNaC::possymbol g{"g", "g"};
  GiNaC::possymbol sliding_friction{"mu_s", "\\mu_s"};
  GiNaC::possymbol rolling_friction{"mu_r", "\\mu_r"};
  GiNaC::possymbol spinning_friction{"mu_sp", "\\mu_{sp}"};
  GiNaC::possymbol t{"t", "t"};
  GiNaC::possymbol slip_speed{"sigma0", "|u_0|"};      ///< |u0| > 0 while sliding
  GiNaC::possymbol ball_speed{"nu0", "|v_0|"};         ///< |v0| > 0 while rolling
  GiNaC::possymbol spin{"omega_z0", "\\omega_{z,0}"};  ///< ω_z0 > 0 (the other sign by symmetry)
  GiNaC::realsymbol vertical_spin{"omega_z", "\\omega_z"};
};

const Symbols& symbols();

/// Appended to a claim's method where n·n = 1 is imposed.
inline constexpr const char* unit_normal_method = "; n·n = 1 imposed by substituting n_z² → 1 − n_x² − n_y²";

/// Two balls in 3-D components and the impulse equations of their contact.
struct Contact {
  Vec v1, w1, v2, w2;  ///< velocities and angular velocities before
  Vec n;               ///< unit normal from ball 1's centre to ball 2's
  Vec a;               ///< an arbitrary vector: t = n × a is tangent to the contact
  Vec J;               ///< a general impulse on ball 2 (−J on ball 1)
  Constraint unit_normal;

  Contact();
  /// The contact points relative to the centres: R1 n and −R2 n.
  Vec r1() const;
  Vec r2() const;
  /// The slip u = (v2 + ω2 × r2) − (v1 + ω1 × r1) of the given state.
  Vec slip(const Vec& v1_, const Vec& w1_, const Vec& v2_, const Vec& w2_) const;
  /// The state after the impulse `impulse` on ball 2: Δv1 = −J/m1, Δv2 = J/m2, Δω1 = I1⁻¹ (r1 × (−J)),
  /// Δω2 = I2⁻¹ (r2 × J). Returns {v1', ω1', v2', ω2'}.
  std::vector<Vec> after(const Vec& impulse) const;
  /// The kinetic energy, translational and rotational, of a state {v1, ω1, v2, ω2}.
  ex kinetic_energy(const std::vector<Vec>& state) const;
  /// A tangent vector n × a.
  Vec tangent() const;
};

// ---- The steps ------------------------------------------------------------------------------------

void record_premises(Recorder& record);

struct Impulse {
  ex k_general;       ///< 1/m1 + 1/m2 + R1²/I1 + R2²/I2, derived
  ex normal_inverse;  ///< 1/m1 + 1/m2, derived
};
Impulse the_impulse(Recorder& record, const Contact& contact);

void conservation(Recorder& record, const Contact& contact, const Impulse& impulse);

struct Friction {
  ex normal_impulse;    ///< J_n in u·n, solved from restitution
  ex sticking_impulse;  ///< |u_t|/k, solved from u_t' = 0
};
Friction the_friction(Recorder& record, const Contact& contact, const Impulse& impulse);

void the_throw(Recorder& record, const Contact& contact, const Friction& friction);

// ---- The cloth: one step per phase (cloth_sliding.cpp, cloth_rolling.cpp, cloth_spinning.cpp) -------

/// ∫₀ᵗ f dτ for each component, f in τ (GiNaC integrates the polynomial).
Vec integrate(const Vec& f, const GiNaC::symbol& tau, const ex& t);
/// f with τ = t.
Vec at_time(const Vec& f, const GiNaC::symbol& tau, const ex& t);

/// A ball on the cloth at t = 0, which every phase starts from: its velocity, horizontal spin and centre (at
/// height R), the integration variable and the moment of inertia of a solid sphere.
struct ClothStart {
  Vec v0, w0, r0;
  GiNaC::symbol tau;
  ex inertia;
  /// ½ m v² + ½ I ω².
  ex kinetic_energy(const Vec& v, const Vec& w) const;
};
ClothStart cloth_start();

/// Each phase's claims; returns the time the phase ends.
ex sliding_on_the_cloth(Recorder& record, const ClothStart& start);
ex rolling_on_the_cloth(Recorder& record, const ClothStart& start);
ex spinning_on_the_cloth(Recorder& record, const ClothStart& start);

struct Cloth {
  ex slide_time, roll_time, spin_time;  ///< derived
};
/// The three phases in the audit's order.
Cloth the_cloth(Recorder& record);

/// The event polynomials' symbols: the differences of two motions (or of a ball's and a fixed point's),
/// the contact distance, and a ball's motion along a cushion's normal.
struct EventSymbols {
  GiNaC::realsymbol dx, dy, dvx, dvy, dax, day;
  GiNaC::possymbol distance;                                ///< D: R1 + R2, R + ρ or ρ
  GiNaC::realsymbol gap, normal_speed, normal_acceleration;  ///< s0 = n·r0 − d, n·v0, n·a
  GiNaC::possymbol radius;                                  ///< the ball's R, for the cushion
  GiNaC::possymbol separation;                              ///< |Δr|
  EventSymbols();
};
const EventSymbols& event_symbols();

struct EventPolynomials {
  std::vector<ex> contact;  ///< c0 … c4 of |Δr(t)|² − D², in EventSymbols
  std::vector<ex> cushion;  ///< c0 … c2 of n·r(t) − d − R
};
/// The section "Event times on the cloth".
EventPolynomials event_times(Recorder& record);

/// The section "Pressed contacts": the forces of sustained contact on the line of the contact.
void pressed_contacts(Recorder& record);

// ---- The kernels ----------------------------------------------------------------------------------

/// The claims the kernels are proven against where the steps do not state the emitted quantity alone.
void kernel_claims(Recorder& record, const Contact& contact, const Impulse& impulse,
                   const Friction& friction);

std::vector<Kernel> spin_kernels(const Cloth& cloth);

}  // namespace billiards::derive::spinning
