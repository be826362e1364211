#include "spherical_robots/ros/freebot_conversions.hpp"
#include "spherical_robots/core/validation.hpp"

#include <stdexcept>

namespace spherical_robots::conversions {
namespace {

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

}  // namespace spherical_robots::conversions
