#include "spherical_robots/ros/freebot_ik_ros.hpp"

#include "spherical_robots/ros/diagnostics_timer.hpp"

#include <sensor_msgs/JointState.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/ros/freebot_conversions.hpp"
#include "spherical_robots/ros/freebot_plant_ros.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {
namespace {

// The errors of a verdict that measured nothing (REJECTED, PREEMPTED): -1, not NaN, which no
// message of this package carries.
constexpr double kNotMeasured = -1.0;


// Goals come from rviz (float32 quaternions) and from people typing 4-digit quaternions.
constexpr double kGoalUnitTolerance = 1e-3;

const char* statusName(std::uint8_t status) {
  switch (status) {
    case spherical_robots::FreebotGoalResult::MOVING: return "moving";
    case spherical_robots::FreebotGoalResult::ARRIVED: return "arrived";
    case spherical_robots::FreebotGoalResult::UNREACHABLE: return "unreachable";
    case spherical_robots::FreebotGoalResult::REJECTED: return "rejected";
    case spherical_robots::FreebotGoalResult::PREEMPTED: return "preempted";
    default: return "aborted";
  }
}

/// An all-zero orientation asks for the position only.
bool positionOnly(const geometry_msgs::Quaternion& q) {
  return q.x == 0.0 && q.y == 0.0 && q.z == 0.0 && q.w == 0.0;
}

}  // namespace

FreebotIkRos::FreebotIkRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : chain_(freebotChainFromParams(nh)),
      goal_position_tolerance_(positiveParam(pnh, "goal_position_tolerance", 1e-4)),
      goal_orientation_tolerance_(positiveParam(pnh, "goal_orientation_tolerance", 1e-3)),
      max_replans_(countParam(pnh, "max_replans", 3, 0)),
      goal_timeout_(positiveParam(pnh, "goal_timeout", 120.0)),
      max_stamp_skew_(positiveParam(pnh, "max_stamp_skew", 1.0)),
      max_goal_distance_(positiveParam(pnh, "max_goal_distance", 100.0)),
      last_drive_(chain_.moduleCount()),
      state_input_(nh.resolveName("freebot_state"), positiveParam(pnh, "input_timeout", 0.1)),
      goal_input_(nh.resolveName("goal"), 1e9),
      work_([this](const spherical_robots::FreebotState& msg) { drive(msg); }, step_publications_),
      updater_(nh, pnh, pnh.getNamespace()) {
  ik_options_.position_tolerance =
      positiveParam(pnh, "ik/position_tolerance", ik_options_.position_tolerance);
  ik_options_.orientation_tolerance =
      positiveParam(pnh, "ik/orientation_tolerance", ik_options_.orientation_tolerance);
  ik_options_.restarts = countParam(pnh, "ik/restarts", ik_options_.restarts, 0);
  ik_options_.max_iterations = countParam(pnh, "ik/max_iterations", ik_options_.max_iterations, 1);
  limits_.max_forward_speed = positiveParam(pnh, "max_forward_speed", limits_.max_forward_speed);
  limits_.max_steering_speed = positiveParam(pnh, "max_steering_speed", limits_.max_steering_speed);
  limits_.max_wheel_speed = positiveParam(pnh, "max_wheel_speed", limits_.max_wheel_speed);
  limits_.heading_tolerance = positiveParam(pnh, "heading_tolerance", limits_.heading_tolerance);
  limits_.contact_tolerance = positiveParam(pnh, "contact_tolerance", limits_.contact_tolerance);
  limits_.steering_distance = positiveParam(pnh, "steering_distance", limits_.steering_distance);

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
  ROS_INFO_STREAM("FreeBOT IK: " << chain_.moduleCount() << " modules, reach "
                                 << chain_.manipulator().reach() << " m; goals on "
                                 << goal_input_.topic() << ", state on " << state_input_.topic());
}

void FreebotIkRos::onState(const spherical_robots::FreebotState& msg) {
  work_.arrived(msg, state_sub_.getTopic());
}

void FreebotIkRos::drive(const spherical_robots::FreebotState& msg) {
  const ros::Time now = msg.header.stamp;
  try {
    // Goal timeouts count from these stamps: one far from the clock must not abort a goal.
    const std::string stamp_problem = stampProblem(now, workingTime(work_.participant()), max_stamp_skew_);
    if (!stamp_problem.empty()) throw std::invalid_argument("freebot_state " + stamp_problem);
    freebot::ChainState state = conversions::chainStateFromMsg(msg);
    chain_.requireValid(state);
    state_ = std::move(state);
  } catch (const std::invalid_argument& e) {
    state_input_.reject(e.what());  // nothing commanded: the hardware's watchdog stops the wheels
    return;
  }
  state_input_.accept(workingTime(work_.participant()));

  std::vector<freebot::WheelSpeeds> wheels(chain_.moduleCount());
  if (goal_) {
    last_drive_ = chain_.drive(*state_, goal_->targets, gains_, limits_);
    bool arrived = true;
    for (const freebot::ModuleDrive& drive : last_drive_) arrived = arrived && drive.arrived;
    if (arrived) {
      const auto [position_error, orientation_error] = errorsTo(*goal_);
      if (position_error <= goal_position_tolerance_ &&
          orientation_error <= goal_orientation_tolerance_) {
        finish(spherical_robots::FreebotGoalResult::ARRIVED, position_error, orientation_error,
               "arrived", now);
      } else if (goal_->replans < max_replans_) {
        ++goal_->replans;  // unequal radii: the path changed the orientations; solve again
        ROS_INFO_STREAM("contact points reached " << position_error << " m, " << orientation_error
                                                  << " rad off the goal: re-plan "
                                                  << goal_->replans << " of " << max_replans_);
        if (!plan(*goal_, now)) goal_.reset();
      } else {
        finish(spherical_robots::FreebotGoalResult::ABORTED, position_error, orientation_error,
               "not within the goal tolerances after " + std::to_string(max_replans_) +
                   " re-plans",
               now);
      }
    } else if ((now - goal_->received).toSec() > goal_timeout_) {
      const auto [position_error, orientation_error] = errorsTo(*goal_);
      finish(spherical_robots::FreebotGoalResult::ABORTED, position_error, orientation_error,
             "goal timeout: holding the pose reached", now);
    } else {
      for (std::size_t i = 0; i < wheels.size(); ++i) wheels[i] = last_drive_[i].wheels;
    }
  }
  command_pub_.publish(conversions::jointStateFromWheelSpeeds(wheels, now));
}

std::pair<double, double> FreebotIkRos::errorsTo(const Goal& goal) const {
  const freebot::LinkPose end = chain_.manipulator().endEffector(state_->joints);
  return {(end.position - goal.position).norm(),
          goal.mode == freebot::IkMode::FullPose
              ? freebot::angleBetween(end.orientation, goal.orientation)
              : 0.0};
}

void FreebotIkRos::onGoal(const geometry_msgs::PoseStamped& msg) {
  const ros::Time now = workingTime(work_.participant());
  Goal goal;
  goal.pose = msg.pose;
  goal.received = now;
  try {
    if (!msg.header.frame_id.empty() && msg.header.frame_id != kWorldFrame)
      throw std::invalid_argument("frame_id '" + msg.header.frame_id + "': expected '" +
                                  kWorldFrame + "' (or empty)");
    goal.position = conversions::boundedPoint(msg.pose.position, "pose.position", max_goal_distance_);
    goal.mode = positionOnly(msg.pose.orientation) ? freebot::IkMode::PositionOnly
                                                   : freebot::IkMode::FullPose;
    goal.orientation = goal.mode == freebot::IkMode::PositionOnly
                           ? Eigen::Quaterniond::Identity()
                           : conversions::fromQuaternion(msg.pose.orientation, "pose.orientation",
                                                         kGoalUnitTolerance);
    if (!state_) throw std::invalid_argument("no chain state on " + state_input_.topic() + " yet");
  } catch (const std::invalid_argument& e) {
    goal_input_.reject(e.what());
    publishResult(goal, spherical_robots::FreebotGoalResult::REJECTED, kNotMeasured, kNotMeasured,
                  std::string("goal rejected: ") + e.what(), now);
    return;
  }
  goal_input_.accept(now);
  ++goals_;
  if (goal_) publishResult(*goal_, spherical_robots::FreebotGoalResult::PREEMPTED, kNotMeasured,
                           kNotMeasured,
                           "replaced by a newer goal", now);
  goal_.reset();
  target_pub_.publish(msg);
  if (plan(goal, now)) goal_ = goal;
}

bool FreebotIkRos::plan(Goal& goal, const ros::Time& now) {
  freebot::IkOptions options = ik_options_;
  options.mode = goal.mode;
  const freebot::IkResult result = freebot::solveIk(chain_.manipulator(), goal.position,
                                                    goal.orientation, state_->joints, options);
  if (result.success) {
    goal.targets = result.joints;
    ROS_INFO_STREAM("goal (" << goal.position.transpose() << ") m: IK solved in "
                             << result.iterations << " iterations (" << result.position_error
                             << " m, " << result.orientation_error << " rad); driving");
    publishResult(goal, spherical_robots::FreebotGoalResult::MOVING, result.position_error,
                  result.orientation_error, "IK solved: moving", now);
    return true;
  }
  ++unreachable_;
  std::ostringstream message;
  message << "goal unreachable: the closest pose found is " << result.position_error * 1e3
          << " mm and " << result.orientation_error * 180.0 / M_PI << " deg off (" << result.starts
          << " IK starts";
  if (goal.position.norm() > chain_.manipulator().reach())
    message << "; |r| = " << goal.position.norm() << " m is beyond the reach of "
            << chain_.manipulator().reach() << " m";
  message << "); the chain holds its pose";
  ROS_WARN_STREAM(message.str());
  publishResult(goal, spherical_robots::FreebotGoalResult::UNREACHABLE, result.position_error,
                result.orientation_error, message.str(), now);
  return false;
}

void FreebotIkRos::finish(std::uint8_t status, double position_error, double orientation_error,
                          const std::string& message, const ros::Time& now) {
  const std::string text = message + " after " +
                           std::to_string((now - goal_->received).toSec()) + " s (" +
                           std::to_string(position_error) + " m, " +
                           std::to_string(orientation_error) + " rad from the goal)";
  if (status == spherical_robots::FreebotGoalResult::ARRIVED)
    ROS_INFO_STREAM(text);
  else
    ROS_WARN_STREAM(text);
  publishResult(*goal_, status, position_error, orientation_error, text, now);
  goal_.reset();
}

void FreebotIkRos::publishResult(const Goal& goal, std::uint8_t status, double position_error,
                                 double orientation_error, const std::string& message,
                                 const ros::Time& now) {
  spherical_robots::FreebotGoalResult result;
  result.header.stamp = now;
  result.header.frame_id = kWorldFrame;
  result.status = status;
  // A rejected goal may hold NaN or 1e300: nothing non-finite is published, so it is not echoed.
  const geometry_msgs::Pose& pose = goal.pose;
  const bool finite = std::isfinite(pose.position.x) && std::isfinite(pose.position.y) &&
                      std::isfinite(pose.position.z) && std::isfinite(pose.orientation.x) &&
                      std::isfinite(pose.orientation.y) && std::isfinite(pose.orientation.z) &&
                      std::isfinite(pose.orientation.w);
  if (finite) result.goal = pose;
  result.position_error = position_error;
  result.orientation_error = orientation_error;
  result.elapsed = goal.received.isZero() ? 0.0 : (now - goal.received).toSec();
  result.message = message;
  result_pub_.publish(result);
  last_result_ = result;
  have_result_ = true;
  updater_.force_update();
}

bool FreebotIkRos::onSolve(spherical_robots::SolveFreebotIk::Request& request,
                           spherical_robots::SolveFreebotIk::Response& response) {
  try {
    const Eigen::Vector3d position = conversions::fromPoint(request.target.position, "target.position");
    freebot::IkOptions options = ik_options_;
    options.mode = request.position_only ? freebot::IkMode::PositionOnly : freebot::IkMode::FullPose;
    const Eigen::Quaterniond orientation =
        request.position_only ? Eigen::Quaterniond::Identity()
                              : conversions::fromQuaternion(request.target.orientation,
                                                            "target.orientation",
                                                            kGoalUnitTolerance);
    if (request.position_tolerance > 0.0) options.position_tolerance = request.position_tolerance;
    if (request.orientation_tolerance > 0.0)
      options.orientation_tolerance = request.orientation_tolerance;
    const std::vector<freebot::SrcJointState> seed =
        state_ ? state_->joints : chain_.alignedState().joints;
    const freebot::IkResult result =
        freebot::solveIk(chain_.manipulator(), position, orientation, seed, options);
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
  if (goal_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "moving to the goal");
  } else if (have_result_ && (last_result_.status == spherical_robots::FreebotGoalResult::UNREACHABLE ||
                              last_result_.status == spherical_robots::FreebotGoalResult::ABORTED ||
                              last_result_.status == spherical_robots::FreebotGoalResult::REJECTED)) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, last_result_.message);
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   have_result_ ? statusName(last_result_.status) : "waiting for a goal");
  }
  status.add("goals", goals_);
  status.add("unreachable goals", unreachable_);
  status.add("rejected goals", goal_input_.rejected());
  status.add("last verdict", have_result_ ? statusName(last_result_.status) : "none");
  status.add("last verdict, position error [m]", have_result_ ? last_result_.position_error : NAN);
  status.add("last verdict, orientation error [rad]",
             have_result_ ? last_result_.orientation_error : NAN);
  for (std::size_t i = 0; i < last_drive_.size(); ++i) {
    status.addf("module " + std::to_string(i + 1) + " arc left [m], heading error [rad]",
                "%.3g, %.3g", last_drive_[i].distance, last_drive_[i].heading_error);
  }
  state_input_.report(status, now);
}

}  // namespace spherical_robots
