/// \file
/// What every engine's balls are made of: a ball's centre and velocity in D dimensions, and the
/// vector of a point or a velocity on a table's plane.
#pragma once

#include <Eigen/Core>

namespace billiards::simulation {

/// A ball of a simulation: its centre and its velocity, in D dimensions.
template <int D>
struct Ball {
  Eigen::Matrix<double, D, 1> position = Eigen::Matrix<double, D, 1>::Zero();  ///< the centre
  Eigen::Matrix<double, D, 1> velocity = Eigen::Matrix<double, D, 1>::Zero();  ///< the velocity
};

/// A point or a velocity on a table's plane.
using TableVector = Eigen::Vector2d;

}  // namespace billiards::simulation
