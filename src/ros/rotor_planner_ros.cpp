#include "spherical_robots/ros/rotor_planner_ros.hpp"

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/timer_jump_guard.hpp"

#include <nav_msgs/Path.h>
#include <visualization_msgs/Marker.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/ros/plant_clock.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "spherical_robots/rotor/geometric_phase.hpp"
#include "spherical_robots/rotor/motion_planner.hpp"

namespace spherical_robots {
namespace {

constexpr double kDefaultRadius = 0.1;        // [m]
constexpr double kDefaultMaxRadius = 0.7;     // [R], the default limit
constexpr int kMarkerSamples = 400;
const std::vector<std::string> kRotors = {"rotor_1", "rotor_2"};
constexpr std::size_t kMaxDrivenPoses = 20000;
// A plant's attitude is a unit quaternion up to its own round-off; farther from unit it is not one.
constexpr double kOdomUnitTolerance = 1e-3;

}  // namespace

RotorPlannerRos::RotorPlannerRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh),
      radius_(positiveParam(pnh, "sphere_radius", kDefaultRadius)),
      max_radius_(positiveParam(pnh, "max_radius", kDefaultMaxRadius * radius_)),
      max_position_(positiveParam(pnh, "max_position", 1e3)),
      max_stamp_skew_(positiveParam(pnh, "max_stamp_skew", 1.0)),
      clock_(positiveParam(pnh, "max_clock_step", kDefaultMaxClockStep)),
      frame_id_(stringParam(pnh, "frame_id", "odom")),
      sphere_frame_(stringParam(pnh, "sphere_frame", "base_link")),
      samples_per_step_(static_cast<int>(positiveParam(pnh, "samples_per_step", 200))),
      inertia_scale_(positiveParam(nh, "rotor_inertia_scale", 12.0)),
      curve_rate_(positiveParam(pnh, "curve_rate", 1.0)),
      ramp_time_(numberParam(pnh, "ramp_time", 1.0)),
      command_period_(1.0 / positiveParam(pnh, "command_rate", 100.0)),
      max_rotor_speed_(numberParam(pnh, "max_rotor_speed", 0.0)),
      settle_(numberParam(pnh, "settle", 1.0)),
      actuator_time_constant_(numberParam(pnh, "actuator_time_constant", 0.0)),
      corrections_(countParam(pnh, "corrections", 0, 0)),
      correction_tolerance_(positiveParam(pnh, "correction_tolerance", 1e-5)),
      correction_heading_tolerance_(positiveParam(pnh, "correction_heading_tolerance", 1e-3)),
      correction_tilt_tolerance_(positiveParam(pnh, "correction_tilt_tolerance", 1e-4)),
      correction_steps_(countParam(pnh, "correction_steps", 1, 1)),
      odom_input_(nh.resolveName("odom"), positiveParam(pnh, "odom_timeout", 0.5)),
      updater_(nh, pnh, pnh.getNamespace()),
      driven_(nh, "driven_path", frame_id_, positiveParam(pnh, "path_period", 0.05),
              kMaxDrivenPoses, true) {
  if (samples_per_step_ < 1) {
    throw std::invalid_argument("parameter " + pnh.resolveName("samples_per_step") +
                                " must be >= 1");
  }
  if (max_radius_ / radius_ >= rotor::kMaxCircleRadius) {
    throw std::invalid_argument("parameter " + pnh.resolveName("max_radius") + " = " +
                                std::to_string(max_radius_) + " m must be < R / sqrt(2) = " +
                                std::to_string(rotor::kMaxCircleRadius * radius_) + " m");
  }
  path_pub_ = nh.advertise<nav_msgs::Path>("planned_path", 1, true);
  marker_pub_ = nh.advertise<visualization_msgs::Marker>("contact_curve", 1, true);
  if (ramp_time_ < 0.0 || settle_ < 0.0 || max_rotor_speed_ < 0.0 ||
      actuator_time_constant_ < 0.0) {
    throw std::invalid_argument("parameters " + pnh.resolveName("ramp_time") + ", " +
                                pnh.resolveName("settle") + ", " +
                                pnh.resolveName("actuator_time_constant") + " and " +
                                pnh.resolveName("max_rotor_speed") + " must be >= 0");
  }
  service_ = pnh.advertiseService("plan", &RotorPlannerRos::onPlan, this);
  command_pub_ = step_publications_.advertise<sensor_msgs::JointState>(nh, "actuators/command");
  done_pub_ = nh.advertise<std_msgs::UInt32>("execution_done", 1, true);
  execute_sub_ = pnh.subscribe("execute", 1, &RotorPlannerRos::onExecute, this);
  odom_sub_ = nh.subscribe("odom", kLoopQueueSize, &RotorPlannerRos::onOdometry, this);
  if (isLockstepParticipant(nh, pnh)) {
    // Asked every command period, also between manoeuvres (it has nothing to send then).
    lockstep_ = std::make_unique<LockstepParticipant>(
        nh, pnh, std::vector<ros::Subscriber>{odom_sub_}, [this](const ros::Time& now) {
          command(now);
          return LockstepParticipant::Done{step_publications_.take(),
                                           now + ros::Duration(command_period_)};
        });
  } else {
    command_timer_ = nh_.createTimer(ros::Duration(command_period_),
                                     &RotorPlannerRos::onCommandTimer, this, false, false);
    timer_guard_ = std::make_unique<TimerJumpGuard>(
        nh, std::vector<std::pair<ros::Timer*, double>>{{&command_timer_, command_period_}},
        clock_.maxStep());
  }
  planStartUpManoeuvre(pnh);
  // The updater publishes only when called: a wall timer keeps /diagnostics going (and the odom
  // input's staleness visible) when no odom arrives.
  diagnostics_timer_ = startDiagnostics(nh, updater_);
  updater_.setHardwareID("rotor sphere");
  updater_.add("rotor planner", this, &RotorPlannerRos::diagnose);
  ROS_INFO_STREAM("rotor_planner: R = " << radius_ << " m, circle radii up to " << max_radius_
                                        << " m; service " << service_.getService());
}

void RotorPlannerRos::planStartUpManoeuvre(const ros::NodeHandle& pnh) {
  if (!pnh.hasParam("manoeuvre")) return;
  spherical_robots::PlanRotorMotion::Request request;
  spherical_robots::PlanRotorMotion::Response response;
  request.k = positiveParam(pnh, "manoeuvre/k", 2.5);
  request.steps = countParam(pnh, "manoeuvre/steps", 2, 1);
  request.u_a = numberParam(pnh, "manoeuvre/u", 0.0);
  request.v_a = numberParam(pnh, "manoeuvre/v", 0.0);
  request.psi = numberParam(pnh, "manoeuvre/psi", 0.0);
  onPlan(request, response);
  if (!response.success)
    throw std::invalid_argument("no plan for the start-up manoeuvre (" +
                                pnh.resolveName("manoeuvre") + "): " + response.reason);
  const int index = countParam(pnh, "manoeuvre/index", 0, 0);
  if (static_cast<std::size_t>(index) >= plans_.size())
    throw std::invalid_argument("parameter " + pnh.resolveName("manoeuvre/index") + " = " +
                                std::to_string(index) + ": the plan has " +
                                std::to_string(plans_.size()) + " solution(s)");
  start_up_execute_ = static_cast<std::uint32_t>(index);
  if (!lockstep_) command_timer_.start();
}

bool RotorPlannerRos::onPlan(spherical_robots::PlanRotorMotion::Request& request,
                             spherical_robots::PlanRotorMotion::Response& response) {
  rotor::PlanRequest plan;
  plan.k = request.k;
  plan.steps = request.steps;
  plan.u_a = request.u_a / radius_;
  plan.v_a = request.v_a / radius_;
  plan.psi = request.psi;
  plan.max_radius = (request.max_radius > 0.0 ? request.max_radius : max_radius_) / radius_;
  plan.heading_turns = request.heading_turns;
  rotor::PlanResult result;
  try {
    result = rotor::planRotorMotion(plan);
  } catch (const std::invalid_argument& error) {
    response.success = false;
    response.reason = std::string("invalid request: ") + error.what();
    refuse(response.reason);
    return true;
  }
  response.success = !result.solutions.empty();
  response.reason = result.reason;
  for (const rotor::RotorPlan& solution : result.solutions) {
    response.a.push_back(solution.a * radius_);
    response.b.push_back(solution.b * radius_);
    response.gamma.push_back(solution.gamma);
    response.psi.push_back(solution.psi);
    response.length.push_back(solution.length * radius_);
    response.final_error.push_back(solution.final_error);
  }
  if (!response.success) {
    refuse(result.reason);
    return true;
  }
  plan_k_ = plan.k;
  plan_steps_ = plan.steps;
  plan_max_radius_ = plan.max_radius;
  plans_.clear();
  plan_targets_.clear();
  for (const rotor::RotorPlan& solution : result.solutions) {
    plans_.emplace_back(solution.a, solution.b, solution.gamma);
    plan_targets_.push_back({plan.u_a, plan.v_a, solution.psi});
  }
  const rotor::RotorPlan& best = result.solutions.front();
  ROS_INFO_STREAM("rotor_planner: " << result.solutions.size() << " plan(s); shortest a = "
                                    << best.a * radius_ << " m, b = " << best.b * radius_
                                    << " m, gamma = " << best.gamma << " rad, final error "
                                    << best.final_error);
  publishPlan(plan.k, plan.steps, best.a, best.b, best.gamma);
  return true;
}

void RotorPlannerRos::publishPlan(double k, int steps, double a, double b, double gamma) {
  const rotor::FigureEight curve(a, b, gamma);
  const ros::Time stamp = workingTime(lockstep_.get());
  nav_msgs::Path path;
  path.header.frame_id = frame_id_;
  path.header.stamp = stamp;
  for (const rotor::ContactCoordinates& c : rotor::samplePath(k, curve, steps, samples_per_step_)) {
    const Eigen::Quaterniond orientation(rotor::orientation(c.u_o, c.v_o, c.psi));
    path.poses.push_back(conversions::toPoseStamped(
        Eigen::Vector3d(c.u_a * radius_, c.v_a * radius_, radius_), orientation, frame_id_, stamp));
  }
  path_pub_.publish(path);

  visualization_msgs::Marker marker;
  marker.header.frame_id = sphere_frame_;
  marker.header.stamp = stamp;
  marker.ns = "contact_curve";
  marker.type = visualization_msgs::Marker::LINE_STRIP;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = 0.02 * radius_;
  marker.color.r = 1.0;
  marker.color.g = 0.6;
  marker.color.a = 1.0;
  for (int i = 0; i <= kMarkerSamples; ++i) {
    marker.points.push_back(
        conversions::toPoint(radius_ * curve.at(2.0 * M_PI * i / kMarkerSamples).point));
  }
  marker_pub_.publish(marker);
}

void RotorPlannerRos::onExecute(const std_msgs::UInt32& msg) {
  if (execution_) {
    refuse("plan " + std::to_string(execution_->index) + " is still executing; ignoring execute " +
           std::to_string(msg.data));
    return;
  }
  if (msg.data >= plans_.size()) {
    refuse("execute " + std::to_string(msg.data) + " refused: the last successful plan request has " +
           std::to_string(plans_.size()) + " solution(s)");
    return;
  }
  double robot_k = 0.0;
  if (nh_.getParam("inertia_ratio", robot_k) && std::abs(robot_k - plan_k_) > 1e-9) {
    ROS_WARN_STREAM("rotor_planner: the plan is for k = " << plan_k_ << " but the robot's "
                                                          << nh_.resolveName("inertia_ratio")
                                                          << " is " << robot_k
                                                          << ": it will not reach the target");
  }
  if (!rest_pose_) {
    ROS_WARN_STREAM("rotor_planner: no odom yet: the goal is the target from the zero state");
  }
  driven_.clear();
  last_problem_.clear();
  if (startExecution(msg.data, plans_[msg.data], plan_steps_,
                 rotor::planEnd(rest_pose_.value_or(rotor::RestPose{}), plan_targets_[msg.data]),
                 corrections_)) {
    ++executions_;
  }
}

bool RotorPlannerRos::startExecution(std::uint32_t index, const rotor::FigureEight& curve,
                                     int steps, const rotor::RestPose& goal, int corrections_left) {
  try {
    const double peak = rotor::peakRotorSpeed(plan_k_, inertia_scale_, curve);
    const double rate = limitedCurveRate(peak);
    const rotor::CurveTiming timing = curveTiming(steps, rate);
    const double k = plan_k_;
    const double scale = inertia_scale_;
    execution_ = Execution{index,
                           [k, scale, curve, timing](double t) {
                             return rotor::planSetPointAt(k, scale, curve, timing, t);
                           },
                           timing.duration(), workingTime(lockstep_.get()), goal, corrections_left, false};
    ROS_INFO_STREAM("rotor_planner: executing plan " << index << " (" << steps
                                                     << " steps, theta rate " << rate
                                                     << " rad/s, peak rotor speed " << peak * rate
                                                     << " rad/s) for " << timing.duration()
                                                     << " s");
  } catch (const std::invalid_argument& error) {
    refuse("execute " + std::to_string(index) + " refused: " + error.what());
    return false;
  }
  command_timer_.start();  // a correction continues in the running timer's phase
  return true;
}

rotor::CurveTiming RotorPlannerRos::curveTiming(int steps, double rate) const {
  // Short manoeuvres at high rates shorten the ramps to fit.
  return rotor::CurveTiming(steps, rate, std::min(ramp_time_, 2.0 * M_PI * steps / rate));
}

double RotorPlannerRos::limitedCurveRate(double peak_at_unit_rate) const {
  if (max_rotor_speed_ <= 0.0 || peak_at_unit_rate * curve_rate_ <= max_rotor_speed_) {
    return curve_rate_;
  }
  const double rate = max_rotor_speed_ / peak_at_unit_rate;
  ROS_WARN_STREAM("rotor_planner: curve rate lowered from " << curve_rate_ << " to " << rate
                                                            << " rad/s: peak rotor speed "
                                                            << peak_at_unit_rate * curve_rate_
                                                            << " > " << max_rotor_speed_
                                                            << " rad/s");
  return rate;
}

bool RotorPlannerRos::startPoleReturn(const rotor::PoleReturnArc& arc, int corrections_left) {
  const double k = plan_k_;
  const double scale = inertia_scale_;
  const rotor::CurveTiming timing = curveTiming(1, limitedCurveRate(rotor::peakRotorSpeed(
      [&](double theta) { return rotor::arcSetPoint(k, scale, arc, theta, 1.0); })));
  const rotor::RestPose goal = execution_->goal;
  execution_ = Execution{execution_->index,
                         [k, scale, arc, timing](double t) {
                           return rotor::arcSetPointAt(k, scale, arc, timing, t);
                         },
                         timing.duration(), workingTime(lockstep_.get()), goal, corrections_left, true};
  command_timer_.start();
  return true;
}

bool RotorPlannerRos::startCorrection() {
  if (execution_->corrections_left <= 0) return false;
  if (!odom_input_.fresh(workingTime(lockstep_.get()))) {
    refuse("no fresh odom on " + odom_input_.topic() + ": no correction from a stale rest");
    return false;
  }
  try {
    return planCorrection();
  } catch (const std::invalid_argument& error) {
    refuse(std::string("no correction: ") + error.what());
    return false;
  }
}

bool RotorPlannerRos::planCorrection() {
  const rotor::RestPose goal = execution_->goal;
  const auto [miss, turn_miss] = missFrom(goal);
  const int left = execution_->corrections_left - 1;
  // First back to the south pole: every figure eight starts and ends there. Never two arcs in a
  // row: an arc that left the contact off the pole was limited by the rotors' noise, which a
  // second one would meet again, while the miss on the plane waits for a figure eight.
  const rotor::PoleReturnArc arc(contact_angles_.x(), contact_angles_.y());
  if (!execution_->pole_return && arc.angle() > correction_tilt_tolerance_) {
    ROS_INFO_STREAM("rotor_planner: contact " << arc.angle() << " rad off the south pole, "
                                              << miss << " m and " << turn_miss
                                              << " rad off the goal: correction "
                                              << corrections_ - left << " of " << corrections_
                                              << ", back to the pole");
    ++corrections_made_;
    return startPoleReturn(arc, left);
  }
  if (miss <= correction_tolerance_ && turn_miss <= correction_heading_tolerance_) return false;
  rotor::PlanRequest request;
  request.k = plan_k_;
  request.steps = correction_steps_;
  request.max_radius = plan_max_radius_;
  const rotor::PlanTarget target = rotor::correctionTarget(*rest_pose_, goal);
  request.u_a = target.u_a;
  request.v_a = target.v_a;
  request.psi = target.psi;
  const rotor::PlanResult result = rotor::planRotorMotion(request);
  if (result.solutions.empty()) {
    std::ostringstream problem;
    problem << miss << " m, " << turn_miss << " rad off the goal, no correction: " << result.reason;
    refuse(problem.str());
    return false;
  }
  const rotor::RotorPlan& best = result.solutions.front();
  ROS_INFO_STREAM("rotor_planner: " << miss << " m, " << turn_miss << " rad off the goal: "
                                    << "correction " << corrections_ - left << " of "
                                    << corrections_ << ", a = " << best.a * radius_
                                    << " m, b = " << best.b * radius_ << " m");
  if (!startExecution(execution_->index, rotor::FigureEight(best.a, best.b, best.gamma),
                      correction_steps_, goal, left)) {
    return false;
  }
  ++corrections_made_;
  return true;
}

std::pair<double, double> RotorPlannerRos::missFrom(const rotor::RestPose& goal) const {
  const rotor::RestPose& reached = rest_pose_.value_or(rotor::RestPose{});
  return {radius_ * std::hypot(goal.u_a - reached.u_a, goal.v_a - reached.v_a),
          std::abs(wrapToPi(goal.psi - reached.psi))};
}

void RotorPlannerRos::refuse(const std::string& problem) {
  ROS_WARN_STREAM("rotor_planner: " << problem);
  last_problem_ = problem;
  updater_.force_update();
}

void RotorPlannerRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  if (execution_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   "executing plan " + std::to_string(execution_->index) + ", " +
                       std::to_string(corrections_ - execution_->corrections_left) + " of " +
                       std::to_string(corrections_) + " corrections");
  } else if (!last_problem_.empty()) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, last_problem_);
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   plans_.empty() ? "waiting for a plan request" : "idle");
  }
  status.add("plans available", plans_.size());
  status.add("executions", executions_);
  status.add("corrections made", corrections_made_);
  status.add("last problem", last_problem_.empty() ? "none" : last_problem_);
  if (last_miss_) {
    status.addf("last end: miss [m]", "%.3e", last_miss_->first);
    status.addf("last end: heading miss [rad]", "%.3e", last_miss_->second);
  }
  odom_input_.report(status, workingTime(lockstep_.get()));
}

void RotorPlannerRos::onCommandTimer(const ros::TimerEvent& event) {
  timer_guard_->observe(event);
  command(ros::Time::now());
  step_publications_.take();
}

void RotorPlannerRos::command(const ros::Time& now) {
  const double jump = clock_.jumpOver(now.toSec());
  if (jump != 0.0 && timer_guard_) timer_guard_->reset();
  if (start_up_execute_) {
    std_msgs::UInt32 start_up;
    start_up.data = *start_up_execute_;
    start_up_execute_.reset();
    onExecute(start_up);
  }
  if (!execution_) return;
  if (jump != 0.0) {
    // The schedule goes on from where it was, not from where the jump would put it.
    execution_->start = ros::Time(std::max(0.0, execution_->start.toSec() + jump));
    ROS_WARN_STREAM("rotor_planner: ROS time jumped by " << jump << " s to " << now.toSec()
                                                         << " s; the manoeuvre continues");
  }
  const double t = (now - execution_->start).toSec();
  const double end = execution_->duration;
  if (t <= end + command_period_) {
    // One sample past the end: the timing is at rest there, so the last set-point is zero.
    const rotor::RotorSpeeds speeds = rotor::lagCompensatedSetPoint(
        execution_->schedule, std::max(t, 0.0), actuator_time_constant_, command_period_);
    command_pub_.publish(conversions::velocityJointState(kRotors, {speeds.phi1, speeds.phi2}, now));
    return;
  }
  if (t < end + settle_ || startCorrection()) return;
  std_msgs::UInt32 done;
  done.data = execution_->index;
  last_miss_ = missFrom(execution_->goal);
  ROS_INFO_STREAM("rotor_planner: plan " << done.data << " executed, " << last_miss_->first
                                         << " m and " << last_miss_->second
                                         << " rad of heading off the goal");
  execution_.reset();
  command_timer_.stop();
  driven_.publish();
  done_pub_.publish(done);
}

void RotorPlannerRos::onOdometry(const nav_msgs::Odometry& msg) {
  const geometry_msgs::Point& centre = msg.pose.pose.position;
  const geometry_msgs::Quaternion& q = msg.pose.pose.orientation;
  try {
    const std::string stamp_problem =
        stampProblem(msg.header.stamp, workingTime(lockstep_.get()), max_stamp_skew_);
    if (!stamp_problem.empty()) throw std::invalid_argument("odom " + stamp_problem);
    conversions::boundedPoint(centre, "odom pose.position", max_position_);
    const Eigen::Quaterniond attitude =
        conversions::fromQuaternion(q, "odom pose.orientation", kOdomUnitTolerance);
    const rotor::RestPose pose = rotor::measuredRestPose(centre.x, centre.y, radius_, attitude);
    contact_angles_ = rotor::measuredContactAngles(attitude);
    rest_pose_ = pose;
  } catch (const std::invalid_argument& error) {
    odom_input_.reject(error.what());  // logged; the last good rest pose stays
    if (lockstep_) lockstep_->received(odom_sub_.getTopic(), msg.header.stamp);
    return;
  }
  odom_input_.accept(workingTime(lockstep_.get()));
  if (execution_ && driven_.due(msg.header.stamp)) {
    driven_.add(msg.header.stamp, {centre.x, centre.y, centre.z},
                conversions::fromQuaternion(q, "odom pose.orientation", kOdomUnitTolerance));
  }
  if (lockstep_) lockstep_->received(odom_sub_.getTopic(), msg.header.stamp);
}

}  // namespace spherical_robots
