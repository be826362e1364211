#include "spherical_robots/ros/freebot_plant_ros.hpp"

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Geometry>
#include <sstream>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/FreebotState.h"
#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {
namespace {

const std::string kWorldFrame = "world";
constexpr double kTrolleyArrow = 0.02;  // [m] length of a trolley's heading arrow
constexpr std::size_t kMaxTrailPoints = 5000;

visualization_msgs::Marker marker(const std::string& frame, const ros::Time& stamp,
                                  const std::string& ns, int id, int type) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame;
  m.header.stamp = stamp;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.frame_locked = true;
  m.pose.orientation.w = 1.0;
  return m;
}

}  // namespace

freebot::FreebotChain freebotChainFromParams(const ros::NodeHandle& nh) {
  std::vector<double> radii;
  if (!nh.getParam("radii", radii))
    throw std::invalid_argument("parameter " + nh.resolveName("radii") +
                                " (list of sphere radii [m], base first) is required");
  freebot::TrolleyGeometry trolley;
  trolley.wheel_radius = positiveParam(nh, "trolley/wheel_radius", trolley.wheel_radius);
  trolley.wheel_interval = positiveParam(nh, "trolley/wheel_interval", trolley.wheel_interval);
  trolley.shell_thickness = positiveParam(nh, "trolley/shell_thickness", trolley.shell_thickness);
  try {
    return freebot::FreebotChain(radii, trolley);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("parameters " + nh.resolveName("radii") + ", " +
                                nh.resolveName("trolley") + ": " + e.what());
  }
}

std::string freebotLinkFrame(const std::string& prefix, std::size_t i) {
  return prefix + "link" + std::to_string(i);
}

FreebotPlantRos::FreebotPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : chain_(freebotChainFromParams(nh)),
      prefix_(stringParam(pnh, "frame_prefix", "")),
      step_(positiveParam(pnh, "step", 0.01)),
      timeline_(pnh),
      max_actuator_rate_(positiveParam(pnh, "max_actuator_rate", 1000.0)),
      publish_period_(1.0 / positiveParam(pnh, "publish_rate", 50.0)),
      trail_(nh, "trail", kWorldFrame, positiveParam(pnh, "trail_period", 0.1), kMaxTrailPoints),
      state_(chain_.alignedState()),
      wheels_(chain_.moduleCount()),
      actuator_input_(nh.resolveName("actuators/state"), positiveParam(pnh, "state_timeout", 0.1)),
      updater_(nh, pnh) {
  actuator_sub_ = nh.subscribe("actuators/state", 10, &FreebotPlantRos::onActuatorState, this);
  state_pub_ = nh.advertise<spherical_robots::FreebotState>("freebot_state", kLoopQueueSize);
  marker_pub_ = nh.advertise<visualization_msgs::MarkerArray>("freebot_markers", kLoopQueueSize);
  updater_.setHardwareID("FreeBOT");
  updater_.add("freebot plant", this, &FreebotPlantRos::diagnose);
  diagnostics_timer_ = startDiagnostics(nh, updater_);

  std::ostringstream radii;
  for (double r : chain_.manipulator().radii()) radii << (radii.tellp() > 0 ? ", " : "") << r;
  ROS_INFO_STREAM("FreeBOT chain: " << chain_.moduleCount() << " modules, radii [" << radii.str()
                                    << "] m, reach " << chain_.manipulator().reach()
                                    << " m; step " << step_ << " s");
  clock_ = makePlantClock(nh, pnh, step_, 1.0, [this](const ros::Time& now) { return tick(now); },
                          state_pub_, actuator_sub_);
}

void FreebotPlantRos::onActuatorState(const sensor_msgs::JointState& msg) {
  try {
    wheels_ = conversions::wheelSpeedsFromJointState(msg, chain_.moduleCount(), max_actuator_rate_);
    actuator_input_.accept(clock_ ? clock_->now() : ros::Time::now());
  } catch (const std::invalid_argument& e) {
    actuator_input_.reject(e.what());
  }
  if (clock_) clock_->received(actuator_sub_.getTopic(), msg.header.stamp);
}

std::vector<std::string> FreebotPlantRos::tick(const ros::Time& now) {
  if (timeline_.finished()) return {};
  const std::vector<freebot::WheelSpeeds> wheels =
      actuator_input_.fresh(now) ? wheels_
                                 : std::vector<freebot::WheelSpeeds>(chain_.moduleCount());
  timeline_.tick(now, [&](double elapsed) {
    freebot::ChainState next = chain_.advance(state_, wheels, elapsed);
    // Nothing non-finite is published: a step that would produce it is a failed step.
    for (std::size_t i = 0; i < next.joints.size(); ++i) {
      if (!next.joints[i].link.coeffs().allFinite() || !next.joints[i].base.coeffs().allFinite() ||
          !std::isfinite(next.headings[i]))
        throw std::runtime_error("the step produced a non-finite state of joint " +
                                 std::to_string(i + 1));
    }
    state_ = std::move(next);
  });
  const freebot::LinkPose end = chain_.manipulator().endEffector(state_.joints);
  state_pub_.publish(conversions::toFreebotStateMsg(state_, end, kWorldFrame, now));
  if (trail_.due(now)) trail_.add(now, end.position, end.orientation);
  std::vector<std::string> published = {state_pub_.getTopic()};
  if (periodDue(last_publish_, now, publish_period_)) {
    publishFrames(now);
    published.insert(published.end(), {marker_pub_.getTopic(), "/tf"});
  }

  if (timeline_.complete(now)) {
    ROS_INFO_STREAM("scenario complete after " << timeline_.duration() << " s");
    clock_->finish();
  }
  return published;
}

void FreebotPlantRos::publishFrames(const ros::Time& now) {
  last_publish_ = now;
  const auto& radii = chain_.manipulator().radii();
  std::vector<geometry_msgs::TransformStamped> transforms;
  transforms.push_back(conversions::toTransform(Eigen::Vector3d::Zero(),
                                                Eigen::Quaterniond::Identity(), kWorldFrame,
                                                freebotLinkFrame(prefix_, 0), now));
  visualization_msgs::MarkerArray markers;
  for (std::size_t i = 0; i <= chain_.moduleCount(); ++i) {
    const std::string frame = freebotLinkFrame(prefix_, i);
    auto sphere = marker(frame, now, "spheres", static_cast<int>(i),
                         visualization_msgs::Marker::SPHERE);
    sphere.scale.x = sphere.scale.y = sphere.scale.z = 2.0 * radii[i];
    sphere.color.r = i == 0 ? 0.5f : 0.2f;
    sphere.color.g = i == 0 ? 0.5f : 0.5f;
    sphere.color.b = i == 0 ? 0.5f : 0.9f;
    sphere.color.a = 0.6f;
    markers.markers.push_back(sphere);
    if (i == 0) continue;
    const freebot::SrcJoint& joint = chain_.manipulator().joint(i - 1);
    const freebot::SrcJointState& state = state_.joints[i - 1];
    transforms.push_back(conversions::toTransform(joint.position(state),
                                                  freebot::SrcJoint::jointQuaternion(state),
                                                  freebotLinkFrame(prefix_, i - 1), frame, now));
    // The trolley at the contact point, heading φ_i in P_i (P_i relative to B_{i-1}: q̃_{i-1,2}).
    auto trolley = marker(freebotLinkFrame(prefix_, i - 1), now, "trolleys", static_cast<int>(i),
                          visualization_msgs::Marker::ARROW);
    const Eigen::Quaterniond plane = state.base.conjugate();
    trolley.pose.position = conversions::toPoint(plane * Eigen::Vector3d(0.0, 0.0, radii[i - 1]));
    trolley.pose.orientation = conversions::toQuaternion(
        plane * Eigen::AngleAxisd(state_.headings[i - 1], Eigen::Vector3d::UnitZ()));
    trolley.scale.x = kTrolleyArrow;
    trolley.scale.y = trolley.scale.z = 0.2 * kTrolleyArrow;
    trolley.color.r = 1.0f;
    trolley.color.g = 0.5f;
    trolley.color.a = 1.0f;
    markers.markers.push_back(trolley);
  }
  tf_broadcaster_.sendTransform(transforms);
  marker_pub_.publish(markers);
}

void FreebotPlantRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const ros::Time now = ros::Time::now();
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "integrating measured wheel speeds");
  status.add("modules", chain_.moduleCount());
  const freebot::LinkPose end = chain_.manipulator().endEffector(state_.joints);
  status.addf("end-effector [m]", "%.6f, %.6f, %.6f", end.position.x(), end.position.y(),
              end.position.z());
  reportPlantHealth(status, now, *clock_, timeline_, actuator_input_);
}

}  // namespace spherical_robots
