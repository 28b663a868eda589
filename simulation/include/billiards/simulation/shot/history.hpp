/// \file
/// A shot's history: each ball's state at each of its events, from which its state at any time follows
/// by its phases on the cloth (the trajectories, sampled at any rate).
#pragma once

#include <billiards/simulation/shot/evolution.hpp>
#include <billiards/simulation/shot/pool_table.hpp>

#include <billiards/cloth.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
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
  /// Ball `ball`'s state from time `time` on (until its next keyframe): free on the cloth (billiards::evolve)
  /// or, given `acceleration` and `spin_acceleration`, in a pressed piece with those constant.
  void add(std::size_t ball, double time, const BallOnCloth<double>& state, bool pocketed,
           const Eigen::Vector2d* acceleration = nullptr, const Eigen::Vector3d* spin_acceleration = nullptr) {
    if (frames_.size() <= ball) frames_.resize(ball + 1);
    std::uint32_t piece = none;
    if (acceleration && spin_acceleration) {
      piece = static_cast<std::uint32_t>(pieces_.size());
      pieces_.push_back({*acceleration, *spin_acceleration});
    }
    frames_[ball].push_back({time, state, pocketed, piece});
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
                                                : as_pool_ball(moved(k, t - k.time, cloth), false));
    }
    return out;
  }

 private:
  struct Keyframe {
    double time;
    BallOnCloth<double> state;
    bool pocketed;
    std::uint32_t piece;  ///< its pressed piece's index in pieces_, or none
  };
  struct Piece {
    Eigen::Vector2d acceleration;
    Eigen::Vector3d spin_acceleration;
  };
  static constexpr std::uint32_t none = ~std::uint32_t{0};
  [[nodiscard]] BallOnCloth<double> moved(const Keyframe& k, double tau, const Cloth<double>& cloth) const {
    if (k.piece == none) return evolve(k.state, cloth, tau);
    return pressed_state(k.state, pieces_[k.piece].acceleration, pieces_[k.piece].spin_acceleration, tau);
  }
  std::vector<std::vector<Keyframe>> frames_;
  std::vector<Piece> pieces_;
};

}  // namespace billiards::simulation::shot
