#pragma once
// Norma's two-layer controller in a stack (the pure_pursuit_controller node with
// ~robot_type: norma): eqs 48-51 and the PID cascade of Fig. 5 (or this project's tracking
// controller) on the plant's state, writing the pendulum torque and the slider force to the
// hardware interface's effort actuators.

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

#include <Eigen/Core>

#include "spherical_robots/NormaState.h"
#include "spherical_robots/norma/norma_controller.hpp"
#include "spherical_robots/ros/input_monitor.hpp"

namespace spherical_robots {

/// Parameters (private, ~): controller (paper | tracking, "paper"); input_timeout [s] (0.05);
/// publish_rate [Hz] (50) of tracking_error and target. In the node handle's namespace:
/// robot_description (urdf/norma.urdf).
/// Subscribes norma_state; for each good one, with the path of eq 52 timed from the first state,
/// publishes actuators/command (effort[] of pendulum_motor [N m] and slider_motor [N]). The PID
/// integrals advance by the time between consecutive states. Publishes tracking_error, target,
/// desired_path (latched, one period of eq 52) and /diagnostics. A bad state is rejected
/// (nothing is commanded for it; the hardware's watchdog catches a silent controller).
/// The loop is real time: nothing waits for the controller. /diagnostics reports how old each
/// state is (in ROS time) when its command leaves, and warns about commands later than 2 ms —
/// the paper's inner loop does not survive much more delay (docs/conventions.md).
class NormaControllerRos {
 public:
  /// @throw std::invalid_argument on a bad parameter or URDF.
  NormaControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void onState(const spherical_robots::NormaState& msg);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  norma::NormaParameters parameters_;
  norma::NormaController controller_;
  double publish_period_;
  ros::Time path_start_;
  ros::Time last_state_;
  ros::Time last_publish_;
  Eigen::Vector3d integrals_ = Eigen::Vector3d::Zero();
  double max_state_age_ = 0.0;         ///< [s] since the last report: ROS time a state waited
  unsigned long late_commands_ = 0;    ///< commands sent more than kLateAge after their state
  norma::ControlOutput last_output_;
  InputMonitor input_;
  ros::Subscriber state_sub_;
  ros::Publisher command_pub_;
  ros::Publisher error_pub_;
  ros::Publisher target_pub_;
  ros::Publisher desired_path_pub_;
  diagnostic_updater::Updater updater_;
};

}  // namespace spherical_robots
