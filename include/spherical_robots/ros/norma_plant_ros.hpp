#pragma once
// The norma_plant plant node: Norma (eq 46, eqs 6 and 12) integrated from the measured
// pendulum torque and slider force of the hardware interface, published as its state, odometry,
// joint states and tf.

#include <optional>
#include <string>

#include "spherical_robots/norma/norma_plant.hpp"
#include "spherical_robots/ros/plant_loop.hpp"

namespace spherical_robots {

/// Parameters (private, ~): variant (text | appendix, "text": docs/errata.md); frame_prefix ("");
/// step [s] (0.001): the tick and the RK4 step; publish_rate [Hz] (50): odom, joint_states, tf;
/// trail_period [s] (0.5); clock ("ros"), speedup (free: 1),
/// lockstep_timeout, wait_for_subscribers, start_timeout: as terrain_plant; duration [s] (0 = forever); state_timeout [s]
/// (0.05): older measured efforts count as zero; initial_psi [rad] (0).
/// In the node handle's namespace: robot_description (urdf/norma.urdf: masses and lengths).
/// Subscribes actuators/state (efforts of pendulum_motor [N m] and slider_motor [N]). Publishes
/// norma_state (every tick), odom, joint_states (tilt_joint φ, shell_joint θ, pendulum_joint α,
/// slider_joint δ of urdf/norma.urdf),
/// tf world -> <prefix>base_link (centre, heading), trail and /diagnostics.
class NormaPlantRos : private PlantModel {
 public:
  /// @throw std::invalid_argument on a bad parameter or URDF.
  NormaPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void read(const sensor_msgs::JointState& actuators) override;
  void advance(double elapsed, bool actuators_fresh) override;
  void publishEveryStep(const ros::Time& now, bool actuators_fresh) override;
  void publishPeriodic(const ros::Time& now, bool actuators_fresh) override;
  std::optional<Pose> trailPose() const override;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) override;
  std::string describeState() const override;

  norma::NormaDynamics dynamics_;
  std::string base_frame_;
  double max_actuator_effort_;  ///< [N m or N] a measured effort beyond it is rejected
  norma::NormaState state_;
  norma::Efforts measured_;  ///< the last good actuator state's efforts
  LoopPublisher state_pub_;
  LoopPublisher odom_pub_;
  LoopPublisher joint_pub_;
  PlantLoop loop_;  ///< last: its clock stops before the rest goes
};

}  // namespace spherical_robots
