#pragma once
// The rotor_sphere_plant node: the two-rotor sphere (Svinin et al.) rolled from the measured rotor
// speeds of the hardware interface (eq 11 solved for ω, eqs 6-10; rotor::advancePlant), published
// as odometry, tf and the rotors' joint states.

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include <memory>
#include <vector>
#include <string>

#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/plant_timeline.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/plant_clock.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/dynamic_realizability.hpp"

namespace spherical_robots {

/// Parameters in the node handle's namespace (shared with rotor_planner): inertia_ratio k (2.5,
/// > 0), rotor_inertia_scale J_zz / J_r (12).
/// Private (~): sphere_radius R [m] (0.1); frame_prefix (""); step [s] (0.001): the tick and
/// the RK4 step; publish_rate [Hz] (50): odom, joint_states, tf; clock ("ros"),
/// speedup (free: 1), lockstep_timeout, wait_for_subscribers, start_timeout: as terrain_kinematics; duration [s] (0 = forever); state_timeout [s]
/// (0.5): the rotors keep the last measured speeds (a late state message does not stop them:
/// the flywheels spin on); older ones count as zero, as the hardware interface's command_timeout
/// brings the rotors to rest.
/// Subscribes actuators/state (velocities of rotor_1 about the sphere's x axis n1 and rotor_2
/// about n2 [rad/s], and their positions). Publishes odom (frame world, child <prefix>base_link:
/// the centre (R u_a, R v_a, R) and orientation R_zᵀ(ψ) R_xᵀ(v_o) R_yᵀ(u_o) of eq 2), tf
/// world -> <prefix>base_link, joint_states (rotor_1, rotor_2: measured positions and velocities)
/// and /diagnostics. Starts at the zero state (contact at the south pole, at the origin, ψ = 0).
class RotorPlantRos {
 public:
  /// @throw std::invalid_argument on a bad parameter.
  RotorPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void onActuatorState(const sensor_msgs::JointState& msg);
  /// One step at now; returns the topics it published.
  std::vector<std::string> tick(const ros::Time& now);
  void publishPose(const ros::Time& now);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  double k_;
  double inertia_scale_;
  double radius_;
  std::string base_frame_;
  double step_;
  PlantTimeline timeline_;
  double max_actuator_rate_;  ///< [rad/s] a measured rate beyond it is rejected (plausibility)
  double publish_period_;
  rotor::ContactCoordinates state_;
  rotor::RotorSpeeds speeds_;  ///< measured [rad/s]
  double positions_[2] = {0.0, 0.0};  ///< measured rotor angles [rad]
  ros::Time last_publish_;
  InputMonitor actuator_input_;
  ros::Subscriber actuator_sub_;
  ros::Publisher odom_pub_;
  ros::Publisher joint_pub_;
  TfPublisher tf_broadcaster_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;  ///< reports on wall time (diagnostics_timer.hpp)
  std::unique_ptr<PlantClock> clock_;  ///< last: it ticks only once everything else exists
};

}  // namespace spherical_robots
