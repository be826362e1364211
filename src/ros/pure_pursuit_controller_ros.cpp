#include "spherical_robots/ros/pure_pursuit_controller_ros.hpp"

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/timer_jump_guard.hpp"

#include <geometry_msgs/PointStamped.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <sensor_msgs/JointState.h>

#include <cmath>
#include <stdexcept>

#include "spherical_robots/TrackingError.h"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {
namespace {

constexpr int kDesiredPathSamples = 400;

}  // namespace

PurePursuitControllerParameters::Mode PurePursuitControllerParameters::modeFromString(
    const std::string& name) {
  if (name == "tracking") return Mode::Tracking;
  if (name == "teleop") return Mode::Teleop;
  throw std::invalid_argument("unknown mode (tracking | teleop)");
}

PurePursuitControllerParameters loadPurePursuitControllerParameters(
    const config::ParameterSource& node) {
  using P = PurePursuitControllerParameters;
  P p;
  p.robot_type = config::parsedText(node, "robot_type", "3R", terrain::robotTypeFromString);
  p.mode = config::parsedText(node, "mode", "tracking", P::modeFromString);
  p.law = config::parsedText(node, "law", "smooth", terrain::pursuitLawFromString);
  p.path = node.text("path").value_or(p.path);
  p.odom_frame = node.text("odom_frame").value_or(p.odom_frame);
  p.rate = config::positiveNumber(node, "rate", p.rate);
  p.input_timeout = config::positiveNumber(node, "input_timeout", p.input_timeout);
  p.max_position = config::positiveNumber(node, "max_position", p.max_position);
  p.max_cmd_vel = config::positiveNumber(node, "max_cmd_vel", p.max_cmd_vel);
  p.max_stamp_skew = config::positiveNumber(node, "max_stamp_skew", p.max_stamp_skew);
  p.max_clock_step = config::positiveNumber(node, "max_clock_step", p.max_clock_step);
  p.teleop_tilt_gain = config::positiveNumber(node, "teleop_tilt_gain", p.teleop_tilt_gain);
  return p;
}

PurePursuitControllerRos::PurePursuitControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : parameters_(loadPurePursuitControllerParameters(RosParameterSource(pnh))),
      radius_(radiusFromRobotDescription(nh)),
      clock_(parameters_.max_clock_step),
      input_(nh.resolveName(parameters_.mode == Mode::Tracking ? "odom" : "cmd_vel"),
             parameters_.input_timeout),
      tilt_input_(nh.resolveName("joint_states"), parameters_.input_timeout),
      updater_(nh, pnh, pnh.getNamespace()) {
  const config::TerrainConfig terrain_config = config::loadTerrainConfig(RosParameterSource(nh));
  controller_ = config::makePursuitController(parameters_.law, parameters_.robot_type,
                                              terrain_config, radius_);

  surface_ = config::makeSurface(terrain_config.surface);
  body_frame_ = std::make_unique<terrain::BodyFrame>(*surface_, radius_);
  command_pub_ = step_publications_.advertise<sensor_msgs::JointState>(nh, "actuators/command");
  // Feedback through standard messages only: odometry (any source's, e.g. robot_localization's)
  // and, for RS, the tilt joint; the terrain model gives the contact geometry.
  std::vector<ros::Subscriber> inputs{
      nh.subscribe("odom", kLoopQueueSize, &PurePursuitControllerRos::onOdometry, this)};
  odom_sub_ = inputs.front();
  if (parameters_.robot_type == terrain::RobotType::RollingAndSteering) {
    joint_sub_ = nh.subscribe("joint_states", kLoopQueueSize, &PurePursuitControllerRos::onJointStates, this);
    inputs.push_back(joint_sub_);
  }
  if (parameters_.mode == Mode::Tracking) {
    try {
      path_ = config::makePath(parameters_.path, terrain_config);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("parameter " + pnh.resolveName("path") + " = '" +
                                  parameters_.path + "': " + e.what());
    }
    tracker_ = std::make_unique<terrain::PathTracker>(*controller_, *path_, *surface_);
    error_pub_ = step_publications_.advertise<spherical_robots::TrackingError>(nh, "tracking_error");
    target_pub_ = step_publications_.advertise<geometry_msgs::PointStamped>(nh, "target");
    desired_path_pub_ = nh.advertise<nav_msgs::Path>("desired_path", 1, true);
    desired_path_pub_.publish(conversions::sampledPath(*path_, *surface_, kDesiredPathSamples,
                                                       parameters_.odom_frame, ros::Time::now()));
    ROS_INFO_STREAM("Tracking " << path_->describe() << " on " << surface_->describe() << " with a "
                                << terrain::toString(parameters_.robot_type) << " sphere, R = " << radius_ << " m");
  } else {
    teleop_mapping_ = std::make_unique<terrain::TeleopMapping>(
        parameters_.robot_type, radius_, terrain_config.tilt_limit, parameters_.teleop_tilt_gain);
    cmd_vel_sub_ = nh.subscribe("cmd_vel", 10, &PurePursuitControllerRos::onCmdVel, this);
    ROS_INFO_STREAM("Teleoperating a " << terrain::toString(parameters_.robot_type) << " sphere, R = " << radius_
                                       << " m, from " << input_.topic());
  }

  updater_.setHardwareID(terrain::toString(parameters_.robot_type) + " sphere");
  updater_.add("pure pursuit controller", this, &PurePursuitControllerRos::diagnose);
  diagnostics_timer_ = startDiagnostics(nh, updater_);
  const double period = 1.0 / parameters_.rate;
  if (isLockstepParticipant(nh, pnh)) {
    lockstep_ = std::make_unique<LockstepParticipant>(
        nh, pnh, inputs, [this, period](const ros::Time& now) {
          return LockstepParticipant::Done{control(now), now + ros::Duration(period)};
        });
    return;
  }
  timer_ = nh.createTimer(ros::Duration(period), &PurePursuitControllerRos::onTimer, this);
  timer_guard_ = std::make_unique<TimerJumpGuard>(
      nh, std::vector<std::pair<ros::Timer*, double>>{{&timer_, period}}, clock_.maxStep());
}

ros::Time PurePursuitControllerRos::now() const { return workingTime(lockstep_.get()); }

void PurePursuitControllerRos::onOdometry(const nav_msgs::Odometry& msg) {
  const bool primary = parameters_.mode == Mode::Tracking;
  try {
    // Everything checked before anything changes: a rejected state leaves the last good one.
    acceptStamp(msg.header.stamp, "odom");
    if (msg.header.frame_id != parameters_.odom_frame)
      throw std::invalid_argument("odom in frame '" + msg.header.frame_id + "', the terrain and the path are in '" +
                                  parameters_.odom_frame + "' (~odom_frame)");
    const terrain::BodyPose body = conversions::bodyPoseFromOdometry(msg, parameters_.max_position);
    geometry_ = terrain::contactGeometry(*surface_, radius_, body_frame_->state(body, tilt_));
    if (primary) input_.accept(inputTime(msg.header.stamp));
  } catch (const std::invalid_argument& e) {
    if (primary) input_.reject(e.what());
    ROS_WARN_STREAM_THROTTLE(1.0, "Ignoring odom: " << e.what());
  }
  if (lockstep_) lockstep_->received(odom_sub_.getTopic(), msg.header.stamp);
}

void PurePursuitControllerRos::onJointStates(const sensor_msgs::JointState& msg) {
  try {
    acceptStamp(msg.header.stamp, "joint_states");
    tilt_ = conversions::tiltFromJointState(msg);
    tilt_input_.accept(inputTime(msg.header.stamp));
  } catch (const std::invalid_argument& e) {
    tilt_input_.reject(e.what());
  }
  if (lockstep_) lockstep_->received(joint_sub_.getTopic(), msg.header.stamp);
}

void PurePursuitControllerRos::acceptStamp(const ros::Time& stamp, const std::string& topic) const {
  const std::string problem = stampProblem(stamp, now(), parameters_.max_stamp_skew);
  if (!problem.empty()) throw std::invalid_argument(topic + " " + problem);
}

ros::Time PurePursuitControllerRos::inputTime(const ros::Time& stamp) const {
  // In lock-step a state is taken in at its own stamp, the step it belongs to, whatever the
  // order the transport delivered it in.
  return lockstep_ ? stamp : ros::Time::now();
}

void PurePursuitControllerRos::onCmdVel(const geometry_msgs::Twist& msg) {
  try {
    const conversions::PlanarTwist twist = conversions::planarTwist(msg, parameters_.max_cmd_vel);
    request_ = twist.request;
    input_.accept(now());
    last_cmd_vel_wall_ = ros::WallTime::now();
    warnIgnoredOnce(twist.ignored);
  } catch (const std::invalid_argument& e) {
    input_.reject(e.what());
  }
}

void PurePursuitControllerRos::warnIgnoredOnce(const std::vector<std::string>& fields) {
  for (const std::string& field : fields) {
    if (warned_ignored_.insert(field).second) {
      ROS_WARN_STREAM("A " << terrain::toString(parameters_.robot_type) << " sphere cannot follow cmd_vel " << field
                           << "; ignoring it (warned once)");
    }
  }
}

void PurePursuitControllerRos::onTimer(const ros::TimerEvent& event) {
  timer_guard_->observe(event);
  control(ros::Time::now());
}

std::vector<std::string> PurePursuitControllerRos::control(const ros::Time& now) {
  const double jump = clock_.jumpOver(now.toSec());
  if (jump != 0.0 && timer_guard_) timer_guard_->reset();
  if (jump != 0.0 && tracker_ && tracker_->started()) {
    tracker_->shiftStart(jump);
    ROS_WARN_STREAM("ROS time jumped by " << jump << " s to " << now.toSec()
                                          << " s; the reference continues where it was");
  }
  try {
    command_ = parameters_.mode == Mode::Tracking ? track(now) : teleop();
  } catch (const std::exception& e) {
    ++failures_;
    command_ = terrain::DriveRates{};
    ROS_ERROR_STREAM_THROTTLE(1.0, "Cannot compute a command (" << failures_
                                                                << " failures so far), commanding zero: "
                                                                << e.what());
  }
  command_pub_.publish(conversions::jointStateFromRates(parameters_.robot_type, command_, now));
  return step_publications_.take();
}

terrain::DriveRates PurePursuitControllerRos::track(const ros::Time& now) {
  if (!geometry_ || !input_.fresh(now)) return {};
  // Throws on a non-finite error or command; control() commands zero instead.
  const terrain::TrackingCommand tracked =
      tracker_->command(nanosecondsOf(now), *geometry_, tilt_);
  error_ = tracked.error;
  error_pub_.publish(conversions::toTrackingErrorMsg(error_, tracked.desired, parameters_.odom_frame, now));
  target_pub_.publish(conversions::toPointStamped(tracked.desired.position, parameters_.odom_frame, now));
  return tracked.rates;
}

terrain::DriveRates PurePursuitControllerRos::teleop() {
  // A person's command timeout counts wall time: at 10x real time, cmd_vel at 10 Hz of wall time
  // would otherwise be 1 s of simulated time apart, twice the timeout.
  if (last_cmd_vel_wall_.isZero() ||
      (ros::WallTime::now() - last_cmd_vel_wall_).toSec() > parameters_.input_timeout)
    return {};
  const terrain::TeleopCommand command = teleop_mapping_->command(request_, tilt_);
  // Named as cmd_vel fields, which is what the operator sends.
  std::vector<std::string> fields;
  for (const std::string& ignored : command.ignored) {
    fields.emplace_back(ignored == "leftward" ? "linear.y" : "angular.z");
  }
  warnIgnoredOnce(fields);
  return command.rates;
}

void PurePursuitControllerRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                 parameters_.mode == Mode::Tracking ? "tracking " + path_->describe() : "teleop");
  status.add("robot type", terrain::toString(parameters_.robot_type));
  if (parameters_.mode == Mode::Tracking) {
    status.add("|e_t| [m]", error_.norm);
    status.add("zeta [rad]", error_.zeta);
  }
  status.add("roll rate set-point [rad/s]", command_.roll_rate);
  status.add("lateral rate set-point [rad/s]", command_.lateral_rate);
  status.add("turn rate set-point [rad/s]", command_.turn_rate);
  status.add("command failures", failures_);
  input_.report(status, now());
  if (parameters_.robot_type == terrain::RobotType::RollingAndSteering) tilt_input_.report(status, now());
}

}  // namespace spherical_robots
