#include "spherical_robots/freebot/trolley_control.hpp"

#include <algorithm>
#include <cmath>

#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::freebot {

double effectiveRadius(const SrcJoint& joint) {
  const double a = joint.linkRadius();
  const double b = joint.baseRadius();
  return a * b / (a + b);
}

Eigen::Vector2d jointVelocityOf(const SrcJoint& joint, double forward_speed, double direction) {
  requireFinite(forward_speed, "trolley forward speed u_f [m/s]");
  requireFinite(direction, "trolley direction phi [rad]");
  // Eq 51 (with l'_i, F8): u_f cos φ = l' ω_y, u_f sin φ = −l' ω_x.
  const double scale = forward_speed / effectiveRadius(joint);
  return {-scale * std::sin(direction), scale * std::cos(direction)};
}

TrolleyReference trolleyReference(const SrcJoint& joint, const Eigen::Vector2d& joint_velocity) {
  requireFinite(joint_velocity.x(), "joint velocity omega_x [rad/s]");
  requireFinite(joint_velocity.y(), "joint velocity omega_y [rad/s]");
  TrolleyReference reference;
  reference.forward_speed = effectiveRadius(joint) * joint_velocity.norm();  // eq 52
  // Eq 52's atan2 with two arguments (F8): the quadrant of (−ω_x, ω_y).
  reference.direction =
      joint_velocity.isZero(0.0) ? 0.0 : std::atan2(-joint_velocity.x(), joint_velocity.y());
  return reference;
}

ArcPlan planArc(const SrcJoint& joint, const SrcJointState& current, const SrcJointState& target) {
  SrcJoint::requireValid(current, "current joint state");
  SrcJoint::requireValid(target, "target joint state");
  const double l = joint.baseRadius();
  const Eigen::Vector3d up(0.0, 0.0, l);
  const Eigen::Vector3d target_contact = target.base.conjugate() * up;  // eq 53
  const Eigen::Vector3d current_contact = current.base.conjugate() * up;
  const Eigen::Vector3d offset = current.base * (target_contact - current_contact);  // eq 54
  ArcPlan plan;
  const double cosine = std::clamp((l - std::abs(offset.z())) / l, -1.0, 1.0);
  plan.distance = l * std::acos(cosine);  // eq 55
  // Eq 55's heading, measured from P_i's x axis as eq 48 measures φ (F9).
  plan.direction = std::atan2(offset.y(), offset.x());
  return plan;
}

double steeringSpeed(double reference_direction, double reference_rate, double direction,
                     const TrolleyGains& gains) {
  return reference_rate + gains.steering * wrapToPi(reference_direction - direction);  // eq 56
}

TrolleySpeeds dependentControl(const TrolleyReference& reference, double reference_rate,
                               double direction, const TrolleyGains& gains) {
  const double error = wrapToPi(reference.direction - direction);
  TrolleySpeeds speeds;
  speeds.forward = reference.forward_speed * std::cos(error);  // eq 57
  speeds.steering = steeringSpeed(reference.direction, reference_rate, direction, gains) +
                    gains.alignment * reference.forward_speed * std::sin(error);
  return speeds;
}

double forwardSpeed(double reference_distance, double reference_rate, double distance,
                    const TrolleyGains& gains) {
  return reference_rate + gains.forward * (reference_distance - distance);  // eq 63
}

ArcDrive driveToContact(const SrcJoint& joint, const SrcJointState& start, double heading,
                        const SrcJointState& target, const TrolleyGains& gains, double dt,
                        double heading_tolerance, double distance_tolerance, double max_time) {
  requirePositive(dt, "time step dt [s]");
  requirePositive(heading_tolerance, "heading tolerance [rad]");
  requirePositive(distance_tolerance, "distance tolerance [m]");
  requireFinite(heading, "trolley heading phi [rad]");
  requireFinite(max_time, "max_time [s]");
  const ArcPlan plan = planArc(joint, start, target);
  ArcDrive drive{start, heading, 0.0, 0.0};
  // Steer first (u_f^r = 0, so eq 57 is u_s = u_s^r of eq 56) ...
  while (std::abs(wrapToPi(plan.direction - drive.heading)) > heading_tolerance &&
         drive.time < max_time) {
    drive.heading += dt * steeringSpeed(plan.direction, 0.0, drive.heading, gains);  // eq 49
    drive.time += dt;
  }
  // ... then move forward along the fixed heading (ṡ = u_f, eq 63).
  while (std::abs(plan.distance - drive.distance) > distance_tolerance && drive.time < max_time) {
    const double speed = forwardSpeed(plan.distance, 0.0, drive.distance, gains);
    drive.state = joint.roll(drive.state, jointVelocityOf(joint, speed, drive.heading), dt);
    drive.distance += dt * speed;
    drive.time += dt;
  }
  return drive;
}

}  // namespace spherical_robots::freebot
