#pragma once
// The terrain controller node (the paper's pursuit laws, eqs 53-58, or the smooth law) and its
// teleoperation mode.

#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/Twist.h>
#include <ros/ros.h>

#include <memory>
#include <optional>
#include <set>
#include <string>

#include "spherical_robots/TerrainState.h"
#include "spherical_robots/ros/terrain_conversions.hpp"
#include "spherical_robots/core/clock_jump.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/terrain/path_tracker.hpp"
#include "spherical_robots/terrain/pure_pursuit.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/surface.hpp"

#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/timer_jump_guard.hpp"

namespace spherical_robots {

/// Parameters (private, ~): robot_type (3R | 2R | RT | RS, "3R"); mode (tracking | teleop,
/// "tracking"); path (circle | diamond, "circle"); rate [Hz] (50); input_timeout [s] (0.5): an
/// older terrain_state (ROS time) or cmd_vel (wall time: a person's commands, at any pace of
/// simulated time) counts as absent and the command is zero; plausibility bounds
/// max_position [m] (1000) of terrain_state's points, max_cmd_vel [m/s, rad/s] (10) of each
/// cmd_vel field, max_stamp_skew [s] (1) between a terrain_state's stamp and the clock (and a
/// zero stamp) beyond which the message is rejected; max_clock_step [s] (5): a longer step of
/// ROS time is a jump, over which the reference does not move.
/// In the node handle's namespace: robot_description (URDF, for the radius) and terrain/...
/// (config/terrain.yaml: surface, paths, gains).
///
/// tracking: subscribes terrain_state; every 1/rate s of ROS time it commands the ~law
/// (smooth | paper, "smooth": terrain::PursuitLaw) towards liftOntoSurface(path, surface, t,
/// the law's window), t = ROS time since the first
/// fresh terrain_state (so the reference waits for the plant), and publishes tracking_error,
/// target and (latched, once) desired_path.
/// teleop: subscribes cmd_vel (geometry_msgs/Twist), mapped by terrain::TeleopMapping (RS servos
/// its tilt, read from terrain_state, with ~teleop_tilt_gain [1/s], default 2); what the robot
/// type cannot follow is ignored with one warning per field.
/// Both publish actuators/command (sensor_msgs/JointState set-points) and /diagnostics.
class PurePursuitControllerRos {
 public:
  /// @throw std::invalid_argument on a bad parameter, URDF or terrain configuration.
  PurePursuitControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  enum class Mode { Tracking, Teleop };
  static Mode modeFromString(const std::string& name);

  void onTerrainState(const spherical_robots::TerrainState& msg);
  void onCmdVel(const geometry_msgs::Twist& msg);
  void onTimer(const ros::TimerEvent& event);
  /// The periodic work at `now` (a timer's or a lock-step request's); returns what it published.
  std::vector<std::string> control(const ros::Time& now);
  /// ROS time, or in lock-step the time of the latest step.
  ros::Time now() const;
  /// The set-points in tracking mode; zero without a fresh terrain_state.
  terrain::DriveRates track(const ros::Time& now);
  /// The set-points in teleop mode; zero without a fresh cmd_vel.
  terrain::DriveRates teleop();
  /// Logs once per field that cmd_vel asks for something this robot cannot do.
  void warnIgnoredOnce(const std::vector<std::string>& fields);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  terrain::RobotType type_;
  Mode mode_;
  double radius_;
  std::unique_ptr<terrain::Surface> surface_;
  std::unique_ptr<terrain::ReferencePath> path_;
  std::unique_ptr<terrain::PursuitController> controller_;
  std::unique_ptr<terrain::PathTracker> tracker_;  ///< tracking mode

  std::optional<terrain::ContactGeometry> geometry_;  ///< from the last good terrain_state
  double tilt_ = 0.0;                                 ///< RS phi from the last good terrain_state
  terrain::VelocityRequest request_;                  ///< from the last good cmd_vel
  std::unique_ptr<terrain::TeleopMapping> teleop_mapping_;
  std::set<std::string> warned_ignored_;
  terrain::DriveRates command_;
  terrain::TrackingError error_;
  unsigned long failures_ = 0;
  double max_position_;
  double max_cmd_vel_;
  double max_stamp_skew_;
  ClockJumpDetector clock_;

  InputMonitor input_;  ///< terrain_state (tracking) or cmd_vel (teleop)
  double input_timeout_;            ///< [s]
  ros::WallTime last_cmd_vel_wall_;  ///< arrival of the last good cmd_vel
  ros::Subscriber state_sub_;
  ros::Subscriber cmd_vel_sub_;
  StepPublications step_publications_;
  LoopPublisher command_pub_;
  LoopPublisher error_pub_;
  LoopPublisher target_pub_;
  ros::Publisher desired_path_pub_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;  ///< reports on wall time (diagnostics_timer.hpp)
  ros::Timer timer_;
  std::unique_ptr<TimerJumpGuard> timer_guard_;  ///< restarts timer_ after a clock jump
  std::unique_ptr<LockstepParticipant> lockstep_;  ///< set instead of timer_ in lock-step
};

}  // namespace spherical_robots
