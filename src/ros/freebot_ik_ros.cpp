#include "spherical_robots/ros/freebot_ik_ros.hpp"

#include <sensor_msgs/JointState.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/config/freebot_config.hpp"
#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/freebot_conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {
namespace {

using freebot::GoalStatus;

// Goals come from rviz (float32 quaternions) and from people typing 4-digit quaternions.
constexpr double kGoalUnitTolerance = 1e-3;

}  // namespace

FreebotIkParameters loadFreebotIkParameters(const config::ParameterSource& stack,
                                            const config::ParameterSource& node) {
  FreebotIkParameters p{config::freebotChain(stack), config::freebotGoalExecutive(stack)};
  p.state_timeout = config::renamedNumber(node, {"state_timeout", "input_timeout"},
                                          p.state_timeout, config::positiveNumber);
  p.max_stamp_skew = config::positiveNumber(node, "max_stamp_skew", p.max_stamp_skew);
  p.max_goal_distance = config::positiveNumber(node, "max_goal_distance", p.max_goal_distance);
  p.base_frame = conversions::freebotLinkFrame(node.text("frame_prefix").value_or(""), 0);
  return p;
}

FreebotIkRos::FreebotIkRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : parameters_(loadFreebotIkParameters(RosParameterSource(nh), RosParameterSource(pnh))),
      executive_(parameters_.chain, parameters_.executive),
      state_input_(nh.resolveName("freebot_state"), parameters_.state_timeout),
      goal_input_(nh.resolveName("move_freebot/goal"), 1e9),
      work_([this](const spherical_robots::FreebotState& msg) { drive(msg); }, step_publications_),
      goals_(nh, "move_freebot",
             [this](const spherical_robots::MoveFreebotGoal& goal) { return check(goal); }),
      updater_(nh, pnh, pnh.getNamespace()) {
  command_pub_ = step_publications_.advertise<sensor_msgs::JointState>(nh, "actuators/command");
  target_pub_ = nh.advertise<geometry_msgs::PoseStamped>("ik_target", 1, true);
  state_sub_ = nh.subscribe("freebot_state", kLoopQueueSize, &FreebotIkRos::onState, this);
  goal_arrival_sub_ =
      nh.subscribe("move_freebot/goal", kLoopQueueSize, &FreebotIkRos::onGoalArrival, this);
  result_topic_ = nh.resolveName("move_freebot/result");
  work_.join(nh, pnh, {state_sub_, goal_arrival_sub_});
  solve_server_ = nh.advertiseService("solve_ik", &FreebotIkRos::onSolve, this);
  updater_.setHardwareID("FreeBOT");
  updater_.add("freebot ik", this, &FreebotIkRos::diagnose);
  diagnostics_timer_ = startDiagnostics(nh, updater_);
  ROS_INFO_STREAM("FreeBOT IK: " << executive_.chain().moduleCount() << " modules, reach "
                                 << executive_.chain().manipulator().reach() << " m; action "
                                 << nh.resolveName("move_freebot") << ", state on "
                                 << state_input_.topic());
}

void FreebotIkRos::onState(const ros::MessageEvent<spherical_robots::FreebotState const>& event) {
  work_.arrived(event);
}

void FreebotIkRos::onGoalArrival(
    const ros::MessageEvent<spherical_robots::MoveFreebotActionGoal const>& event) {
  if (LockstepParticipant* participant = work_.participant())
    participant->received(goal_arrival_sub_.getTopic(), event);
}

void FreebotIkRos::notePublishedResult() { step_publications_.note(result_topic_); }

void FreebotIkRos::drive(const spherical_robots::FreebotState& msg) {
  const ros::Time now = msg.header.stamp;
  freebot::ExecutiveStep step;
  try {
    // Goal timeouts count from these stamps: one far from the clock must not abort a goal.
    const std::string stamp_problem =
        stampProblem(now, workingTime(work_.participant()), parameters_.max_stamp_skew);
    if (!stamp_problem.empty()) throw std::invalid_argument("freebot_state " + stamp_problem);
    const freebot::ChainState measurement = conversions::chainStateFromMsg(msg);
    // Before the step: a cancel stops the wheels at this step, a new goal drives from it.
    takeGoals(now);
    step = executive_.step(nanosecondsOf(now), measurement);
  } catch (const std::invalid_argument& e) {
    state_input_.reject(e.what());  // nothing commanded: the hardware's watchdog stops the wheels
    return;
  }
  state_input_.accept(workingTime(work_.participant()));
  for (const freebot::GoalVerdict& verdict : step.verdicts) follow(verdict);
  if (step.progress) goals_.publishFeedback(conversions::toMoveFreebotFeedback(*step.progress));
  command_pub_.publish(conversions::jointStateFromWheelSpeeds(step.wheels, now));
}

freebot::GoalPose FreebotIkRos::goalPose(const geometry_msgs::PoseStamped& target) const {
  return conversions::goalPoseFromMsg(target, parameters_.base_frame, parameters_.max_goal_distance,
                                      kGoalUnitTolerance);
}

std::optional<spherical_robots::MoveFreebotResult> FreebotIkRos::check(
    const spherical_robots::MoveFreebotGoal& goal) {
  try {
    goalPose(goal.target);
    return std::nullopt;
  } catch (const std::invalid_argument& e) {
    return rejection(e.what());
  }
}

spherical_robots::MoveFreebotResult FreebotIkRos::rejection(const std::string& why) {
  goal_input_.reject(why);  // logged, counted on /diagnostics
  freebot::GoalVerdict rejected;
  rejected.status = GoalStatus::Rejected;
  rejected.message = "goal rejected: " + why;
  last_verdict_ = rejected;
  updater_.force_update();
  return conversions::toMoveFreebotResult(rejected);
}

void FreebotIkRos::takeGoals(const ros::Time& t) {
  if (goals_.preemptRequested()) follow(executive_.cancel(nanosecondsOf(t)));
  const spherical_robots::MoveFreebotGoal* goal = goals_.pending();
  if (!goal || !executive_.measurement()) return;
  freebot::GoalVerdict verdict;
  try {
    verdict = executive_.accept(goalPose(goal->target), nanosecondsOf(t));
  } catch (const std::invalid_argument& e) {  // checked when it came: not expected
    goals_.reject(rejection(e.what()));
    notePublishedResult();
    return;
  }
  goal_input_.accept(t);
  ++goals_taken_;
  geometry_msgs::PoseStamped target = goal->target;
  target.header.stamp = t;  // when it took effect
  target_pub_.publish(target);
  target_ = target.pose.position;
  goals_.take();
  follow(verdict);
}

void FreebotIkRos::follow(const freebot::GoalVerdict& verdict) {
  std::ostringstream text;
  text << "goal (" << target_.x << ", " << target_.y << ", " << target_.z
       << ") m: " << verdict.message;
  if (verdict.status == GoalStatus::Unreachable || verdict.status == GoalStatus::Aborted)
    ROS_WARN_STREAM(text.str());
  else
    ROS_INFO_STREAM(text.str());
  if (verdict.status == GoalStatus::Unreachable) ++unreachable_;
  last_verdict_ = verdict;
  updater_.force_update();
  if (verdict.status == GoalStatus::Moving) return;  // planned, or planned again
  const spherical_robots::MoveFreebotResult result = conversions::toMoveFreebotResult(verdict);
  if (verdict.status == GoalStatus::Arrived)
    goals_.succeed(result);
  else if (verdict.status == GoalStatus::Preempted)
    goals_.preempt(result);
  else
    goals_.abort(result);  // Unreachable, Aborted
  notePublishedResult();
}

bool FreebotIkRos::onSolve(spherical_robots::SolveFreebotIk::Request& request,
                           spherical_robots::SolveFreebotIk::Response& response) {
  try {
    const Eigen::Vector3d position = conversions::fromPoint(request.target.position, "target.position");
    freebot::IkOptions options = executive_.parameters().ik;
    options.mode = request.position_only ? freebot::IkMode::PositionOnly : freebot::IkMode::FullPose;
    const Eigen::Quaterniond orientation =
        request.position_only ? Eigen::Quaterniond::Identity()
                              : conversions::fromQuaternion(request.target.orientation,
                                                            "target.orientation",
                                                            kGoalUnitTolerance);
    if (request.position_tolerance > 0.0) options.position_tolerance = request.position_tolerance;
    if (request.orientation_tolerance > 0.0)
      options.orientation_tolerance = request.orientation_tolerance;
    const freebot::FreebotChain& chain = executive_.chain();
    const std::vector<freebot::SrcJointState> seed =
        executive_.measurement() ? executive_.measurement()->joints : chain.alignedState().joints;
    const freebot::IkResult result =
        freebot::solveIk(chain.manipulator(), position, orientation, seed, options);
    response.success = result.success;
    response.position_error = result.position_error;
    response.orientation_error = result.orientation_error;
    for (const freebot::SrcJointState& joint : result.joints) {
      response.joint_quaternions.push_back(
          conversions::toQuaternion(freebot::SrcJoint::jointQuaternion(joint)));
      response.link.push_back(conversions::toQuaternion(joint.link));
      response.base.push_back(conversions::toQuaternion(joint.base));
    }
    response.iterations = result.iterations;
    std::ostringstream message;
    message << (result.success ? "reached" : "unreachable: closest pose") << " within "
            << result.position_error << " m, " << result.orientation_error << " rad ("
            << result.starts << " starts)";
    response.message = message.str();
  } catch (const std::invalid_argument& e) {
    response.success = false;
    response.message = std::string("bad request: ") + e.what();
  }
  return true;
}

void FreebotIkRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const ros::Time now = workingTime(work_.participant());
  const bool failed = last_verdict_ && (last_verdict_->status == GoalStatus::Unreachable ||
                                        last_verdict_->status == GoalStatus::Aborted ||
                                        last_verdict_->status == GoalStatus::Rejected);
  const char* last = last_verdict_ ? toString(last_verdict_->status) : "none";
  if (executive_.active())
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "moving to the goal");
  else if (failed)
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, last_verdict_->message);
  else
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   last_verdict_ ? last : "waiting for a goal");
  status.add("goals", goals_taken_);
  status.add("unreachable goals", unreachable_);
  status.add("rejected goals", goal_input_.rejected());
  status.add("last verdict", last);
  status.add("last verdict, position error [m]",
             last_verdict_ ? last_verdict_->position_error : NAN);
  status.add("last verdict, orientation error [rad]",
             last_verdict_ ? last_verdict_->orientation_error : NAN);
  const std::vector<freebot::ModuleDrive>& drives = executive_.drives();
  for (std::size_t i = 0; i < drives.size(); ++i) {
    status.addf("module " + std::to_string(i + 1) + " arc left [m], heading error [rad]",
                "%.3g, %.3g", drives[i].distance, drives[i].heading_error);
  }
  state_input_.report(status, now);
}

}  // namespace spherical_robots
