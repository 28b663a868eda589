/// \file
/// The gas's measurements as files: what gas::measure measured as JSON (billiards-gas's output) and its
/// time series, one row a block, as CSV.
#pragma once

#include <billiards/io/json.hpp>

#include <billiards/simulation/gas.hpp>

#include <sstream>
#include <string>

namespace billiards::io {

/// What gas::measure measured, as one JSON object (every number with 17 digits; one that is not finite
/// is null): billiards-gas's output.
inline std::string measurement_json(const billiards::simulation::gas::Result& r) {
  std::ostringstream out;
  out << "{\n"
      << "  \"dimension\": " << r.dimension << ",\n"
      << "  \"balls\": " << r.balls << ",\n"
      << "  \"packing_fraction\": " << json_number(r.packing_fraction) << ",\n"
      << "  \"collisions\": " << r.collisions << ",\n"
      << "  \"time\": " << json_number(r.time) << ",\n"
      << "  \"compressibility_factor\": " << json_number(r.compressibility_factor) << ",\n"
      << "  \"compressibility_factor_error\": " << json_number(r.compressibility_factor_error) << ",\n"
      << "  \"compressibility_factor_from_collision_rate\": "
      << json_number(r.compressibility_factor_from_collision_rate) << ",\n"
      << "  \"compressibility_factor_from_collision_rate_error\": "
      << json_number(r.compressibility_factor_from_collision_rate_error) << ",\n"
      << "  \"pressure\": " << json_number(r.pressure) << ",\n"
      << "  \"pressure_error\": " << json_number(r.pressure_error) << ",\n"
      << "  \"equation_of_state\": " << json_number(r.equation_of_state) << ",\n"
      << "  \"mean_free_time\": " << json_number(r.mean_free_time) << ",\n"
      << "  \"temperature\": " << json_number(r.temperature) << ",\n"
      << "  \"largest_temperature_change\": " << json_number(r.largest_temperature_change) << ",\n"
      << "  \"momentum\": " << json_number(r.momentum) << ",\n"
      << "  \"largest_overlap\": " << json_number(r.largest_overlap) << ",\n"
      << "  \"largest_gap\": " << json_number(r.largest_gap) << ",\n"
      << "  \"cell_crossings\": " << r.cell_crossings << ",\n"
      << "  \"list_rebuilds\": " << r.list_rebuilds << ",\n"
      << "  \"events_per_second\": " << json_number(r.events_per_second) << "\n"
      << "}\n";
  return out.str();
}

/// The time series of gas::measure as CSV: a header, then one row a block (time, collisions,
/// compressibility_factor, pressure, temperature, mean_squared_displacement, collision_rate).
inline std::string series_csv(const billiards::simulation::gas::Result& r) {
  std::string out =
      "time,collisions,compressibility_factor,pressure,temperature,mean_squared_displacement,collision_"
      "rate\n";
  for (const billiards::simulation::gas::Block& b : r.blocks) {
    out += json_number(b.time) + "," + std::to_string(b.collisions) + "," +
           json_number(b.compressibility_factor) + "," + json_number(b.pressure) + "," +
           json_number(b.temperature) + "," + json_number(b.mean_squared_displacement) + "," +
           json_number(b.collision_rate) + "\n";
  }
  return out;
}

}  // namespace billiards::io
