#include "spherical_robots/core/angles.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spherical_robots {

double wrapToPi(double angle) {
  const double wrapped = std::remainder(angle, 2.0 * M_PI);  // in [−π, π]
  return wrapped <= -M_PI ? wrapped + 2.0 * M_PI : wrapped;
}

Eigen::Quaterniond yawRotation(double yaw) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
}

double yawOf(const Eigen::Quaterniond& orientation) {
  const double x = orientation.x(), y = orientation.y(), z = orientation.z(), w = orientation.w();
  if (!orientation.coeffs().allFinite()) throw std::invalid_argument("orientation is not finite");
  // (R00, R10) times |q|^2: the x axis's horizontal part.
  const double along = w * w + x * x - y * y - z * z;
  const double across = 2.0 * (x * y + w * z);
  if (!(std::hypot(along, across) > 1e-9 * orientation.coeffs().squaredNorm())) {
    std::ostringstream what;
    what << "orientation (x " << x << ", y " << y << ", z " << z << ", w " << w
         << ") has a vertical x axis: no heading";
    throw std::invalid_argument(what.str());
  }
  return std::atan2(across, along);
}

}  // namespace spherical_robots
