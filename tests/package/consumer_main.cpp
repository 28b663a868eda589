// A user's program, written from the README: collide two balls and bounce one off a cushion; throw an
// object ball with a stun shot and let a stun shot roll on the cloth.
#include <billiards/cloth.hpp>
#include <billiards/collision.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>

int main() {
  // Equal masses, the first at rest, hit head-on: the first takes all the velocity, the second stops.
  const Eigen::Vector3d n(1, 0, 0);
  const Eigen::Vector3d v1 = Eigen::Vector3d::Zero(), v2(2, 0, 0);
  const auto [x1, x2] = billiards::collide(1.0, v1, 1.0, v2, n);
  // The cushion: v − 2(v·n)n.
  const Eigen::Vector2f w = billiards::reflect(Eigen::Vector2f(1, -1), Eigen::Vector2f(0, 1));
  bool ok = x1 == v2 && x2.isZero(0) && w == Eigen::Vector2f(1, 1);
  // A half-ball stun shot (30° cut) with ball-ball friction 0.06 throws the object ball by
  // atan(min(0.06, tan 30°/7)) = atan(0.06) = 3.43°: it slides throughout.
  const double phi = std::acos(-1.0) / 6;
  const billiards::SpinningBall<double> cue{{2, 0, 0}, {0, 0, 0}, 0.17, 0.028575};
  const billiards::SpinningBall<double> object{{0, 0, 0}, {0, 0, 0}, 0.17, 0.028575};
  const auto [a, b] = billiards::collide_with_friction(
      cue, object, Eigen::Vector3d(std::cos(phi), std::sin(phi), 0), 1.0, 0.06);
  const double thrown = phi - std::atan2(b.velocity.y(), b.velocity.x());
  ok = ok && std::fabs(thrown - std::atan(std::min(0.06, std::tan(phi) / 7))) < 1e-12 &&
       a.velocity.norm() < cue.velocity.norm();
  // A stun shot on the cloth rolls on at 5/7 of its speed.
  const billiards::Cloth<double> cloth{0.2, 0.01, 0.044};
  const billiards::BallOnCloth<double> ball{{0, 0, 0.028575}, {2, 0, 0}, {0, 0, 0}, 0.028575};
  const billiards::BallOnCloth<double> later =
      billiards::evolve(ball, cloth, billiards::transition_time(ball, cloth));
  ok = ok && billiards::motion(later, cloth) == billiards::Motion::rolling &&
       std::fabs(later.velocity.x() - 10.0 / 7) < 1e-12;
  std::printf("billiards %s: %s\n", BILLIARDS_VERSION, ok ? "the paper's answers" : "WRONG");
  return ok ? 0 : 1;
}
