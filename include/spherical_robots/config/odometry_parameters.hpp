#pragma once
// A simulated plant's odometry and IMU (docs/nodes.md, "Odometry and IMU"): the covariances its
// nav_msgs/Odometry claims, the seeded noise it adds (off by default) and whether and how often
// it publishes sensor_msgs/Imu, loaded and checked in one place for every plant with odometry.

#include <array>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/core/simulated_sensors.hpp"

namespace spherical_robots::config {

/// The variance every published covariance has at least, (1 mm)^2, (1 mrad)^2, (1 mm/s)^2,
/// (1 mrad/s)^2 and (1 mm/s^2)^2 in its units: the exactly integrated model's own error is far
/// smaller, but a zero covariance is one a filter cannot weigh (docs/nodes.md).
inline constexpr double kCovarianceFloor = 1e-6;

/// N entries of kCovarianceFloor.
template <std::size_t N>
constexpr std::array<double, N> floors() {
  std::array<double, N> entries{};
  for (double& entry : entries) entry = kCovarianceFloor;
  return entries;
}

struct OdometryParameters {
  /// Diagonal of pose.covariance: x, y, z [m^2], roll, pitch, yaw [rad^2].
  std::array<double, 6> pose_covariance_diagonal = floors<6>();
  /// Diagonal of twist.covariance: linear [(m/s)^2], angular [(rad/s)^2].
  std::array<double, 6> twist_covariance_diagonal = floors<6>();
  SensorNoise noise;      ///< all 0: exact odometry and IMU
  double imu_rate = 0.0;  ///< [Hz] of sensor_msgs/Imu; 0: none
  /// The Imu's covariance diagonals: orientation [rad^2], angular velocity [(rad/s)^2], linear
  /// acceleration [(m/s^2)^2]: the floor plus the noise's variance.
  std::array<double, 3> imu_orientation_covariance_diagonal = floors<3>();
  std::array<double, 3> imu_angular_velocity_covariance_diagonal = floors<3>();
  std::array<double, 3> imu_linear_acceleration_covariance_diagonal = floors<3>();
};

/// Keys noise/{position, yaw, linear_velocity, angular_velocity, linear_acceleration} (standard
/// deviations >= 0, default 0) and noise/seed (integer >= 0, default 0); imu_rate (>= 0 [Hz],
/// default 0); pose_covariance_diagonal and twist_covariance_diagonal (six finite numbers >= 0;
/// default kCovarianceFloor plus the variance of the noise on that component).
/// @throw std::invalid_argument naming the origin, the key and the bad value or length.
OdometryParameters loadOdometryParameters(const ParameterSource& node);

}  // namespace spherical_robots::config
