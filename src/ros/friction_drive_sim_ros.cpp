#include "spherical_robots/ros/friction_drive_sim_ros.hpp"

#include <stdexcept>

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/plant_clock.hpp"
#include "spherical_robots/ros/roller_drive_parameters.hpp"
#include "spherical_robots/ros/roller_conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/ros/terrain_conversions.hpp"

namespace spherical_robots {

FrictionDriveSimParameters loadFrictionDriveSimParameters(const config::ParameterSource& node) {
  FrictionDriveSimParameters p;
  p.frame_prefix = node.text("frame_prefix").value_or("");
  p.marker_rate = config::positiveNumber(node, "marker_rate", p.marker_rate);
  p.max_actuator_rate = config::positiveNumber(node, "max_actuator_rate", p.max_actuator_rate);
  p.state_timeout = config::renamedNumber(node, {"state_timeout", "input_timeout"},
                                          p.state_timeout, config::positiveNumber);
  return p;
}

FrictionDriveSimRos::FrictionDriveSimRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : actuation_(loadRollerActuation(nh)),
      parameters_(loadFrictionDriveSimParameters(RosParameterSource(pnh))),
      heading_frame_(parameters_.frame_prefix + "heading"),
      input_(nh.resolveName("actuators/state"), parameters_.state_timeout),
      work_([this](const sensor_msgs::JointState& msg) { drive(msg); }, step_publications_),
      updater_(nh, pnh, pnh.getNamespace()) {
  drive_state_pub_ = step_publications_.advertise<sensor_msgs::JointState>(nh, "drive/state");
  drive_pub_ = step_publications_.advertise<spherical_robots::RollerDrive>(nh, "roller_drive");
  marker_pub_ = step_publications_.advertise<visualization_msgs::MarkerArray>(nh, "roller_markers");
  state_sub_ = nh.subscribe("actuators/state", kLoopQueueSize, &FrictionDriveSimRos::onActuatorState, this);
  work_.join(nh, pnh, {state_sub_});
  updater_.setHardwareID("friction drive");
  updater_.add("friction drive forward", this, &FrictionDriveSimRos::diagnose);
  diagnostics_timer_ = startDiagnostics(nh, updater_);
  ROS_INFO_STREAM("Friction drive forward: " << input_.topic() << " (roller motors) -> "
                                             << drive_state_pub_.topic() << " (2R rates)");
}

void FrictionDriveSimRos::onActuatorState(const ros::MessageEvent<sensor_msgs::JointState const>& event) {
  work_.arrived(event);
}

void FrictionDriveSimRos::drive(const sensor_msgs::JointState& msg) {
  roller::DriveState state;
  try {
    const std::vector<double> rates =
        conversions::velocitiesByName(msg, rollerMotorNames(), parameters_.max_actuator_rate);
    state = actuation_.driveState({rates[0], rates[1]});
  } catch (const std::invalid_argument& e) {
    input_.reject(e.what());  // the plant keeps the last good drive state until it goes stale
    return;
  }
  last_state_ = state;
  input_.accept(workingTime(work_.participant()));
  drive_state_pub_.publish(conversions::jointStateFromRates(
      terrain::RobotType::TwoAxisRolling, roller::rollingRates(state.omega), msg.header.stamp));

  drive_pub_.publish(conversions::toRollerDriveMsg(state, msg.header.stamp));

  // On the message's time, not the clock's, so that lock-step runs publish the same markers.
  if (periodDue(last_markers_, msg.header.stamp, 1.0 / parameters_.marker_rate)) {
    last_markers_ = msg.header.stamp;
    marker_pub_.publish(conversions::rollerMarkers(actuation_.drive().geometry(),
                                                   actuation_.rollerRadius(), state,
                                                   heading_frame_, msg.header.stamp));
  }
}

void FrictionDriveSimRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "driving the sphere");
  describeRollerDrive(actuation_, status);
  status.addf("v1, v2 [m/s]", "%.6g, %.6g", last_state_.speeds.v1, last_state_.speeds.v2);
  status.addf("S1, S2 [m/s]", "%.6g, %.6g", last_state_.slip[0], last_state_.slip[1]);
  input_.report(status, workingTime(work_.participant()));
}

}  // namespace spherical_robots
