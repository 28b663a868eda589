/// \file
/// A shot's history: each ball's state at each of its events, from which its state at any time follows
/// by its phases on the cloth (the trajectories, sampled at any rate).
#pragma once

#include <billiards/simulation/shot/evolution.hpp>
#include <billiards/simulation/shot/pool_table.hpp>

#include <billiards/cloth.hpp>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <vector>

namespace billiards::simulation::shot {

/// A ball on the cloth as a shot reports it.
[[nodiscard]] inline PoolBall as_pool_ball(const BallOnCloth<double>& s, bool pocketed) {
  return {s.position, s.velocity, s.angular_velocity, pocketed};
}

/// Each ball's states at its events, in time order.
class History {
 public:
  /// Every ball's first state: as placed.
  [[nodiscard]] std::vector<PoolBall> first() const {
    std::vector<PoolBall> out;
    out.reserve(frames_.size());
    for (const std::vector<Keyframe>& frames : frames_)
      out.push_back(as_pool_ball(frames.front().state, frames.front().pocketed));
    return out;
  }
  /// Ball `ball`'s state from time `time` on (until its next keyframe), in `phase` (a free phase follows
  /// billiards::evolve; a pressed piece its constant accelerations).
  void add(std::size_t ball, double time, const BallOnCloth<double>& state, bool pocketed,
           const Phase& phase = {}) {
    if (frames_.size() <= ball) frames_.resize(ball + 1);
    frames_[ball].push_back({time, state, pocketed, phase.pressed == Pressed::none ? Phase{} : phase});
  }
  /// The balls at time `t` on `cloth`, each moved by its phases from its last keyframe at or before `t`
  /// (its first where `t` precedes them all); at a keyframe's time, the state it holds.
  [[nodiscard]] std::vector<PoolBall> at(double t, const Cloth<double>& cloth) const {
    std::vector<PoolBall> out;
    out.reserve(frames_.size());
    for (const std::vector<Keyframe>& frames : frames_) {
      const auto it = std::upper_bound(frames.begin(), frames.end(), t,
                                       [](double time, const Keyframe& k) { return time < k.time; });
      const Keyframe& k = it == frames.begin() ? frames.front() : *std::prev(it);
      out.push_back(k.pocketed || !(t > k.time) ? as_pool_ball(k.state, k.pocketed)
                                                : as_pool_ball(state_in(k.state, k.phase, t - k.time, cloth), false));
    }
    return out;
  }

 private:
  struct Keyframe {
    double time;
    BallOnCloth<double> state;
    bool pocketed;
    Phase phase;  ///< a pressed piece's, else free
  };
  std::vector<std::vector<Keyframe>> frames_;
};

}  // namespace billiards::simulation::shot
