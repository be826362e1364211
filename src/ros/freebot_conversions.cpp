#include "spherical_robots/ros/freebot_conversions.hpp"
#include "spherical_robots/core/validation.hpp"

#include <Eigen/Geometry>
#include <cstdint>
#include <stdexcept>

namespace spherical_robots::conversions {
namespace {

constexpr double kTrolleyArrow = 0.02;  // [m] length of a trolley's heading arrow
// [rad] a trolley heading is an angle the chain winds up; no run turns a trolley a million radians.
constexpr double kMaxHeading = 1e6;

}  // namespace

std::vector<std::string> freebotWheelNames(std::size_t modules) {
  std::vector<std::string> names;
  for (std::size_t i = 1; i <= modules; ++i) {
    names.push_back("module" + std::to_string(i) + "_wheel_right");
    names.push_back("module" + std::to_string(i) + "_wheel_left");
  }
  return names;
}

std::vector<freebot::WheelSpeeds> wheelSpeedsFromJointState(const sensor_msgs::JointState& msg,
                                                            std::size_t modules, double max_rate) {
  const std::vector<double> values = velocitiesByName(msg, freebotWheelNames(modules), max_rate);
  std::vector<freebot::WheelSpeeds> wheels(modules);
  for (std::size_t i = 0; i < modules; ++i) wheels[i] = {values[2 * i], values[2 * i + 1]};
  return wheels;
}

sensor_msgs::JointState jointStateFromWheelSpeeds(const std::vector<freebot::WheelSpeeds>& wheels,
                                                  const ros::Time& stamp) {
  std::vector<double> values;
  for (const freebot::WheelSpeeds& pair : wheels) {
    values.push_back(pair.right);
    values.push_back(pair.left);
  }
  return velocityJointState(freebotWheelNames(wheels.size()), values, stamp);
}

spherical_robots::FreebotState toFreebotStateMsg(const freebot::ChainState& state,
                                                 const freebot::LinkPose& end,
                                                 const std::string& frame, const ros::Time& stamp) {
  spherical_robots::FreebotState msg;
  msg.header.stamp = stamp;
  msg.header.frame_id = frame;
  for (const freebot::SrcJointState& joint : state.joints) {
    msg.link.push_back(toQuaternion(joint.link));
    msg.base.push_back(toQuaternion(joint.base));
  }
  msg.heading = state.headings;
  msg.end_effector.position = toPoint(end.position);
  msg.end_effector.orientation = toQuaternion(end.orientation);
  return msg;
}

freebot::ChainState chainStateFromMsg(const spherical_robots::FreebotState& msg) {
  if (msg.link.size() != msg.base.size() || msg.link.size() != msg.heading.size()) {
    throw std::invalid_argument("link, base and heading must have one entry per joint, got " +
                                std::to_string(msg.link.size()) + ", " +
                                std::to_string(msg.base.size()) + ", " +
                                std::to_string(msg.heading.size()));
  }
  freebot::ChainState state;
  for (std::size_t i = 0; i < msg.link.size(); ++i) {
    const std::string joint = "[" + std::to_string(i) + "]";
    state.joints.push_back({fromQuaternion(msg.link[i], "link" + joint),
                            fromQuaternion(msg.base[i], "base" + joint)});
    requireMagnitudeAtMost(msg.heading[i], kMaxHeading, "heading" + joint + " [rad]");
    state.headings.push_back(msg.heading[i]);
  }
  return state;
}


freebot::GoalPose goalPoseFromMsg(const geometry_msgs::PoseStamped& target, const std::string& frame,
                                  double max_distance, double unit_tolerance) {
  const std::string& frame_id = target.header.frame_id;
  if (!frame_id.empty() && frame_id != frame)
    throw std::invalid_argument("target frame_id '" + frame_id + "': expected '" + frame +
                                "' (or empty)");
  const geometry_msgs::Quaternion& q = target.pose.orientation;
  freebot::GoalPose goal;
  goal.position = boundedPoint(target.pose.position, "target.pose.position", max_distance);
  if (q.x == 0.0 && q.y == 0.0 && q.z == 0.0 && q.w == 0.0)
    goal.mode = freebot::IkMode::PositionOnly;
  else
    goal.orientation = fromQuaternion(q, "target.pose.orientation", unit_tolerance);
  return goal;
}

namespace {

using Result = spherical_robots::MoveFreebotResult;
using freebot::GoalStatus;
static_assert(static_cast<int>(GoalStatus::Moving) == spherical_robots::MoveFreebotFeedback::MOVING &&
                  static_cast<int>(GoalStatus::Arrived) == Result::ARRIVED &&
                  static_cast<int>(GoalStatus::Unreachable) == Result::UNREACHABLE &&
                  static_cast<int>(GoalStatus::Rejected) == Result::REJECTED &&
                  static_cast<int>(GoalStatus::Preempted) == Result::PREEMPTED &&
                  static_cast<int>(GoalStatus::Aborted) == Result::ABORTED,
              "freebot::GoalStatus must list action/MoveFreebot.action's codes in order");

/// The fields a result and a feedback share, from a verdict.
template <typename Message>
Message fromVerdict(const freebot::GoalVerdict& verdict) {
  Message message;
  message.status = static_cast<std::uint8_t>(verdict.status);
  message.position_error = verdict.position_error;
  message.orientation_error = verdict.orientation_error;
  message.elapsed = verdict.elapsed;
  message.replans = static_cast<std::uint32_t>(verdict.replans);
  message.message = verdict.message;
  return message;
}

}  // namespace

spherical_robots::MoveFreebotResult toMoveFreebotResult(const freebot::GoalVerdict& verdict) {
  return fromVerdict<spherical_robots::MoveFreebotResult>(verdict);
}

spherical_robots::MoveFreebotFeedback toMoveFreebotFeedback(const freebot::GoalVerdict& progress) {
  return fromVerdict<spherical_robots::MoveFreebotFeedback>(progress);
}

std::string freebotLinkFrame(const std::string& prefix, std::size_t i) {
  return prefix + "link" + std::to_string(i);
}

std::vector<geometry_msgs::TransformStamped> freebotChainTransforms(
    const freebot::SrcManipulator& manipulator, const freebot::ChainState& state,
    const std::string& prefix, const ros::Time& stamp) {
  std::vector<geometry_msgs::TransformStamped> transforms;
  for (std::size_t i = 1; i <= state.joints.size(); ++i) {
    const freebot::SrcJointState& joint = state.joints[i - 1];
    transforms.push_back(toTransform(manipulator.joint(i - 1).position(joint),
                                     freebot::SrcJoint::jointQuaternion(joint),
                                     freebotLinkFrame(prefix, i - 1), freebotLinkFrame(prefix, i),
                                     stamp));
  }
  return transforms;
}

visualization_msgs::MarkerArray freebotChainMarkers(const freebot::SrcManipulator& manipulator,
                                                    const freebot::ChainState& state,
                                                    const std::string& prefix,
                                                    const ros::Time& stamp) {
  const std::vector<double>& radii = manipulator.radii();
  visualization_msgs::MarkerArray markers;
  for (std::size_t i = 0; i <= state.joints.size(); ++i) {
    auto sphere = marker("spheres", static_cast<int>(i), visualization_msgs::Marker::SPHERE,
                         freebotLinkFrame(prefix, i), stamp);
    sphere.frame_locked = true;
    sphere.scale.x = sphere.scale.y = sphere.scale.z = 2.0 * radii[i];
    sphere.color.r = i == 0 ? 0.5f : 0.2f;
    sphere.color.g = 0.5f;
    sphere.color.b = i == 0 ? 0.5f : 0.9f;
    sphere.color.a = 0.6f;
    markers.markers.push_back(sphere);
    if (i == 0) continue;
    // The trolley at the contact point, heading φ_i in P_i (P_i relative to B_{i-1}: q̃_{i-1,2}).
    auto trolley = marker("trolleys", static_cast<int>(i), visualization_msgs::Marker::ARROW,
                          freebotLinkFrame(prefix, i - 1), stamp);
    trolley.frame_locked = true;
    const Eigen::Quaterniond plane = state.joints[i - 1].base.conjugate();
    trolley.pose.position = toPoint(plane * Eigen::Vector3d(0.0, 0.0, radii[i - 1]));
    trolley.pose.orientation =
        toQuaternion(plane * Eigen::AngleAxisd(state.headings[i - 1], Eigen::Vector3d::UnitZ()));
    trolley.scale.x = kTrolleyArrow;
    trolley.scale.y = trolley.scale.z = 0.2 * kTrolleyArrow;
    trolley.color.r = 1.0f;
    trolley.color.g = 0.5f;
    trolley.color.b = 0.0f;
    markers.markers.push_back(trolley);
  }
  return markers;
}

}  // namespace spherical_robots::conversions
