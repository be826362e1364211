#pragma once
// Dynamically realizable contact kinematics along a curve c(θ) on the sphere (Svinin et al.,
// eqs 21-30): the contact point is prescribed as c(θ) in Σ_o and the plane coordinates and
// heading follow from u_a'(θ), v_a'(θ), ψ'(θ). Lengths in units of R. No ROS.

#include <Eigen/Core>

namespace spherical_robots::rotor {

/// The largest inertia ratio k = J_xx / J_zz any function here takes: far above any sphere's
/// (section IV: 0-5), and small enough that a step cannot stall its integrator (k = 1e300 did).
constexpr double kMaxInertiaRatio = 100.0;

/// The coordinates integrated along a curve: contact point on the plane and heading.
struct PlaneState {
  double u_a = 0.0;  ///< [R]
  double v_a = 0.0;  ///< [R]
  double psi = 0.0;  ///< [rad], accumulated (not wrapped)
};

/// A point c(θ) of a contact curve on the unit sphere and its derivative c_θ.
struct CurvePoint {
  Eigen::Vector3d point = Eigen::Vector3d(0.0, 0.0, -1.0);
  Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
};

/// Eqs 24-25: u_o, v_o [rad] of a point on the unit sphere, {u_o, v_o}.
/// @throw std::invalid_argument if the point is not finite or not on the lower hemisphere band
///        where eq 30 holds (z >= 0 or y² >= 1).
Eigen::Vector2d contactAngles(const Eigen::Vector3d& point);

/// Eqs 26-27: u_o'(θ), v_o'(θ) [rad per unit θ] of a curve point.
/// @throw std::invalid_argument as contactAngles().
Eigen::Vector2d contactAngleRates(const CurvePoint& curve);

/// Eqs 28-30: (u_a', v_a', ψ') for inertia ratio k >= 0 at a curve point and heading ψ.
/// @throw std::invalid_argument as contactAngles(), or on a non-finite or negative k.
PlaneState realizableCurveRates(double k, const CurvePoint& curve, double psi);

}  // namespace spherical_robots::rotor
