// Reads one call a line on stdin and prints what the runtime returns, for a peer's comparison script
// (compare_pooltool.py): "strike m R M V azimuth elevation a b e_tip" (the ball at rest) and
// "cushion m R vx vy wx wy wz nx ny h e_c mu_c" (the ball on the cloth); each answer is a line of the
// ball's velocity and spin, six numbers to 17 digits. A line it cannot read ends it with status 2.
#include <billiards/shot.hpp>

#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

int main() {
  using V = Eigen::Vector3d;
  std::string line;
  for (int number = 1; std::getline(std::cin, line); ++number) {
    std::istringstream in(line);
    std::string call;
    in >> call;
    billiards::SpinningBall<double> after{V::Zero(), V::Zero(), 1, 1};
    if (call == "strike") {
      double m, R, M, speed, azimuth, elevation, a, b, e;
      if (!(in >> m >> R >> M >> speed >> azimuth >> elevation >> a >> b >> e)) call.clear();
      else after = billiards::checked::strike(billiards::SpinningBall<double>{V::Zero(), V::Zero(), m, R},
                                              billiards::Cue<double>{M, speed, azimuth, elevation, a, b, e});
    } else if (call == "cushion") {
      double m, R, vx, vy, wx, wy, wz, nx, ny, h, e, mu;
      if (!(in >> m >> R >> vx >> vy >> wx >> wy >> wz >> nx >> ny >> h >> e >> mu)) call.clear();
      else after = billiards::checked::collide_with_cushion(billiards::SpinningBall<double>{V(vx, vy, 0), V(wx, wy, wz), m, R},
                                                            billiards::Cushion<double>{V(nx, ny, 0), h, e, mu});
    } else {
      call.clear();
    }
    if (call.empty()) {
      std::cerr << "shot_physics_probe: line " << number << ": expected 'strike' with 9 numbers or 'cushion' with 12\n";
      return 2;
    }
    std::printf("%.17g %.17g %.17g %.17g %.17g %.17g\n", after.velocity.x(), after.velocity.y(), after.velocity.z(),
                after.angular_velocity.x(), after.angular_velocity.y(), after.angular_velocity.z());
  }
  return 0;
}
