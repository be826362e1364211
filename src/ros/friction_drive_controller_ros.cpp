#include "spherical_robots/ros/friction_drive_controller_ros.hpp"

#include <stdexcept>

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/plant_clock.hpp"
#include "spherical_robots/ros/roller_drive_parameters.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/ros/terrain_conversions.hpp"

namespace spherical_robots {

FrictionDriveControllerParameters loadFrictionDriveControllerParameters(
    const config::ParameterSource& node) {
  FrictionDriveControllerParameters p;
  p.max_actuator_rate = config::positiveNumber(node, "max_actuator_rate", p.max_actuator_rate);
  p.command_timeout = config::renamedNumber(node, {"command_timeout", "input_timeout"},
                                            p.command_timeout, config::positiveNumber);
  return p;
}

FrictionDriveControllerRos::FrictionDriveControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : actuation_(loadRollerActuation(nh)),
      last_motor_rates_(2, 0.0),
      parameters_(loadFrictionDriveControllerParameters(RosParameterSource(pnh))),
      input_(nh.resolveName("drive/command"), parameters_.command_timeout),
      work_([this](const sensor_msgs::JointState& msg) { convert(msg); }, step_publications_),
      updater_(nh, pnh, pnh.getNamespace()) {
  command_pub_ = step_publications_.advertise<sensor_msgs::JointState>(nh, "actuators/command");
  command_sub_ = nh.subscribe("drive/command", kLoopQueueSize, &FrictionDriveControllerRos::onDriveCommand, this);
  work_.join(nh, pnh, {command_sub_});
  updater_.setHardwareID("friction drive");
  updater_.add("friction drive inverse", this, &FrictionDriveControllerRos::diagnose);
  diagnostics_timer_ = startDiagnostics(nh, updater_);
  ROS_INFO_STREAM("Friction drive inverse: " << input_.topic() << " (2R rates) -> "
                                             << command_pub_.topic() << " (roller motors)");
}

void FrictionDriveControllerRos::onDriveCommand(const ros::MessageEvent<sensor_msgs::JointState const>& event) {
  work_.arrived(event);
}

void FrictionDriveControllerRos::convert(const sensor_msgs::JointState& msg) {
  try {
    const std::array<double, 2> motor_rates =
        actuation_.motorRates(conversions::ratesFromJointState(terrain::RobotType::TwoAxisRolling,
                                                               msg, parameters_.max_actuator_rate));
    last_motor_rates_.assign(motor_rates.begin(), motor_rates.end());
    input_.accept(workingTime(work_.participant()));
    command_pub_.publish(conversions::velocityJointState(rollerMotorNames(), last_motor_rates_, msg.header.stamp));
  } catch (const std::invalid_argument& e) {
    input_.reject(e.what());  // nothing published: the hardware keeps the last good set-points
  }
}

void FrictionDriveControllerRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "converting drive commands");
  describeRollerDrive(actuation_, status);
  status.addf("roller_1, roller_2 set-points [rad/s]", "%.6g, %.6g", last_motor_rates_[0],
              last_motor_rates_[1]);
  input_.report(status, workingTime(work_.participant()));
}

}  // namespace spherical_robots
