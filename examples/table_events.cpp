// The frictionless table from a setup file's text (billiards::io), run until a time with every event
// told to a callback as it happens, and the balls read back.
#include <billiards/io/table.hpp>
#include <billiards/simulation/table.hpp>

#include <cstdio>
#include <sstream>

int main() {
  using namespace billiards::simulation;
  std::istringstream text(
      "table 2.54 1.27\n"
      "ball 0.6 0.635 2 0     # the cue ball, at 2 m/s along the table\n"
      "ball 1.9 0.64 0 0\n"
      "ball 1.95 0.70 0 0\n");
  Table table(billiards::io::read_setup(text, "three_balls"));
  const std::uint64_t ran = table.run_until(3.0, [](const TableEvent& e) {
    std::printf("t = %.4f s: %s, ball %zu and %s %zu\n", e.time, kind_name(e.kind), e.first,
                e.kind == TableEvent::Kind::ball ? "ball" : "cushion", e.second);
  });
  std::printf("%llu events; at t = %.1f s the energy is %.6f J\n", static_cast<unsigned long long>(ran),
              table.time(), table.energy());
  for (const Ball<2>& b : table.balls())
    std::printf("  (%.4f, %.4f) moving at (%.4f, %.4f)\n", b.position.x(), b.position.y(), b.velocity.x(),
                b.velocity.y());
}
