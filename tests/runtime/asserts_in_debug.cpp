// Built without NDEBUG: the unchecked call's assert must stop a negative mass (the test expects this
// program to abort).
#include <billiards/collision.hpp>

#include <cstdio>

int main() {
  const Eigen::Vector3d v = Eigen::Vector3d::UnitX(), n = Eigen::Vector3d::UnitX();
  const auto result = billiards::collide(-1.0, v, 1.0, v, n);
  std::printf("not stopped: %g\n", result.first[0]);
  return 0;
}
