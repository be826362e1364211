#pragma once
// The freebot_plant node: a FreeBOT chain's state integrated from the MEASURED wheel speeds of the
// hardware interface (core FreebotChain::advance), published as the chain state, tf for every
// module's sphere and rviz markers. With a real driver it is the chain's dead-reckoning estimate.

#include <optional>
#include <string>
#include <vector>

#include "spherical_robots/freebot/freebot_chain.hpp"
#include "spherical_robots/ros/plant_loop.hpp"

namespace spherical_robots {

/// The chain both FreeBOT nodes read from the node handle's namespace: radii (list [m]: l_0 the
/// fixed base's, l_1 … l_n, at least two) and trolley/{wheel_radius, wheel_interval,
/// shell_thickness} [m] (Table II defaults 0.005, 0.046, 0.002).
/// @throw std::invalid_argument naming the parameter if one is missing or bad.
freebot::FreebotChain freebotChainFromParams(const ros::NodeHandle& nh);

/// The tf frame of sphere B_i (i = 0: the fixed base): "<prefix>link<i>".
std::string freebotLinkFrame(const std::string& prefix, std::size_t i);

/// Parameters (private, ~): frame_prefix (""); step [s] (0.01): the tick and the integration
/// step; publish_rate [Hz] (50): tf and markers; state_timeout [s] (0.1): older measured wheel
/// speeds count as zero; clock ("ros"), speedup (free: 1),
/// lockstep_timeout, wait_for_subscribers, start_timeout: as terrain_kinematics; duration [s] (0 = forever); trail_period [s] (0.1):
/// spacing of the end-effector trail's points.
/// Subscribes actuators/state (velocities of module<i>_wheel_right/left [rad/s]). Publishes
/// freebot_state (every tick), tf world -> <prefix>link0 (identity) and <prefix>link<i-1> ->
/// <prefix>link<i> (B_i's centre and q_i), freebot_markers (spheres and trolleys), trail (B_n's
/// centre, nav_msgs/Path in world) and /diagnostics.
class FreebotPlantRos : private PlantModel {
 public:
  /// @throw std::invalid_argument on a bad parameter.
  FreebotPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void read(const sensor_msgs::JointState& actuators) override;
  void advance(double elapsed, bool actuators_fresh) override;
  void publishEveryStep(const ros::Time& now, bool actuators_fresh) override;
  /// tf of every module's sphere and the markers.
  void publishPeriodic(const ros::Time& now, bool actuators_fresh) override;
  std::optional<Pose> trailPose() const override;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) override;
  std::string describeState() const override;

  freebot::FreebotChain chain_;
  std::string prefix_;
  double max_actuator_rate_;  ///< [rad/s] a measured rate beyond it is rejected (plausibility)
  freebot::ChainState state_;
  std::vector<freebot::WheelSpeeds> wheels_;  ///< last measured [rad/s]
  LoopPublisher state_pub_;
  LoopPublisher marker_pub_;
  PlantLoop loop_;  ///< last: its clock stops before the rest goes
};

}  // namespace spherical_robots
