#include "spherical_robots/freebot/src_joint.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::freebot {
namespace {

void requireFiniteVelocity(const Eigen::Vector2d& joint_velocity) {
  requireFinite(joint_velocity.x(), "joint velocity omega_x [rad/s]");
  requireFinite(joint_velocity.y(), "joint velocity omega_y [rad/s]");
}

}  // namespace

Eigen::Quaterniond quaternionRate(const Eigen::Quaterniond& q, const Eigen::Vector3d& omega) {
  requireFinite(q.w(), "quaternion w");
  requireFinite(q.x(), "quaternion x");
  requireFinite(q.y(), "quaternion y");
  requireFinite(q.z(), "quaternion z");
  requireFinite(omega.x(), "omega_x [rad/s]");
  requireFinite(omega.y(), "omega_y [rad/s]");
  requireFinite(omega.z(), "omega_z [rad/s]");
  // Eq 2: η̇ = −½ ω·ε, ε̇ = ½ (η ω − ε × ω).
  const Eigen::Vector3d epsilon = q.vec();
  const Eigen::Vector3d epsilon_rate = 0.5 * (q.w() * omega - epsilon.cross(omega));
  return Eigen::Quaterniond(-0.5 * omega.dot(epsilon), epsilon_rate.x(), epsilon_rate.y(),
                            epsilon_rate.z());
}

Eigen::Quaterniond rotationQuaternion(const Eigen::Vector3d& rotation_vector) {
  const double angle = rotation_vector.norm();
  // sin(θ/2)/θ by its series where dividing would lose digits.
  const double half_sinc =
      angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(0.5 * angle) / angle;
  const Eigen::Vector3d v = half_sinc * rotation_vector;
  return Eigen::Quaterniond(std::cos(0.5 * angle), v.x(), v.y(), v.z());
}

Eigen::Vector3d rotationVector(const Eigen::Quaterniond& q) {
  // q and −q are one rotation: take the one with w >= 0 for an angle in [0, π].
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;
  const Eigen::Vector3d v = sign * q.vec();
  const double s = v.norm();
  if (s == 0.0) {
    return Eigen::Vector3d::Zero();
  }
  const double angle = 2.0 * std::atan2(s, sign * q.w());
  return angle / s * v;
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

void requireUnit(const Eigen::Quaterniond& q, const char* what) {
  for (int k = 0; k < 4; ++k) {
    requireFinite(q.coeffs()[k], what);
  }
  const double deviation = std::abs(q.norm() - 1.0);
  if (deviation > kUnitTolerance) {
    std::ostringstream message;
    message << what << " must be a unit quaternion (||q| - 1| <= " << kUnitTolerance
            << "), got |q| = ";
    message.precision(17);
    message << q.norm();
    throw std::invalid_argument(message.str());
  }
}

SrcJoint::SrcJoint(double base_radius, double link_radius)
    : base_radius_(base_radius), link_radius_(link_radius) {
  requireLength(base_radius, "base sphere radius l_{i-1} [m]");
  requireLength(link_radius, "link sphere radius l_i [m]");
}

Eigen::Vector3d SrcJoint::linkRateInPlane(const Eigen::Vector2d& joint_velocity) const {
  requireFiniteVelocity(joint_velocity);
  const double ratio = base_radius_ / (base_radius_ + link_radius_);  // eq 1 corrected (F1)
  return {ratio * joint_velocity.x(), ratio * joint_velocity.y(), 0.0};
}

Eigen::Vector3d SrcJoint::baseRateInPlane(const Eigen::Vector2d& joint_velocity) const {
  requireFiniteVelocity(joint_velocity);
  const double ratio = -link_radius_ / (base_radius_ + link_radius_);  // eq 13 corrected (F1)
  return {ratio * joint_velocity.x(), ratio * joint_velocity.y(), 0.0};
}

SrcJointState SrcJoint::roll(const SrcJointState& state, const Eigen::Vector2d& joint_velocity,
                             double dt) const {
  requireFinite(dt, "roll duration dt [s]");
  // Both rates are constant in P_i, so eq 2 integrates to a left product (0, ω) ⊗ q → exp(ω dt) q.
  SrcJointState next;
  next.link = rotationQuaternion(dt * linkRateInPlane(joint_velocity)) * state.link;
  next.base = rotationQuaternion(dt * baseRateInPlane(joint_velocity)) * state.base;
  return next;
}

SrcJointState SrcJoint::straightRoll(const Eigen::Vector2d& rotation_vector) const {
  return roll(SrcJointState{}, rotation_vector, 1.0);
}

Eigen::Quaterniond SrcJoint::jointQuaternion(const SrcJointState& state) {
  return state.base.conjugate() * state.link;  // eq 6
}

Eigen::Vector3d SrcJoint::position(const SrcJointState& state) const {
  // Eq 7 is [0, 0, l_i + l_{i-1}] in Σ P_i; ^{B_{i-1}}R_{P_i} = R(q̃_{i-1,2}) = [f1 f2 f3] (eq 10).
  return (base_radius_ + link_radius_) * (state.base.conjugate() * Eigen::Vector3d::UnitZ());
}

FreeModes SrcJoint::freeModes(const SrcJointState& state) const {
  const Eigen::Matrix3d plane = state.base.conjugate().toRotationMatrix();  // [f1 f2 f3], eq 10
  FreeModes phi;
  phi.topRows<3>() = plane.leftCols<2>();  // eq 11
  phi.bottomRows<3>() =
      -link_radius_ * skew(plane.col(2)) * plane.leftCols<2>();  // eqs 15, 16 (F2, F3)
  return phi;
}

Eigen::Vector2d SrcJoint::rotationVectorOf(const SrcJointState& state) const {
  const Eigen::Vector3d normal = state.base.conjugate() * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ().cross(normal);
  const double tilt = std::atan2(axis.norm(), normal.z());  // polar angle of the contact point
  // A straight roll u tilts the contact by l_i / (l_i + l_{i-1}) ‖u‖ about u.
  const double length = tilt * (base_radius_ + link_radius_) / link_radius_;
  if (axis.norm() < 1e-300) {
    return normal.z() > 0.0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(length, 0.0);
  }
  return length * axis.head<2>() / axis.norm();
}

void SrcJoint::requireValid(const SrcJointState& state, const char* what) {
  const std::string name(what);
  requireUnit(state.link, (name + " q_{i,1}").c_str());
  requireUnit(state.base, (name + " q_{i-1,2}").c_str());
}

}  // namespace spherical_robots::freebot
