#pragma once
// ROS wrapper of hardware::SimulatedActuators: the simulated side of the hardware seam described
// in docs/hardware_interface.md. Parameters in, set-points in, measured states and diagnostics
// out; every rule about limits, the watchdog and the e-stop lives in the core class.

#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>
#include <sensor_msgs/JointState.h>
#include <std_msgs/Bool.h>

#include <memory>

#include "spherical_robots/HardwareInterfaceSimConfig.h"
#include "spherical_robots/config/hardware_interface_config.hpp"
#include "spherical_robots/core/clock_jump.hpp"
#include "spherical_robots/hardware/simulated_actuators.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/topic_rate.hpp"

#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/timer_jump_guard.hpp"

namespace spherical_robots {

/// Callbacks are meant for one spinner thread (ros::spin): they share the actuators unguarded.
class HardwareInterfaceSimRos {
 public:
  /// @param nh the stack's namespace: topics actuators/command, actuators/state, estop.
  /// @param pnh the node's private namespace: its parameters (config::HardwareInterfaceSimParameters,
  ///        docs/nodes.md).
  /// @throw std::invalid_argument on a missing or malformed parameter, naming it and its value.
  HardwareInterfaceSimRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void commandCallback(const ros::MessageEvent<sensor_msgs::JointState const>& event);
  void eStopCallback(const std_msgs::Bool::ConstPtr& msg);
  void timerCallback(const ros::TimerEvent& event);
  /// The actuators' update and their state at `now` (a timer's or a lock-step request's time).
  void update(const ros::Time& now);
  /// ROS time, or in lock-step the time of the latest step.
  ros::Time now() const;
  /// Rebases the actuators when ROS time jumped (a stray /clock, a replay looping back).
  void followClock(const ros::Time& now);
  void publishState(const ros::Time& stamp);
  /// dynamic_reconfigure (cfg/HardwareInterfaceSim.cfg): the velocity actuators' limits and the
  /// watchdog's timeout, checked as at start-up; a refused change keeps the last good values and
  /// hands them back in config.
  void onReconfigure(spherical_robots::HardwareInterfaceSimConfig& config, std::uint32_t level);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  config::HardwareInterfaceSimParameters parameters_;
  hardware::SimulatedActuators actuators_;
  ros::Publisher state_pub_;
  ros::Subscriber command_sub_;
  ros::Subscriber e_stop_sub_;
  ros::Timer timer_;
  std::unique_ptr<TimerJumpGuard> timer_guard_;  ///< restarts timer_ after a clock jump
  std::unique_ptr<LockstepParticipant> lockstep_;  ///< set instead of timer_ in lock-step
  /// Counts accepted and rejected commands and logs rejections; the watchdog is the actuators'.
  InputMonitor command_input_;
  ClockJumpDetector clock_;
  TopicRate state_rate_;  ///< actuators/state against ~rate
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;  ///< reports on wall time (diagnostics_timer.hpp)
  bool reported_timeout_ = false;
  std::string reconfigure_problem_;  ///< why the last refused reconfiguration was refused
  /// Last member: its first callback applies the values on the parameter server to the actuators.
  std::unique_ptr<dynamic_reconfigure::Server<spherical_robots::HardwareInterfaceSimConfig>>
      reconfigure_;
};

}  // namespace spherical_robots
