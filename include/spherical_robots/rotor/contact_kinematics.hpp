#pragma once
// Contact kinematics of a sphere rolling on a plane (Svinin, Morinaga, Yamamoto: "On the geometric
// phase approach to motion planning for a spherical rolling robot in dynamic formulation", eqs
// 1-10 and 15-19). No ROS.
//
// Lengths are in units of the sphere radius R. Σ_a is the plane frame (z up), Σ_o the sphere's
// frame; the contact coordinates are the point (u_a, v_a) on the plane, the angles (u_o, v_o) of
// the contact point on the sphere (eq 1, origin at the south pole) and the contact angle ψ.
// The sphere rolls without slipping but may spin about the vertical (ω_z is free here; the rotor
// drive constrains it, see dynamic_realizability.hpp). docs/conventions.md, "Rotor sphere".

#include <Eigen/Core>

namespace spherical_robots::rotor {

/// Contact coordinates (u_a, v_a [R], u_o, v_o, ψ [rad]). |v_o| < π/2 (eq 8 divides by cos v_o).
struct ContactCoordinates {
  double u_a = 0.0;
  double v_a = 0.0;
  double u_o = 0.0;
  double v_o = 0.0;
  double psi = 0.0;
};

/// Time derivatives of the contact coordinates, same order and units per second.
struct ContactRates {
  double u_a = 0.0;
  double v_a = 0.0;
  double u_o = 0.0;
  double v_o = 0.0;
  double psi = 0.0;
};

/// Eq 1: the contact point on the unit sphere in Σ_o, c = (−sin u_o cos v_o, sin v_o,
/// −cos u_o cos v_o). @throw std::invalid_argument on a non-finite angle.
Eigen::Vector3d contactPoint(double u_o, double v_o);

/// Eqs 2-5: orientation of Σ_o in Σ_a, R = R_zᵀ(ψ) R_xᵀ(v_o) R_yᵀ(u_o) = [n1 n2 n3].
/// Eq 3 is misprinted (n1_z = sin u_o cos v_o, docs/errata.md S1).
/// @throw std::invalid_argument on a non-finite angle.
Eigen::Matrix3d orientation(double u_o, double v_o, double psi);

/// Eqs 17-19: the angular velocity ω of the sphere [rad/s, in Σ_a] for given rates of u_o, v_o, ψ;
/// the inverse of eqs 8-10. @throw std::invalid_argument on a non-finite input or |v_o| >= π/2.
Eigen::Vector3d angularVelocity(const ContactCoordinates& coordinates, double u_o_rate,
                                double v_o_rate, double psi_rate);

/// Eqs 6-10 (Montana's equations for rolling without slip; eq 6 reads u̇_a = R ω_y): the rates of
/// all contact coordinates for an angular velocity ω [rad/s, in Σ_a].
/// @throw std::invalid_argument on a non-finite input or |v_o| >= π/2.
ContactRates contactRates(const ContactCoordinates& coordinates, const Eigen::Vector3d& omega);

}  // namespace spherical_robots::rotor
