#pragma once
// The norma_dynamics plant node: Norma (eq 46, eqs 6 and 12) integrated from the measured
// pendulum torque and slider force of the hardware interface, published as its state, odometry,
// joint states and tf.

#include <diagnostic_updater/diagnostic_updater.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include <memory>
#include <vector>
#include <string>

#include "spherical_robots/norma/norma_plant.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/trail.hpp"
#include "spherical_robots/ros/plant_timeline.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/plant_clock.hpp"

namespace spherical_robots {

/// Parameters (private, ~): variant (text | appendix, "text": docs/errata.md); frame_prefix ("");
/// step [s] (0.001): the tick and the RK4 step; publish_rate [Hz] (50): odom, joint_states, tf;
/// trail_period [s] (0.5); clock ("ros"), speedup (free: 1),
/// lockstep_timeout, wait_for_subscribers, start_timeout: as terrain_kinematics; duration [s] (0 = forever); state_timeout [s]
/// (0.05): older measured efforts count as zero; initial_psi [rad] (0).
/// In the node handle's namespace: robot_description (urdf/norma.urdf: masses and lengths).
/// Subscribes actuators/state (efforts of pendulum_motor [N m] and slider_motor [N]). Publishes
/// norma_state (every tick), odom, joint_states (tilt_joint φ, shell_joint θ, pendulum_joint α,
/// slider_joint δ of urdf/norma.urdf),
/// tf world -> <prefix>base_link (centre, heading), trail and /diagnostics.
class NormaPlantRos {
 public:
  /// @throw std::invalid_argument on a bad parameter or URDF.
  NormaPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void onActuatorState(const sensor_msgs::JointState& msg);
  /// One step at now; returns the topics it published.
  std::vector<std::string> tick(const ros::Time& now);
  void publishState(const ros::Time& now);
  void publishPose(const ros::Time& now);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  norma::NormaDynamics dynamics_;
  std::string base_frame_;
  double step_;
  PlantTimeline timeline_;
  double max_actuator_effort_;  ///< [N m or N] a measured effort beyond it is rejected
  double publish_period_;
  Trail trail_;
  norma::NormaState state_;
  double torque_ = 0.0;  ///< measured T [N m]
  double force_ = 0.0;   ///< measured F [N]
  ros::Time last_publish_;
  InputMonitor actuator_input_;
  ros::Subscriber actuator_sub_;
  ros::Publisher state_pub_;
  ros::Publisher odom_pub_;
  ros::Publisher joint_pub_;
  TfPublisher tf_broadcaster_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;  ///< reports on wall time (diagnostics_timer.hpp)
  std::unique_ptr<PlantClock> clock_;  ///< last: it ticks only once everything else exists
};

}  // namespace spherical_robots
