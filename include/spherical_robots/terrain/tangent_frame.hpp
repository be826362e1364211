#pragma once
// The tangent frame F_T (paper eqs 10-24) and the heading frame F_L (eqs 25-27) at a point of
// z = f(x, y), in a form that is exact and finite everywhere, flat points included.

#include <Eigen/Core>

namespace spherical_robots::terrain {

/// Upward unit normal n = s_n (-f_x, -f_y, 1) (eq 10) from the gradient (f_x, f_y).
Eigen::Vector3d surfaceNormal(const Eigen::Vector2d& gradient);

/// R_T: world <- tangent frame, columns (i_T, j_T, n). It is the minimal rotation taking the world
/// z axis to n (Rodrigues, eq 19, about e = z x n), written as I + [k]x + [k]x^2 / (1 + n_z) with
/// k = z x n, which equals eq 23 wherever that is defined and is the identity at flat points.
/// @throw std::invalid_argument on a non-finite gradient.
Eigen::Matrix3d tangentFrame(const Eigen::Vector2d& gradient);

/// The rate [rad/s] at which the tangent frame turns about n while n changes at n_dot [1/s]:
/// z . (n_dot x n) / (1 + n_z) (the minimal rotation's own turning; docs/conventions.md).
double tangentFrameSpin(const Eigen::Vector3d& normal, const Eigen::Vector3d& normal_rate);

/// R_L = R_T Rz(psi): world <- heading frame, columns (h, l, n), with psi [rad] the heading
/// measured right-handed about n (docs/conventions.md; the printed eq 25 has the opposite sign).
Eigen::Matrix3d headingFrame(const Eigen::Vector2d& gradient, double psi);

}  // namespace spherical_robots::terrain
