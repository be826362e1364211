#pragma once
// The terrain plant node: a sphere rolling over z = f(x, y), integrated from the measured
// actuator rates (terrain::stepWithHeldRates) and published as odometry, tf, state and trail.

#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>

#include "spherical_robots/ros/plant_loop.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace spherical_robots {

/// Parameters (private, ~):
/// * robot_type (3R | 2R | RT | RS, "3R"), contact_model (paper | rolling, "paper");
/// * frame_prefix (""): prepended to every frame but `world`;
/// * step [s] (0.01): integration step; publish_rate [Hz] (50): odom, tf and terrain_state;
/// * clock (lockstep | free | ros, "ros"), speedup (lockstep: a cap, 0 = none; free: the pace,
///   10), lockstep_timeout [s] (2), wait_for_subscribers (1), start_timeout [s] (10): the clock
///   mode (plant_clock.hpp, docs/lockstep.md);
/// * duration [s] (0 = forever): at this much ROS time after the first step, log "scenario
///   complete" and shut the node down;
/// * state_timeout [s] (0.5): older measured rates count as zero;
/// * max_actuator_rate [rad/s] (1000, far above every stack's actuator limit): a measured rate
///   beyond it is no measurement (1e300 is finite) and the message is rejected;
/// * max_clock_step [s] (5): a longer forward step of ROS time is a jump (PlantTimeline);
/// * initial_x, initial_y [m], initial_psi [rad] (0): the initial contact point and heading;
/// * trail_period [s] (0.5): spacing of the driven trail's points;
/// * marker_half_extent [m] (3), marker_resolution [m] (0.1): the terrain mesh [-e, e]^2.
/// In the node handle's namespace: robot_description (URDF; the radius is base_link's collision
/// sphere) and terrain/... (config/terrain.yaml).
/// Subscribes actuators/state (sensor_msgs/JointState, measured rates). Publishes odom, tf
/// world -> <prefix>base_link (centre, shell orientation) and world -> <prefix>heading (contact
/// point, R_L), terrain_state, trail, terrain_marker (latched) and /diagnostics.
class TerrainPlantRos : private PlantModel {
 public:
  /// @throw std::invalid_argument on a bad parameter, URDF or terrain configuration.
  TerrainPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void read(const sensor_msgs::JointState& actuators) override;
  void advance(double elapsed, bool actuators_fresh) override;
  void publishPeriodic(const ros::Time& now, bool actuators_fresh) override;
  std::optional<Pose> trailPose() const override;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) override;
  std::string describeState() const override;

  terrain::DriveRates rates(bool actuators_fresh) const;

  terrain::RobotType type_;
  std::string base_frame_;
  std::string heading_frame_;
  std::unique_ptr<terrain::Surface> surface_;
  std::unique_ptr<terrain::TerrainKinematics> kinematics_;
  terrain::TerrainState state_;
  Eigen::Quaterniond orientation_;  ///< shell (base_link) orientation, world <- body
  terrain::DriveRates measured_;
  double max_actuator_rate_;
  ros::Publisher marker_pub_;
  LoopPublisher odom_pub_;
  LoopPublisher state_pub_;
  PlantLoop loop_;  ///< last: its clock stops before the rest goes
};

}  // namespace spherical_robots
