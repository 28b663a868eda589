// A hard-sphere gas run in the engines' common vocabulary, its state written as an extended XYZ
// snapshot through billiards::io and read back into a gas that runs on from it.
// Usage: gas_snapshot [FOLDER] (default: the current folder).
#include <billiards/io/snapshots.hpp>
#include <billiards/simulation/gas.hpp>

#include <cstdio>
#include <filesystem>

int main(int argc, char** argv) {
  using namespace billiards::simulation;
  const std::filesystem::path file = std::filesystem::path(argc > 1 ? argv[1] : ".") / "gas.xyz";
  gas::Options options;  // 1000 spheres at packing fraction 0.3, kT = 1
  Gas<3> gas(gas::lattice<3>(options));
  const std::uint64_t ran = gas.run_events(20000, [](const GasEvent&) {});
  billiards::io::write_snapshot_file(file.string(), billiards::io::snapshot_of(gas.setup(), gas.time()));
  // Read back: every position and velocity as written (17 digits).
  const billiards::io::Snapshot read = billiards::io::read_snapshot_file(file.string());
  Gas<3> again(billiards::io::gas_setup<3>(read, file.string(), 1));
  const double drift = (again.energy() - gas.energy()) / gas.energy();
  std::printf("%llu collisions to t = %.4f; %s holds %zu balls, energy %.17g (read back: %.1e apart)\n",
              static_cast<unsigned long long>(ran), gas.time(), file.c_str(), again.balls().size(),
              gas.energy(), drift);
  again.run_until(again.time() + 1.0);
  std::printf("run on from the snapshot to t = %.4f: %llu collisions\n", again.time(),
              static_cast<unsigned long long>(again.event_count()));
  return drift == 0 ? 0 : 1;
}
