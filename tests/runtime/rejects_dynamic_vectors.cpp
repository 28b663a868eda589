// Must not compile: billiards::collide takes fixed-size vectors only, and says so.
#include <billiards/collision.hpp>

int main() {
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(3);
  const auto result = billiards::collide(1.0, v, 1.0, v, v);
  return static_cast<int>(result.first.size());
}
