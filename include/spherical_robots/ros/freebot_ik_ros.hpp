#pragma once
// The freebot_ik node: goals (the move_freebot action) and chain states in, the core
// GoalExecutive's wheel set-points, feedback and verdicts out; IK alone as a service
// (docs/nodes.md, "freebot_ik").

#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/PoseStamped.h>
#include <ros/ros.h>

#include <optional>

#include "spherical_robots/FreebotState.h"
#include "spherical_robots/MoveFreebotAction.h"
#include "spherical_robots/SolveFreebotIk.h"
#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/freebot/goal_executive.hpp"
#include "spherical_robots/ros/input_monitor.hpp"
#include "spherical_robots/ros/lockstep_participant.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/single_goal_server.hpp"

namespace spherical_robots {

/// Every parameter of freebot_ik (docs/nodes.md).
struct FreebotIkParameters {
  freebot::FreebotChain chain;                 ///< freebot/radii, freebot/trolley/*
  freebot::GoalExecutiveParameters executive;  ///< freebot/{ik,gains,drive,goal}/*
  double state_timeout = 0.1;        ///< [s] an older freebot_state (the chain's) is stale
  double max_stamp_skew = 1.0;       ///< [s] a freebot_state stamped further off the clock: rejected
  double max_goal_distance = 100.0;  ///< [m] a goal coordinate beyond it: REJECTED, not planned
  /// The fixed base B_0's frame, <~frame_prefix>link0, in which goals are (Σ I of the paper).
  std::string base_frame = "link0";
};

/// stack: the stack's namespace (config/freebot.yaml); node: the private one.
/// @throw std::invalid_argument naming the parameter on a missing or bad one.
FreebotIkParameters loadFreebotIkParameters(const config::ParameterSource& stack,
                                            const config::ParameterSource& node);

class FreebotIkRos {
 public:
  /// @throw std::invalid_argument on a bad parameter.
  FreebotIkRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  void onState(const ros::MessageEvent<spherical_robots::FreebotState const>& event);
  /// A goal the action server has just queued (its callback ran first): in lock-step, an input
  /// of the step it is stamped with (docs/lockstep.md, "The FreeBOT stack's goals").
  void onGoalArrival(const ros::MessageEvent<spherical_robots::MoveFreebotActionGoal const>& event);
  /// In a step: an action result was published (listed in the step's acknowledgement).
  void notePublishedResult();
  /// One executive step from one state (nothing for a rejected state): the goals' ends and
  /// starts, set-points, feedback and verdicts.
  void drive(const spherical_robots::FreebotState& msg);
  /// The goal a target asks for. @throw std::invalid_argument naming what is wrong.
  freebot::GoalPose goalPose(const geometry_msgs::PoseStamped& target) const;
  /// In the goal callback: the rejection of a malformed goal, or nullopt.
  std::optional<spherical_robots::MoveFreebotResult> check(
      const spherical_robots::MoveFreebotGoal& goal);
  /// Rejects a goal for `why`: logged, counted and kept for diagnostics; its result.
  spherical_robots::MoveFreebotResult rejection(const std::string& why);
  /// At a step at t: ends the goal in force if it is canceled or replaced, then takes the
  /// waiting goal once a chain state has been measured to plan from.
  void takeGoals(const ros::Time& t);
  bool onSolve(spherical_robots::SolveFreebotIk::Request& request,
               spherical_robots::SolveFreebotIk::Response& response);
  /// A verdict on the goal in force: logged and kept for diagnostics; one that ends the goal
  /// ends its action goal in the state it maps to.
  void follow(const freebot::GoalVerdict& verdict);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  FreebotIkParameters parameters_;
  freebot::GoalExecutive executive_;
  geometry_msgs::Point target_;  ///< of the goal in force, for the logs
  std::optional<freebot::GoalVerdict> last_verdict_;
  unsigned long goals_taken_ = 0;
  unsigned long unreachable_ = 0;
  InputMonitor state_input_;
  InputMonitor goal_input_;
  StepPublications step_publications_;
  /// Drives from each state when it comes, or in lock-step at the step it is stamped with.
  MessageDrivenWork<spherical_robots::FreebotState> work_;
  ros::Subscriber state_sub_;
  LoopPublisher command_pub_;
  ros::Publisher target_pub_;
  SingleGoalServer<spherical_robots::MoveFreebotAction> goals_;  ///< move_freebot
  /// move_freebot/goal once more, after the action server's own subscription: roscpp runs one
  /// topic's callbacks of one queue in the order they were added, so the goal is queued by the
  /// time the lock-step participant learns it came.
  ros::Subscriber goal_arrival_sub_;
  std::string result_topic_;  ///< move_freebot/result, resolved
  ros::ServiceServer solve_server_;
  diagnostic_updater::Updater updater_;
  ros::WallTimer diagnostics_timer_;  ///< reports on wall time (diagnostics_timer.hpp)
};

}  // namespace spherical_robots
