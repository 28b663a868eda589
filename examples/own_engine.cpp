// Using the derived kernels from an engine of your own: its own 3-vector type, no Eigen, no runtime
// wrapper. The kernels (billiards/kernels.hpp, billiards/spin_kernels.hpp) take masses and dot
// products, so an engine computes the few dot products in its own types and applies the returned
// changes along its own normal. The guide is docs/own_engine.md.
//
// The program collides two balls, reflects one off a cushion, finds a time of impact and a friction
// impulse, and checks each against the textbook formula written out here by hand. Exit status 0 when
// every check holds, 1 otherwise.
#include <billiards/kernels.hpp>
#include <billiards/spin_kernels.hpp>

#include <cmath>
#include <cstdio>

namespace engine {

// An engine's own vector: three doubles and the operators it needs.
struct Vec3 {
  double x, y, z;
};
constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
constexpr double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

struct Body {
  Vec3 position, velocity;
  double mass, radius;
};

// A collision with restitution e along the unit normal n (from a to b): the kernel gives the change of
// each velocity's component along n; the engine applies it along its own n.
void collide(Body& a, Body& b, Vec3 n, double restitution) {
  const auto change = billiards::kernels::normal_velocity_change(a.mass, b.mass, dot(a.velocity, n),
                                                                 dot(b.velocity, n), restitution);
  a.velocity = a.velocity + change.first * n;
  b.velocity = b.velocity + change.second * n;
}

// The time until two moving balls touch (+∞ when they never do): the kernel takes p·p, p·w, w·w and
// |p × w|² of the relative position p and velocity w.
double time_of_impact(const Body& a, const Body& b) {
  const Vec3 p = b.position - a.position, w = b.velocity - a.velocity;
  const Vec3 c = cross(p, w);
  return billiards::kernels::time_of_impact(dot(p, p), dot(p, w), dot(w, w), dot(c, c), a.radius + b.radius);
}

}  // namespace engine

namespace {

int failures = 0;

void expect_near(const char* what, double got, double expected) {
  const bool ok = std::fabs(got - expected) <= 1e-12 * (1 + std::fabs(expected));
  std::printf("%-58s %.15g (by hand %.15g) %s\n", what, got, expected, ok ? "ok" : "MISMATCH");
  if (!ok) ++failures;
}

}  // namespace

int main() {
  using engine::Body;
  using engine::Vec3;

  // Two balls meeting head-on along x, masses 1 and 3, e = 0.9.
  Body a{{0, 0, 0}, {2, 0.5, 0}, 1.0, 0.5};
  Body b{{1, 0, 0}, {-1, 0, 0}, 3.0, 0.5};
  const Vec3 n{1, 0, 0};
  const double e = 0.9, m1 = a.mass, m2 = b.mass;
  const double u1 = dot(a.velocity, n), u2 = dot(b.velocity, n);
  // By hand: x1·n = u1 + (1 + e) m2 (u2 − u1)/(m1 + m2), and likewise for ball 2.
  const double x1 = u1 + (1 + e) * m2 * (u2 - u1) / (m1 + m2);
  const double x2 = u2 - (1 + e) * m1 * (u2 - u1) / (m1 + m2);
  const double momentum_before = m1 * u1 + m2 * u2;
  engine::collide(a, b, n, e);
  expect_near("collision: ball 1's normal velocity", a.velocity.x, x1);
  expect_near("collision: ball 2's normal velocity", b.velocity.x, x2);
  expect_near("collision: ball 1's tangential velocity, unchanged", a.velocity.y, 0.5);
  expect_near("collision: momentum along n", m1 * a.velocity.x + m2 * b.velocity.x, momentum_before);

  // A cushion: the change of the normal component is −2 v·n (the paper's reflection).
  const Vec3 v{3, -4, 0}, wall{0, 1, 0};
  const Vec3 reflected = v + billiards::kernels::cushion_normal_velocity_change(dot(v, wall)) * wall;
  expect_near("cushion: the normal component reversed", reflected.y, 4);
  expect_near("cushion: the tangential component kept", reflected.x, 3);

  // A time of impact: centres 10 apart along x closing at 4, contact distance 1: t = (10 − 1)/4.
  const Body c{{0, 0, 0}, {3, 0, 0}, 1.0, 0.5}, d{{10, 0, 0}, {-1, 0, 0}, 1.0, 0.5};
  expect_near("time of impact, head-on", engine::time_of_impact(c, d), 9.0 / 4.0);
  // Offset by 0.6 across the line: they touch where |p + w t| = 1, t = (10 − 0.8)/4.
  const Body f{{10, 0.6, 0}, {-1, 0, 0}, 1.0, 0.5};
  expect_near("time of impact, offset 0.6", engine::time_of_impact(c, f), (10 - std::sqrt(1 - 0.36)) / 4);
  const Body g{{10, 1.5, 0}, {-1, 0, 0}, 1.0, 0.5};
  const double miss = engine::time_of_impact(c, g);
  std::printf("%-58s %g %s\n", "time of impact, a miss: +inf", miss, std::isinf(miss) ? "ok" : "MISMATCH");
  if (!std::isinf(miss)) ++failures;

  // Ball-ball friction: the tangential impulse is min(μ J_n, |u_t|/k), k = (7/2)(1/m1 + 1/m2) for two
  // solid spheres (the spinning-ball model's kernels).
  const double k = billiards::kernels::spin::tangential_inverse_effective_mass(1.0, 3.0);
  expect_near("friction: k for masses 1 and 3", k, 3.5 * (1 + 1.0 / 3));
  // Approaching at (v2 − v1)·n = −2 with e = 1: J_n = (1 + e) m1 m2/(m1 + m2) · 2 = 3.
  const double jn = billiards::kernels::spin::normal_impulse(1.0, 3.0, 1.0, -2.0);
  expect_near("friction: J_n = (1 + e) m1 m2/(m1 + m2) |s|", jn, 2 * 0.75 * 2);
  expect_near("friction: sliding, J_t = mu J_n", billiards::kernels::spin::friction_impulse(0.06, jn, 5.0, k),
              0.06 * jn);
  expect_near("friction: sticking, J_t = |u_t|/k",
              billiards::kernels::spin::friction_impulse(0.5, jn, 0.1, k), 0.1 / k);

  std::printf("%s\n", failures == 0 ? "every kernel agrees with the formula by hand" : "MISMATCHES");
  return failures == 0 ? 0 : 1;
}
