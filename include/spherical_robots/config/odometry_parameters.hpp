#pragma once
// What a plant's nav_msgs/Odometry claims about itself (docs/nodes.md, "Odometry"): the
// covariances it publishes, loaded and checked in one place for every plant that has odometry.

#include <array>

#include "spherical_robots/config/parameter_source.hpp"

namespace spherical_robots::config {

struct OdometryParameters {
  /// Diagonal of pose.covariance: x, y, z [m^2], roll, pitch, yaw [rad^2]. The default, (1 mm)^2
  /// and (1 mrad)^2, is an exactly integrated model's: far better than any wheel odometry, yet not
  /// the zero a filter cannot weigh (docs/nodes.md).
  std::array<double, 6> pose_covariance_diagonal{1e-6, 1e-6, 1e-6, 1e-6, 1e-6, 1e-6};
  /// Diagonal of twist.covariance: linear [(m/s)^2], angular [(rad/s)^2]; (1 mm/s)^2, (1 mrad/s)^2.
  std::array<double, 6> twist_covariance_diagonal{1e-6, 1e-6, 1e-6, 1e-6, 1e-6, 1e-6};
};

/// Keys pose_covariance_diagonal and twist_covariance_diagonal: six finite numbers >= 0 each.
/// @throw std::invalid_argument naming the origin, the key and the bad value or length.
OdometryParameters loadOdometryParameters(const ParameterSource& node);

}  // namespace spherical_robots::config
