#pragma once
// The norma_controller node: Norma's two-layer controller in a stack, eqs 48-51 and the PID cascade of Fig. 5 (or this project's tracking
// controller) on the plant's state, writing the pendulum torque and the slider force to the
// hardware interface's effort actuators.

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include <Eigen/Core>

#include "spherical_robots/NormaState.h"
#include <sensor_msgs/JointState.h>

#include "spherical_robots/norma/norma_control_loop.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

namespace spherical_robots {

/// Parameters (private, ~): controller (paper | tracking, "paper"); input_timeout [s] (0.05);
/// publish_rate [Hz] (50) of tracking_error and target; max_torque [N m] (20) and max_force [N]
/// (200), the actuators' limits (as given to the hardware interface) for the anti-windup;
/// max_stamp_skew [s] (1): a state stamped further from the clock, or at 0, is rejected. In the
/// node handle's namespace: robot_description (urdf/norma.urdf).
/// Subscribes norma_state; for each good one, the loop of norma::NormaControlLoop (path of eq 52
/// timed from the first state, PID integrals advanced by the time between states, held while
/// saturated or while the actuators apply nothing: e-stop, watchdog) publishes
/// actuators/command (effort[] of pendulum_motor [N m] and slider_motor [N]). Subscribes
/// actuators/state for the applied efforts. Publishes tracking_error, target,
/// desired_path (latched, one period of eq 52) and /diagnostics. A bad state is rejected and
/// changes nothing (nothing is commanded for it; the hardware's watchdog catches a silent
/// controller).
/// The loop is real time: nothing waits for the controller. /diagnostics reports how old each
/// state is (in ROS time) when its command leaves, and warns about commands later than 2 ms —
/// the paper's inner loop does not survive much more delay (docs/conventions.md).
class NormaControllerRos {
 public:
  /// @throw std::invalid_argument on a bad parameter or URDF.
  NormaControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void onState(const spherical_robots::NormaState& msg);
  /// Commands from one state (nothing for a rejected one).
  void control(const spherical_robots::NormaState& msg);
  /// ROS time, or in lock-step the time of the latest step.
  ros::Time now() const;
  void onActuatorState(const sensor_msgs::JointState& msg);
  const norma::NormaController& controller() const { return loop_.controller(); }
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  norma::NormaParameters parameters_;
  norma::NormaControlLoop loop_;
  double publish_period_;
  double max_stamp_skew_;
  ros::Time last_publish_;
  double max_state_age_ = 0.0;         ///< [s] since the last report: ROS time a state waited
  unsigned long late_commands_ = 0;    ///< commands sent more than kLateAge after their state
  InputMonitor input_;
  InputMonitor actuator_input_;
  ros::Subscriber state_sub_;
  ros::Subscriber actuator_sub_;
  StepPublications step_publications_;
  /// Commands each state when it comes, or in lock-step at the step it is stamped with.
  MessageDrivenWork<spherical_robots::NormaState> work_;
  LoopPublisher command_pub_;
  LoopPublisher error_pub_;
  LoopPublisher target_pub_;
  ros::Publisher desired_path_pub_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;  ///< reports on wall time (diagnostics_timer.hpp)
};

}  // namespace spherical_robots
