#include "spherical_robots/freebot/goal_executive.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::freebot {
namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;

double secondsSince(Nanoseconds start, Nanoseconds t) { return stampSeconds(t - start); }

}  // namespace

const char* toString(GoalStatus status) {
  switch (status) {
    case GoalStatus::Moving: return "moving";
    case GoalStatus::Arrived: return "arrived";
    case GoalStatus::Unreachable: return "unreachable";
    case GoalStatus::Rejected: return "rejected";
    case GoalStatus::Preempted: return "preempted";
    case GoalStatus::Aborted: return "aborted";
  }
  return "unknown";
}

GoalExecutive::GoalExecutive(FreebotChain chain, const GoalExecutiveParameters& parameters)
    : chain_(std::move(chain)), parameters_(parameters), drives_(chain_.moduleCount()) {
  requirePositive(parameters.position_tolerance, "goal position tolerance [m]");
  requirePositive(parameters.orientation_tolerance, "goal orientation tolerance [rad]");
  requirePositive(parameters.timeout, "goal timeout [s]");
  if (parameters.max_replans < 0)
    throw std::invalid_argument("max re-plans must be >= 0, got " +
                                std::to_string(parameters.max_replans));
}

GoalVerdict GoalExecutive::accept(const GoalPose& pose, Nanoseconds t) {
  if (goal_) throw std::logic_error("a goal is in force: cancel it before accepting another");
  if (!measurement_) throw std::invalid_argument("no chain state measured yet to plan from");
  ActiveGoal goal{pose, t, {}, 0, {}};
  // Planned before anything is kept: solveIk's rejection of a bad goal changes nothing.
  const GoalVerdict planned = plan(goal, t, "");
  if (planned.status == GoalStatus::Moving) goal_ = std::move(goal);
  return planned;
}

GoalVerdict GoalExecutive::cancel(Nanoseconds t) {
  if (!goal_) throw std::logic_error("no goal in force to cancel");
  return finish(GoalStatus::Preempted, "stopped", t);
}

ExecutiveStep GoalExecutive::step(Nanoseconds t, const ChainState& measurement) {
  chain_.requireValid(measurement);
  measurement_ = measurement;
  ExecutiveStep out;
  out.wheels.resize(chain_.moduleCount());
  if (!goal_) return out;
  drives_ = chain_.drive(measurement, goal_->targets, parameters_.gains, parameters_.limits);
  const bool arrived = std::all_of(drives_.begin(), drives_.end(),
                                   [](const ModuleDrive& drive) { return drive.arrived; });
  if (arrived) {
    const auto [position_error, orientation_error] = errors();
    if (position_error <= parameters_.position_tolerance &&
        orientation_error <= parameters_.orientation_tolerance) {
      out.verdicts.push_back(finish(GoalStatus::Arrived, "arrived", t));
    } else if (goal_->replans < parameters_.max_replans) {
      // Unequal radii: the arcs to the contact points changed the orientations.
      ++goal_->replans;
      std::ostringstream why;
      why << "contact points reached " << position_error << " m, " << orientation_error
          << " rad off the goal: re-plan " << goal_->replans << " of "
          << parameters_.max_replans << "; ";
      out.verdicts.push_back(plan(*goal_, t, why.str()));
      if (out.verdicts.back().status != GoalStatus::Moving) goal_.reset();
    } else {
      out.verdicts.push_back(finish(GoalStatus::Aborted,
                                    "not within the goal tolerances after " +
                                        std::to_string(parameters_.max_replans) + " re-plans",
                                    t));
    }
  } else if (secondsSince(goal_->accepted, t) > parameters_.timeout) {
    out.verdicts.push_back(
        finish(GoalStatus::Aborted, "goal timeout: holding the pose reached", t));
  } else {
    for (std::size_t i = 0; i < drives_.size(); ++i) out.wheels[i] = drives_[i].wheels;
  }
  if (goal_) {
    out.joint_targets = goal_->targets;
    out.progress = progress(t);
  }
  return out;
}

GoalVerdict GoalExecutive::plan(ActiveGoal& goal, Nanoseconds t, const std::string& why) const {
  IkOptions options = parameters_.ik;
  options.mode = goal.pose.mode;
  const IkResult result = solveIk(chain_.manipulator(), goal.pose.position,
                                  goal.pose.orientation, measurement_->joints, options);
  std::ostringstream message;
  message << why;
  if (result.success) {
    goal.targets = result.joints;
    message << "IK solved in " << result.iterations << " iterations: moving";
    goal.plan = message.str();
  } else {
    const double reach = chain_.manipulator().reach();
    message << "goal unreachable: the closest pose found is " << result.position_error * 1e3
            << " mm and " << result.orientation_error * kDegreesPerRadian << " deg off ("
            << result.starts << " IK starts";
    if (goal.pose.position.norm() > reach)
      message << "; |r| = " << goal.pose.position.norm() << " m is beyond the reach of " << reach
              << " m";
    message << "); the chain holds its pose";
  }
  return {result.success ? GoalStatus::Moving : GoalStatus::Unreachable, result.position_error,
          result.orientation_error, secondsSince(goal.accepted, t), goal.replans, message.str()};
}

std::pair<double, double> GoalExecutive::errors() const {
  const LinkPose end = chain_.manipulator().endEffector(measurement_->joints);
  const GoalPose& pose = goal_->pose;
  return {(end.position - pose.position).norm(),
          pose.mode == IkMode::FullPose ? angleBetween(end.orientation, pose.orientation) : 0.0};
}

GoalVerdict GoalExecutive::finish(GoalStatus status, const std::string& why, Nanoseconds t) {
  const auto [position_error, orientation_error] = errors();
  const double elapsed = secondsSince(goal_->accepted, t);
  std::ostringstream message;
  message << why << " after " << elapsed << " s (" << position_error << " m, "
          << orientation_error << " rad from the goal)";
  const int replans = goal_->replans;
  goal_.reset();
  return {status, position_error, orientation_error, elapsed, replans, message.str()};
}

GoalVerdict GoalExecutive::progress(Nanoseconds t) const {
  const auto [position_error, orientation_error] = errors();
  return {GoalStatus::Moving, position_error, orientation_error, secondsSince(goal_->accepted, t),
          goal_->replans, goal_->plan};
}

}  // namespace spherical_robots::freebot
