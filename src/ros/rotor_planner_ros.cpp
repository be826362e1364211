#include "spherical_robots/ros/rotor_planner_ros.hpp"

#include <nav_msgs/Path.h>
#include <visualization_msgs/Marker.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/ros/rotor_conversions.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/geometric_phase.hpp"

namespace spherical_robots {
namespace {

constexpr int kMarkerSamples = 400;
const std::vector<std::string> kRotors = {"rotor_1", "rotor_2"};
constexpr std::size_t kMaxDrivenPoses = 20000;
// A plant's attitude is a unit quaternion up to its own round-off; farther from unit it is not one.
constexpr double kOdomUnitTolerance = 1e-3;

}  // namespace

RotorPlannerRos::RotorPlannerRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh),
      params_(loadRotorPlannerParameters(RosParameterSource(nh), RosParameterSource(pnh))),
      radius_(params_.executive.radius),
      executive_(params_.executive),
      odom_input_(nh.resolveName("odom"), params_.odom_timeout),
      command_rate_(nh.resolveName("actuators/command"), 1.0 / params_.executive.command_period,
                    loadRateTolerance(RosParameterSource(pnh)),
                    [this] { return workingTime(lockstep_.get()); },
                    [this] { return executive_.busy(); }),
      updater_(nh, pnh, pnh.getNamespace()),
      driven_(nh, "driven_path", params_.frame_id, params_.path_period, kMaxDrivenPoses, true),
      // Every goal waits for a step, where it is planned; on a timer the step must run.
      goals_(pnh, "execute_manoeuvre", nullptr, [this] {
        if (!lockstep_) command_timer_.start();
      }) {
  const double period = params_.executive.command_period;
  path_pub_ = nh.advertise<nav_msgs::Path>("planned_path", 1, true);
  marker_pub_ = nh.advertise<visualization_msgs::Marker>("contact_curve", 1, true);
  service_ = pnh.advertiseService("plan", &RotorPlannerRos::onPlan, this);
  command_pub_ = step_publications_.advertise<sensor_msgs::JointState>(nh, "actuators/command");
  odom_sub_ = nh.subscribe("odom", kLoopQueueSize, &RotorPlannerRos::onOdometry, this);
  if (isLockstepParticipant(nh, pnh)) {
    // Asked every command period, also between manoeuvres (it has nothing to send then).
    lockstep_ = std::make_unique<LockstepParticipant>(
        nh, pnh, std::vector<ros::Subscriber>{odom_sub_}, [this, period](const ros::Time& now) {
          command(now);
          return LockstepParticipant::Done{step_publications_.take(), now + ros::Duration(period)};
        });
  } else {
    command_timer_ = nh_.createTimer(ros::Duration(period), &RotorPlannerRos::onCommandTimer, this,
                                     false, false);
    timer_guard_ = std::make_unique<TimerJumpGuard>(
        nh, std::vector<std::pair<ros::Timer*, double>>{{&command_timer_, period}},
        params_.executive.max_clock_step);
  }
  planStartUpManoeuvre(pnh);
  // The updater publishes only when called: a wall timer keeps /diagnostics going (and the odom
  // input's staleness visible) when no odom arrives.
  diagnostics_timer_ = startDiagnostics(nh, updater_);
  updater_.setHardwareID("rotor sphere");
  updater_.add("rotor planner", this, &RotorPlannerRos::diagnose);
  command_rate_.addTo(updater_);
  ROS_INFO_STREAM("rotor_planner: R = " << radius_ << " m, circle radii up to "
                                        << params_.max_radius << " m; service "
                                        << service_.getService() << ", action "
                                        << pnh.resolveName("execute_manoeuvre"));
}

void RotorPlannerRos::planStartUpManoeuvre(const ros::NodeHandle& pnh) {
  if (!params_.manoeuvre) return;
  const RotorPlannerParameters::StartUpManoeuvre& m = *params_.manoeuvre;
  spherical_robots::PlanRotorMotion::Request request;
  request.k = m.k;
  request.steps = m.steps;
  request.u_a = m.u;
  request.v_a = m.v;
  request.psi = m.psi;
  const rotor::PlanRequest plan_request =
      conversions::toPlanRequest(request, radius_, params_.max_radius);
  const rotor::PlanResult result = plan(plan_request);
  if (result.solutions.empty())
    throw std::invalid_argument("no plan for the start-up manoeuvre (" +
                                pnh.resolveName("manoeuvre") + "): " + result.reason);
  executive_.offerPlans(plan_request, result);
  const std::string refused = executive_.execute(static_cast<std::uint32_t>(m.index));
  if (!refused.empty())
    throw std::invalid_argument("parameter " + pnh.resolveName("manoeuvre/index") + " = " +
                                std::to_string(m.index) + ": " + refused);
  if (!lockstep_) command_timer_.start();
}

bool RotorPlannerRos::onPlan(spherical_robots::PlanRotorMotion::Request& request,
                             spherical_robots::PlanRotorMotion::Response& response) {
  const rotor::PlanResult result =
      plan(conversions::toPlanRequest(request, radius_, params_.max_radius));
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
  return true;
}

rotor::PlanResult RotorPlannerRos::plan(const rotor::PlanRequest& request) {
  rotor::PlanResult result;
  try {
    result = rotor::planRotorMotion(request);
  } catch (const std::invalid_argument& error) {
    result.reason = std::string("invalid request: ") + error.what();
  }
  if (result.solutions.empty()) {
    refuse(result.reason);
    return result;
  }
  const rotor::RotorPlan& best = result.solutions.front();
  ROS_INFO_STREAM("rotor_planner: " << result.solutions.size() << " plan(s); shortest a = "
                                    << best.a * radius_ << " m, b = " << best.b * radius_
                                    << " m, gamma = " << best.gamma << " rad, final error "
                                    << best.final_error);
  if (params_.robot_inertia_ratio && std::abs(*params_.robot_inertia_ratio - request.k) > 1e-9) {
    ROS_WARN_STREAM("rotor_planner: the plan is for k = " << request.k << " but the robot's "
                    << nh_.resolveName("inertia_ratio") << " is " << *params_.robot_inertia_ratio
                    << ": it will not reach the target");
  }
  publishPlan(request.k, request.steps, best.a, best.b, best.gamma);
  return result;
}

void RotorPlannerRos::publishPlan(double k, int steps, double a, double b, double gamma) {
  const rotor::FigureEight curve(a, b, gamma);
  const ros::Time stamp = workingTime(lockstep_.get());
  nav_msgs::Path path;
  path.header.frame_id = params_.frame_id;
  path.header.stamp = stamp;
  for (const rotor::ContactCoordinates& c :
       rotor::samplePath(k, curve, steps, params_.samples_per_step)) {
    path.poses.push_back(conversions::toPoseStamped(
        Eigen::Vector3d(c.u_a * radius_, c.v_a * radius_, radius_),
        Eigen::Quaterniond(rotor::orientation(c.u_o, c.v_o, c.psi)), params_.frame_id, stamp));
  }
  path_pub_.publish(path);

  visualization_msgs::Marker marker;
  marker.header.frame_id = params_.sphere_frame;
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

void RotorPlannerRos::takeGoals(const ros::Time& now) {
  const spherical_robots::ExecuteRotorManoeuvreGoal* goal = goals_.pending();
  rotor::PlanRequest request;
  rotor::PlanResult result;
  if (goal) {
    request = conversions::toPlanRequest(*goal, radius_, params_.max_radius);
    result = plan(request);
    std::string problem = result.reason;
    if (!result.solutions.empty() && goal->plan_index >= result.solutions.size()) {
      problem = "plan_index " + std::to_string(goal->plan_index) + " refused: the request has " +
                std::to_string(result.solutions.size()) + " plan(s)";
      refuse(problem);
    }
    if (!problem.empty()) {
      goals_.reject(conversions::rejectedManoeuvreResult(problem));
      goal = nullptr;
    }
  }
  const Nanoseconds t = nanosecondsOf(now);
  if (goals_.preemptRequested()) endGoal(executive_.cancel(t, rest_));
  if (!goal) return;
  if (executive_.executing())  // the start-up manoeuvre, which no goal stands for
    ROS_INFO_STREAM("rotor_planner: " << executive_.cancel(t, rest_).message << " for a goal");
  executive_.offerPlans(request, result);
  const std::string refused = executive_.execute(goal->plan_index);
  if (!refused.empty()) {  // the index was checked above: not expected
    refuse(refused);
    goals_.reject(conversions::rejectedManoeuvreResult(refused));
    return;
  }
  goals_.take();
  driven_.clear();
  last_problem_.clear();
}

void RotorPlannerRos::endGoal(const rotor::ManoeuvreVerdict& verdict) {
  const spherical_robots::ExecuteRotorManoeuvreResult result =
      conversions::toManoeuvreResult(verdict);
  switch (verdict.end) {
    case rotor::ManoeuvreEnd::kExecuted:
      goals_.succeed(result);
      break;
    case rotor::ManoeuvreEnd::kRefused:
      goals_.abort(result);
      break;
    case rotor::ManoeuvreEnd::kCanceled:
      ROS_INFO_STREAM("rotor_planner: " << verdict.message);
      goals_.preempt(result);
      break;
  }
}

void RotorPlannerRos::refuse(const std::string& problem) {
  ROS_WARN_STREAM("rotor_planner: " << problem);
  last_problem_ = problem;
  updater_.force_update();
}

void RotorPlannerRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  if (executive_.busy() || last_problem_.empty()) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, executive_.describe());
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, last_problem_);
  }
  status.add("state", rotor::toString(executive_.state()));
  status.add("plans available", executive_.plansAvailable());
  status.add("executions", executive_.executions());
  status.add("corrections made", executive_.correctionsMade());
  status.add("last problem", last_problem_.empty() ? "none" : last_problem_);
  if (const std::optional<rotor::Miss>& miss = executive_.lastMiss()) {
    status.addf("last end: miss [m]", "%.3e", miss->distance);
    status.addf("last end: heading miss [rad]", "%.3e", miss->heading);
  }
  odom_input_.report(status, workingTime(lockstep_.get()));
}

void RotorPlannerRos::onCommandTimer(const ros::TimerEvent& event) {
  timer_guard_->observe(event);
  command(ros::Time::now());
  step_publications_.take();
}

void RotorPlannerRos::command(const ros::Time& now) {
  if (rest_) rest_->fresh = odom_input_.fresh(now);
  takeGoals(now);
  const rotor::ManoeuvreExecutive::Output out = executive_.step(nanosecondsOf(now), rest_);
  if (out.clock_jump != 0.0 && timer_guard_) timer_guard_->reset();
  for (const rotor::ManoeuvreExecutive::Report& report : out.reports) {
    if (report.kind == rotor::ManoeuvreExecutive::Report::Kind::kRefusal) {
      refuse(report.text);
    } else if (report.kind == rotor::ManoeuvreExecutive::Report::Kind::kWarning) {
      ROS_WARN_STREAM("rotor_planner: " << report.text);
    } else {
      ROS_INFO_STREAM("rotor_planner: " << report.text);
    }
  }
  if (out.set_point) {
    command_pub_.publish(
        conversions::velocityJointState(kRotors, {out.set_point->phi1, out.set_point->phi2}, now));
    command_rate_.tick();
  }
  if (out.ended) {
    driven_.publish();
    if (goals_.active()) endGoal(*out.ended);  // else the start-up manoeuvre's end
    updater_.force_update();
  } else if (out.progress && goals_.active()) {
    goals_.publishFeedback(conversions::toManoeuvreFeedback(*out.progress));
  }
  if (!executive_.busy()) command_timer_.stop();
}

void RotorPlannerRos::onOdometry(const ros::MessageEvent<nav_msgs::Odometry const>& event) {
  const nav_msgs::Odometry& msg = *event.getConstMessage();
  const geometry_msgs::Point& centre = msg.pose.pose.position;
  try {
    const std::string stamp_problem = stampProblem(msg.header.stamp, workingTime(lockstep_.get()),
                                                   params_.max_stamp_skew);
    if (!stamp_problem.empty()) throw std::invalid_argument("odom " + stamp_problem);
    conversions::boundedPoint(centre, "odom pose.position", params_.max_position);
    const Eigen::Quaterniond attitude = conversions::fromQuaternion(
        msg.pose.pose.orientation, "odom pose.orientation", kOdomUnitTolerance);
    rest_ = rotor::measureRest(centre.x, centre.y, radius_, attitude);
    odom_input_.accept(workingTime(lockstep_.get()));
    if (executive_.busy() && driven_.due(msg.header.stamp))
      driven_.add(msg.header.stamp, {centre.x, centre.y, centre.z}, attitude);
  } catch (const std::invalid_argument& error) {
    odom_input_.reject(error.what());  // logged; the last good rest stays
  }
  if (lockstep_) lockstep_->received(odom_sub_.getTopic(), event);
}

}  // namespace spherical_robots
