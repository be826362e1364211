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

/// An all-zero orientation asks for the position only.
bool positionOnly(const geometry_msgs::Quaternion& q) {
  return q.x == 0.0 && q.y == 0.0 && q.z == 0.0 && q.w == 0.0;
}

}  // namespace

FreebotIkParameters loadFreebotIkParameters(const config::ParameterSource& stack,
                                            const config::ParameterSource& node) {
  FreebotIkParameters p{config::freebotChain(stack), config::freebotGoalExecutive(stack)};
  p.input_timeout = config::positiveNumber(node, "input_timeout", p.input_timeout);
  p.max_stamp_skew = config::positiveNumber(node, "max_stamp_skew", p.max_stamp_skew);
  p.max_goal_distance = config::positiveNumber(node, "max_goal_distance", p.max_goal_distance);
  p.base_frame = conversions::freebotLinkFrame(node.text("frame_prefix").value_or(""), 0);
  return p;
}

FreebotIkRos::FreebotIkRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : parameters_(loadFreebotIkParameters(RosParameterSource(nh), RosParameterSource(pnh))),
      executive_(parameters_.chain, parameters_.executive),
      state_input_(nh.resolveName("freebot_state"), parameters_.input_timeout),
      goal_input_(nh.resolveName("goal"), 1e9),
      work_([this](const spherical_robots::FreebotState& msg) { drive(msg); }, step_publications_),
      updater_(nh, pnh, pnh.getNamespace()) {
  command_pub_ = step_publications_.advertise<sensor_msgs::JointState>(nh, "actuators/command");
  result_pub_ = nh.advertise<spherical_robots::FreebotGoalResult>("goal_result", 10, true);
  target_pub_ = nh.advertise<geometry_msgs::PoseStamped>("ik_target", 1, true);
  state_sub_ = nh.subscribe("freebot_state", kLoopQueueSize, &FreebotIkRos::onState, this);
  work_.join(nh, pnh, {state_sub_});
  goal_sub_ = nh.subscribe("goal", 10, &FreebotIkRos::onGoal, this);
  solve_server_ = nh.advertiseService("solve_ik", &FreebotIkRos::onSolve, this);
  updater_.setHardwareID("FreeBOT");
  updater_.add("freebot ik", this, &FreebotIkRos::diagnose);
  diagnostics_timer_ = startDiagnostics(nh, updater_);
  ROS_INFO_STREAM("FreeBOT IK: " << executive_.chain().moduleCount() << " modules, reach "
                                 << executive_.chain().manipulator().reach() << " m; goals on "
                                 << goal_input_.topic() << ", state on " << state_input_.topic());
}

void FreebotIkRos::onState(const spherical_robots::FreebotState& msg) {
  work_.arrived(msg, state_sub_.getTopic());
}

void FreebotIkRos::drive(const spherical_robots::FreebotState& msg) {
  const ros::Time now = msg.header.stamp;
  freebot::ExecutiveStep step;
  try {
    // Goal timeouts count from these stamps: one far from the clock must not abort a goal.
    const std::string stamp_problem =
        stampProblem(now, workingTime(work_.participant()), parameters_.max_stamp_skew);
    if (!stamp_problem.empty()) throw std::invalid_argument("freebot_state " + stamp_problem);
    step = executive_.step(nanosecondsOf(now), conversions::chainStateFromMsg(msg));
  } catch (const std::invalid_argument& e) {
    state_input_.reject(e.what());  // nothing commanded: the hardware's watchdog stops the wheels
    return;
  }
  state_input_.accept(workingTime(work_.participant()));
  for (const freebot::GoalVerdict& verdict : step.verdicts) publishResult(verdict, goal_pose_, now);
  command_pub_.publish(conversions::jointStateFromWheelSpeeds(step.wheels, now));
}

void FreebotIkRos::onGoal(const geometry_msgs::PoseStamped& msg) {
  const ros::Time now = workingTime(work_.participant());
  std::vector<freebot::GoalVerdict> verdicts;
  try {
    if (!msg.header.frame_id.empty() && msg.header.frame_id != parameters_.base_frame)
      throw std::invalid_argument("frame_id '" + msg.header.frame_id + "': expected '" +
                                  parameters_.base_frame + "' (or empty)");
    freebot::GoalPose goal;
    goal.position = conversions::boundedPoint(msg.pose.position, "pose.position",
                                              parameters_.max_goal_distance);
    if (positionOnly(msg.pose.orientation))
      goal.mode = freebot::IkMode::PositionOnly;
    else
      goal.orientation = conversions::fromQuaternion(msg.pose.orientation, "pose.orientation",
                                                     kGoalUnitTolerance);
    verdicts = executive_.accept(goal, nanosecondsOf(now));
  } catch (const std::invalid_argument& e) {
    goal_input_.reject(e.what());
    publishResult({GoalStatus::Rejected, freebot::kNotMeasured, freebot::kNotMeasured, 0.0,
                   std::string("goal rejected: ") + e.what()},
                  msg.pose, now);
    return;
  }
  goal_input_.accept(now);
  ++goals_;
  target_pub_.publish(msg);
  for (const freebot::GoalVerdict& verdict : verdicts)
    publishResult(verdict, verdict.status == GoalStatus::Preempted ? goal_pose_ : msg.pose, now);
  goal_pose_ = msg.pose;
}

void FreebotIkRos::publishResult(const freebot::GoalVerdict& verdict,
                                 const geometry_msgs::Pose& pose, const ros::Time& now) {
  if (verdict.status == GoalStatus::Unreachable) ++unreachable_;
  const bool failed = verdict.status == GoalStatus::Unreachable ||
                      verdict.status == GoalStatus::Aborted;
  std::ostringstream text;
  text << "goal (" << pose.position.x << ", " << pose.position.y << ", " << pose.position.z
       << ") m: " << verdict.message;
  if (failed)
    ROS_WARN_STREAM(text.str());
  else if (verdict.status != GoalStatus::Rejected)  // logged by its input monitor
    ROS_INFO_STREAM(text.str());
  result_pub_.publish(conversions::toGoalResultMsg(verdict, pose, parameters_.base_frame, now));
  last_verdict_ = verdict;
  updater_.force_update();
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
  status.add("goals", goals_);
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
