/// \file
/// A shot's history: each ball's state at each of its events, from which its state at any time follows
/// by its phases on the cloth (the trajectories, sampled at any rate).
#pragma once

#include <billiards/simulation/shot/evolution.hpp>
#include <billiards/simulation/shot/pool_table.hpp>

#include <billiards/cloth.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace billiards::simulation::shot {

/// A ball on the cloth as a shot reports it.
[[nodiscard]] inline PoolBall as_pool_ball(const BallOnCloth<double>& s, bool pocketed) {
  return {s.position, s.velocity, s.angular_velocity, pocketed};
}

/// Each ball's states at its events, in time order: one array for every ball's, each keyframe linked to
/// its ball's previous one.
class History {
 public:
  /// Room for `frames` keyframes of `balls` balls before the arrays grow.
  void reserve(std::size_t balls, std::size_t frames) {
    first_.reserve(balls);
    last_.reserve(balls);
    frames_.reserve(frames);
  }
  /// Every ball's first state: as placed.
  [[nodiscard]] std::vector<PoolBall> first() const {
    std::vector<PoolBall> out;
    out.reserve(first_.size());
    for (const std::uint32_t k : first_) out.push_back(as_pool_ball(frames_[k].state, frames_[k].pocketed));
    return out;
  }
  /// Ball `ball`'s state from time `time` on (until its next keyframe): free on the cloth (billiards::evolve)
  /// or, given `acceleration` and `spin_acceleration`, in a pressed piece with those constant. A ball's
  /// keyframes come in time order, and every ball below `ball` has one before at() or first() is called.
  void add(std::size_t ball, double time, const BallOnCloth<double>& state, bool pocketed,
           const Eigen::Vector2d* acceleration = nullptr, const Eigen::Vector3d* spin_acceleration = nullptr) {
    if (last_.size() <= ball) {
      first_.resize(ball + 1, none);
      last_.resize(ball + 1, none);
    }
    std::uint32_t piece = none;
    if (acceleration && spin_acceleration) {
      piece = static_cast<std::uint32_t>(pieces_.size());
      pieces_.push_back({*acceleration, *spin_acceleration});
    }
    const auto index = static_cast<std::uint32_t>(frames_.size());
    frames_.emplace_back(time, state, pocketed, piece, last_[ball]);  // made in place, written once
    if (first_[ball] == none) first_[ball] = index;
    last_[ball] = index;
  }
  /// The balls at time `t` on `cloth`, each moved by its phases from its last keyframe at or before `t`
  /// (its first where `t` precedes them all); at a keyframe's time, the state it holds.
  [[nodiscard]] std::vector<PoolBall> at(double t, const Cloth<double>& cloth) const {
    std::vector<PoolBall> out;
    out.reserve(last_.size());
    for (std::uint32_t index : last_) {
      while (frames_[index].time > t && frames_[index].previous != none) index = frames_[index].previous;
      const Keyframe& k = frames_[index];
      out.push_back(k.pocketed || !(t > k.time) ? as_pool_ball(k.state, k.pocketed)
                                                : as_pool_ball(moved(k, t - k.time, cloth), false));
    }
    return out;
  }

 private:
  static constexpr std::uint32_t none = ~std::uint32_t{0};
  struct Keyframe {
    Keyframe(double t, const BallOnCloth<double>& s, bool p, std::uint32_t k, std::uint32_t before)
        : time(t), state(s), pocketed(p), piece(k), previous(before) {}
    double time;
    BallOnCloth<double> state;
    bool pocketed;
    std::uint32_t piece;     ///< its pressed piece's index in pieces_, or none
    std::uint32_t previous;  ///< its ball's previous keyframe's index in frames_, or none
  };
  struct Piece {
    Eigen::Vector2d acceleration;
    Eigen::Vector3d spin_acceleration;
  };
  [[nodiscard]] BallOnCloth<double> moved(const Keyframe& k, double tau, const Cloth<double>& cloth) const {
    if (k.piece == none) return evolve(k.state, cloth, tau);
    return pressed_state(k.state, pieces_[k.piece].acceleration, pieces_[k.piece].spin_acceleration, tau);
  }
  std::vector<Keyframe> frames_;
  std::vector<std::uint32_t> first_, last_;  // each ball's first and last keyframe's index in frames_
  std::vector<Piece> pieces_;
};

}  // namespace billiards::simulation::shot
