/// \file
/// The gas's setups made in code (the lattice start, thermal velocities) and its measurements (the
/// equation of state's Z with errors from blocks, the pressure, the mean free time, the mean squared
/// displacement, snapshots at intervals).
#pragma once

#include <billiards/simulation/gas/gas.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace billiards::simulation {

namespace gas {

/// Gives the balls of `setup` (at least two) Gaussian velocities drawn with `seed`, ball i's of
/// variance 1/m_i, less the centre of mass's velocity (total momentum zero), rescaled to kT = 1
/// (Σ m v² = d N).
template <int D>
void thermal_velocities(GasSetup<D>& setup, std::uint64_t seed) {
  using Vector = Eigen::Matrix<double, D, 1>;
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gaussian;
  const std::size_t n = setup.balls.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double spread = 1 / std::sqrt(setup.mass_of(i));
    for (int k = 0; k < D; ++k) setup.balls[i].velocity[k] = gaussian(random) * spread;
  }
  Eigen::Matrix<long double, D, 1> momentum = Eigen::Matrix<long double, D, 1>::Zero();
  long double mass = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto m = static_cast<long double>(setup.mass_of(i));
    momentum += m * setup.balls[i].velocity.template cast<long double>();
    mass += m;
  }
  const Vector mean = momentum.template cast<double>() / static_cast<double>(mass);
  for (Ball<D>& b : setup.balls) b.velocity -= mean;
  long double squares = 0;
  for (std::size_t i = 0; i < n; ++i) {
    squares += static_cast<long double>(setup.mass_of(i)) *
               static_cast<long double>(setup.balls[i].velocity.squaredNorm());
  }
  const double scale = 1 / std::sqrt(static_cast<double>(squares / (D * static_cast<long double>(n))));
  for (Ball<D>& b : setup.balls) b.velocity *= scale;
}

/// The lattice start of `options` (validated: std::invalid_argument naming the option): N balls of
/// diameter 1 and mass 1 on a square (2-D) or FCC (3-D) lattice filling the box of packing fraction η,
/// with Gaussian velocities of total momentum zero, rescaled to kT = 1.
template <int D>
GasSetup<D> lattice(const Options& options) {
  validate(options);
  if (options.dimension != D) {
    throw std::invalid_argument("--dimension is " + std::to_string(options.dimension) + ", expected " +
                                std::to_string(D) + " for gas::lattice<" + std::to_string(D) + ">");
  }
  using Vector = Eigen::Matrix<double, D, 1>;
  GasSetup<D> setup;
  setup.side = box_side(D, options.balls, options.packing_fraction);
  setup.balls.resize(options.balls);
  const std::size_t n = lattice_cells(D, options.balls);
  const double spacing = setup.side / static_cast<double>(n);
  std::size_t placed = 0;
  if constexpr (D == 2) {
    for (std::size_t i = 0; i < n && placed < options.balls; ++i) {
      for (std::size_t j = 0; j < n && placed < options.balls; ++j) {
        setup.balls[placed++].position =
            Vector((static_cast<double>(i) + 0.5) * spacing, (static_cast<double>(j) + 0.5) * spacing);
      }
    }
  } else {
    const double basis[4][3] = {
        {0.25, 0.25, 0.25}, {0.75, 0.75, 0.25}, {0.75, 0.25, 0.75}, {0.25, 0.75, 0.75}};
    for (std::size_t i = 0; i < n && placed < options.balls; ++i) {
      for (std::size_t j = 0; j < n && placed < options.balls; ++j) {
        for (std::size_t k = 0; k < n && placed < options.balls; ++k) {
          for (int b = 0; b < 4 && placed < options.balls; ++b) {
            setup.balls[placed++].position = Vector((static_cast<double>(i) + basis[b][0]) * spacing,
                                                    (static_cast<double>(j) + basis[b][1]) * spacing,
                                                    (static_cast<double>(k) + basis[b][2]) * spacing);
          }
        }
      }
    }
  }
  thermal_velocities(setup, options.seed);
  return setup;
}

/// The standard error of the mean of `x` (0 for fewer than two values).
inline double standard_error(const std::vector<double>& x) {
  if (x.size() < 2) return 0;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double squares = 0;
  for (double v : x) squares += (v - mean) * (v - mean);
  return std::sqrt(squares / static_cast<double>(x.size() - 1) / static_cast<double>(x.size()));
}

/// Z of the equation of state for the balls of `gas`: Henderson's (disks) or Carnahan–Starling's
/// (spheres) for equal balls, BMCSL for spheres of unequal radii, NaN for disks of unequal radii.
template <int D>
double equation_of_state(const Gas<D>& gas) {
  const std::vector<double> radii = gas.radii();
  const double volume = std::pow(gas.side(), D);
  if (std::all_of(radii.begin(), radii.end(), [&](double r) { return r == radii[0]; })) {
    return equation_of_state(D, static_cast<double>(radii.size()) * ball_volume(D) * std::pow(2 * radii[0], D) / volume);
  }
  if constexpr (D == 2) {
    return std::numeric_limits<double>::quiet_NaN();
  } else {
    std::vector<double> diameters(radii.size());
    for (std::size_t i = 0; i < radii.size(); ++i) diameters[i] = 2 * radii[i];
    return boublik_mansoori(diameters, volume);
  }
}

/// The packing fraction of `gas`: the balls' volume (areas in 2-D) over the box's.
template <int D>
double packing_fraction(const Gas<D>& gas) {
  double filled = 0;
  for (double r : gas.radii()) filled += ball_volume(D) * std::pow(2 * r, D);
  return filled / std::pow(gas.side(), D);
}

namespace detail {

/// The mean of |now_i − start_i|² over the balls (unwrapped positions), summed in long double.
template <int D>
double mean_squared_displacement(const std::vector<Eigen::Matrix<double, D, 1>>& start,
                                 const std::vector<Eigen::Matrix<double, D, 1>>& now) {
  long double squares = 0;
  for (std::size_t i = 0; i < now.size(); ++i) squares += static_cast<long double>((now[i] - start[i]).squaredNorm());
  return static_cast<double>(squares / static_cast<long double>(now.size()));
}

/// The time of the snapshot after `count` of them from `start` at `interval`; throws
/// std::invalid_argument where it does not lie after `now` (an interval lost in the time's rounding).
inline double next_snapshot(double start, double interval, std::uint64_t count, double now) {
  const double next = start + interval * static_cast<double>(count);
  if (!(next > now)) {
    std::ostringstream text;
    text << "--snapshot-every is " << interval << ", expected an interval the gas's time " << now
         << " can advance by (at least " << 2 * std::numeric_limits<double>::epsilon() * now << ")";
    throw std::invalid_argument(text.str());
  }
  return next;
}

/// Throws std::invalid_argument naming the option where `options` cannot be measured (no block, an
/// interval negative or not finite), and where the gas's `energy` is 0 (every ball at rest).
inline void check_measurable(const Options& options, double energy) {
  if (options.blocks < 1) {
    throw std::invalid_argument("--blocks is " + std::to_string(options.blocks) + ", expected at least 1");
  }
  if (!(options.snapshot_interval >= 0) || !std::isfinite(options.snapshot_interval)) {
    throw std::invalid_argument("--snapshot-every is " + std::to_string(options.snapshot_interval) +
                                ", expected a finite time, 0 or more");
  }
  if (!(energy > 0)) {
    throw std::invalid_argument("gas setup: every ball is at rest, expected balls that move (a gas at rest has "
                                "no collision to measure)");
  }
}

}  // namespace detail

/// Runs `options.equilibrate` collisions of `gas` unmeasured, then `options.events` measured in
/// `options.blocks` blocks, and returns what was measured, with errors from the scatter of the blocks
/// and the time series block by block (no more blocks than events). Where `options.snapshot_interval`
/// is positive, calls `on_snapshot(gas)` at the measured span's start and every interval of the gas's
/// time after it while the span lasts (the gas brought to that time). Throws std::invalid_argument
/// naming the option where there is no block, or the interval is negative, not finite, or too small to
/// advance the gas's time, or every ball is at rest.
template <int D, typename OnSnapshot>
Result measure(Gas<D>& gas, const Options& options, OnSnapshot&& on_snapshot) {
  detail::check_measurable(options, gas.energy());
  gas.run_events(options.equilibrate);
  // No more blocks than collisions: each block holds at least one.
  const std::uint64_t blocks = std::max<std::uint64_t>(1, std::min<std::uint64_t>(static_cast<std::uint64_t>(options.blocks), options.events));
  const double kT = gas.temperature(), n = static_cast<double>(gas.size());
  const double density = n / std::pow(gas.side(), D);
  Result r;
  r.dimension = D;
  r.balls = gas.size();
  r.packing_fraction = packing_fraction(gas);
  r.equation_of_state = equation_of_state(gas);
  std::vector<double> z_blocks, p_blocks, rate_blocks;
  double total_virial = 0, rate_excess = 0;  // rate_excess: Σ (Z_rate − 1) t over the blocks
  const std::vector<Eigen::Matrix<double, D, 1>> start = gas.unwrapped_positions();
  const double start_time = gas.time();
  const bool snapshots = options.snapshot_interval > 0;
  std::uint64_t snapshot_count = 0;
  double next_snapshot = start_time;
  const auto wall_start = std::chrono::steady_clock::now();
  std::uint64_t done = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t target = options.events * (b + 1) / blocks;
    gas.reset_measurements();
    while (done < target) {
      if (snapshots && next_snapshot <= gas.time()) {
        on_snapshot(static_cast<const Gas<D>&>(gas));
        next_snapshot = detail::next_snapshot(start_time, options.snapshot_interval, ++snapshot_count, gas.time());
      }
      done += gas.run(target - done, snapshots ? next_snapshot : std::numeric_limits<double>::infinity());
    }
    const GasMeasurement block = gas.measured();
    total_virial += block.virial;
    rate_excess += (block.compressibility_factor_from_collision_rate - 1) * block.time;
    r.time += block.time;
    r.cell_crossings += block.cell_crossings;
    r.list_rebuilds += block.list_rebuilds;
    const double temperature = gas.temperature();
    r.largest_temperature_change = std::max(r.largest_temperature_change, std::fabs(temperature - kT) / kT);
    Block row;
    row.time = gas.time() - start_time;
    row.collisions = block.collisions;
    row.compressibility_factor = block.compressibility_factor;
    row.pressure = block.compressibility_factor * density * block.temperature;
    row.temperature = temperature;
    row.mean_squared_displacement = detail::mean_squared_displacement<D>(start, gas.unwrapped_positions());
    row.collision_rate = block.time > 0 ? 2 * static_cast<double>(block.collisions) / (n * block.time) : 0;
    r.blocks.push_back(row);
    if (block.time > 0 && block.collisions > 0) {
      z_blocks.push_back(block.compressibility_factor);
      p_blocks.push_back(row.pressure);
      rate_blocks.push_back(block.compressibility_factor_from_collision_rate);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  r.collisions = done;
  r.temperature = gas.temperature();
  r.momentum = gas.momentum().norm();
  r.largest_overlap = gas.largest_overlap();
  r.largest_gap = gas.largest_gap();
  r.events_per_second = seconds > 0 ? static_cast<double>(done) / seconds : 0;
  r.compressibility_factor = r.time > 0 ? 1 + total_virial / (D * n * kT * r.time) : 1;
  r.pressure = r.compressibility_factor * density * kT;
  r.mean_free_time =
      done > 0 ? r.time * n / (2 * static_cast<double>(done)) : std::numeric_limits<double>::infinity();
  r.compressibility_factor_from_collision_rate = r.time > 0 ? 1 + rate_excess / r.time : 1;
  r.compressibility_factor_error = standard_error(z_blocks);
  r.pressure_error = standard_error(p_blocks);
  r.compressibility_factor_from_collision_rate_error = standard_error(rate_blocks);
  return r;
}

/// Runs and measures `gas` as above, without snapshots.
template <int D>
Result measure(Gas<D>& gas, const Options& options) {
  return measure(gas, options, [](const Gas<D>&) {});
}

/// Validates `options`, runs the lattice gas of its dimension and returns what it measured.
inline Result measure(const Options& options) {
  validate(options);
  if (options.dimension == 2) {
    Gas<2> gas(lattice<2>(options), options.max_events_without_collision, options.method);
    return measure(gas, options);
  }
  Gas<3> gas(lattice<3>(options), options.max_events_without_collision, options.method);
  return measure(gas, options);
}

}  // namespace gas
}  // namespace billiards::simulation

