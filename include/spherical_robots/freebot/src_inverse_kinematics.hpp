#pragma once
// Inverse kinematics of the SRC-joint manipulator (Zong, Liang, Lam 2022, section III-B): the
// adaptive damped least squares of eqs 39-44 applied to the closed-loop reference velocity of
// eqs 45-47, integrated by rolling the joints. No ROS.
//
// Step size and stopping rule (the paper gives neither; docs/conventions.md, "FreeBOT IK"):
// each iteration rolls every joint for `step` seconds at the DLS joint velocity of
// v^r = K_p e_p, ω^r = K_a δ (eqs 45, 46 with a fixed target). With K_p = K_a = 2 I and
// step = 2/3 s the linearised errors shrink by |1 − 2·step| = 1/3 (position) and
// |1 − step| = 1/3 (orientation, since δ ≈ half the rotation vector) per iteration. The step is
// shortened so that no joint rolls more than max_joint_step, and halved (up to 10 times) until
// the residual ‖e_p‖² + ‖δ‖² falls; eq 44's damping fades as the residual vanishes. A start
// ends on success (both errors within tolerance), after max_iterations, when no halved step lowers
// the residual, or when the residual fell by less than 0.02 % over stall_window iterations; the
// solver then restarts from a seeded random configuration, up to `restarts` times, and returns the
// best pose found (errors weighted by their tolerances).

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "spherical_robots/freebot/src_manipulator.hpp"

namespace spherical_robots::freebot {

enum class IkMode {
  FullPose,      ///< position and orientation of B_n (J_{B_n}, 6 rows)
  PositionOnly,  ///< B_n's centre only (J_{B_n v}, 3 rows)
};

struct IkOptions {
  IkMode mode = IkMode::FullPose;
  double position_tolerance = 1e-5;     ///< success: ‖r^d − r‖ <= this [m]
  double orientation_tolerance = 1e-4;  ///< success: angle between q^d and q <= this [rad]
  double position_gain = 2.0;           ///< K_p = k I [1/s] (Table II)
  double orientation_gain = 2.0;        ///< K_a = k I [1/s] (Table II)
  double step = 2.0 / 3.0;              ///< integration step of the joint velocity [s]
  double max_joint_step = 1.0;          ///< largest roll of one joint per iteration [rad]
  double singular_region = 0.01;        ///< ξ of eq 44 (Table II)
  double max_damping = 0.01;            ///< λ_max of eq 44 (Table II)
  /// λ_max is scaled by min(1, ‖r‖ / this) for the residual ‖r‖ = sqrt(‖e_p‖² + ‖δ‖²) [m, −]
  /// (0: eq 44 as printed, which stalls next to singular targets; F7).
  double damping_residual = 0.01;
  int max_iterations = 100;  ///< per start
  int stall_window = 10;     ///< iterations without a 0.02 % improvement end a start
  int restarts = 60;         ///< random restarts after the first start
  std::uint32_t seed = 1;    ///< of the restarts' random configurations
};

struct IkResult {
  bool success = false;
  double position_error = 0.0;        ///< ‖r^d − r‖ [m] of the returned joints
  double orientation_error = 0.0;     ///< angle between q^d and q_{n,I} [rad]; 0 in PositionOnly
  std::vector<SrcJointState> joints;  ///< the best configuration found (closest when unsuccessful)
  LinkPose end;                       ///< B_n's pose for `joints`
  int iterations = 0;                 ///< over all starts
  int starts = 0;                     ///< 1 + restarts used
};

/// Eq 47: δ = η ε^d − η^d ε − ε^d × ε, the vector part of q^d q̃ (orientation error, ≈ half the
/// rotation vector from q to q^d, in the inertial frame).
Eigen::Vector3d orientationError(const Eigen::Quaterniond& current,
                                 const Eigen::Quaterniond& desired);

/// The angle [rad] in [0, π] of the rotation between two unit quaternions.
double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

/// Eqs 39-44: ω = V Σ* U^T x for J x ≈ target twist, with the adaptive damping of eq 44.
Eigen::VectorXd dampedLeastSquares(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& twist,
                                   double singular_region, double max_damping);

/// Solves for the joints that put B_n at the target. `seed`: the first start (empty: aligned).
/// @throw std::invalid_argument on a non-finite target, a non-unit target orientation (FullPose),
/// a seed that does not fit the chain, or options out of range (tolerances, gains, step <= 0,
/// max_iterations < 1, stall_window < 1, restarts < 0, ξ, λ_max or damping_residual < 0).
IkResult solveIk(const SrcManipulator& manipulator, const Eigen::Vector3d& target_position,
                 const Eigen::Quaterniond& target_orientation,
                 const std::vector<SrcJointState>& seed, const IkOptions& options);

}  // namespace spherical_robots::freebot
