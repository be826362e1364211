#pragma once
// An actionlib action server with one goal in force, driven from a node's step: the goal and
// cancel callbacks only check and queue; the node's step takes the waiting goal, ends the one in
// force and publishes feedback, so that what the core executive decides happens at a step, with
// the step's time.
//
// Why not actionlib::SimpleActionServer: it has no way to reject a goal (every goal it hands out
// is already ACTIVE), and any new goal, a malformed one too, preempts the goal in force, which
// acceptNewGoal() then ends with an empty result. Here a malformed goal is rejected at once with
// a result that says why, and the goal in force is not touched (a node keeps its last good state
// on bad input); a valid goal waits for the step, which preempts the goal in force with the
// executive's own verdict.

#include <actionlib/server/action_server.h>
#include <ros/node_handle.h>

#include <functional>
#include <optional>
#include <string>
#include <utility>

namespace spherical_robots {

/// Action: a generated action type (e.g. spherical_robots::MoveFreebotAction) whose Result has a
/// `std::string message`, given as the status text of the goal it ends.
template <typename Action>
class SingleGoalServer {
 public:
  using Goal = typename Action::_action_goal_type::_goal_type;
  using Result = typename Action::_action_result_type::_result_type;
  using Feedback = typename Action::_action_feedback_type::_feedback_type;
  using GoalHandle = actionlib::ServerGoalHandle<Action>;
  /// The result that rejects a malformed goal, or nullopt if the goal may be taken.
  using Check = std::function<std::optional<Result>(const Goal&)>;

  /// Serves action `name` (relative to nh). `check` (may be empty: every goal waits for the
  /// step) runs in the goal callback; `on_goal` (may be empty) after a goal starts to wait, e.g.
  /// to wake a node that steps on a timer only while it works.
  SingleGoalServer(ros::NodeHandle nh, const std::string& name, Check check,
                   std::function<void()> on_goal = {})
      : check_(std::move(check)), on_goal_(std::move(on_goal)), server_(nh, name, false) {
    server_.registerGoalCallback([this](GoalHandle goal) { onGoal(goal); });
    server_.registerCancelCallback([this](GoalHandle goal) { onCancel(goal); });
    server_.start();
  }

  /// The latest valid goal, waiting for a step to take it; null if none.
  const Goal* pending() const { return pending_ ? pending_->getGoal().get() : nullptr; }
  /// Whether a goal is in force (taken, not ended).
  bool active() const { return current_.has_value(); }
  /// Whether the goal in force must end at this step: its client canceled it, or a newer goal
  /// waits.
  bool preemptRequested() const { return current_ && (cancel_requested_ || pending_); }

  /// The waiting goal becomes the one in force (ACTIVE). End the one in force first.
  void take() {
    pending_->setAccepted();
    current_ = pending_;
    pending_.reset();
    cancel_requested_ = false;
  }
  /// Rejects the waiting goal (a problem found at the step): the goal in force is not touched.
  void reject(const Result& result) {
    pending_->setRejected(result, result.message);
    pending_.reset();
  }

  void publishFeedback(const Feedback& feedback) { current_->publishFeedback(feedback); }
  /// Ends the goal in force.
  void succeed(const Result& result) { end(result, &GoalHandle::setSucceeded); }
  void abort(const Result& result) { end(result, &GoalHandle::setAborted); }
  /// PREEMPTED: canceled, or replaced by the waiting goal.
  void preempt(const Result& result) { end(result, &GoalHandle::setCanceled); }

 private:
  void onGoal(GoalHandle goal) {
    if (check_) {
      if (const std::optional<Result> rejection = check_(*goal.getGoal())) {
        goal.setRejected(*rejection, rejection->message);
        return;
      }
    }
    if (pending_) pending_->setCanceled(Result(), "replaced by a newer goal before it was taken");
    pending_ = goal;
    if (on_goal_) on_goal_();
  }

  void onCancel(GoalHandle goal) {
    if (pending_ && goal == *pending_) {
      pending_->setCanceled(Result(), "canceled before it was taken");
      pending_.reset();
    } else if (current_ && goal == *current_) {
      cancel_requested_ = true;
    }
  }

  void end(const Result& result,
           void (GoalHandle::*set)(const Result&, const std::string&)) {
    ((*current_).*set)(result, result.message);
    current_.reset();
    cancel_requested_ = false;
  }

  Check check_;
  std::function<void()> on_goal_;
  std::optional<GoalHandle> pending_;
  std::optional<GoalHandle> current_;
  bool cancel_requested_ = false;
  actionlib::ActionServer<Action> server_;  ///< last: its callbacks use the members above
};

}  // namespace spherical_robots
