#pragma once
// The serial SRC-joint manipulator of Zong, Liang, Lam 2022 (section III): a fixed base sphere
// B_0 (centre at the inertial origin, frames aligned) and links B_1 … B_n, joint i rolling B_i
// on B_{i-1}. Forward kinematics (eqs 17, 26, 27) and the Jacobian J_{B_n} (eqs 24, 25, 31, 32,
// 38). No ROS.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <vector>

#include "spherical_robots/freebot/src_joint.hpp"

namespace spherical_robots::freebot {

/// Pose of link B_i in the inertial frame.
struct LinkPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< ^I r_{B_i} [m], the sphere's centre
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< q_{i,I}: B_i → I
  Eigen::Quaterniond joint = Eigen::Quaterniond::Identity();  ///< q_i of eq 6: B_i → B_{i-1}
};

/// A chain of n >= 1 SRC joints.
class SrcManipulator {
 public:
  /// radii [m] = l_0 (the base's), l_1, …, l_n.
  /// @throw std::invalid_argument if fewer than two radii, or a radius is not finite and > 0.
  explicit SrcManipulator(const std::vector<double>& radii);

  std::size_t jointCount() const { return joints_.size(); }
  const SrcJoint& joint(std::size_t i) const { return joints_.at(i); }  ///< joint i + 1
  const std::vector<double>& radii() const { return radii_; }
  /// Σ (l_{i-1} + l_i) [m]: the largest distance of B_n's centre from B_0's.
  double reach() const { return reach_; }

  /// Every joint rolled straight from the aligned start by its rotation vector [rad].
  /// @throw std::invalid_argument on a count that is not jointCount() or a non-finite value.
  std::vector<SrcJointState> straightRolls(
      const std::vector<Eigen::Vector2d>& rotation_vectors) const;

  /// Eqs 17, 26: the pose of every link B_1 … B_n.
  /// @throw std::invalid_argument on a count that is not jointCount() or a non-unit quaternion.
  std::vector<LinkPose> forwardKinematics(const std::vector<SrcJointState>& joints) const;

  /// Eqs 17, 27: the end-effector B_n's pose; no input checks (the solvers' inner loop).
  LinkPose endEffector(const std::vector<SrcJointState>& joints) const;

  /// Eq 38 (with eqs 25, 31, 32 read in the inertial frame, F5): J_{B_n} [6 × 2n], rows
  /// [v_x, v_y, v_z, ω_x, ω_y, ω_z] of B_n, columns joint 1 x, joint 1 y, joint 2 x, … .
  /// No input checks (the solvers' inner loop); forwardKinematics() checks the same input.
  Eigen::MatrixXd jacobian(const std::vector<SrcJointState>& joints) const;
  /// J_{B_n} and B_n's pose in one pass.
  Eigen::MatrixXd jacobian(const std::vector<SrcJointState>& joints, LinkPose& end) const;

  /// Every joint rolled by its velocity ω (2n values, the order of eq 21) [rad/s] for dt [s].
  std::vector<SrcJointState> roll(const std::vector<SrcJointState>& joints,
                                  const Eigen::VectorXd& joint_velocity, double dt) const;

  /// @throw std::invalid_argument naming the problem unless joints fits this chain.
  void requireValid(const std::vector<SrcJointState>& joints) const;

 private:
  std::vector<double> radii_;
  std::vector<SrcJoint> joints_;
  double reach_ = 0.0;
};

}  // namespace spherical_robots::freebot
