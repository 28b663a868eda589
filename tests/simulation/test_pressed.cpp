// Pressed contacts against an independent reference: shots whose balls move on one line (a cue ball with
// follow into a frozen pair, a rolling ball pushing the ball it met, a ball with topspin pressed into a
// cushion), played by the engine and by a fine time-stepped integration of the same model written here
// from its equations — each ball's slide and roll on the cloth in closed form over a step of dt, then the
// contact laws' impulses (the paper's normal impulse with restitution, Coulomb friction at the contact
// with the vertical velocity dropped, the cushion's nose above the equator) wherever bodies touch and
// approach. Pressed bodies meet again at every step there, so the integration reaches the contact force
// as dt → 0 by the impulses themselves, not by the engine's equations of sustained contact.
#include <billiards/simulation/shot.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

using billiards::simulation::PoolBall;
using billiards::simulation::PoolPhysics;
using billiards::simulation::PoolTable;
using billiards::simulation::Shot;
using billiards::simulation::ShotOptions;

namespace {

// A ball on the line y = const: its centre x, velocity v and spin W = R ω_y (m/s; ω about ŷ = ẑ × x̂,
// so that W = v rolls).
struct LineBall {
  double x, v, W;
};

// The time-stepped reference on a line between the head cushion's nose (x = 0) and the foot's (x = L).
class LineReference {
 public:
  LineReference(const PoolPhysics& p, double length, double nose_height) : p_(p), length_(length) {
    sin_nose_ = nose_height / p.radius - 1;
    cos_nose_ = std::sqrt(1 - sin_nose_ * sin_nose_);
  }

  // Plays `balls` (in order along x) with step `dt` until every ball rests; returns the time it took.
  double play(std::vector<LineBall>& balls, double dt) const {
    double t = 0;
    while (t < 60 && std::any_of(balls.begin(), balls.end(), [](const LineBall& b) { return b.v != 0 || b.W != 0; })) {
      for (LineBall& b : balls) free_flight(b, dt);
      t += dt;
      for (std::size_t k = 0; k + 1 < balls.size(); ++k) {
        if (balls[k + 1].x - balls[k].x <= 2 * p_.radius && balls[k].v > balls[k + 1].v)
          between_balls(balls[k], balls[k + 1]);
      }
      if (balls.front().x <= p_.radius && balls.front().v < 0) mirrored_cushion(balls.front());
      if (balls.back().x >= length_ - p_.radius && balls.back().v > 0) cushion(balls.back());
    }
    return t;
  }

 private:
  // The slide (u = v − W ≠ 0: v̇ = −μ_s g sgn u, Ẇ = (5/2) μ_s g sgn u) and the roll (v̇ = Ẇ = −μ_r g
  // sgn v) over `dt`, each in closed form up to its end.
  void free_flight(LineBall& b, double dt) const {
    const double g = p_.cloth.gravity, slide = p_.cloth.sliding_friction * g, roll = p_.cloth.rolling_friction * g;
    double left = dt;
    while (left > 0) {
      const double u = b.v - b.W;
      if (u != 0) {
        const double s = u > 0 ? 1 : -1, end = std::fabs(u) / (3.5 * slide), tau = std::min(left, end);
        b.x += b.v * tau - 0.5 * slide * s * tau * tau;
        b.v -= slide * s * tau;
        b.W += 2.5 * slide * s * tau;
        if (tau == end) b.W = b.v;
        left -= tau;
      } else if (b.v != 0) {
        const double s = b.v > 0 ? 1 : -1, end = std::fabs(b.v) / roll, tau = std::min(left, end);
        b.x += b.v * tau - 0.5 * roll * s * tau * tau;
        b.v -= roll * s * tau;
        b.W = b.v;
        if (tau == end) b.v = b.W = 0;
        left -= tau;
      } else {
        return;
      }
    }
  }

  // Two equal balls, a behind b, meeting: the normal impulse (1 + e)/2 of the approach per unit mass,
  // then friction against the vertical slip σ = W_a + W_b of their contact points, μ times the normal
  // impulse or what stops the slip (σ/7: each ball's vertical velocity and spin change with it), the
  // vertical velocities dropped.
  void between_balls(LineBall& a, LineBall& b) const {
    const double J = 0.5 * (1 + p_.ball_restitution) * (a.v - b.v);
    a.v -= J;
    b.v += J;
    const double sigma = a.W + b.W;
    if (sigma == 0) return;
    const double j = std::min(p_.ball_friction * J, std::fabs(sigma) / 7) * (sigma > 0 ? 1 : -1);
    a.W -= 2.5 * j;
    b.W -= 2.5 * j;
  }

  // A ball meeting the foot cushion (moving in +x): the nose θ above the equator; p = (1 + e_c) v cos θ,
  // the slip down the nose s = v sin θ + W, friction k = 2/7 (sticking) or μ_c p/|s|; Δv = −p cos θ −
  // k s sin θ, ΔW = −(5/2) k s.
  void cushion(LineBall& b) const {
    const double p = (1 + p_.cushion_restitution) * b.v * cos_nose_, s = b.v * sin_nose_ + b.W;
    const double k = 2 * std::fabs(s) <= 7 * p_.cushion_friction * p ? 2.0 / 7.0 : p_.cushion_friction * p / std::fabs(s);
    b.v += -p * cos_nose_ - k * s * sin_nose_;
    b.W += -2.5 * k * s;
  }
  // The head cushion: the foot's law in the mirrored line (x → −x, which turns v and W over).
  void mirrored_cushion(LineBall& b) const {
    LineBall m{-b.x, -b.v, -b.W};
    cushion(m);
    b.v = -m.v;
    b.W = -m.W;
  }

  PoolPhysics p_;
  double length_, sin_nose_, cos_nose_;
};

struct Played {
  std::vector<double> x;
  double rest = 0;
  std::size_t events = 0;
};

// The engine's shot from `line` (at height y, every ball on the line), played to rest.
Played engine(const PoolTable& table, const PoolPhysics& physics, const std::vector<LineBall>& line, double y,
              double pressing_speed) {
  std::vector<PoolBall> balls;
  for (const LineBall& b : line) {
    PoolBall ball;
    ball.position = {b.x, y, physics.radius};
    ball.velocity = {b.v, 0, 0};
    ball.angular_velocity = {0, b.W / physics.radius, 0};
    balls.push_back(ball);
  }
  ShotOptions options;
  options.check_invariants = true;
  options.pressing_speed = pressing_speed;
  options.event_limit = 100000;
  Shot shot(table, physics, balls, options);
  Played out;
  out.events = shot.play();
  out.rest = shot.time();
  for (const PoolBall& b : shot.balls()) {
    out.x.push_back(b.position.x());
    CHECK(b.position.y() == y);
  }
  return out;
}

double farthest(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, std::fabs(a[k] - b[k]));
  return d;
}

void compare_with_reference(const std::vector<LineBall>& start, double tolerance) {
  const PoolTable table = billiards::simulation::pool_table("7ft");
  const PoolPhysics physics;
  const LineReference reference(physics, table.length, table.nose_height);
  const auto integrate = [&](double dt, double& rest) {
    std::vector<LineBall> balls = start;
    rest = reference.play(balls, dt);
    std::vector<double> x;
    for (const LineBall& b : balls) x.push_back(b.x);
    return x;
  };
  double rest_coarse = 0, rest_fine = 0;
  const std::vector<double> coarse = integrate(4e-6, rest_coarse), fine = integrate(1e-6, rest_fine);
  const Played played = engine(table, physics, start, 0.5, ShotOptions{}.pressing_speed);
  INFO("reference at dt = 4e-6 and 1e-6 s apart by " << farthest(coarse, fine) << " m; the engine ("
       << played.events << " events) from the finer by " << farthest(played.x, fine) << " m; at rest at "
       << played.rest << " s against " << rest_fine << " s");
  CHECK(farthest(coarse, fine) < tolerance);         // the reference has converged
  CHECK(farthest(played.x, fine) < tolerance);       // and the engine lies on its limit
  CHECK(std::fabs(played.rest - rest_fine) < 2e-4);  // s
  CHECK(played.events < 1000);
  WARN("reference at dt = 4e-6 and 1e-6 s apart by " << farthest(coarse, fine) << " m; the engine ("
       << played.events << " events) from the finer by " << farthest(played.x, fine) << " m; at rest at "
       << played.rest << " s against " << rest_fine << " s");
}

}  // namespace

TEST_CASE("Pressed: a cue ball with follow pressing a frozen pair ends where the time-stepped model does",
          "[simulation][shot][pressed]") {
  const double R = PoolPhysics{}.radius;
  compare_with_reference({{0.6, 2.0, 2.5}, {1.0, 0, 0}, {1.0 + 2 * R, 0, 0}}, 5e-5);
}

TEST_CASE("Pressed: a rolling ball pushing a sliding ball in front ends where the time-stepped model does",
          "[simulation][shot][pressed]") {
  const double R = PoolPhysics{}.radius;
  compare_with_reference({{0.6, 0.5, 0.5}, {0.6 + 2 * R, 0.5, 0}}, 5e-5);
}

TEST_CASE("Pressed: a ball with topspin pressed into a cushion rests when the time-stepped model does",
          "[simulation][shot][pressed]") {
  const double R = PoolPhysics{}.radius;
  compare_with_reference({{billiards::simulation::pool_table("7ft").length - R - 1e-3, 0.05, 3.0}}, 5e-5);
}

TEST_CASE("Pressed: the pressed-pair shot converges as the pressing speed shrinks, in boundedly many events",
          "[simulation][shot][pressed]") {
  const PoolTable table = billiards::simulation::pool_table("7ft");
  const PoolPhysics physics;
  const double R = physics.radius;
  const std::vector<LineBall> start{{0.6, 2.0, 2.5}, {1.0, 0, 0}, {1.0 + 2 * R, 0, 0}};
  const Played coarse = engine(table, physics, start, 0.5, 1e-3), middle = engine(table, physics, start, 0.5, 1e-5),
               fine = engine(table, physics, start, 0.5, 1e-7);
  INFO("events " << coarse.events << ", " << middle.events << ", " << fine.events << "; apart by "
                 << farthest(coarse.x, middle.x) << " and " << farthest(middle.x, fine.x) << " m");
  CHECK(farthest(middle.x, fine.x) < farthest(coarse.x, middle.x));
  CHECK(farthest(coarse.x, fine.x) < 5e-4);  // the default within 0.5 mm of the limit
  // Each tenfold smaller tolerance resolves more of an inelastic collapse's bounces (e^k of the approach:
  // ln 10/ln(1/e) of them), not tenfold the events.
  CHECK(fine.events < coarse.events + 4 * 120);
}

TEST_CASE("Pressed: random shots on one line end, keeping every invariant", "[simulation][shot][pressed]") {
  // Two to four balls on a line, with random speeds and follow or draw (some touching at the start): the
  // pressed pieces' modes (sliding, rolling, sticking between the balls), their ends and releases, with
  // every invariant checked at every event and a bounded number of events.
  const PoolTable table = billiards::simulation::pool_table("7ft");
  const PoolPhysics physics;
  const double R = physics.radius;
  std::mt19937_64 random(55);
  std::uniform_real_distribution<double> unit(0, 1);
  std::size_t touching_at_rest = 0, most_events = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<PoolBall> balls;
    double x = 0.2 + 0.3 * unit(random);
    const int count = 2 + trial % 3;
    for (int k = 0; k < count; ++k) {
      PoolBall b;
      b.position = {x, 0.5, R};
      b.velocity = {4 * unit(random) - 2, 0, 0};
      // The first ball (behind) mostly with follow beyond rolling: it presses those it meets.
      const double spin = k == 0 && trial % 2 == 0 ? b.velocity.x() + 4 * unit(random) : 8 * unit(random) - 4;
      b.angular_velocity = {0, spin / R, 0};
      balls.push_back(b);
      x += 2 * R + (unit(random) < 0.5 ? 0.0 : 0.2 * unit(random));
    }
    ShotOptions options;
    options.check_invariants = true;
    options.event_limit = 20000;
    Shot shot(table, physics, balls, options);
    INFO("trial " << trial);
    REQUIRE_NOTHROW(shot.play());
    const std::vector<PoolBall> end = shot.balls();
    for (const PoolBall& b : end) CHECK(b.position.y() == 0.5);
    for (std::size_t k = 0; k + 1 < end.size(); ++k) {
      if (!end[k].pocketed && !end[k + 1].pocketed &&
          std::fabs(std::fabs(end[k + 1].position.x() - end[k].position.x()) - 2 * R) < 1e-9) {
        ++touching_at_rest;
        break;
      }
    }
    most_events = std::max<std::size_t>(most_events, shot.event_count());
  }
  INFO("shots ending with two balls touching: " << touching_at_rest << "; the most events " << most_events);
  CHECK(touching_at_rest > 0);  // pressed pairs that rolled to rest together
  CHECK(most_events < 2000);
}
