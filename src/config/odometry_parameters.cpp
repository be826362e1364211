#include "spherical_robots/config/odometry_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace spherical_robots::config {
namespace {

std::array<double, 6> variances(const ParameterSource& node, const std::string& key,
                                const std::array<double, 6>& fallback) {
  const std::optional<std::vector<double>> values = node.numbers(key);
  if (!values) return fallback;
  std::ostringstream problem;
  if (values->size() != fallback.size()) {
    problem << "has " << values->size() << " entries, expected " << fallback.size()
            << " (x, y, z, roll, pitch, yaw)";
  } else {
    for (std::size_t i = 0; i < values->size(); ++i) {
      if (!std::isfinite((*values)[i]) || (*values)[i] < 0.0) {
        problem << "entry " << i << " = " << (*values)[i] << " is not a variance (finite, >= 0)";
        break;
      }
    }
  }
  if (!problem.str().empty())
    throw std::invalid_argument(node.origin() + ": parameter '" + key + "' " + problem.str());
  std::array<double, 6> result;
  std::copy(values->begin(), values->end(), result.begin());
  return result;
}

/// The floor plus sigma^2.
double variance(double sigma) { return kCovarianceFloor + sigma * sigma; }

}  // namespace

OdometryParameters loadOdometryParameters(const ParameterSource& node) {
  OdometryParameters p;
  SensorNoise& noise = p.noise;
  noise.position = nonNegativeNumber(node, "noise/position", noise.position);
  noise.yaw = nonNegativeNumber(node, "noise/yaw", noise.yaw);
  noise.linear_velocity = nonNegativeNumber(node, "noise/linear_velocity", noise.linear_velocity);
  noise.angular_velocity = nonNegativeNumber(node, "noise/angular_velocity", noise.angular_velocity);
  noise.linear_acceleration =
      nonNegativeNumber(node, "noise/linear_acceleration", noise.linear_acceleration);
  noise.seed = static_cast<std::uint32_t>(
      wholeNumber(node, "noise/seed", static_cast<int>(noise.seed), 0));
  p.imu_rate = nonNegativeNumber(node, "imu_rate", p.imu_rate);
  const double position = variance(noise.position), linear = variance(noise.linear_velocity);
  const double angular = variance(noise.angular_velocity);
  p.pose_covariance_diagonal = variances(
      node, "pose_covariance_diagonal",
      {position, position, position, kCovarianceFloor, kCovarianceFloor, variance(noise.yaw)});
  p.twist_covariance_diagonal = variances(node, "twist_covariance_diagonal",
                                          {linear, linear, linear, angular, angular, angular});
  p.imu_orientation_covariance_diagonal = {kCovarianceFloor, kCovarianceFloor, variance(noise.yaw)};
  p.imu_angular_velocity_covariance_diagonal = {angular, angular, angular};
  const double acceleration = variance(noise.linear_acceleration);
  p.imu_linear_acceleration_covariance_diagonal = {acceleration, acceleration, acceleration};
  return p;
}

}  // namespace spherical_robots::config
