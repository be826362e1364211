#include "spherical_robots/ros/pure_pursuit_controller_ros.hpp"

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/timer_jump_guard.hpp"

#include <geometry_msgs/PointStamped.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <sensor_msgs/JointState.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/TrackingError.h"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {
namespace {

constexpr int kDesiredPathSamples = 400;      // a built-in path on desired_path
constexpr int kSamplesPerPathPoint = 4;       // a received path's, up to
constexpr int kMaxDesiredPathSamples = 10000;

}  // namespace

PurePursuitControllerParameters::Mode PurePursuitControllerParameters::modeFromString(
    const std::string& name) {
  if (name == "tracking") return Mode::Tracking;
  if (name == "teleop") return Mode::Teleop;
  throw std::invalid_argument("unknown mode (tracking | teleop)");
}

spherical_robots::PurePursuitControllerConfig reconfigureConfigOf(
    terrain::PursuitLaw law, const config::TerrainConfig& terrain, terrain::RobotType type) {
  spherical_robots::PurePursuitControllerConfig config =
      spherical_robots::PurePursuitControllerConfig::__getDefault__();
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  const std::vector<std::pair<std::string, double>> gains = config::namedPursuitGains(terrain, type);
  for (dynamic_reconfigure::DoubleParameter& field : message.doubles) {
    const auto gain = std::find_if(gains.begin(), gains.end(),
                                   [&](const auto& named) { return named.first == field.name; });
    if (gain == gains.end())
      throw std::invalid_argument("cfg/PurePursuitController.cfg's '" + field.name +
                                  "' is no pursuit gain");
    field.value = gain->second;
  }
  config.__fromMessage__(message);
  config.law = terrain::toString(law);
  return config;
}

config::TerrainConfig withReconfiguredGains(const spherical_robots::PurePursuitControllerConfig& config,
                                            config::TerrainConfig terrain, terrain::RobotType type) {
  dynamic_reconfigure::Config message;
  config.__toMessage__(message);
  for (const dynamic_reconfigure::DoubleParameter& field : message.doubles)
    config::setNamedPursuitGain(terrain, type, field.name, field.value);
  return terrain;
}

PurePursuitControllerParameters loadPurePursuitControllerParameters(
    const config::ParameterSource& node) {
  using P = PurePursuitControllerParameters;
  P p;
  p.robot_type = config::parsedText(node, "robot_type", "3R", terrain::robotTypeFromString);
  p.mode = config::parsedText(node, "mode", "tracking", P::modeFromString);
  p.law = config::parsedText(node, "law", "smooth", terrain::pursuitLawFromString);
  p.path = node.text("path").value_or(p.path);
  p.untimed_speed = config::positiveNumber(node, "untimed_speed", p.untimed_speed);
  p.path_tf_timeout = config::positiveNumber(node, "path_tf_timeout", p.path_tf_timeout);
  p.odom_frame = node.text("odom_frame").value_or(p.odom_frame);
  p.rate = config::positiveNumber(node, "rate", p.rate);
  // One name (input_timeout) timed both up to 0.2.0: for one release it still sets both.
  p.state_timeout = config::renamedNumber(node, {"state_timeout", "input_timeout"},
                                          p.state_timeout, config::positiveNumber);
  p.cmd_vel_timeout = config::renamedNumber(node, {"cmd_vel_timeout", "input_timeout"},
                                            p.cmd_vel_timeout, config::positiveNumber);
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
             parameters_.mode == Mode::Tracking ? parameters_.state_timeout
                                                : parameters_.cmd_vel_timeout),
      tilt_input_(nh.resolveName("joint_states"), parameters_.state_timeout),
      command_rate_(nh.resolveName("actuators/command"), parameters_.rate,
                    loadRateTolerance(RosParameterSource(pnh)), [this] { return now(); }),
      updater_(nh, pnh, pnh.getNamespace()) {
  terrain_config_ = config::loadTerrainConfig(RosParameterSource(nh));
  law_ = parameters_.law;
  controller_ = config::makePursuitController(law_, parameters_.robot_type, terrain_config_, radius_);

  surface_ = config::makeSurface(terrain_config_.surface);
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
    error_pub_ = step_publications_.advertise<spherical_robots::TrackingError>(nh, "tracking_error");
    target_pub_ = step_publications_.advertise<geometry_msgs::PointStamped>(nh, "target");
    desired_path_pub_ = nh.advertise<nav_msgs::Path>("desired_path", 1, true);
    if (parameters_.path != PurePursuitControllerParameters::kPathFromTopic) {
      try {
        path_ = config::makePath(parameters_.path, terrain_config_);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("parameter " + pnh.resolveName("path") + " = '" +
                                    parameters_.path + "': " + e.what() + ", or " +
                                    PurePursuitControllerParameters::kPathFromTopic +
                                    " to follow only the paths received on " +
                                    nh.resolveName("path"));
      }
      path_origin_ = pnh.resolveName("path") + " = " + parameters_.path;
      tracker_ = std::make_unique<terrain::PathTracker>(*controller_, *path_, *surface_);
      publishDesiredPath(kDesiredPathSamples);
    }
    path_reception_ = std::make_unique<PathReception>(
        nh,
        PathReception::Parameters{parameters_.odom_frame, parameters_.path_tf_timeout,
                                  parameters_.max_position, parameters_.untimed_speed},
        [this] { return now(); },
        [this](std::unique_ptr<terrain::SampledPath> path, const ros::Time& first_stamp,
               const ros::Time& received, const std::string& origin) {
          follow(std::move(path), first_stamp, received, origin);
        },
        [this] { return path_ ? path_->describe() : std::string(); }, updater_);
    // The server starts from the law and gains loaded above (config/terrain.yaml), not the .cfg's.
    reconfigure_ =
        std::make_unique<dynamic_reconfigure::Server<spherical_robots::PurePursuitControllerConfig>>(pnh);
    reconfigure_->updateConfig(reconfigureConfigOf(law_, terrain_config_, parameters_.robot_type));
    reconfigure_->setCallback([this](spherical_robots::PurePursuitControllerConfig& config,
                                     std::uint32_t level) { onReconfigure(config, level); });
    ROS_INFO_STREAM("Tracking " << (path_ ? path_->describe() : "nothing until a path arrives")
                                << " (a nav_msgs/Path on " << path_reception_->topic()
                                << " replaces it) on " << surface_->describe() << " with a "
                                << terrain::toString(parameters_.robot_type)
                                << " sphere, R = " << radius_ << " m");
  } else {
    teleop_mapping_ = std::make_unique<terrain::TeleopMapping>(
        parameters_.robot_type, radius_, terrain_config_.tilt_limit, parameters_.teleop_tilt_gain);
    cmd_vel_sub_ = nh.subscribe("cmd_vel", 10, &PurePursuitControllerRos::onCmdVel, this);
    ROS_INFO_STREAM("Teleoperating a " << terrain::toString(parameters_.robot_type) << " sphere, R = " << radius_
                                       << " m, from " << input_.topic());
  }

  updater_.setHardwareID(terrain::toString(parameters_.robot_type) + " sphere");
  updater_.add("pure pursuit controller", this, &PurePursuitControllerRos::diagnose);
  command_rate_.addTo(updater_);
  diagnostics_timer_ = startDiagnostics(nh, updater_);
  const double period = 1.0 / parameters_.rate;
  if (isLockstepParticipant(nh, pnh)) {
    lockstep_ = std::make_unique<LockstepParticipant>(
        nh, pnh, inputs, [this, period](const ros::Time& now) {
          return LockstepParticipant::Done{control(now), now + ros::Duration(period)};
        });
    // Time starts with a path to follow (~path topic: once one has arrived), so that a path sent
    // before the start is followed from the first step, as a built-in one.
    if (parameters_.mode == Mode::Tracking) lockstep_->joinOnlyWhen([this] { return path_ != nullptr; });
    return;
  }
  timer_ = nh.createTimer(ros::Duration(period), &PurePursuitControllerRos::onTimer, this);
  timer_guard_ = std::make_unique<TimerJumpGuard>(
      nh, std::vector<std::pair<ros::Timer*, double>>{{&timer_, period}}, clock_.maxStep());
}

ros::Time PurePursuitControllerRos::now() const { return workingTime(lockstep_.get()); }

void PurePursuitControllerRos::onOdometry(const ros::MessageEvent<nav_msgs::Odometry const>& event) {
  const nav_msgs::Odometry& msg = *event.getConstMessage();
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
  } catch (const std::exception& e) {
    // std::invalid_argument for a malformed message, terrain::OffMapError for a centre whose
    // contact point is off a height map: either way the last good state stays.
    if (primary) input_.reject(e.what());
    ROS_WARN_STREAM_THROTTLE(1.0, "Ignoring odom: " << e.what());
  }
  if (lockstep_) lockstep_->received(odom_sub_.getTopic(), event);
}

void PurePursuitControllerRos::onJointStates(const ros::MessageEvent<sensor_msgs::JointState const>& event) {
  const sensor_msgs::JointState& msg = *event.getConstMessage();
  try {
    acceptStamp(msg.header.stamp, "joint_states");
    tilt_ = conversions::tiltFromJointState(msg);
    tilt_input_.accept(inputTime(msg.header.stamp));
  } catch (const std::invalid_argument& e) {
    tilt_input_.reject(e.what());
  }
  if (lockstep_) lockstep_->received(joint_sub_.getTopic(), event);
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

void PurePursuitControllerRos::follow(std::unique_ptr<terrain::SampledPath> path,
                                      const ros::Time& first_stamp, const ros::Time& received,
                                      const std::string& origin) {
  if (!tracker_) tracker_ = std::make_unique<terrain::PathTracker>(*controller_, *path, *surface_);
  tracker_->follow(*path, nanosecondsOf(first_stamp), nanosecondsOf(received));
  const int samples = static_cast<int>(
      std::min<std::size_t>(kMaxDesiredPathSamples, kSamplesPerPathPoint * path->size()));
  path_ = std::move(path);
  path_origin_ = origin;
  publishDesiredPath(std::max(samples, kDesiredPathSamples));
  ROS_INFO_STREAM("Following a " << path_->describe() << " received on " << origin
                                  << (first_stamp > received ? ", from its first stamp " : ", from ")
                                  << (first_stamp > received ? first_stamp.toSec() : received.toSec())
                                  << " s");
}

void PurePursuitControllerRos::publishDesiredPath(int samples) {
  desired_path_pub_.publish(
      conversions::sampledPath(*path_, *surface_, samples, parameters_.odom_frame, now()));
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
  command_rate_.tick();
  return step_publications_.take();
}

terrain::DriveRates PurePursuitControllerRos::track(const ros::Time& now) {
  if (!tracker_ || !geometry_ || !input_.fresh(now)) return {};
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
      (ros::WallTime::now() - last_cmd_vel_wall_).toSec() > parameters_.cmd_vel_timeout)
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

void PurePursuitControllerRos::onReconfigure(spherical_robots::PurePursuitControllerConfig& config,
                                             std::uint32_t /*level*/) {
  const terrain::RobotType type = parameters_.robot_type;
  try {
    const terrain::PursuitLaw law = terrain::pursuitLawFromString(config.law);
    config::TerrainConfig tuned = withReconfiguredGains(config, terrain_config_, type);
    // The server's first call hands back the start-up law and gains: nothing changes.
    if (law == law_ && config::namedPursuitGains(tuned, type) ==
                           config::namedPursuitGains(terrain_config_, type))
      return;
    std::unique_ptr<terrain::PursuitController> controller =
        config::makePursuitController(law, type, tuned, radius_);
    if (tracker_) tracker_->setLaw(*controller);
    controller_ = std::move(controller);
    terrain_config_ = std::move(tuned);
    law_ = law;
    ROS_INFO_STREAM("pure_pursuit_controller: reconfigured: the " << terrain::toString(law_)
                                                                  << " law with the new gains");
  } catch (const std::invalid_argument& e) {
    reconfigure_problem_ = e.what();
    ROS_ERROR_STREAM("pure_pursuit_controller: reconfiguration refused, the last good law and "
                     "gains kept: "
                     << e.what());
    config = reconfigureConfigOf(law_, terrain_config_, type);
  }
  updater_.force_update();
}

void PurePursuitControllerRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                 parameters_.mode == Mode::Tracking
                     ? (path_ ? "tracking " + path_->describe() : "no path to track: at rest")
                     : "teleop");
  status.add("robot type", terrain::toString(parameters_.robot_type));
  if (parameters_.mode == Mode::Tracking) {
    status.add("law", terrain::toString(law_));
    if (!reconfigure_problem_.empty()) status.add("last refused reconfiguration", reconfigure_problem_);
    status.add("path", path_ ? path_->describe() : "none");
    status.add("path from", path_ ? path_origin_ : "nothing yet: waiting on " + path_reception_->topic());
    path_reception_->report(status, path_ != nullptr);
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
