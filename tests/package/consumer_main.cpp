// A user's program, written from the README: collide two balls and bounce one off a cushion; throw an
// object ball with a stun shot and let a stun shot roll on the cloth; play a table and a gas of its own
// with the simulation library.
#include <billiards/cloth.hpp>
#include <billiards/collision.hpp>
#include <billiards/io/table.hpp>
#include <billiards/simulation/gas.hpp>
#include <billiards/simulation/table.hpp>
#include <billiards/spin.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

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
  // The table: equal balls head on exchange their velocities at the first event, after the gap of
  // 1 − 2r = 0.75 has closed at 2 m/s.
  billiards::simulation::TableSetup setup;
  setup.width = 4;
  setup.height = 2;
  setup.radius = 0.125;
  setup.balls = {{{1, 1}, {1, 0}}, {{2, 1}, {-1, 0}}};
  billiards::simulation::Table table(setup);
  double first_time = -1;
  table.run_events(1, [&](const billiards::simulation::TableEvent& event) { first_time = event.time; });
  ok = ok && std::fabs(first_time - 0.375) < 1e-14 && table.balls()[0].velocity.x() == -1 &&
       table.balls()[1].velocity.x() == 1;
  // The gas: two disks in a periodic box of 10 meet across it.
  billiards::simulation::GasSetup<2> disks;
  disks.side = 10;
  disks.balls = {{{2, 5}, {1, 0}}, {{6, 5}, {-1, 0}}};
  billiards::simulation::Gas<2> gas(disks);
  ok = ok && gas.run_until(1.0) == 0 && gas.run_events(1) == 1 && std::fabs(gas.time() - 1.5) < 1e-14;
  // billiards::io: a table setup file's text read into the same setup.
  std::istringstream text("table 4 2\nradius 0.125\nball 1 1 1 0\nball 2 1 -1 0\n");
  const billiards::simulation::TableSetup read = billiards::io::read_setup(text, "consumer");
  ok = ok && read.width == 4 && read.balls.size() == 2 && read.balls[1].velocity.x() == -1;
  std::printf("billiards %s: %s\n", BILLIARDS_VERSION, ok ? "the paper's answers" : "WRONG");
  return ok ? 0 : 1;
}
