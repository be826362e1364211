#pragma once
// The roller stack's simulated friction drive (launch/roller_stack.launch), a thin node over
// roller::RollerActuation:
//
//   hardware interface --actuators/state--> friction_drive_sim --drive/state--> terrain plant (2R)
//
// It turns the measured motor rates into the sphere's angular velocity (forward, with slip) for the
// plant, and shows the slip. On a real robot it is the physical contact between rollers and sphere.

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include <string>
#include <vector>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/roller/roller_actuation.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

namespace spherical_robots {

/// The private parameters of friction_drive_sim (the drive itself is the stack's roller/... and
/// robot_description: loadRollerActuation; docs/nodes.md).
struct FrictionDriveSimParameters {
  std::string frame_prefix;           ///< of the markers' heading frame
  double marker_rate = 20.0;          ///< [Hz] of roller_markers
  double max_actuator_rate = 1000.0;  ///< [rad/s] a measured rate beyond it is rejected
  double state_timeout = 0.5;         ///< [s] an older actuator state is stale
};

/// @throw std::invalid_argument naming the parameter, its value and its limit.
FrictionDriveSimParameters loadFrictionDriveSimParameters(const config::ParameterSource& node);

/// Turns each good measured motor state into the sphere's angular velocity (with slip) for the
/// plant, and shows the slip (docs/nodes.md, "friction_drive_sim").
class FrictionDriveSimRos {
 public:
  /// @throw std::invalid_argument on a bad parameter, URDF or drive geometry.
  FrictionDriveSimRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void onActuatorState(const ros::MessageEvent<sensor_msgs::JointState const>& event);
  void drive(const sensor_msgs::JointState& msg);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  roller::RollerActuation actuation_;
  FrictionDriveSimParameters parameters_;
  std::string heading_frame_;
  ros::Time last_markers_;
  roller::DriveState last_state_;
  InputMonitor input_;
  StepPublications step_publications_;
  MessageDrivenWork<sensor_msgs::JointState> work_;
  ros::Subscriber state_sub_;
  LoopPublisher drive_state_pub_;
  LoopPublisher drive_pub_;
  LoopPublisher marker_pub_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;
};

}  // namespace spherical_robots
