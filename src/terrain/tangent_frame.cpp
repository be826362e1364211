#include "spherical_robots/terrain/tangent_frame.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/core/sin_cos.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::terrain {
namespace {

void requireFiniteGradient(const Eigen::Vector2d& gradient) {
  if (!allFinite(gradient.x(), gradient.y())) {
    throw std::invalid_argument("tangent frame: surface gradient is not finite");
  }
}

}  // namespace

// Eq 10.
Eigen::Vector3d surfaceNormal(const Eigen::Vector2d& gradient) {
  requireFiniteGradient(gradient);
  return Eigen::Vector3d(-gradient.x(), -gradient.y(), 1.0).normalized();
}

// Eqs 19/23 in the form I + [k]x + [k]x^2 / (1 + c): with k = z x n = sin(gamma) e and
// c = cos(gamma), (1 - cos gamma) / sin^2 gamma = 1 / (1 + cos gamma), which never divides by
// zero because n_z = s_n > 0 on a graph z = f(x, y). With L = sqrt(1 + f_x^2 + f_y^2),
// n = (-f_x, -f_y, 1) / L, c = 1 / L and [k]x^2 / (1 + c) = -[f_i f_j] / (L (L + 1)) in the
// plane: one division d = 1 / (L (L + 1)) gives both, c = (L + 1) d (the closed loop builds
// this frame at every RK stage, where divisions are what its time goes to).
namespace {

// Declared inline so that GCC inlines it into headingFrame, at every RK stage of a run, instead of
// returning the nine entries through memory.
inline Eigen::Matrix3d minimalRotation(const Eigen::Vector2d& gradient) {
  requireFiniteGradient(gradient);
  const double gx = gradient.x();
  const double gy = gradient.y();
  const double length = std::sqrt(1.0 + gx * gx + gy * gy);
  const double d = 1.0 / (length * (length + 1.0));
  const double c = (length + 1.0) * d;
  const double gxy = d * gx * gy;
  Eigen::Matrix3d frame;
  frame << 1.0 - d * gx * gx, -gxy, -c * gx,
           -gxy, 1.0 - d * gy * gy, -c * gy,
           c * gx, c * gy, c;
  return frame;
}

}  // namespace

Eigen::Matrix3d tangentFrame(const Eigen::Vector2d& gradient) { return minimalRotation(gradient); }

double tangentFrameSpin(const Eigen::Vector3d& normal, const Eigen::Vector3d& normal_rate) {
  return normal_rate.cross(normal).z() / (1.0 + normal.z());
}

// Eq 26 with R_LT = Rz(psi): psi is right-handed about n (the printed eq 25 is Rz(-psi)).
Eigen::Matrix3d headingFrame(const Eigen::Vector2d& gradient, double psi) {
  if (!std::isfinite(psi)) {
    throw std::invalid_argument("heading frame: psi is not finite");
  }
  const Eigen::Matrix3d tangent = minimalRotation(gradient);
  const SinCos turn = sinCos(psi);
  Eigen::Matrix3d heading;
  heading.col(0) = turn.cos * tangent.col(0) + turn.sin * tangent.col(1);
  heading.col(1) = -turn.sin * tangent.col(0) + turn.cos * tangent.col(1);
  heading.col(2) = tangent.col(2);
  return heading;
}

}  // namespace spherical_robots::terrain
