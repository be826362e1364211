#include "spherical_robots/config/odometry_parameters.hpp"

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

}  // namespace

OdometryParameters loadOdometryParameters(const ParameterSource& node) {
  OdometryParameters p;
  p.pose_covariance_diagonal = variances(node, "pose_covariance_diagonal", p.pose_covariance_diagonal);
  p.twist_covariance_diagonal =
      variances(node, "twist_covariance_diagonal", p.twist_covariance_diagonal);
  return p;
}

}  // namespace spherical_robots::config
