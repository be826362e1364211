#pragma once
// The terrain controller node (the paper's pursuit laws, eqs 53-58, or the smooth law) and its
// teleoperation mode.

#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Path.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/JointState.h>
#include <ros/ros.h>

#include <memory>
#include <optional>
#include <set>
#include <string>

#include "spherical_robots/PurePursuitControllerConfig.h"
#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/ros/terrain_conversions.hpp"
#include "spherical_robots/core/clock_jump.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/topic_rate.hpp"
#include "spherical_robots/terrain/body_frame.hpp"
#include "spherical_robots/terrain/path_tracker.hpp"
#include "spherical_robots/terrain/pursuit_law.hpp"
#include "spherical_robots/terrain/pure_pursuit.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/sampled_path.hpp"
#include "spherical_robots/terrain/surface.hpp"

#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/path_reception.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/timer_jump_guard.hpp"

namespace spherical_robots {

/// Every private parameter of pure_pursuit_controller (docs/nodes.md); the surface, paths and
/// gains are the stack's terrain/... (config/terrain.yaml).
struct PurePursuitControllerParameters {
  enum class Mode { Tracking, Teleop };
  /// @throw std::invalid_argument unless name is tracking or teleop.
  static Mode modeFromString(const std::string& name);

  terrain::RobotType robot_type = terrain::RobotType::ThreeAxisRolling;
  Mode mode = Mode::Tracking;
  terrain::PursuitLaw law = terrain::PursuitLaw::Smooth;
  /// A path of config/terrain.yaml (tracking), or kPathFromTopic: none until one arrives on
  /// `path`. A nav_msgs/Path received on `path` replaces whichever is followed.
  std::string path = "circle";
  static inline const std::string kPathFromTopic = "topic";
  double untimed_speed = 0.1;      ///< [m/s] along a received path whose stamps are all equal
  /// [s] of wall time a received path in another frame waits for tf before it is refused
  double path_tf_timeout = 1.0;
  /// The frame of the odometry it reads, in which the terrain and the path are (the stack's
  /// <prefix>odom); odometry in another frame is rejected, a path in another frame transformed.
  std::string odom_frame = "odom";
  double rate = 50.0;              ///< [Hz] of actuators/command
  /// [s] of ROS time: an older odom (tracking: the command is zero) or RS joint_states is stale.
  double state_timeout = 0.5;
  /// [s] of wall time: an older cmd_vel (teleop: a person's commands) is stale, the command zero.
  double cmd_vel_timeout = 0.5;
  double max_position = 1e3;       ///< [m] an odom position beyond it is rejected
  double max_cmd_vel = 10.0;       ///< [m/s, rad/s] a cmd_vel field beyond it is rejected
  double max_stamp_skew = 1.0;     ///< [s] odom or joint_states stamped further from the clock is rejected
  double max_clock_step = kDefaultMaxClockStep;  ///< [s] a longer step of ROS time is a jump
  double teleop_tilt_gain = 2.0;   ///< [1/s] RS in teleop: the tilt servo's gain
};

/// @throw std::invalid_argument naming the parameter, its value and its limit.
PurePursuitControllerParameters loadPurePursuitControllerParameters(
    const config::ParameterSource& node);

/// The law and a robot type's gains as dynamic_reconfigure shows them
/// (cfg/PurePursuitController.cfg, whose gains are config::namedPursuitGains').
/// @throw std::invalid_argument naming a parameter of the .cfg that is no pursuit gain.
spherical_robots::PurePursuitControllerConfig reconfigureConfigOf(
    terrain::PursuitLaw law, const config::TerrainConfig& terrain, terrain::RobotType type);
/// terrain with type's gains as config has them; nothing is checked (the law's constructor does).
/// @throw std::invalid_argument naming a parameter of the .cfg that is no pursuit gain.
config::TerrainConfig withReconfiguredGains(const spherical_robots::PurePursuitControllerConfig& config,
                                            config::TerrainConfig terrain, terrain::RobotType type);

/// The terrain stack's controller: tracks a path of config/terrain.yaml or a received
/// nav_msgs/Path with a pursuit law, or maps a person's cmd_vel onto the robot type's drive
/// (docs/nodes.md, "pure_pursuit_controller").
class PurePursuitControllerRos {
 public:
  /// @throw std::invalid_argument on a bad parameter, URDF or terrain configuration.
  PurePursuitControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  using Mode = PurePursuitControllerParameters::Mode;

  void onOdometry(const ros::MessageEvent<nav_msgs::Odometry const>& event);
  /// RS: its tilt.
  void onJointStates(const ros::MessageEvent<sensor_msgs::JointState const>& event);
  /// @throw std::invalid_argument naming `topic` if `stamp` is unset or too far from now().
  void acceptStamp(const ros::Time& stamp, const std::string& topic) const;
  /// When an input stamped `stamp` counts as received.
  ros::Time inputTime(const ros::Time& stamp) const;
  /// Follows `path` (received at `received`, its first pose stamped `first_stamp`), from `origin`.
  void follow(std::unique_ptr<terrain::SampledPath> path, const ros::Time& first_stamp,
              const ros::Time& received, const std::string& origin);
  void publishDesiredPath(int samples);
  void onCmdVel(const geometry_msgs::Twist& msg);
  void onTimer(const ros::TimerEvent& event);
  /// The periodic work at `now` (a timer's or a lock-step request's); returns what it published.
  std::vector<std::string> control(const ros::Time& now);
  /// ROS time, or in lock-step the time of the latest step.
  ros::Time now() const;
  /// The set-points in tracking mode; zero without a fresh odom.
  terrain::DriveRates track(const ros::Time& now);
  /// The set-points in teleop mode; zero without a fresh cmd_vel.
  terrain::DriveRates teleop();
  /// Logs once per field that cmd_vel asks for something this robot cannot do.
  void warnIgnoredOnce(const std::vector<std::string>& fields);
  /// dynamic_reconfigure (tracking mode): the law built anew with the new gains, through the
  /// same checks as at start-up; a refused change keeps the last good law and hands it back.
  void onReconfigure(spherical_robots::PurePursuitControllerConfig& config, std::uint32_t level);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  PurePursuitControllerParameters parameters_;
  double radius_;
  std::unique_ptr<terrain::Surface> surface_;
  std::unique_ptr<terrain::BodyFrame> body_frame_;  ///< odometry's pose to the contact geometry
  config::TerrainConfig terrain_config_;  ///< the stack's terrain/..., with the gains in use
  terrain::PursuitLaw law_;                ///< in use: ~law, or as reconfigured since
  std::unique_ptr<terrain::PursuitController> controller_;
  std::string reconfigure_problem_;  ///< why the last refused reconfiguration was refused
  std::unique_ptr<dynamic_reconfigure::Server<spherical_robots::PurePursuitControllerConfig>> reconfigure_;
  // Tracking mode: the path followed (null with ~path topic until one arrives) and its tracker.
  std::unique_ptr<terrain::ReferencePath> path_;
  std::string path_origin_;  ///< where path_ came from, for the log and /diagnostics
  std::unique_ptr<terrain::PathTracker> tracker_;

  std::optional<terrain::ContactGeometry> geometry_;  ///< from the last good odom
  double tilt_ = 0.0;                                 ///< RS phi from the last good joint_states
  terrain::VelocityRequest request_;                  ///< from the last good cmd_vel
  std::unique_ptr<terrain::TeleopMapping> teleop_mapping_;
  std::set<std::string> warned_ignored_;
  terrain::DriveRates command_;
  terrain::TrackingError error_;
  unsigned long failures_ = 0;
  ClockJumpDetector clock_;

  InputMonitor input_;  ///< odom (tracking) or cmd_vel (teleop)
  InputMonitor tilt_input_;  ///< RS: joint_states
  ros::WallTime last_cmd_vel_wall_;  ///< arrival of the last good cmd_vel
  ros::Subscriber odom_sub_;
  ros::Subscriber joint_sub_;  ///< RS only
  ros::Subscriber cmd_vel_sub_;
  StepPublications step_publications_;
  LoopPublisher command_pub_;
  LoopPublisher error_pub_;
  LoopPublisher target_pub_;
  ros::Publisher desired_path_pub_;
  TopicRate command_rate_;  ///< actuators/command against ~rate
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;  ///< reports on wall time (diagnostics_timer.hpp)
  std::unique_ptr<PathReception> path_reception_;  ///< tracking mode: paths sent on `path`
  ros::Timer timer_;
  std::unique_ptr<TimerJumpGuard> timer_guard_;  ///< restarts timer_ after a clock jump
  std::unique_ptr<LockstepParticipant> lockstep_;  ///< set instead of timer_ in lock-step
};

}  // namespace spherical_robots
