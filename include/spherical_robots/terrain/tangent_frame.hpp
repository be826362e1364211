#pragma once
// The tangent frame F_T (paper eqs 10-24) and the heading frame F_L (eqs 25-27) at a point of
// z = f(x, y), in a form that is exact and finite everywhere, flat points included.

#include <Eigen/Core>
#include <cmath>

#include "spherical_robots/core/sin_cos.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::terrain {

/// Upward unit normal n = s_n (-f_x, -f_y, 1) (eq 10) from the gradient (f_x, f_y).
Eigen::Vector3d surfaceNormal(const Eigen::Vector2d& gradient);

/// R_T: world <- tangent frame, columns (i_T, j_T, n). It is the minimal rotation taking the world
/// z axis to n (Rodrigues, eq 19, about e = z x n), written as I + [k]x + [k]x^2 / (1 + n_z) with
/// k = z x n, which equals eq 23 wherever that is defined and is the identity at flat points.
/// @throw std::invalid_argument on a non-finite gradient.
inline Eigen::Matrix3d tangentFrame(const Eigen::Vector2d& gradient);

/// The rate [rad/s] at which the tangent frame turns about n while n changes at n_dot [1/s]:
/// z . (n_dot x n) / (1 + n_z) (the minimal rotation's own turning; docs/conventions.md).
double tangentFrameSpin(const Eigen::Vector3d& normal, const Eigen::Vector3d& normal_rate);

/// R_L = R_T Rz(psi): world <- heading frame, columns (h, l, n), with psi [rad] the heading
/// measured right-handed about n (docs/conventions.md; the printed eq 25 has the opposite sign).
/// @throw std::invalid_argument on a non-finite gradient or psi.
inline Eigen::Matrix3d headingFrame(const Eigen::Vector2d& gradient, double psi);

// Inline below: the closed loop builds the heading frame at every RK stage, and out of line its
// nine entries went through memory on the chain of operations from one stage to the next.
namespace tangent_frame_detail {

/// @throw std::invalid_argument naming what is not finite (out of line: the checks stay compares).
[[noreturn]] void rejectGradient();
[[noreturn]] void rejectHeading();

inline void requireFiniteGradient(const Eigen::Vector2d& gradient) {
  if (!allFinite(gradient.x(), gradient.y())) rejectGradient();
}

// Eqs 19/23 in the form I + [k]x + [k]x^2 / (1 + c): with k = z x n = sin(gamma) e and
// c = cos(gamma), (1 - cos gamma) / sin^2 gamma = 1 / (1 + cos gamma), which never divides by
// zero because n_z = s_n > 0 on a graph z = f(x, y). With L = sqrt(1 + f_x^2 + f_y^2),
// n = (-f_x, -f_y, 1) / L, c = 1 / L and [k]x^2 / (1 + c) = -[f_i f_j] / (L (L + 1)) in the
// plane: one division d = 1 / (L (L + 1)) gives both, c = (L + 1) d (the closed loop builds
// this frame at every RK stage, where divisions are what its time goes to).
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

}  // namespace tangent_frame_detail

inline Eigen::Matrix3d tangentFrame(const Eigen::Vector2d& gradient) {
  return tangent_frame_detail::minimalRotation(gradient);
}

// Eq 26 with R_LT = Rz(psi): psi is right-handed about n (the printed eq 25 is Rz(-psi)).
inline Eigen::Matrix3d headingFrame(const Eigen::Vector2d& gradient, double psi) {
  if (!std::isfinite(psi)) tangent_frame_detail::rejectHeading();
  const Eigen::Matrix3d tangent = tangent_frame_detail::minimalRotation(gradient);
  const SinCos turn = sinCos(psi);
  Eigen::Matrix3d heading;
  heading.col(0) = turn.cos * tangent.col(0) + turn.sin * tangent.col(1);
  heading.col(1) = -turn.sin * tangent.col(0) + turn.cos * tangent.col(1);
  heading.col(2) = tangent.col(2);
  return heading;
}

}  // namespace spherical_robots::terrain
