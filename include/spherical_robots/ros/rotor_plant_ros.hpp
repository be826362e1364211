#pragma once
// The rotor_plant node: the two-rotor sphere (Svinin et al.) rolled from the measured rotor
// speeds of the hardware interface (eq 11 solved for ω, eqs 6-10; rotor::advancePlant), published
// as odometry, tf and the rotors' joint states.

#include <array>
#include <string>

#include "spherical_robots/ros/plant_loop.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/dynamic_realizability.hpp"

namespace spherical_robots {

/// Parameters in the node handle's namespace (shared with rotor_planner): inertia_ratio k (2.5,
/// > 0), rotor_inertia_scale J_zz / J_r (12).
/// Private (~): sphere_radius R [m] (0.1); frame_prefix (""); step [s] (0.001): the tick and
/// the RK4 step; publish_rate [Hz] (50): odom, joint_states, tf; clock ("ros"),
/// speedup (free: 1), lockstep_timeout, wait_for_subscribers, start_timeout: as terrain_plant; duration [s] (0 = forever); state_timeout [s]
/// (0.5): the rotors keep the last measured speeds (a late state message does not stop them:
/// the flywheels spin on); older ones count as zero, as the hardware interface's command_timeout
/// brings the rotors to rest.
/// Subscribes actuators/state (velocities of rotor_1 about the sphere's x axis n1 and rotor_2
/// about n2 [rad/s], and their positions). Publishes odom (frame world, child <prefix>base_link:
/// the centre (R u_a, R v_a, R) and orientation R_zᵀ(ψ) R_xᵀ(v_o) R_yᵀ(u_o) of eq 2), tf
/// world -> <prefix>base_link, joint_states (rotor_1, rotor_2: measured positions and velocities)
/// and /diagnostics. Starts at the zero state (contact at the south pole, at the origin, ψ = 0).
class RotorPlantRos : private PlantModel {
 public:
  /// @throw std::invalid_argument on a bad parameter.
  RotorPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void read(const sensor_msgs::JointState& actuators) override;
  void advance(double elapsed, bool actuators_fresh) override;
  void publishPeriodic(const ros::Time& now, bool actuators_fresh) override;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) override;
  std::string describeState() const override;

  double k_;
  double inertia_scale_;
  double radius_;
  std::string base_frame_;
  double max_actuator_rate_;  ///< [rad/s] a measured rate beyond it is rejected (plausibility)
  rotor::ContactCoordinates state_;
  rotor::RotorSpeeds speeds_;  ///< measured [rad/s]
  std::array<double, 2> positions_{};  ///< measured rotor angles [rad], for the URDF joints
  LoopPublisher odom_pub_;
  LoopPublisher joint_pub_;
  PlantLoop loop_;  ///< last: its clock stops before the rest goes
};

}  // namespace spherical_robots
