// A user's program, written from the README: collide two balls and bounce one off a cushion.
#include <billiards/collision.hpp>

#include <Eigen/Core>

#include <cstdio>

int main() {
  // Equal masses, the first at rest, hit head-on: the first takes all the velocity, the second stops.
  const Eigen::Vector3d n(1, 0, 0);
  const Eigen::Vector3d v1 = Eigen::Vector3d::Zero(), v2(2, 0, 0);
  const auto [x1, x2] = billiards::collide(1.0, v1, 1.0, v2, n);
  // The cushion: v − 2(v·n)n.
  const Eigen::Vector2f w = billiards::reflect(Eigen::Vector2f(1, -1), Eigen::Vector2f(0, 1));
  const bool ok = x1 == v2 && x2.isZero(0) && w == Eigen::Vector2f(1, 1);
  std::printf("billiards %s: %s\n", BILLIARDS_VERSION, ok ? "the paper's answers" : "WRONG");
  return ok ? 0 : 1;
}
