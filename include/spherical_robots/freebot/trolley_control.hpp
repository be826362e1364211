#pragma once
// Driving an SRC joint with the FreeBOT trolley (Zong, Liang, Lam 2022, sections IV-B, IV-C):
// joint velocity ↔ trolley forward speed and heading (eqs 48-52), the arc to a target joint
// state (eqs 53-55), and the trolley control laws (eqs 56-63). No ROS.
//
// The trolley sits in B_i at the contact point and heads along φ in the tangent plane P_i
// (φ = 0 along P_i's x axis, counter-clockwise about its normal). Moving forward at u_f it
// rolls the joint at ω = (−sin φ, cos φ) u_f / l' with l' = l_i l_{i-1} / (l_i + l_{i-1})
// (eq 51), and the contact point runs along φ on a great circle of B_{i-1} at the speed u_f.

#include <Eigen/Core>

#include "spherical_robots/freebot/src_joint.hpp"
#include "spherical_robots/freebot/trolley_drive.hpp"

namespace spherical_robots::freebot {

/// A trolley motion along a fixed heading: u_f^r [m/s] >= 0 and φ^r [rad] in (−π, π].
struct TrolleyReference {
  double forward_speed = 0.0;
  double direction = 0.0;
};

/// The arc the contact point has to run on B_{i-1}: s^r [m] >= 0 along φ^r [rad] in (−π, π].
struct ArcPlan {
  double distance = 0.0;
  double direction = 0.0;
};

/// Gains of eqs 56, 57, 63 (Table II: k_s = 3, k_φ1 = 6, k_φ2 = 1).
struct TrolleyGains {
  double forward = 3.0;    ///< k_s [1/s]
  double steering = 6.0;   ///< k_φ1 [1/s]
  double alignment = 1.0;  ///< k_φ2 [1/m]
};

/// l' = l_i l_{i-1} / (l_i + l_{i-1}) [m] of eq 51.
double effectiveRadius(const SrcJoint& joint);

/// Eqs 50, 51: the joint velocity [rad/s] produced by the trolley moving at u_f [m/s] along φ
/// [rad].
/// @throw std::invalid_argument on a non-finite input.
Eigen::Vector2d jointVelocityOf(const SrcJoint& joint, double forward_speed, double direction);

/// Eq 52: the trolley motion that produces the joint velocity [rad/s]. A zero velocity gives
/// u_f = 0, φ = 0. @throw std::invalid_argument on a non-finite velocity.
TrolleyReference trolleyReference(const SrcJoint& joint, const Eigen::Vector2d& joint_velocity);

/// Eqs 53-55: the arc from the contact point of `current` to that of `target`, expressed in the
/// current P_i. @throw std::invalid_argument on a non-unit quaternion.
ArcPlan planArc(const SrcJoint& joint, const SrcJointState& current, const SrcJointState& target);

/// Eq 56: u_s^r = φ̇^r + k_φ1 (φ^r − φ) [rad/s], the heading error wrapped into (−π, π].
double steeringSpeed(double reference_direction, double reference_rate, double direction,
                     const TrolleyGains& gains);

/// Eq 57 (forward and steering dependent): u_f = u_f^r cos φ_e,
/// u_s = u_s^r + k_φ2 u_f^r sin φ_e with φ_e = φ^r − φ.
TrolleySpeeds dependentControl(const TrolleyReference& reference, double reference_rate,
                               double direction, const TrolleyGains& gains);

/// Eq 63: u_f = ṡ^r + k_s (s^r − s) [m/s].
double forwardSpeed(double reference_distance, double reference_rate, double distance,
                    const TrolleyGains& gains);

/// Result of driveToContact().
struct ArcDrive {
  SrcJointState state;    ///< the joint state at the end
  double heading = 0.0;   ///< the trolley's final φ [rad]
  double distance = 0.0;  ///< arc run s [m]
  double time = 0.0;      ///< [s]
};

/// Section IV-C2 (forward and steering independent) run with explicit Euler steps of dt [s]:
/// steer by eq 56 until |φ^r − φ| <= heading_tolerance [rad], then move forward by eq 63 until
/// |s^r − s| <= distance_tolerance [m], each step rolling the joint by eq 51. Stops at
/// max_time [s] otherwise.
/// @throw std::invalid_argument on a non-unit state, dt or a tolerance not > 0.
ArcDrive driveToContact(const SrcJoint& joint, const SrcJointState& start, double heading,
                        const SrcJointState& target, const TrolleyGains& gains, double dt,
                        double heading_tolerance, double distance_tolerance, double max_time);

}  // namespace spherical_robots::freebot
