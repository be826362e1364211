#pragma once
// The rotor_planner node: the two-rotor sphere's geometric-phase planner (Svinin et al.) as a
// service, with the chosen plan published for rviz, and the execution of a plan through the
// rotors (the execute_manoeuvre action), decided by rotor::ManoeuvreExecutive.

#include <diagnostic_updater/diagnostic_updater.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include <memory>
#include <optional>
#include <string>

#include "spherical_robots/ExecuteRotorManoeuvreAction.h"
#include "spherical_robots/PlanRotorMotion.h"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/topic_rate.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/rotor_planner_parameters.hpp"
#include "spherical_robots/ros/single_goal_server.hpp"
#include "spherical_robots/ros/timer_jump_guard.hpp"
#include "spherical_robots/ros/trail.hpp"
#include "spherical_robots/rotor/manoeuvre_executive.hpp"

namespace spherical_robots {

/// Translates for the executive: the ~plan service (spherical_robots/PlanRotorMotion) and the
/// plan's planned_path and contact_curve, the ~execute_manoeuvre action (plan, then execute;
/// feedback every command period, the verdict as its result) and a start-up ~manoeuvre, odom in
/// as the measured rest, the executive's set-points out on actuators/command every command
/// period (on a timer, or when asked in lock-step), driven_path and /diagnostics ("rotor
/// planner"). A bad request or odom is logged, refused and reported, never fatal. Parameters:
/// docs/nodes.md, "rotor_planner".
class RotorPlannerRos {
 public:
  /// @throw std::invalid_argument on a bad parameter, or a start-up manoeuvre without a plan.
  RotorPlannerRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  bool onPlan(spherical_robots::PlanRotorMotion::Request& request,
              spherical_robots::PlanRotorMotion::Response& response);
  /// Plans `request` (units of R); on success logs it and publishes the shortest plan's path
  /// and marker, else refuses it.
  rotor::PlanResult plan(const rotor::PlanRequest& request);
  /// Publishes the path and marker of the plan (a, b, γ in units of R) for inertia ratio k.
  void publishPlan(double k, int steps, double a, double b, double gamma);
  /// Plans ~manoeuvre (if set) and asks the executive to execute it at the first step.
  void planStartUpManoeuvre(const ros::NodeHandle& pnh);
  /// At a step: plans the waiting goal (rejected, the execution in force untouched, without a
  /// plan), ends the goal in force if it is canceled or replaced, and starts the waiting one.
  void takeGoals(const ros::Time& now);
  /// Ends the goal in force with the executive's verdict, in the action state it maps to.
  void endGoal(const rotor::ManoeuvreVerdict& verdict);
  /// Logs a refusal as a warning and keeps it for /diagnostics.
  void refuse(const std::string& problem);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);
  void onCommandTimer(const ros::TimerEvent& event);
  /// Steps the executive at now and does what it says.
  void command(const ros::Time& now);
  void onOdometry(const ros::MessageEvent<nav_msgs::Odometry const>& event);

  ros::NodeHandle nh_;
  RotorPlannerParameters params_;
  double radius_;  ///< [m]
  rotor::ManoeuvreExecutive executive_;
  std::optional<rotor::RestMeasurement> rest_;  ///< from the latest valid odom
  ros::ServiceServer service_;
  ros::Publisher path_pub_;
  ros::Publisher marker_pub_;
  InputMonitor odom_input_;
  std::string last_problem_;
  /// actuators/command against ~command_rate, while a manoeuvre runs
  TopicRate command_rate_;
  diagnostic_updater::Updater updater_;
  ros::Subscriber odom_sub_;
  StepPublications step_publications_;
  LoopPublisher command_pub_;
  Trail driven_;  ///< driven_path, latched
  ros::Timer command_timer_;
  std::unique_ptr<TimerJumpGuard> timer_guard_;  ///< restarts command_timer_ after a jump
  std::unique_ptr<LockstepParticipant> lockstep_;  ///< in lock-step, instead of the timer
  SingleGoalServer<spherical_robots::ExecuteRotorManoeuvreAction> goals_;  ///< ~execute_manoeuvre
  ros::WallTimer diagnostics_timer_;
};

}  // namespace spherical_robots
