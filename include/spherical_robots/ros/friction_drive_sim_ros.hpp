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

#include "spherical_robots/roller/roller_actuation.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

namespace spherical_robots {

/// Parameters: as friction_drive_controller (roller/..., robot_description, ~input_timeout), plus ~frame_prefix ("") and ~marker_rate [Hz] (20).
/// Subscribes actuators/state (roller_1, roller_2 measured [rad/s]); publishes, for each good
/// state, drive/state (JointState theta, phi [rad/s], the horizontal part of eq 11's ω) and
/// roller_drive (spherical_robots/RollerDrive: ω, slip), and roller_markers
/// (visualization_msgs/MarkerArray in <prefix>heading: rollers and slip arrows).
class FrictionDriveSimRos {
 public:
  /// @throw std::invalid_argument on a bad parameter, URDF or drive geometry.
  FrictionDriveSimRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void onActuatorState(const sensor_msgs::JointState& msg);
  void drive(const sensor_msgs::JointState& msg);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  roller::RollerActuation actuation_;
  std::string heading_frame_;
  double marker_period_;
  double max_actuator_rate_;  ///< [rad/s] a measured rate beyond it is rejected (plausibility)
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
