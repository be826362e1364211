#include "spherical_robots/ros/freebot_plant_ros.hpp"

#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Geometry>
#include <sstream>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/FreebotState.h"
#include "spherical_robots/ros/freebot_conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {
namespace {

constexpr double kTrolleyArrow = 0.02;  // [m] length of a trolley's heading arrow

PlantLoop::Defaults loopDefaults() {
  PlantLoop::Defaults defaults;
  defaults.task = "freebot plant";
  defaults.hardware_id = "FreeBOT";
  defaults.step = 0.01;
  defaults.pace = 1.0;
  defaults.state_timeout = 0.1;
  defaults.trail_period = 0.1;
  defaults.max_trail_points = 5000;
  return defaults;
}

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
      max_actuator_rate_(positiveParam(pnh, "max_actuator_rate", 1000.0)),
      state_(chain_.alignedState()),
      wheels_(chain_.moduleCount()),
      loop_(nh, pnh, loopDefaults()) {
  state_pub_ = loop_.advertise<spherical_robots::FreebotState>("freebot_state");
  marker_pub_ = loop_.advertise<visualization_msgs::MarkerArray>("freebot_markers");
  std::ostringstream radii;
  for (double r : chain_.manipulator().radii()) radii << (radii.tellp() > 0 ? ", " : "") << r;
  ROS_INFO_STREAM("FreeBOT chain: " << chain_.moduleCount() << " modules, radii [" << radii.str()
                                    << "] m, reach " << chain_.manipulator().reach()
                                    << " m; step " << loop_.step() << " s");
  loop_.start(*this, state_pub_);
}

void FreebotPlantRos::read(const sensor_msgs::JointState& actuators) {
  wheels_ = conversions::wheelSpeedsFromJointState(actuators, chain_.moduleCount(), max_actuator_rate_);
}

void FreebotPlantRos::advance(double elapsed, bool actuators_fresh) {
  freebot::ChainState next = chain_.advance(
      state_, actuators_fresh ? wheels_ : std::vector<freebot::WheelSpeeds>(chain_.moduleCount()),
      elapsed);
  // Nothing non-finite is published: a step that would produce it is a failed step.
  for (std::size_t i = 0; i < next.joints.size(); ++i) {
    if (!next.joints[i].link.coeffs().allFinite() || !next.joints[i].base.coeffs().allFinite() ||
        !std::isfinite(next.headings[i]))
      throw std::runtime_error("the step produced a non-finite state of joint " +
                               std::to_string(i + 1));
  }
  state_ = std::move(next);
}

void FreebotPlantRos::publishEveryStep(const ros::Time& now, bool /*actuators_fresh*/) {
  const freebot::LinkPose end = chain_.manipulator().endEffector(state_.joints);
  state_pub_.publish(conversions::toFreebotStateMsg(state_, end, kWorldFrame, now));
}

std::optional<PlantModel::Pose> FreebotPlantRos::trailPose() const {
  const freebot::LinkPose end = chain_.manipulator().endEffector(state_.joints);
  return Pose{end.position, end.orientation};
}

void FreebotPlantRos::publishPeriodic(const ros::Time& now, bool /*actuators_fresh*/) {
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
  loop_.tf().sendTransform(transforms);
  marker_pub_.publish(markers);
}

void FreebotPlantRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "integrating measured wheel speeds");
  status.add("modules", chain_.moduleCount());
  const freebot::LinkPose end = chain_.manipulator().endEffector(state_.joints);
  status.addf("end-effector [m]", "%.6f, %.6f, %.6f", end.position.x(), end.position.y(),
              end.position.z());
}

std::string FreebotPlantRos::describeState() const {
  const freebot::LinkPose end = chain_.manipulator().endEffector(state_.joints);
  std::ostringstream text;
  text << "end-effector at (" << end.position.x() << ", " << end.position.y() << ", "
       << end.position.z() << ") m";
  return text.str();
}

}  // namespace spherical_robots
