#include "spherical_robots/freebot/src_manipulator.hpp"

#include <stdexcept>
#include <string>

namespace spherical_robots::freebot {

SrcManipulator::SrcManipulator(const std::vector<double>& radii) : radii_(radii) {
  if (radii_.size() < 2) {
    throw std::invalid_argument(
        "an SRC manipulator needs at least 2 radii (base l_0 and l_1), got " +
        std::to_string(radii_.size()));
  }
  for (std::size_t i = 1; i < radii_.size(); ++i) {
    joints_.emplace_back(radii_[i - 1], radii_[i]);
    reach_ += radii_[i - 1] + radii_[i];
  }
}

void SrcManipulator::requireValid(const std::vector<SrcJointState>& joints) const {
  if (joints.size() != joints_.size()) {
    throw std::invalid_argument("joint count must equal the number of radii minus 1 (" +
                                std::to_string(joints_.size()) + "), got " +
                                std::to_string(joints.size()));
  }
  for (std::size_t i = 0; i < joints.size(); ++i) {
    SrcJoint::requireValid(joints[i], ("joint " + std::to_string(i + 1)).c_str());
  }
}

std::vector<SrcJointState> SrcManipulator::straightRolls(
    const std::vector<Eigen::Vector2d>& rotation_vectors) const {
  if (rotation_vectors.size() != joints_.size()) {
    throw std::invalid_argument("joint count must equal the number of radii minus 1 (" +
                                std::to_string(joints_.size()) + "), got " +
                                std::to_string(rotation_vectors.size()));
  }
  std::vector<SrcJointState> states;
  states.reserve(joints_.size());
  for (std::size_t i = 0; i < joints_.size(); ++i) {
    states.push_back(joints_[i].straightRoll(rotation_vectors[i]));
  }
  return states;
}

std::vector<LinkPose> SrcManipulator::forwardKinematics(
    const std::vector<SrcJointState>& joints) const {
  requireValid(joints);
  std::vector<LinkPose> poses;
  poses.reserve(joints.size());
  LinkPose previous;  // B_0: at the origin, aligned with I
  for (std::size_t i = 0; i < joints.size(); ++i) {
    LinkPose pose;
    pose.joint = SrcJoint::jointQuaternion(joints[i]);
    pose.position =
        previous.position + previous.orientation * joints_[i].position(joints[i]);  // eq 26
    pose.orientation = (previous.orientation * pose.joint).normalized();            // eq 17
    poses.push_back(pose);
    previous = pose;
  }
  return poses;
}

LinkPose SrcManipulator::endEffector(const std::vector<SrcJointState>& joints) const {
  LinkPose pose;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    pose.joint = SrcJoint::jointQuaternion(joints[i]);
    pose.position += pose.orientation * joints_[i].position(joints[i]);  // eq 27
    pose.orientation = pose.orientation * pose.joint;                    // eq 17
  }
  pose.orientation.normalize();
  return pose;
}

Eigen::MatrixXd SrcManipulator::jacobian(const std::vector<SrcJointState>& joints) const {
  LinkPose end;
  return jacobian(joints, end);
}

Eigen::MatrixXd SrcManipulator::jacobian(const std::vector<SrcJointState>& joints,
                                         LinkPose& end) const {
  const std::size_t n = joints.size();
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(6, 2 * static_cast<Eigen::Index>(n));
  // Angular part, eq 25: column pair i is ^I R_{B_{i-1}} Φ_{iω}. Linear part, eqs 31, 32:
  // ^I R_{B_{i-1}} Φ_{iv} − Σ_{j > i} d_j^× ^I R_{B_{i-1}} Φ_{iω}, with d_j = ^I r_{B_j} − ^I
  // r_{B_{j-1}}: joint i turns all of B_i … B_n rigidly, so its angular column moves B_n's centre
  // by ω × (r_n − r_i). Accumulated in one forward pass as −d_j^× J_{B_{j-1}ω}.
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Matrix3d rotation = orientation.toRotationMatrix();
    const FreeModes phi = joints_[i].freeModes(joints[i]);
    const Eigen::Index column = 2 * static_cast<Eigen::Index>(i);
    jac.block<3, 2>(3, column) = rotation * phi.topRows<3>();
    jac.block<3, 2>(0, column) = rotation * phi.bottomRows<3>();
    const Eigen::Vector3d step = rotation * joints_[i].position(joints[i]);
    // Link i+1's displacement is swung by every joint up to and including i+1's base rotation.
    jac.block(0, 0, 3, column) -= skew(step) * jac.block(3, 0, 3, column);
    position += step;
    orientation = orientation * SrcJoint::jointQuaternion(joints[i]);
  }
  end.position = position;
  end.orientation = orientation.normalized();
  end.joint = n > 0 ? SrcJoint::jointQuaternion(joints.back()) : Eigen::Quaterniond::Identity();
  return jac;
}

std::vector<SrcJointState> SrcManipulator::roll(const std::vector<SrcJointState>& joints,
                                                const Eigen::VectorXd& joint_velocity,
                                                double dt) const {
  std::vector<SrcJointState> next;
  next.reserve(joints.size());
  for (std::size_t i = 0; i < joints.size(); ++i) {
    next.push_back(joints_[i].roll(joints[i], joint_velocity.segment<2>(2 * i), dt));
  }
  return next;
}

}  // namespace spherical_robots::freebot
