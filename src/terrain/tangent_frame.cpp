#include "spherical_robots/terrain/tangent_frame.hpp"

#include <cmath>
#include <stdexcept>

namespace spherical_robots::terrain {

// Eq 10.
Eigen::Vector3d surfaceNormal(const Eigen::Vector2d& gradient) {
  if (!gradient.allFinite()) {
    throw std::invalid_argument("tangent frame: surface gradient is not finite");
  }
  return Eigen::Vector3d(-gradient.x(), -gradient.y(), 1.0).normalized();
}

// Eqs 19/23 in the form I + [k]x + [k]x^2 / (1 + c): with k = z x n = sin(gamma) e and
// c = cos(gamma), (1 - cos gamma) / sin^2 gamma = 1 / (1 + cos gamma), which never divides by
// zero because n_z = s_n > 0 on a graph z = f(x, y).
Eigen::Matrix3d tangentFrame(const Eigen::Vector2d& gradient) {
  const Eigen::Vector3d n = surfaceNormal(gradient);
  const double kx = -n.y();
  const double ky = n.x();
  const double c = n.z();
  const double q = 1.0 / (1.0 + c);
  Eigen::Matrix3d frame;
  frame << 1.0 - q * ky * ky, q * kx * ky, n.x(),
           q * kx * ky, 1.0 - q * kx * kx, n.y(),
           -ky, kx, c;
  return frame;
}

// Eq 26 with R_LT = Rz(psi): psi is right-handed about n (the printed eq 25 is Rz(-psi)).
Eigen::Matrix3d headingFrame(const Eigen::Vector2d& gradient, double psi) {
  if (!std::isfinite(psi)) {
    throw std::invalid_argument("heading frame: psi is not finite");
  }
  const Eigen::Matrix3d tangent = tangentFrame(gradient);
  const double c = std::cos(psi);
  const double s = std::sin(psi);
  Eigen::Matrix3d heading;
  heading.col(0) = c * tangent.col(0) + s * tangent.col(1);
  heading.col(1) = -s * tangent.col(0) + c * tangent.col(1);
  heading.col(2) = tangent.col(2);
  return heading;
}

}  // namespace spherical_robots::terrain
