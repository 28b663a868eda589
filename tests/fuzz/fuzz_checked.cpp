// libFuzzer harness for the checked API: every checked call (collide with and without restitution,
// collide_along_direction, collide_if_approaching, reflect, time_of_impact; collide_with_friction,
// motion, transition_time and evolve on the cloth; earliest_contact; strike; collide_with_cushion). Arbitrary bytes are
// shaped into arguments so that most inputs are valid (masses over the whole range, finite velocities,
// unit normals, restitution in [0, 1], lengths and speeds scaled by powers of two over the type's
// exponent range for time_of_impact) and a few are not (NaN, infinities, zero or negative masses,
// non-unit normals). For every accepted input: no crash, no sanitizer report, a finite result (a time
// ≥ 0 or +∞), and the result within rounding of the same physics computed independently in long
// double (reference.hpp: the formulas as printed in the guides, not the kernels); for elastic
// collisions of finite masses, momentum conserved to rounding. The spinning-ball calls are held to
// spin_reference.hpp's long-double references the same way, with no energy created (to rounding) by a
// collision or on the cloth. A rejected input must throw billiards::invalid_argument and nothing else.
#include "reference.hpp"
#include "han_2005.hpp"
#include "spin_reference.hpp"

#include <billiards/checked.hpp>
#include <billiards/cloth.hpp>
#include <billiards/events.hpp>
#include <billiards/shot.hpp>
#include <billiards/spin.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <string>

namespace {

long accepted_inputs = 0;
long all_inputs = 0;
std::map<std::string, long> rejected_by_argument;

// Prints the acceptance figure when the fuzzer exits (libFuzzer calls exit()).
struct Report {
  ~Report() {
    std::fprintf(stderr, "billiards fuzz: %ld of %ld inputs accepted by the checked API\n", accepted_inputs,
                 all_inputs);
    for (const auto& [argument, count] : rejected_by_argument) {
      std::fprintf(stderr, "  rejected for %s: %ld\n", argument.c_str(), count);
    }
  }
} report;

class Shaper {
 public:
  Shaper(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  // The input read cyclically (a short input still shapes every argument); an empty one is all 128s.
  std::uint8_t byte() { return size_ == 0 ? 128 : data_[position_++ % size_]; }

  // A value of `Scalar` that is almost always valid for its role, and sometimes one of the edge cases.
  // Edge cases are behind a rare selector byte (0xA5), not behind 0–6, which the fuzzer's mutations
  // favour: so most inputs are valid and the rest still reach every edge case.
  template <typename Scalar>
  Scalar special_or(Scalar usual) {
    if (byte() != 0xA5) return usual;
    switch (byte() % 8) {
      case 0: return std::numeric_limits<Scalar>::quiet_NaN();
      case 1: return std::numeric_limits<Scalar>::infinity();
      case 2: return -std::numeric_limits<Scalar>::infinity();
      case 3: return Scalar(0);
      case 4: return -usual;
      case 5: return std::numeric_limits<Scalar>::denorm_min();
      case 6: return std::numeric_limits<Scalar>::max();
      default: return usual;
    }
  }
  template <typename Scalar>
  Scalar mass() {
    const int exponent = static_cast<int>(byte()) - 128;  // 2^-128 … 2^127, then scaled
    const Scalar usual = std::ldexp(Scalar(1) + Scalar(byte()) / Scalar(256), exponent);
    return special_or(usual > 0 ? usual : std::numeric_limits<Scalar>::denorm_min());
  }
  template <typename Scalar>
  Scalar component() {
    const int exponent = static_cast<int>(byte() % 64) - 32;
    const Scalar magnitude = std::ldexp(Scalar(byte()) / Scalar(255), exponent);
    return special_or(byte() % 2 ? magnitude : -magnitude);
  }
  template <typename Vector>
  Vector vector() {
    Vector v;
    for (int i = 0; i < v.size(); ++i) v[i] = component<typename Vector::Scalar>();
    return v;
  }
  template <typename Vector>
  Vector unit() {
    Vector v = vector<Vector>();
    const auto norm = v.norm();
    if (byte() != 0xA5 && std::isfinite(norm) && norm > 0) v /= norm;  // 0xA5: leave it unnormalised
    return v;
  }
  /// 2^k for k anywhere in the type's exponent range (subnormal powers included).
  template <typename Scalar>
  Scalar power_of_two() {
    using limits = std::numeric_limits<Scalar>;
    const int span = limits::max_exponent - (limits::min_exponent - limits::digits);
    const int k = static_cast<int>((static_cast<unsigned>(byte()) << 8 | byte()) % unsigned(span));
    return std::ldexp(Scalar(1), limits::min_exponent - limits::digits + k);
  }
  /// An input the checked calls must reject now and then (NaN, ±∞, 0, −usual), else `usual`.
  template <typename Scalar>
  Scalar invalid_or(Scalar usual) {
    if (byte() != 0xA5) return usual;
    switch (byte() % 5) {
      case 0: return std::numeric_limits<Scalar>::quiet_NaN();
      case 1: return std::numeric_limits<Scalar>::infinity();
      case 2: return -std::numeric_limits<Scalar>::infinity();
      case 3: return Scalar(0);
      default: return -usual;
    }
  }
  /// A positive quantity within 2^±(E/4), E the type's largest exponent: where the cloth's phase
  /// times, a few quotients, cannot underflow or overflow in between (see docs/accuracy_and_fuzzing.md).
  template <typename Scalar>
  Scalar moderate() {
    const int quarter = std::numeric_limits<Scalar>::max_exponent / 4;
    const int exponent =
        static_cast<int>((static_cast<unsigned>(byte()) << 8 | byte()) % unsigned(2 * quarter)) - quarter;
    return invalid_or(std::ldexp(Scalar(1) + Scalar(byte()) / Scalar(256), exponent));
  }
  template <typename Scalar>
  Scalar restitution() {
    return special_or(Scalar(byte()) / Scalar(255));
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

// A broken property: say which, with the values, then crash so that libFuzzer keeps the input.
template <typename Vector>
[[noreturn]] void fail(const char* property, const billiards::Collision<Vector>& result) {
  std::fprintf(stderr, "billiards fuzz: %s violated\n", property);
  for (int i = 0; i < result.first.size(); ++i) {
    std::fprintf(stderr, "  x1[%d] = %a  x2[%d] = %a\n", i, static_cast<double>(result.first[i]), i,
                 static_cast<double>(result.second[i]));
  }
  std::abort();
}

template <typename Vector>
void require_finite(const billiards::Collision<Vector>& result) {
  if (!result.first.allFinite() || !result.second.allFinite()) fail("finite result", result);
}

// Momentum m1 v1 + m2 v2 conserved to rounding (finite masses only).
template <typename Vector>
void require_momentum(typename Vector::Scalar m1, const Vector& v1, typename Vector::Scalar m2,
                      const Vector& v2, const billiards::Collision<Vector>& result) {
  if (std::isinf(m1) || std::isinf(m2)) return;
  using Long = Eigen::Matrix<long double, Vector::RowsAtCompileTime, 1>;
  const long double M1 = m1, M2 = m2;
  const Long before = M1 * v1.template cast<long double>() + M2 * v2.template cast<long double>();
  const Long after =
      M1 * result.first.template cast<long double>() + M2 * result.second.template cast<long double>();
  const long double scale = M1 * v1.template cast<long double>().norm() +
                            M2 * v2.template cast<long double>().norm() +
                            M1 * result.first.template cast<long double>().norm() +
                            M2 * result.second.template cast<long double>().norm();
  // Rounding is relative (ε) for normal results and absolute (the smallest subnormal) below them: a
  // heavy ball's velocity cannot change by less than denorm_min, whatever momentum that carries.
  const long double epsilon = std::numeric_limits<typename Vector::Scalar>::epsilon();
  const long double absolute = (M1 + M2) * std::numeric_limits<typename Vector::Scalar>::denorm_min() * 4;
  if (!((after - before).cwiseAbs().maxCoeff() <= 64 * epsilon * scale + absolute)) {
    std::fprintf(stderr, "  m1 = %.17Lg m2 = %.17Lg, momentum change %.17Lg, scale %.17Lg\n", M1, M2,
                 (after - before).cwiseAbs().maxCoeff(), scale);
    fail("momentum conservation", result);
  }
}

template <typename Vector>
void require_reference(const char* call, const billiards::Collision<Vector>& result,
                       const billiards_fuzz::Expected<Vector>& expected) {
  if (const char* broken = billiards_fuzz::compare(result, expected)) {
    std::fprintf(stderr, "billiards fuzz: %s: %s\n", call, broken);
    for (int i = 0; i < expected.v1.size(); ++i) {
      std::fprintf(stderr,
                   "  v1[%d] = %a  v2[%d] = %a  n or d %a  reference %.17Lg ± %.3Lg, %.17Lg ± %.3Lg\n", i,
                   static_cast<double>(expected.v1[i]), i, static_cast<double>(expected.v2[i]),
                   static_cast<double>(expected.direction[i]), expected.first[i], expected.first_bound[i],
                   expected.second[i], expected.second_bound[i]);
    }
    fail("agreement with the long-double reference", result);
  }
}

template <typename Vector>
void exercise_time_of_impact(Shaper& shape) {
  using Scalar = typename Vector::Scalar;
  // Lengths and speeds each scaled by a power of two anywhere in the exponent range: the contact is
  // the same, at a scaled time, and must not be missed by underflow or overflow.
  const Scalar length = shape.power_of_two<Scalar>(), speed = shape.power_of_two<Scalar>();
  const Vector p1 = shape.vector<Vector>() * length, p2 = shape.vector<Vector>() * length;
  const Vector v1 = shape.vector<Vector>() * speed;
  // Half the inputs aimed at the other ball, so that hits are common.
  const Vector v2 = shape.byte() % 2
                        ? Vector(shape.vector<Vector>() * speed)
                        : Vector(v1 - (p2 - p1) * (speed / length) + shape.vector<Vector>() * speed / 64);
  const Scalar r = shape.special_or(std::fabs(shape.component<Scalar>()) * length);
  ++all_inputs;
  try {
    const Scalar t = billiards::checked::time_of_impact(p1, v1, p2, v2, r);
    if (const char* broken = billiards_fuzz::compare_time(t, p1, v1, p2, v2, r)) {
      std::fprintf(stderr, "billiards fuzz: time_of_impact: %s\n  t = %.17Lg, r = %.17Lg\n", broken,
                   static_cast<long double>(t), static_cast<long double>(r));
      for (int i = 0; i < p1.size(); ++i) {
        std::fprintf(stderr, "  p1[%d] = %.17Lg v1[%d] = %.17Lg p2[%d] = %.17Lg v2[%d] = %.17Lg\n", i,
                     static_cast<long double>(p1[i]), i, static_cast<long double>(v1[i]), i,
                     static_cast<long double>(p2[i]), i, static_cast<long double>(v2[i]));
      }
      std::abort();
    }
    ++accepted_inputs;
  } catch (const billiards::invalid_argument& error) {
    ++rejected_by_argument[error.argument()];
  }
}

template <typename Vector>
void exercise(Shaper& shape) {
  using Scalar = typename Vector::Scalar;
  using billiards_fuzz::expected_collision;
  const std::uint8_t call = shape.byte() % 6;
  if (call == 5) return exercise_time_of_impact<Vector>(shape);
  const Scalar m1 = shape.mass<Scalar>(), m2 = shape.mass<Scalar>();
  const Vector v1 = shape.vector<Vector>(), v2 = shape.vector<Vector>();
  ++all_inputs;
  try {
    switch (call) {
      case 0:
      case 1: {  // the elastic call (its own overload) and the call with restitution
        const Vector n = shape.unit<Vector>();
        const bool elastic = call == 0;
        const Scalar e = elastic ? Scalar(1) : shape.restitution<Scalar>();
        const auto result = elastic ? billiards::checked::collide(m1, v1, m2, v2, n)
                                    : billiards::checked::collide(m1, v1, m2, v2, n, e);
        require_finite(result);
        if (elastic) require_momentum(m1, v1, m2, v2, result);
        require_reference(elastic ? "collide" : "collide with restitution", result,
                          expected_collision(m1, v1, m2, v2, n, e, /*unit=*/true));
        break;
      }
      case 2: {
        const Vector d = shape.vector<Vector>();
        const Scalar e = shape.restitution<Scalar>();
        const auto result = billiards::checked::collide_along_direction(m1, v1, m2, v2, d, e);
        require_finite(result);
        require_reference("collide_along_direction", result,
                          expected_collision(m1, v1, m2, v2, d, e, /*unit=*/false));
        break;
      }
      case 3: {
        const Vector p1 = shape.vector<Vector>(), p2 = shape.vector<Vector>();
        const Scalar e = shape.restitution<Scalar>();
        const auto result = billiards::checked::collide_if_approaching(m1, p1, v1, m2, p2, v2, e);
        require_finite(result);
        require_reference("collide_if_approaching", result,
                          billiards_fuzz::expected_if_approaching(m1, p1, v1, m2, p2, v2, e));
        break;
      }
      default: {
        const Vector n = shape.unit<Vector>();
        const Vector x = billiards::checked::reflect(v1, n);
        const billiards::Collision<Vector> result{x, v1};  // v1, validated, beside its reflection
        require_finite(result);
        require_reference("reflect", result, billiards_fuzz::expected_reflection(v1, n, v1));
        break;
      }
    }
    ++accepted_inputs;
  } catch (const billiards::invalid_argument& error) {
    ++rejected_by_argument[error.argument()];
    // Rejected with a clear error: fine. Anything else escaping is a bug and crashes the fuzzer.
  }
}

template <typename Scalar>
[[noreturn]] void fail_spin(const char* call, const char* broken) {
  std::fprintf(stderr, "billiards fuzz: %s: %s\n", call, broken);
  std::abort();
}

template <typename Scalar>
void print_ball(const char* name, const Eigen::Matrix<Scalar, 3, 1>& v, const Eigen::Matrix<Scalar, 3, 1>& w,
                Scalar radius) {
  std::fprintf(stderr, "  %s: v = (%a, %a, %a) w = (%a, %a, %a) R = %a\n", name, double(v.x()), double(v.y()),
               double(v.z()), double(w.x()), double(w.y()), double(w.z()), double(radius));
}

// collide_with_friction: masses and radii over the whole range, spins of any size, μ in [0, 2].
template <typename Scalar>
void exercise_spin(Shaper& shape) {
  using V = Eigen::Matrix<Scalar, 3, 1>;
  const billiards::SpinningBall<Scalar> a{shape.vector<V>(), shape.vector<V>(), shape.mass<Scalar>(),
                                          shape.mass<Scalar>()};
  const billiards::SpinningBall<Scalar> b{shape.vector<V>(), shape.vector<V>(), shape.mass<Scalar>(),
                                          shape.mass<Scalar>()};
  const V n = shape.unit<V>();
  const Scalar e = shape.restitution<Scalar>(), mu = shape.special_or(Scalar(shape.byte()) / Scalar(128));
  ++all_inputs;
  try {
    const auto result = billiards::checked::collide_with_friction(a, b, n, e, mu);
    const billiards_fuzz::ExpectedSpin expected = billiards_fuzz::expected_friction_collision(a, b, n, e, mu);
    const char* broken = billiards_fuzz::compare_spin(result, a, b, expected);
    const billiards_fuzz::Long before =
        billiards_fuzz::twice_energy(a.mass, a.radius, a.velocity, a.angular_velocity) +
        billiards_fuzz::twice_energy(b.mass, b.radius, b.velocity, b.angular_velocity);
    const billiards_fuzz::Long after =
        billiards_fuzz::twice_energy(a.mass, a.radius, result.first.velocity, result.first.angular_velocity) +
        billiards_fuzz::twice_energy(b.mass, b.radius, result.second.velocity,
                                     result.second.angular_velocity);
    const billiards_fuzz::Long underflow =
        billiards_fuzz::subnormal_energy(a.mass, a.radius, a.velocity, a.angular_velocity,
                                         result.first.velocity, result.first.angular_velocity) +
        billiards_fuzz::subnormal_energy(b.mass, b.radius, b.velocity, b.angular_velocity,
                                         result.second.velocity, result.second.angular_velocity);
    if (!broken &&
        !(after <= before * (1 + billiards_fuzz::tolerance * std::numeric_limits<Scalar>::epsilon()) +
                       billiards_fuzz::Long(std::numeric_limits<Scalar>::denorm_min()) * (a.mass + b.mass) +
                       underflow))
      broken = "energy created";
    if (broken) {
      std::fprintf(stderr, "  m1 = %a m2 = %a e = %a mu = %a n = (%a, %a, %a)\n", double(a.mass),
                   double(b.mass), double(e), double(mu), double(n.x()), double(n.y()), double(n.z()));
      print_ball("ball1", a.velocity, a.angular_velocity, a.radius);
      print_ball("ball2", b.velocity, b.angular_velocity, b.radius);
      print_ball("first", result.first.velocity, result.first.angular_velocity, a.radius);
      print_ball("second", result.second.velocity, result.second.angular_velocity, b.radius);
      fail_spin<Scalar>("collide_with_friction", broken);
    }
    ++accepted_inputs;
  } catch (const billiards::invalid_argument& error) {
    ++rejected_by_argument[error.argument()];
  }
}

// A ball on the cloth: motion, transition_time and evolve; radius and gravity within 2^±(E/4), friction
// coefficients 0 or in [1/128, 2], velocities and spins of any size.
template <typename Scalar>
void exercise_cloth(Shaper& shape) {
  using V = Eigen::Matrix<Scalar, 3, 1>;
  const Scalar radius = shape.moderate<Scalar>();
  V position = shape.vector<V>(), velocity = shape.vector<V>();
  position.z() = shape.special_or(radius);  // on the table, now and then not
  velocity.z() = shape.special_or(Scalar(0));
  // Now and then rolling: ω_h = ẑ × v/R (to rounding).
  V spin = shape.vector<V>();
  if (shape.byte() % 4 == 0) {
    spin.x() = -velocity.y() / radius;
    spin.y() = velocity.x() / radius;
  }
  const billiards::BallOnCloth<Scalar> ball{position, velocity, spin, radius};
  const auto friction = [&] {
    const std::uint8_t level = shape.byte();
    return shape.invalid_or(level == 0 ? Scalar(0) : Scalar(level) / Scalar(128));
  };
  const billiards::Cloth<Scalar> cloth{friction(), friction(), friction(), shape.moderate<Scalar>()};
  const Scalar t = shape.special_or(std::fabs(shape.component<Scalar>()));
  ++all_inputs;
  try {
    const billiards::Motion phase = billiards::checked::motion(ball, cloth);
    const Scalar until = billiards::checked::transition_time(ball, cloth);
    if (std::isnan(until) || until < 0)
      fail_spin<Scalar>("transition_time", "a time that is NaN or negative");
    if (phase == billiards::Motion::stationary && !std::isinf(until))
      fail_spin<Scalar>("transition_time", "a finite time for a stationary ball");
    const billiards::BallOnCloth<Scalar> later = billiards::checked::evolve(ball, cloth, t);
    const char* broken = nullptr;
    if (!later.position.allFinite() || !later.velocity.allFinite() || !later.angular_velocity.allFinite())
      broken = "a state that is not finite";
    else if (later.position.z() != ball.position.z() || later.radius != ball.radius)
      broken = "the ball left the table";
    const billiards_fuzz::Long before = billiards_fuzz::twice_energy(1, radius, ball.velocity,
                                                                     ball.angular_velocity),
                               after = billiards_fuzz::twice_energy(1, radius, later.velocity,
                                                                    later.angular_velocity);
    if (!broken &&
        !(after <= before * (1 + billiards_fuzz::tolerance * std::numeric_limits<Scalar>::epsilon()) +
                       billiards_fuzz::Long(std::numeric_limits<Scalar>::denorm_min()) +
                       billiards_fuzz::subnormal_energy(1, radius, ball.velocity, ball.angular_velocity,
                                                        later.velocity, later.angular_velocity)))
      broken = "energy created";
    const billiards_fuzz::ExpectedCloth expected = billiards_fuzz::expected_on_cloth(ball, cloth, t);
    if (!broken && expected.known) {
      const auto off = [](const V& x, const billiards_fuzz::Long3& reference) {
        return (x.template cast<billiards_fuzz::Long>() - reference).norm();
      };
      if (!(off(later.position, expected.position) <= expected.position_bound))
        broken = "a position farther from the phase's closed form than rounding allows";
      else if (!(off(later.velocity, expected.velocity) <= expected.velocity_bound))
        broken = "a velocity farther from the phase's closed form than rounding allows";
      else if (!(off(later.angular_velocity, expected.angular_velocity) <= expected.angular_bound))
        broken = "an angular velocity farther from the phase's closed form than rounding allows";
    }
    if (broken) {
      std::fprintf(stderr, "  t = %a cloth = (%a, %a, %a, g %a), position = (%a, %a, %a)\n", double(t),
                   double(cloth.sliding_friction), double(cloth.rolling_friction),
                   double(cloth.spinning_friction), double(cloth.gravity), double(position.x()),
                   double(position.y()), double(position.z()));
      print_ball("ball", ball.velocity, ball.angular_velocity, radius);
      print_ball("later", later.velocity, later.angular_velocity, radius);
      fail_spin<Scalar>("evolve", broken);
    }
    ++accepted_inputs;
  } catch (const billiards::invalid_argument& error) {
    ++rejected_by_argument[error.argument()];
  }
}

// strike: the ball in any state, the cue with any of its fields now and then invalid; held to the
// impulse equations solved in long double (J from the tip's restitution along d), each component within
// 64 ε of the speeds involved (the spin's over R), plus 64 times the smallest normal number where a
// component falls below the normal range.
template <typename Scalar>
void exercise_strike(Shaper& shape) {
  using V = Eigen::Matrix<Scalar, 3, 1>;
  using Long = long double;
  using L3 = Eigen::Matrix<Long, 3, 1>;
  const Scalar radius = shape.moderate<Scalar>(), mass = shape.moderate<Scalar>();
  const billiards::SpinningBall<Scalar> ball{shape.vector<V>(), shape.vector<V>(), mass, radius};
  const auto offset = [&] { return shape.special_or(Scalar(int(shape.byte()) - 128) / Scalar(181)); };
  const billiards::Cue<Scalar> cue{shape.moderate<Scalar>(), shape.special_or(std::fabs(shape.component<Scalar>())),
                                   shape.special_or(Scalar(shape.byte()) / Scalar(40)),
                                   shape.special_or(Scalar(shape.byte()) / Scalar(170)), offset(), offset(),
                                   shape.special_or(Scalar(shape.byte()) / Scalar(255))};
  ++all_inputs;
  try {
    const billiards::SpinningBall<Scalar> struck = billiards::checked::strike(ball, cue);
    const Long phi = cue.azimuth, theta = cue.elevation, a = cue.side_offset, b = cue.up_offset;
    const L3 d(std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), -std::sin(theta));
    const L3 s(std::sin(phi), -std::cos(phi), 0), u = s.cross(d);
    const Long m = mass, R = radius, M = cue.mass, inertia = Long(2) / 5 * m * R * R;
    const L3 r = R * (a * s + b * u - std::sqrt(std::max(Long(0), 1 - a * a - b * b)) * d);
    const L3 v = ball.velocity.template cast<Long>(), w = ball.angular_velocity.template cast<Long>();
    const Long approach = Long(cue.speed) - (v + w.cross(r)).dot(d);
    L3 v_after = v, w_after = w;
    Long J = 0;
    if (approach > 0) {
      J = (1 + Long(cue.tip_restitution)) * approach / (1 / m + 1 / M + r.cross(d).squaredNorm() / inertia);
      v_after = v + J / m * d;
      w_after = w + r.cross(J * d) / inertia;
    }
    const Long speeds = Long(cue.speed) + v.norm() + R * w.norm() + (v_after - v).norm();
    const Long bound = 64 * Long(std::numeric_limits<Scalar>::epsilon()) * speeds + 64 * Long(std::numeric_limits<Scalar>::min());
    const char* broken = nullptr;
    if (!struck.velocity.allFinite() || !struck.angular_velocity.allFinite()) broken = "a state that is not finite";
    else if (!((struck.velocity.template cast<Long>() - v_after).norm() <= bound))
      broken = "a velocity farther from the impulse equations than rounding allows";
    // The spin's own underflow: its components are rounded below the normal range on their own scale.
    else if (!((struck.angular_velocity.template cast<Long>() - w_after).norm() <=
               bound / R + 64 * Long(std::numeric_limits<Scalar>::min())))
      broken = "a spin farther from the impulse equations than rounding allows";
    if (broken) {
      std::fprintf(stderr, "  cue = (M %a, V %a, phi %a, theta %a, a %a, b %a, e %a)\n", double(cue.mass),
                   double(cue.speed), double(cue.azimuth), double(cue.elevation), double(cue.side_offset),
                   double(cue.up_offset), double(cue.tip_restitution));
      print_ball("ball", ball.velocity, ball.angular_velocity, radius);
      print_ball("struck", struck.velocity, struck.angular_velocity, radius);
      fail_spin<Scalar>("strike", broken);
    }
    ++accepted_inputs;
  } catch (const billiards::invalid_argument& error) {
    ++rejected_by_argument[error.argument()];
  }
}

// earliest_contact on polynomials of degree up to 4 with coefficients of any sign over 2^±32 and the
// edge values, held in long double: the time within [0, horizon]; t = 0 only for bodies that touch and
// approach; no overlap beyond rounding at the time reported; and no clear entry into overlap before it
// (or anywhere, when none is reported) on a grid of 256 points. "Beyond rounding" is beyond 16 ε Σ |c_k| t^k
// and, at the time reported, the change of p over one spacing of the type's numbers there.
template <typename Scalar>
void exercise_events(Shaper& shape) {
  std::array<Scalar, 5> c{};
  const int degree = shape.byte() % 5;
  for (int k = 0; k <= degree; ++k) c[static_cast<std::size_t>(k)] = shape.byte() % 4 == 0 ? Scalar(0) : shape.component<Scalar>();
  const Scalar horizon = shape.special_or(std::fabs(shape.component<Scalar>()));
  ++all_inputs;
  try {
    const std::optional<Scalar> found = billiards::checked::earliest_contact(c, horizon);
    using Long = long double;
    const auto value = [&](Long t) {
      Long r = 0;
      for (int k = 4; k >= 0; --k) r = r * t + Long(c[static_cast<std::size_t>(k)]);
      return r;
    };
    const auto rounding = [&](Long t) {
      Long r = 0;
      for (int k = 4; k >= 0; --k) r = r * t + std::fabs(Long(c[static_cast<std::size_t>(k)]));
      return 16 * Long(std::numeric_limits<Scalar>::epsilon()) * r + 16 * Long(std::numeric_limits<Scalar>::denorm_min());
    };
    // The time itself is a Scalar: the contact may lie between two of them, a spacing apart, over which
    // p changes by up to |p'| times it.
    const auto steepness = [&](Long t) {
      Long r = 0;
      for (int k = 4; k >= 1; --k) r = r * t + k * std::fabs(Long(c[static_cast<std::size_t>(k)]));
      return r;
    };
    const auto spacing = [](Scalar t) {
      return Long(std::max(std::numeric_limits<Scalar>::denorm_min(), std::numeric_limits<Scalar>::epsilon() * t));
    };
    const auto fail = [&](const char* broken) {
      std::fprintf(stderr, "  c = (%a, %a, %a, %a, %a), horizon = %a, found = %a\n", double(c[0]), double(c[1]),
                   double(c[2]), double(c[3]), double(c[4]), double(horizon), found ? double(*found) : -1.0);
      fail_spin<Scalar>("earliest_contact", broken);
    };
    if (found) {
      const Scalar t = *found;
      if (!(t >= 0 && t <= horizon)) fail("a time outside [0, horizon]");
      if (t == 0) {
        int first = 1;
        while (first <= 4 && c[static_cast<std::size_t>(first)] == 0) ++first;
        if (!(c[0] <= 0 && first <= 4 && c[static_cast<std::size_t>(first)] < 0))
          fail("a contact at t = 0 for bodies apart or not approaching");
      } else if (value(t) < -rounding(t) - steepness(t) * spacing(t)) {
        fail("a time at which the bodies overlap beyond rounding");
      }
    }
    // A clear entry: apart beyond rounding at one grid point, overlapping beyond it at a later one.
    const Long end = found ? Long(*found) : Long(horizon);
    bool apart = c[0] > 0 && Long(c[0]) > rounding(0);
    for (int i = 1; i <= 256 && end > 0; ++i) {
      const Long s = end * i / 256;
      if (found && i == 256) break;  // the reported time itself
      const Long v = value(s);
      if (v > rounding(s)) apart = true;
      if (apart && v < -rounding(s))
        fail("an entry into overlap before the time reported (a missed contact)");
    }
    ++accepted_inputs;
  } catch (const billiards::invalid_argument& error) {
    ++rejected_by_argument[error.argument()];
  }
}

// collide_with_cushion: the ball in any state (on the cloth, now and then not), the cushion's normal at
// any angle in the table's plane (now and then any vector), its nose at [R, 2R) and its coefficients now
// and then invalid; held to Han (2005)'s eqs 14–23 with μ in long double (han_2005.hpp), each part within
// 64 ε of the speeds involved, and to no energy created beyond rounding.
template <typename Scalar>
void exercise_cushion(Shaper& shape) {
  using V = Eigen::Matrix<Scalar, 3, 1>;
  using Long = long double;
  using L3 = Eigen::Matrix<Long, 3, 1>;
  const Scalar radius = shape.moderate<Scalar>(), mass = shape.moderate<Scalar>();
  V velocity = shape.vector<V>();
  velocity.z() = shape.special_or(Scalar(0));
  const billiards::SpinningBall<Scalar> ball{velocity, shape.vector<V>(), mass, radius};
  const Scalar psi = Scalar(shape.byte()) / Scalar(40);
  V normal(std::cos(psi), std::sin(psi), 0);
  if (shape.byte() % 16 == 0) normal = shape.vector<V>();
  const billiards::Cushion<Scalar> cushion{normal, shape.special_or(radius * (1 + Scalar(shape.byte()) / Scalar(256))),
                                           shape.special_or(Scalar(shape.byte()) / Scalar(255)),
                                           shape.special_or(Scalar(shape.byte()) / Scalar(64))};
  ++all_inputs;
  try {
    const billiards::SpinningBall<Scalar> after = billiards::checked::collide_with_cushion(ball, cushion);
    const billiards::SpinningBall<Long> expected = billiards_fuzz::han_2005(ball, cushion);
    const Long R = radius;
    const L3 v = ball.velocity.template cast<Long>(), w = ball.angular_velocity.template cast<Long>();
    const Long speeds = v.norm() + R * w.norm();
    const Long bound = 64 * Long(std::numeric_limits<Scalar>::epsilon()) * speeds + 64 * Long(std::numeric_limits<Scalar>::min());
    const auto energy = [&](const auto& b) {
      return b.velocity.template cast<Long>().squaredNorm() + Long(2) / 5 * R * R * b.angular_velocity.template cast<Long>().squaredNorm();
    };
    // Where the normal impulse per unit mass, (1 + e_c) v_n cos θ_a, falls below the normal range it
    // loses its digits, and with it the friction μ_c times it allows (μ_c up to the largest finite
    // number): held to finiteness and energy only.
    const Long nose_sin = Long(cushion.height) / R - 1;
    const Long normal_impulse = (1 + Long(cushion.restitution)) * Long(ball.velocity.dot(normal)) *
                                std::sqrt(std::max(Long(0), 1 - nose_sin * nose_sin));
    const bool impulse_normal = std::fabs(normal_impulse) >= Long(std::numeric_limits<Scalar>::min());
    const char* broken = nullptr;
    if (!after.velocity.allFinite() || !after.angular_velocity.allFinite()) broken = "a state that is not finite";
    else if (impulse_normal && !((after.velocity.template cast<Long>() - expected.velocity).norm() <= bound))
      broken = "a velocity farther from Han (2005) than rounding allows";
    else if (impulse_normal && !((after.angular_velocity.template cast<Long>() - expected.angular_velocity).norm() <=
                                 bound / R + 64 * Long(std::numeric_limits<Scalar>::min())))
      broken = "a spin farther from Han (2005) than rounding allows";
    else if (!(energy(after) <= energy(ball) * (1 + 64 * Long(std::numeric_limits<Scalar>::epsilon())) +
                                    64 * Long(std::numeric_limits<Scalar>::min())))
      broken = "energy created";
    if (broken) {
      std::fprintf(stderr, "  cushion = (n %a %a %a, h %a, e %a, mu %a)\n", double(normal.x()), double(normal.y()),
                   double(normal.z()), double(cushion.height), double(cushion.restitution), double(cushion.friction));
      print_ball("ball", ball.velocity, ball.angular_velocity, radius);
      print_ball("after", after.velocity, after.angular_velocity, radius);
      fail_spin<Scalar>("collide_with_cushion", broken);
    }
    ++accepted_inputs;
  } catch (const billiards::invalid_argument& error) {
    ++rejected_by_argument[error.argument()];
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Shaper shape(data, size);
  switch (shape.byte() % 14) {
    case 0: exercise<Eigen::Vector3d>(shape); break;
    case 1: exercise<Eigen::Vector2d>(shape); break;
    case 2: exercise<Eigen::Vector3f>(shape); break;
    case 3: exercise<Eigen::Vector2f>(shape); break;
    case 4: exercise_spin<double>(shape); break;
    case 5: exercise_spin<float>(shape); break;
    case 6: exercise_cloth<double>(shape); break;
    case 7: exercise_cloth<float>(shape); break;
    case 8: exercise_events<double>(shape); break;
    case 9: exercise_events<float>(shape); break;
    case 10: exercise_strike<double>(shape); break;
    case 11: exercise_strike<float>(shape); break;
    case 12: exercise_cushion<double>(shape); break;
    default: exercise_cushion<float>(shape); break;
  }
  return 0;
}
