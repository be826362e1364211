#include "spherical_robots/ros/freebot_plant_ros.hpp"

#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Geometry>
#include <sstream>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/FreebotState.h"
#include "spherical_robots/config/freebot_config.hpp"
#include "spherical_robots/config/freebot_description.hpp"
#include "spherical_robots/ros/freebot_conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {
namespace {


PlantLoop::Defaults loopDefaults(const std::string& base_frame) {
  PlantLoop::Defaults defaults;
  defaults.root_frame = base_frame;
  defaults.task = "freebot plant";
  defaults.hardware_id = "FreeBOT";
  defaults.parameters.step = 0.01;
  defaults.parameters.speedup = 1.0;
  defaults.parameters.state_timeout = 0.1;
  defaults.parameters.trail_period = 0.1;
  defaults.max_trail_points = 5000;
  return defaults;
}

}  // namespace

FreebotPlantParameters loadFreebotPlantParameters(const config::ParameterSource& stack,
                                                  const config::ParameterSource& node) {
  FreebotPlantParameters p{config::freebotChain(stack), node.text("frame_prefix").value_or("")};
  p.max_actuator_rate = config::positiveNumber(node, "max_actuator_rate", p.max_actuator_rate);
  return p;
}

FreebotPlantRos::FreebotPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : parameters_(loadFreebotPlantParameters(RosParameterSource(nh), RosParameterSource(pnh))),
      state_(chain().alignedState()),
      wheels_(chain().moduleCount()),
      loop_(nh, pnh, loopDefaults(conversions::freebotLinkFrame(parameters_.frame_prefix, 0))) {
  // For rviz's RobotModel and any other user: the very radii this node integrates.
  nh.setParam("robot_description", config::freebotRobotDescription(chain().manipulator().radii()));
  state_pub_ = loop_.advertise<spherical_robots::FreebotState>("freebot_state");
  marker_pub_ = loop_.advertise<visualization_msgs::MarkerArray>("freebot_markers");
  std::ostringstream radii;
  for (double r : chain().manipulator().radii()) radii << (radii.tellp() > 0 ? ", " : "") << r;
  ROS_INFO_STREAM("FreeBOT chain: " << chain().moduleCount() << " modules, radii [" << radii.str()
                                    << "] m, reach " << chain().manipulator().reach()
                                    << " m; step " << loop_.step() << " s");
  loop_.start(*this, state_pub_, 1.0 / loop_.step());  // every step
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
  state_pub_.publish(conversions::toFreebotStateMsg(state_, end, loop_.rootFrame(), now));
}

std::optional<PlantModel::Pose> FreebotPlantRos::trailPose() const {
  const freebot::LinkPose end = chain().manipulator().endEffector(state_.joints);
  return Pose{end.position, end.orientation};
}

void FreebotPlantRos::publishPeriodic(const ros::Time& now, bool /*actuators_fresh*/) {
  loop_.tf().sendTransform(conversions::freebotChainTransforms(chain().manipulator(), state_,
                                                               parameters_.frame_prefix, now));
  marker_pub_.publish(conversions::freebotChainMarkers(chain().manipulator(), state_,
                                                       parameters_.frame_prefix, now));
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
