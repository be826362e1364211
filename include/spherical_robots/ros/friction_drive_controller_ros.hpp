#pragma once
// The roller stack's inverse end of the friction drive (launch/roller_stack.launch), a thin node
// over roller::RollerActuation:
//
//   pure_pursuit_controller (2R) --drive/command--> friction_drive_controller --actuators/command-->
//   hardware interface
//
// The controller asks for a sphere velocity as 2R drive rates; the inverse kinematics turns it
// into roller motor rates for the hardware interface.

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include <vector>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/roller/roller_actuation.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

namespace spherical_robots {

/// The private parameters of friction_drive_controller (the drive itself is the stack's
/// roller/... and robot_description: loadRollerActuation; docs/nodes.md).
struct FrictionDriveControllerParameters {
  double max_actuator_rate = 1000.0;  ///< [rad/s] a commanded rate beyond it is rejected
  /// [s] an older drive command is stale (named as hardware_interface_sim's set-point watchdog)
  double command_timeout = 0.5;
};

/// @throw std::invalid_argument naming the parameter, its value and its limit.
FrictionDriveControllerParameters loadFrictionDriveControllerParameters(
    const config::ParameterSource& node);

/// Turns each good drive command (2R rates) into roller motor rates; nothing for a bad one, so
/// the hardware interface's watchdog sees a silent controller (docs/nodes.md).
class FrictionDriveControllerRos {
 public:
  /// @throw std::invalid_argument on a bad parameter, URDF or drive geometry.
  FrictionDriveControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void onDriveCommand(const ros::MessageEvent<sensor_msgs::JointState const>& event);
  void convert(const sensor_msgs::JointState& msg);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  roller::RollerActuation actuation_;
  std::vector<double> last_motor_rates_;
  FrictionDriveControllerParameters parameters_;
  InputMonitor input_;
  StepPublications step_publications_;
  MessageDrivenWork<sensor_msgs::JointState> work_;
  ros::Subscriber command_sub_;
  LoopPublisher command_pub_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;
};

}  // namespace spherical_robots
