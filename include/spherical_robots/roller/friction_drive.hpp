#pragma once
// A sphere driven by two constraint rollers, with slip (Kimura, Ogata, Ishii 2019): roller
// peripheral speeds to the sphere's angular velocity (forward, eq 11) and a desired motion to
// roller speeds (inverse, eqs 18, 19, 22), the roller slip velocities (eqs 25-28) and the sphere's
// resulting motion (eqs 13-15). No ROS.
//
// Each roller allows the angular velocities on a line l_i(v_i) = {−(v_i/r) η_i + k P_i} (eq 4):
// on it the sphere rolls on roller i without slipping. Two such lines meet only when
// v1 sin α1 = v2 sin α2; otherwise no ω satisfies both rollers and the paper's ω (eq 11) is the
// midpoint of their common perpendicular. That point minimises the sum of squared distances to
// the two lines, and since ‖ζ_i‖ = r · dist(ω, l_i), it is the angular velocity with the least
// total squared slip ‖ζ1‖² + ‖ζ2‖² (docs/conventions.md, "Friction drive").

#include <Eigen/Core>
#include <array>
#include <cstddef>

#include "spherical_robots/roller/roller_geometry.hpp"

namespace spherical_robots::roller {

/// Roller peripheral speeds [m/s], signed: roller i's surface at P_i moves with v_i e_i
/// (RollerContact::rolling_direction), the convention of eqs 2 and 22.
struct RollerSpeeds {
  double v1 = 0.0;
  double v2 = 0.0;
};

/// The sphere's motion on a horizontal floor below O, rolling there without slip (eqs 13-15):
/// V = ω × r z = r (ω_y, −ω_x, 0) is the velocity of the centre O.
struct SphereMotion {
  double speed = 0.0;      ///< ‖V‖ [m/s], >= 0
  double direction = 0.0;  ///< φ [rad] in [0, 2π): V = ‖V‖ (cos φ, sin φ, 0)
  double rho = 0.0;        ///< ρ [rad] in (−π/2, π/2): elevation of ω above the xy plane
};

/// Everything the drive determines for one set of roller speeds.
struct DriveState {
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();  ///< ω [rad/s]
  SphereMotion motion;
  RollerSpeeds speeds;           ///< v1, v2 [m/s]
  std::array<double, 2> slip{};  ///< S1, S2 [m/s]: ζ_i = S_i X_i (eqs 27, 28)
};

/// The friction drive's kinematics over a checked RollerGeometry.
class FrictionDrive {
 public:
  explicit FrictionDrive(const RollerGeometry& geometry);

  const RollerGeometry& geometry() const { return geometry_; }

  /// ∂ω/∂v_i [1/m] of eq 11: ω = v1 b_1 + v2 b_2. b_1 is the paper's Y and b_2 its X (eq 17);
  /// index 0 is roller 1. They span the plane every forward ω lies in ("span{X, Y}").
  const Eigen::Vector3d& omegaPerSpeed(std::size_t roller) const;
  /// Unit normal of span{X, Y} (the direction of X × Y, eq 18).
  const Eigen::Vector3d& omegaPlaneNormal() const { return plane_normal_; }

  /// Eq 11: ω [rad/s] = ω_t + ω_s for roller speeds [m/s]; the midpoint of the common
  /// perpendicular of l_1(v1) and l_2(v2), i.e. their intersection when they meet.
  /// @throw std::invalid_argument on a non-finite speed.
  Eigen::Vector3d angularVelocity(const RollerSpeeds& speeds) const;

  /// Eq 22: the roller speeds [m/s] for which ω [rad/s] satisfies eq 20,
  /// ⟨ω, X_i⟩ = −v_i cos α_i / r (the roller drives ω's component in span{P1, P2}).
  /// @throw std::invalid_argument on a non-finite component.
  RollerSpeeds rollerSpeeds(const Eigen::Vector3d& omega) const;

  /// Eq 18: the axis elevation ρ [rad] in (−π/2, π/2) of the ω in span{X, Y} whose horizontal part
  /// drives the sphere in direction φ [rad].
  /// @throw std::invalid_argument if φ is not finite, or if span{X, Y} is vertical
  ///        (|(X × Y)_z| <= kDegenerateTolerance ‖X × Y‖): eq 18 divides by (X × Y)_z, and only
  ///        two opposite directions can be driven.
  double rho(double direction) const;

  /// Eqs 15, 18, 19: ω [rad/s] for speed ‖V‖ [m/s] >= 0 in direction φ [rad].
  /// @throw std::invalid_argument as rho(), or if the speed is negative or not finite.
  Eigen::Vector3d angularVelocityFor(double speed, double direction) const;

  /// Eq 25: roller i's slip velocity ζ_i = ω × P_i − v_i e_i [m/s], the sphere's surface velocity
  /// at P_i relative to the roller's, for any ω [rad/s] and speeds [m/s]; roller 0 is roller 1.
  /// @throw std::out_of_range if roller > 1, std::invalid_argument on a non-finite input.
  Eigen::Vector3d slipVelocity(const Eigen::Vector3d& omega, const RollerSpeeds& speeds,
                               std::size_t roller) const;

  /// Eq 28: S_i = ⟨ζ_i, X_i⟩ [m/s]. For ω from eq 11, ζ_i = S_i X_i (eqs 26, 27) and
  /// S1 = −S2 = (v1 sin α1 − v2 sin α2) / 2.
  /// @throw std::invalid_argument on a non-finite input.
  std::array<double, 2> slipSpeeds(const Eigen::Vector3d& omega, const RollerSpeeds& speeds) const;

  /// ‖ζ1‖² + ‖ζ2‖² [m²/s²] for any ω [rad/s]: the quantity eq 11's ω minimises over all ω for
  /// given speeds [m/s]. Equals r² (d1² + d2²) with d_i = constraintLineDistance(…, i).
  /// @throw std::invalid_argument on a non-finite input.
  double squaredSlip(const Eigen::Vector3d& omega, const RollerSpeeds& speeds) const;

  /// Distance [rad/s] from ω [rad/s] to roller i's constraint line l_i(v_i) (eq 4).
  /// @throw std::out_of_range if roller > 1, std::invalid_argument on a non-finite input.
  double constraintLineDistance(const Eigen::Vector3d& omega, const RollerSpeeds& speeds,
                                std::size_t roller) const;

  /// Distance [rad/s] between the lines l_1(v1) and l_2(v2): |v1 sin α1 − v2 sin α2| / r (eq 9).
  /// Zero exactly when they meet, and then eq 11's ω rolls on both rollers without slip.
  /// @throw std::invalid_argument on a non-finite speed.
  double constraintLineGap(const RollerSpeeds& speeds) const;

  /// Forward kinematics: ω (eq 11), the motion (eq 14) and the slip (eq 28) for roller speeds
  /// [m/s].
  /// @throw std::invalid_argument on a non-finite speed, or if ω has no horizontal component
  ///        (see sphereMotion): the sphere does not translate and has no direction.
  DriveState forward(const RollerSpeeds& speeds) const;

  /// Inverse kinematics: ω (eqs 18, 19), the roller speeds (eq 22) and the slip (eq 28) for speed
  /// ‖V‖ [m/s] >= 0 in direction φ [rad]. forward(inverse(‖V‖, φ).speeds) gives back ω, ‖V‖, φ and
  /// ρ (for ‖V‖ > 0), whether or not the constraint lines meet.
  /// @throw std::invalid_argument as angularVelocityFor().
  DriveState inverse(double speed, double direction) const;

 private:
  const RollerContact& contact(std::size_t roller) const;
  /// tan ρ of eq 18, with rho()'s checks.
  double tanRho(double direction) const;

  RollerGeometry geometry_;
  std::array<Eigen::Vector3d, 2> omega_per_speed_;
  Eigen::Vector3d plane_normal_;
};

/// Eq 14 done right: the motion of a sphere of radius r [m] spinning at ω [rad/s] on a floor below
/// its centre: ‖V‖ = r ‖ω_xy‖, φ = atan2(−ω_x, ω_y) in [0, 2π), ρ = atan(ω_z / ‖ω_xy‖).
/// @throw std::invalid_argument if r is not finite and > 0, ω is not finite, or ω has no
///        horizontal component (‖ω_xy‖ <= kDegenerateTolerance ‖ω‖, ω = 0 included): φ undefined.
SphereMotion sphereMotion(const Eigen::Vector3d& omega, double radius);

}  // namespace spherical_robots::roller
