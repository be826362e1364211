#include "spherical_robots/ros/freebot_plant_ros.hpp"

#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Geometry>
#include <sstream>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/FreebotState.h"
#include "spherical_robots/config/freebot_config.hpp"
#include "spherical_robots/ros/conversions.hpp"
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

FreebotPlantParameters loadFreebotPlantParameters(const config::ParameterSource& stack,
                                                  const config::ParameterSource& node) {
  FreebotPlantParameters p{config::freebotChain(stack), node.text("frame_prefix").value_or("")};
  p.max_actuator_rate = config::positiveNumber(node, "max_actuator_rate", p.max_actuator_rate);
  return p;
}

std::string freebotLinkFrame(const std::string& prefix, std::size_t i) {
  return prefix + "link" + std::to_string(i);
}

FreebotPlantRos::FreebotPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : parameters_(loadFreebotPlantParameters(RosParameterSource(nh), RosParameterSource(pnh))),
      state_(chain().alignedState()),
      wheels_(chain().moduleCount()),
      loop_(nh, pnh, loopDefaults()) {
  state_pub_ = loop_.advertise<spherical_robots::FreebotState>("freebot_state");
  marker_pub_ = loop_.advertise<visualization_msgs::MarkerArray>("freebot_markers");
  std::ostringstream radii;
  for (double r : chain().manipulator().radii()) radii << (radii.tellp() > 0 ? ", " : "") << r;
  ROS_INFO_STREAM("FreeBOT chain: " << chain().moduleCount() << " modules, radii [" << radii.str()
                                    << "] m, reach " << chain().manipulator().reach()
                                    << " m; step " << loop_.step() << " s");
  loop_.start(*this, state_pub_);
}

void FreebotPlantRos::read(const sensor_msgs::JointState& actuators) {
  wheels_ = conversions::wheelSpeedsFromJointState(actuators, chain().moduleCount(),
                                                   parameters_.max_actuator_rate);
}

void FreebotPlantRos::advance(double elapsed, bool actuators_fresh) {
  freebot::ChainState next = chain().advance(
      state_, actuators_fresh ? wheels_ : std::vector<freebot::WheelSpeeds>(chain().moduleCount()),
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
  const freebot::LinkPose end = chain().manipulator().endEffector(state_.joints);
  state_pub_.publish(conversions::toFreebotStateMsg(state_, end, kWorldFrame, now));
}

std::optional<PlantModel::Pose> FreebotPlantRos::trailPose() const {
  const freebot::LinkPose end = chain().manipulator().endEffector(state_.joints);
  return Pose{end.position, end.orientation};
}

void FreebotPlantRos::publishPeriodic(const ros::Time& now, bool /*actuators_fresh*/) {
  const auto& radii = chain().manipulator().radii();
  const std::string& prefix = parameters_.frame_prefix;
  std::vector<geometry_msgs::TransformStamped> transforms;
  transforms.push_back(conversions::toTransform(Eigen::Vector3d::Zero(),
                                                Eigen::Quaterniond::Identity(), kWorldFrame,
                                                freebotLinkFrame(prefix, 0), now));
  visualization_msgs::MarkerArray markers;
  for (std::size_t i = 0; i <= chain().moduleCount(); ++i) {
    const std::string frame = freebotLinkFrame(prefix, i);
    auto sphere = marker(frame, now, "spheres", static_cast<int>(i),
                         visualization_msgs::Marker::SPHERE);
    sphere.scale.x = sphere.scale.y = sphere.scale.z = 2.0 * radii[i];
    sphere.color.r = i == 0 ? 0.5f : 0.2f;
    sphere.color.g = i == 0 ? 0.5f : 0.5f;
    sphere.color.b = i == 0 ? 0.5f : 0.9f;
    sphere.color.a = 0.6f;
    markers.markers.push_back(sphere);
    if (i == 0) continue;
    const freebot::SrcJoint& joint = chain().manipulator().joint(i - 1);
    const freebot::SrcJointState& state = state_.joints[i - 1];
    transforms.push_back(conversions::toTransform(joint.position(state),
                                                  freebot::SrcJoint::jointQuaternion(state),
                                                  freebotLinkFrame(prefix, i - 1), frame, now));
    // The trolley at the contact point, heading φ_i in P_i (P_i relative to B_{i-1}: q̃_{i-1,2}).
    auto trolley = marker(freebotLinkFrame(prefix, i - 1), now, "trolleys", static_cast<int>(i),
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
  status.add("modules", chain().moduleCount());
  const freebot::LinkPose end = chain().manipulator().endEffector(state_.joints);
  status.addf("end-effector [m]", "%.6f, %.6f, %.6f", end.position.x(), end.position.y(),
              end.position.z());
}

std::string FreebotPlantRos::describeState() const {
  const freebot::LinkPose end = chain().manipulator().endEffector(state_.joints);
  std::ostringstream text;
  text << "end-effector at (" << end.position.x() << ", " << end.position.y() << ", "
       << end.position.z() << ") m";
  return text.str();
}

}  // namespace spherical_robots
