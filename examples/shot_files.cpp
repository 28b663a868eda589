// A 9-ball break played to rest, written as a user's program writes its files: the events as JSON
// (docs/events.schema.json), the trajectories as CSV, the shot as SVG, each written atomically through
// billiards::io. Usage: shot_files [FOLDER] (default: the current folder).
#include <billiards/io/shot.hpp>
#include <billiards/simulation/shot.hpp>

#include <cstdio>
#include <filesystem>

int main(int argc, char** argv) {
  using namespace billiards::simulation;
  const std::filesystem::path folder = argc > 1 ? argv[1] : ".";
  const PoolTable table = pool_table("9ft");
  const PoolPhysics physics;
  Shot shot(table, physics, rack(table, physics, Rack::nine_ball));
  shot.strike(0, billiards::Cue<double>{0.567, 8.0, 0.0, 0.0, 0.0, 0.25});
  shot.play();
  billiards::io::write_file_atomically(folder / "break.json", billiards::io::shot_json(shot, "9ft"));
  billiards::io::write_file_atomically(folder / "break.csv", billiards::io::trajectories_csv(shot, 100));
  billiards::io::write_file_atomically(folder / "break.svg", billiards::io::shot_svg(shot, "A 9-ball break"));
  std::printf("%zu events to rest after %.3f s: break.json, break.csv, break.svg in %s\n",
              shot.events().size(), shot.time(), folder.c_str());
}
