#pragma once
// The norma_controller node: Norma's two-layer controller in a stack, eqs 48-51 and the PID cascade of Fig. 5 (or this project's tracking
// controller) on the plant's state, writing the pendulum torque and the slider force to the
// hardware interface's effort actuators.

#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>

#include <Eigen/Core>
#include <memory>
#include <optional>

#include "spherical_robots/NormaControllerConfig.h"
#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/core/periodic_schedule.hpp"
#include "spherical_robots/norma/norma_control_loop.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

namespace spherical_robots {

/// Every private parameter of norma_controller (docs/nodes.md).
struct NormaControllerParameters {
  norma::ControllerKind controller = norma::ControllerKind::kPaper;
  norma::ControllerGains gains;  ///< ~gains/... (config/norma.yaml)
  /// The actuators' limits (as the hardware interface has them), for the anti-windup.
  norma::EffortLimits limits;
  double publish_rate = 50.0;   ///< [Hz] of tracking_error and target
  double max_stamp_skew = 1.0;  ///< [s] joint_states or odom stamped further from the clock: rejected
  double state_timeout = 0.05;  ///< [s] older joint states, odometry and actuator states are stale
  /// The frame of the odometry it reads, in which the path is (the stack's <prefix>odom).
  std::string odom_frame = "odom";
};

/// @throw std::invalid_argument naming the parameter, its value and its limit.
NormaControllerParameters loadNormaControllerParameters(const config::ParameterSource& node);

/// The gains as dynamic_reconfigure shows them (cfg/NormaController.cfg), and back: every
/// reconfigurable gain of `base` replaced by the config's.
spherical_robots::NormaControllerConfig reconfigureConfigOf(const norma::ControllerGains& gains);
norma::ControllerGains gainsOf(const spherical_robots::NormaControllerConfig& config,
                               norma::ControllerGains base);

/// Norma's two-layer controller in a stack (eqs 48-51 and the PID cascade of Fig. 5, or this
/// project's tracking controller) on the plant's state, commanding the pendulum torque and the
/// slider force (docs/nodes.md, "norma_controller"). The loop is real time: nothing waits for the
/// controller, and /diagnostics warns about commands later than 2 ms, which the paper's inner
/// loop does not survive (docs/conventions.md).
class NormaControllerRos {
 public:
  /// @throw std::invalid_argument on a bad parameter or URDF.
  NormaControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void onJointStates(const ros::MessageEvent<sensor_msgs::JointState const>& event);
  void onOdometry(const ros::MessageEvent<nav_msgs::Odometry const>& event);
  /// Commands from one joint state with the latest pose (nothing for a rejected one).
  void control(const sensor_msgs::JointState& msg);
  /// ROS time, or in lock-step the time of the latest step.
  ros::Time now() const;
  void onActuatorState(const ros::MessageEvent<sensor_msgs::JointState const>& event);
  const norma::NormaController& controller() const { return loop_.controller(); }
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);
  /// dynamic_reconfigure: new gains through norma::validate, as at start-up; a refused change
  /// keeps the last good gains and hands them back in config.
  void onReconfigure(spherical_robots::NormaControllerConfig& config, std::uint32_t level);
  /// A controller respawned within a launch takes up the path start of eq 52 that its first
  /// incarnation kept in ~path_start, so that it tracks the run's path, not a new one.
  void resumePathStart();
  void keepPathStart();

  ros::NodeHandle pnh_;
  NormaControllerParameters parameters_;
  norma::NormaParameters robot_;
  norma::NormaControlLoop loop_;
  PeriodicSchedule publication_{1.0 / parameters_.publish_rate};
  double max_state_age_ = 0.0;         ///< [s] since the last report: ROS time a state waited
  unsigned long late_commands_ = 0;    ///< commands sent more than kLateAge after their state
  std::optional<norma::NormaMeasurement> pose_;  ///< X, Y, psi of the last good odom
  InputMonitor input_;       ///< joint_states
  InputMonitor odom_input_;
  InputMonitor actuator_input_;
  ros::Subscriber joint_sub_;
  ros::Subscriber odom_sub_;
  ros::Subscriber actuator_sub_;
  StepPublications step_publications_;
  /// Commands each joint state when it comes, or in lock-step at the step it is stamped with.
  MessageDrivenWork<sensor_msgs::JointState> work_;
  LoopPublisher command_pub_;
  LoopPublisher error_pub_;
  LoopPublisher target_pub_;
  ros::Publisher desired_path_pub_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;  ///< reports on wall time (diagnostics_timer.hpp)
  std::string reconfigure_problem_;   ///< why the last refused reconfiguration was refused
  std::string run_id_;                ///< roslaunch's /run_id; empty: no path start is kept
  bool path_start_kept_ = false;      ///< ~path_start holds this launch's path start
  std::unique_ptr<dynamic_reconfigure::Server<spherical_robots::NormaControllerConfig>> reconfigure_;
};

}  // namespace spherical_robots
