// Must not compile: all vectors share one scalar type, and the error says so.
#include <billiards/collision.hpp>

int main() {
  const Eigen::Vector3d v = Eigen::Vector3d::Zero();
  const Eigen::Vector3f n = Eigen::Vector3f::UnitX();
  const auto result = billiards::collide(1.0, v, 1.0, v, n);
  return static_cast<int>(result.first.size());
}
