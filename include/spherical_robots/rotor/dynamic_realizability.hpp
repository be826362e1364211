#pragma once
// The two-rotor sphere's drive (Svinin et al., eqs 11-14 and 20): the angular momentum about the
// contact point is conserved, J_c ω + J_r (n1 φ̇1 + n2 φ̇2) = 0 (eq 11), so the rotors on the body
// axes n1, n2 can produce any ω whose momentum J_c ω has no n3 component (eq 12). No ROS.
//
// J_c = J_zz diag(k, k, 1) in Σ_a with the inertia ratio k = J_xx / J_zz (eq 14).

#include <Eigen/Core>

#include "spherical_robots/rotor/contact_curve.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"

namespace spherical_robots::rotor {

/// Mass properties of the composite system (eq 11, 14), SI units.
struct RotorSphereInertia {
  double total_mass = 0.0;     ///< M [kg]
  double shell_mass = 0.0;     ///< m_o [kg]
  double radius = 0.0;         ///< R [m]
  double rotor_axial = 0.0;    ///< J_r [kg m²], one rotor about its axis
  double rotor_diametral = 0.0;  ///< J_p [kg m²], one rotor about a diameter
};

/// Eq 14: k = 1 + M R² / (2/3 m_o R² + 2 J_p + J_r) (> 1 for any real robot).
/// @throw std::invalid_argument unless every member is finite and > 0 (J_p >= 0).
double inertiaRatio(const RotorSphereInertia& inertia);

/// J_zz / J_r = (2/3 m_o R² + 2 J_p + J_r) / J_r, the scale of the rotor speeds (eq 11).
/// @throw std::invalid_argument as inertiaRatio().
double rotorInertiaScale(const RotorSphereInertia& inertia);

/// Eq 13 divided by J_zz: k (n3x ω_x + n3y ω_y) + n3z ω_z, zero for a realizable ω [rad/s].
/// @throw std::invalid_argument on a non-finite input or k < 0.
double realizabilityResidual(double k, const ContactCoordinates& coordinates,
                             const Eigen::Vector3d& omega);

/// Eq 20: the heading rate ψ̇ that makes the motion realizable for rates u̇_o, v̇_o,
/// ψ̇ = (1 − k) sin v_o u̇_o + k tan u_o / cos v_o v̇_o.
/// @throw std::invalid_argument on a non-finite input, k < 0, |v_o| >= π/2 or
///        cos u_o cos v_o <= 0 (n3z = 0: eq 13 cannot be solved for ω_z; the contact point is
///        on or above the sphere's equator).
double realizableHeadingRate(double k, const ContactCoordinates& coordinates, double u_o_rate,
                             double v_o_rate);

/// The angular velocity [rad/s, in Σ_a] of the sphere tracing a contact curve at rate θ̇ [1/s]
/// with heading ψ: u̇_o, v̇_o from eq 27, ψ̇ from eq 30 (= eq 20), ω from eqs 17-19. It satisfies
/// eq 13, so rotorSpeeds() can realize it: this is how a plan is executed.
/// @throw std::invalid_argument as realizableCurveRates(), or on a non-finite θ̇.
Eigen::Vector3d curveAngularVelocity(double k, const CurvePoint& curve, double psi,
                                     double theta_rate);

/// Rotor speeds φ̇1, φ̇2 [rad/s] about n1, n2 (eq 11 projected on n1 and n2):
/// φ̇_i = −(J_zz / J_r) n_i · diag(k, k, 1) ω.
struct RotorSpeeds {
  double phi1 = 0.0;
  double phi2 = 0.0;
};

/// Eq 11: rotor speeds for ω [rad/s]; inertia_scale = J_zz / J_r (rotorInertiaScale).
/// @throw std::invalid_argument on a non-finite input, k < 0, inertia_scale <= 0, or if ω is not
///        realizable: |realizabilityResidual| > 1e-9 (|ω| + 1).
RotorSpeeds rotorSpeeds(double k, double inertia_scale, const ContactCoordinates& coordinates,
                        const Eigen::Vector3d& omega);

/// Eq 11 solved for ω [rad/s, in Σ_a], the plant's direction: the sphere's angular velocity for
/// measured rotor speeds, ω = −(1/inertia_scale) diag(1/k, 1/k, 1) (n1 φ̇1 + n2 φ̇2). It always
/// satisfies eq 13. With contactRates() (eqs 6-10) it integrates the rolling sphere.
/// @throw std::invalid_argument on a non-finite input, k <= 0 (J_c singular) or
///        inertia_scale <= 0.
Eigen::Vector3d rotorAngularVelocity(double k, double inertia_scale,
                                     const ContactCoordinates& coordinates,
                                     const RotorSpeeds& speeds);

}  // namespace spherical_robots::rotor
