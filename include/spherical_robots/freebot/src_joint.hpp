#pragma once
// The two-DOF spherical rolling-contact (SRC) joint of Zong, Liang, Lam 2022 (section II): a
// sphere B_i of radius l_i rolling without slipping or spinning on a sphere B_{i-1} of radius
// l_{i-1}. No ROS.
//
// Frames (docs/conventions.md, "FreeBOT"): Σ B_{i-1}, Σ B_i at the sphere centres, Σ P_i at the
// contact point with z along the outward normal of B_{i-1} (towards B_i) and x, y the joint axes
// in the common tangent plane. At the aligned start the three frames have the same orientation
// and B_i sits on top of B_{i-1}. P_i never spins about its normal relative to either body.
//
// Rolling without slipping, derived (docs/errata.md F1-F3): for a joint velocity ω (of B_i
// relative to B_{i-1}, tangent, expressed in P_i) the contact point sweeps the arc length
// l_i l_{i-1} / (l_i + l_{i-1}) ‖ω‖ dt on both spheres, so
//   ^Pω_{B_i}     =  l_{i-1} / (l_i + l_{i-1}) ω    (eq 1 with the radii exchanged)
//   ^Pω_{B_{i-1}} = −l_i     / (l_i + l_{i-1}) ω    (eq 13 with the radii exchanged)
// and B_i's centre moves at −l_i f3^× ω (eq 14 with l_i for l_{i-1}, eq 16's sign, not Table I's).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace spherical_robots::freebot {

/// Largest |‖q‖ − 1| accepted for a quaternion given as input.
constexpr double kUnitTolerance = 1e-9;

/// Full state of one SRC joint: the two quaternions of eq 6 (Hamilton, Eigen's (w, x, y, z)).
/// With unequal radii the state is not a function of q_i alone: it depends on the rolling path.
struct SrcJointState {
  /// q_{i,1}: orientation of B_i relative to P_i (maps B_i coordinates to P_i coordinates).
  Eigen::Quaterniond link = Eigen::Quaterniond::Identity();
  /// q_{i-1,2}: orientation of B_{i-1} relative to P_i (maps B_{i-1} coordinates to P_i's).
  Eigen::Quaterniond base = Eigen::Quaterniond::Identity();
};

/// Spatial velocity basis of eq 8, rows [ω; v] as the paper's ν = [ω^T, v^T]^T.
using FreeModes = Eigen::Matrix<double, 6, 2>;

/// Eq 2: q̇ of a unit quaternion q that maps a body frame into a reference frame, for the body's
/// angular velocity ω [rad/s] relative to and expressed in the reference frame: q̇ = ½ (0, ω) ⊗ q.
/// Returned as a (w, x, y, z) quaternion whose coefficients are the derivative.
/// @throw std::invalid_argument if q or ω is not finite.
Eigen::Quaterniond quaternionRate(const Eigen::Quaterniond& q, const Eigen::Vector3d& omega);

/// The unit quaternion of rotation vector v [rad] (angle ‖v‖ about v / ‖v‖): the exact integral of
/// eq 2 over one second for a constant ω = v in the reference frame.
Eigen::Quaterniond rotationQuaternion(const Eigen::Vector3d& rotation_vector);

/// The rotation vector [rad] of unit q, angle in [0, π].
Eigen::Vector3d rotationVector(const Eigen::Quaterniond& q);

/// The cross-product matrix of v: skew(v) u = v × u.
Eigen::Matrix3d skew(const Eigen::Vector3d& v);

/// @throw std::invalid_argument naming `what` if q has a non-finite coefficient or
/// |‖q‖ − 1| > kUnitTolerance.
void requireUnit(const Eigen::Quaterniond& q, const char* what);

/// One SRC joint between a base sphere of radius l_{i-1} and a link sphere of radius l_i.
class SrcJoint {
 public:
  /// @throw std::invalid_argument if a radius [m] is not finite and > 0.
  SrcJoint(double base_radius, double link_radius);

  double baseRadius() const { return base_radius_; }  ///< l_{i-1} [m]
  double linkRadius() const { return link_radius_; }  ///< l_i [m]

  /// Eq 1, corrected: ^{P_i}ω_{B_i} [rad/s] (B_i relative to P_i, in P_i) for the joint velocity
  /// (ω_x, ω_y) [rad/s] of B_i relative to B_{i-1} along the P_i axes.
  Eigen::Vector3d linkRateInPlane(const Eigen::Vector2d& joint_velocity) const;
  /// Eq 13, corrected: ^{P_i}ω_{B_{i-1}} [rad/s] for the same joint velocity.
  Eigen::Vector3d baseRateInPlane(const Eigen::Vector2d& joint_velocity) const;

  /// The state reached from `state` by rolling with the constant joint velocity [rad/s] for dt
  /// [s]: eqs 1, 13 give both bodies' rates in P_i, and eq 2 integrates exactly for a rate
  /// constant in P_i. Equivalent to eqs 3-5 (corrected ratio) for Δq_{i,1}, Δq_{i-1,2}.
  /// @throw std::invalid_argument on a non-finite velocity or dt.
  SrcJointState roll(const SrcJointState& state, const Eigen::Vector2d& joint_velocity,
                     double dt) const;

  /// The state reached from the aligned start by rolling straight with the constant joint
  /// velocity (u_x, u_y) [rad/s] for one second; its joint quaternion is exp(u) for any radii.
  SrcJointState straightRoll(const Eigen::Vector2d& rotation_vector) const;

  /// Eq 6: q_i = q̃_{i-1,2} q_{i,1}, the orientation of B_i relative to B_{i-1}.
  static Eigen::Quaterniond jointQuaternion(const SrcJointState& state);

  /// Eq 7 rotated into Σ B_{i-1}: centre of B_i [m] relative to B_{i-1}'s,
  /// (l_i + l_{i-1}) f3(q_{i-1,2}).
  Eigen::Vector3d position(const SrcJointState& state) const;

  /// Eq 16, corrected (F2, F3): Φ_i = [f1 f2; −l_i f3^× f1  −l_i f3^× f2], the spatial velocity
  /// [ω; v] of B_i relative to B_{i-1}, in Σ B_{i-1}, per unit joint velocity.
  FreeModes freeModes(const SrcJointState& state) const;

  /// The rotation vector (u_x, u_y) [rad] whose straight roll from the aligned start puts the
  /// contact point where `state` has it on B_{i-1}. It reproduces the whole state when
  /// l_i = l_{i-1} (the reachable states are then exactly the straight rolls); with unequal radii
  /// the orientation may differ. Contact point antipodal to the start: the roll about x.
  Eigen::Vector2d rotationVectorOf(const SrcJointState& state) const;

  /// @throw std::invalid_argument naming the joint if a quaternion is not unit.
  static void requireValid(const SrcJointState& state, const char* what);

 private:
  double base_radius_;
  double link_radius_;
};

}  // namespace spherical_robots::freebot
