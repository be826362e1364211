#include "spherical_robots/ros/norma_controller_ros.hpp"

#include "spherical_robots/ros/diagnostics_timer.hpp"

#include <XmlRpcException.h>
#include <geometry_msgs/PointStamped.h>
#include <nav_msgs/Path.h>
#include <sensor_msgs/JointState.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/config/norma_config.hpp"
#include "spherical_robots/config/norma_description.hpp"
#include "spherical_robots/core/plant_checkpoint.hpp"
#include "spherical_robots/hardware/simulated_actuators.hpp"
#include "spherical_robots/norma/norma_simulation.hpp"
#include "spherical_robots/ros/norma_conversions.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/ros/plant_clock.hpp"

namespace spherical_robots {
namespace {

constexpr double kPathPeriod = 200.0 * M_PI;  // [s] eq 52 repeats after 2π / 0.01
constexpr int kDesiredPathSamples = 2000;
constexpr double kLateAge = 0.002;
// Where the first controller of a launch keeps the path's start for a respawned one: {run_id, start [s]}.
constexpr const char* kPathStartParameter = "path_start";           // [s] two 1 ms ticks: the delay the 1 kHz loop is built for

using GainsConfig = spherical_robots::NormaControllerConfig;

/// Where each reconfigurable gain lives in the config and in norma::ControllerGains.
struct GainField {
  double GainsConfig::*config;
  double& (*gain)(norma::ControllerGains&);
};

// clang-format off
const GainField kGainFields[] = {
  {&GainsConfig::kinematic_k1, [](norma::ControllerGains& g) -> double& { return g.kinematic.k1; }},
  {&GainsConfig::kinematic_k2, [](norma::ControllerGains& g) -> double& { return g.kinematic.k2; }},
  {&GainsConfig::kinematic_k3, [](norma::ControllerGains& g) -> double& { return g.kinematic.k3; }},
  {&GainsConfig::rate_kp, [](norma::ControllerGains& g) -> double& { return g.rate.kp; }},
  {&GainsConfig::rate_ki, [](norma::ControllerGains& g) -> double& { return g.rate.ki; }},
  {&GainsConfig::pendulum_kp, [](norma::ControllerGains& g) -> double& { return g.pendulum.kp; }},
  {&GainsConfig::pendulum_ki, [](norma::ControllerGains& g) -> double& { return g.pendulum.ki; }},
  {&GainsConfig::pendulum_kd, [](norma::ControllerGains& g) -> double& { return g.pendulum.kd; }},
  {&GainsConfig::slider_kp, [](norma::ControllerGains& g) -> double& { return g.slider.kp; }},
  {&GainsConfig::slider_ki, [](norma::ControllerGains& g) -> double& { return g.slider.ki; }},
  {&GainsConfig::slider_kd, [](norma::ControllerGains& g) -> double& { return g.slider.kd; }},
  {&GainsConfig::tracking_slider_kp, [](norma::ControllerGains& g) -> double& { return g.tracking_slider.kp; }},
  {&GainsConfig::tracking_slider_ki, [](norma::ControllerGains& g) -> double& { return g.tracking_slider.ki; }},
  {&GainsConfig::tracking_slider_kd, [](norma::ControllerGains& g) -> double& { return g.tracking_slider.kd; }},
  {&GainsConfig::along_gain, [](norma::ControllerGains& g) -> double& { return g.along_gain; }},
  {&GainsConfig::cross_gain, [](norma::ControllerGains& g) -> double& { return g.cross_gain; }},
  {&GainsConfig::heading_gain, [](norma::ControllerGains& g) -> double& { return g.heading_gain; }},
  {&GainsConfig::tilt_gain, [](norma::ControllerGains& g) -> double& { return g.tilt_gain; }},
  {&GainsConfig::tilt_damping, [](norma::ControllerGains& g) -> double& { return g.tilt_damping; }},
  {&GainsConfig::max_slider, [](norma::ControllerGains& g) -> double& { return g.max_slider; }},
};
// clang-format on

}  // namespace

GainsConfig reconfigureConfigOf(const norma::ControllerGains& gains) {
  GainsConfig config = GainsConfig::__getDefault__();
  norma::ControllerGains copy = gains;
  for (const GainField& field : kGainFields) config.*field.config = field.gain(copy);
  return config;
}

norma::ControllerGains gainsOf(const GainsConfig& config, norma::ControllerGains base) {
  for (const GainField& field : kGainFields) field.gain(base) = config.*field.config;
  return base;
}

NormaControllerParameters loadNormaControllerParameters(const config::ParameterSource& node) {
  NormaControllerParameters p;
  const config::NormaControlParameters control = config::normaControlParameters(node);
  p.controller = control.controller;
  p.gains = control.gains;
  p.limits = control.limits;
  p.publish_rate = config::positiveNumber(node, "publish_rate", p.publish_rate);
  p.max_stamp_skew = config::positiveNumber(node, "max_stamp_skew", p.max_stamp_skew);
  p.state_timeout = config::renamedNumber(node, {"state_timeout", "input_timeout"},
                                          p.state_timeout, config::positiveNumber);
  p.odom_frame = node.text("odom_frame").value_or(p.odom_frame);
  return p;
}

NormaControllerRos::NormaControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : pnh_(pnh),
      parameters_(loadNormaControllerParameters(RosParameterSource(pnh))),
      robot_(fromRobotDescription(nh, config::normaParametersFromUrdf)),
      loop_(norma::NormaController(robot_, parameters_.controller, parameters_.gains),
            parameters_.limits),
      input_(nh.resolveName("joint_states"), parameters_.state_timeout),
      odom_input_(nh.resolveName("odom"), parameters_.state_timeout),
      actuator_input_(nh.resolveName("actuators/state"), parameters_.state_timeout),
      work_([this](const sensor_msgs::JointState& msg) { control(msg); }, step_publications_),
      updater_(nh, pnh, pnh.getNamespace()) {
  command_pub_ = step_publications_.advertise<sensor_msgs::JointState>(nh, "actuators/command");
  error_pub_ = step_publications_.advertise<spherical_robots::TrackingError>(nh, "tracking_error");
  target_pub_ = step_publications_.advertise<geometry_msgs::PointStamped>(nh, "target");
  desired_path_pub_ = nh.advertise<nav_msgs::Path>("desired_path", 1, true);
  desired_path_pub_.publish(
      conversions::lissajousPathMsg(kPathPeriod, kDesiredPathSamples, parameters_.odom_frame,
                                    ros::Time::now()));
  // Feedback through standard messages only: the internal joints drive the loop at the plant's
  // rate, with the latest odometry (any source's) for the pose.
  joint_sub_ = nh.subscribe("joint_states", kLoopQueueSize, &NormaControllerRos::onJointStates, this);
  odom_sub_ = nh.subscribe("odom", kLoopQueueSize, &NormaControllerRos::onOdometry, this);
  actuator_sub_ = nh.subscribe("actuators/state", kLoopQueueSize, &NormaControllerRos::onActuatorState, this);
  updater_.setHardwareID("Norma");
  updater_.add("norma controller", this, &NormaControllerRos::diagnose);
  diagnostics_timer_ = startDiagnostics(nh, updater_);
  resumePathStart();
  work_.join(nh, pnh, {joint_sub_, odom_sub_, actuator_sub_});
  // The server starts from the gains loaded above (config/norma.yaml), not from the .cfg's.
  reconfigure_ = std::make_unique<dynamic_reconfigure::Server<GainsConfig>>(pnh);
  reconfigure_->updateConfig(reconfigureConfigOf(parameters_.gains));
  reconfigure_->setCallback(
      [this](GainsConfig& config, std::uint32_t level) { onReconfigure(config, level); });
  ROS_INFO_STREAM("Norma controller: "
                  << norma::toString(controller().kind())
                  << ", path eq 52 from "
                  << (path_start_kept_ ? "this launch's start" : "the first state") << " on "
                  << input_.topic() << " and "
                  << odom_input_.topic());
}

void NormaControllerRos::resumePathStart() {
  if (!ros::param::get("/run_id", run_id_)) return;  // not launched: nothing to resume
  XmlRpc::XmlRpcValue kept;
  if (!pnh_.getParam(kPathStartParameter, kept)) return;
  try {
    const std::string mismatch =
        keyMismatch({static_cast<std::string>(kept["run_id"]), {}}, {run_id_, {}});
    if (!mismatch.empty()) {
      ROS_INFO_STREAM("~" << kPathStartParameter << " not taken up: " << mismatch);
      return;
    }
    loop_.startPathAt(static_cast<double>(kept["start"]));
  } catch (const XmlRpc::XmlRpcException& e) {
    ROS_WARN_STREAM("~" << kPathStartParameter << " = " << kept.toXml() << " is no {run_id, start}: "
                        << e.getMessage() << "; timing the path from the first state");
    return;
  }
  path_start_kept_ = true;
  ROS_INFO_STREAM("Respawned: eq 52's path goes on from this launch's start at "
                  << *loop_.pathStart() << " s");
}

void NormaControllerRos::keepPathStart() {
  XmlRpc::XmlRpcValue kept;
  kept["run_id"] = run_id_;
  kept["start"] = *loop_.pathStart();
  pnh_.setParam(kPathStartParameter, kept);
  path_start_kept_ = true;
}

void NormaControllerRos::onReconfigure(GainsConfig& config, std::uint32_t /*level*/) {
  try {
    loop_.setGains(gainsOf(config, controller().gains()));
  } catch (const std::invalid_argument& e) {
    reconfigure_problem_ = e.what();
    ROS_ERROR_STREAM("norma_controller: reconfiguration refused, the last good gains kept: "
                     << e.what());
    config = reconfigureConfigOf(controller().gains());
    updater_.force_update();
  }
}

void NormaControllerRos::onActuatorState(const ros::MessageEvent<sensor_msgs::JointState const>& event) {
  const sensor_msgs::JointState& msg = *event.getConstMessage();
  try {
    const norma::EffortLimits& limits = loop_.limits();
    const std::vector<double> efforts = conversions::effortsByName(
        msg, conversions::normaActuatorNames(), hardware::kImplausibleFactor * std::max(limits.max_torque, limits.max_force));
    loop_.actuatorsApplied(efforts[0], efforts[1]);
    actuator_input_.accept(now());
  } catch (const std::invalid_argument& e) {
    actuator_input_.reject(e.what());
  }
  if (work_.participant()) work_.participant()->received(actuator_sub_.getTopic(), event);
}

ros::Time NormaControllerRos::now() const { return workingTime(work_.participant()); }

void NormaControllerRos::onJointStates(const ros::MessageEvent<sensor_msgs::JointState const>& event) {
  work_.arrived(event);
}

void NormaControllerRos::onOdometry(const ros::MessageEvent<nav_msgs::Odometry const>& event) {
  const nav_msgs::Odometry& msg = *event.getConstMessage();
  try {
    const std::string stamp_problem = stampProblem(msg.header.stamp, now(), parameters_.max_stamp_skew);
    if (!stamp_problem.empty()) throw std::invalid_argument("odom " + stamp_problem);
    if (msg.header.frame_id != parameters_.odom_frame)
      throw std::invalid_argument("odom in frame '" + msg.header.frame_id + "', the path is in '" +
                                  parameters_.odom_frame + "' (~odom_frame)");
    pose_ = conversions::normaPoseFromOdometry(msg);
    odom_input_.accept(now());
  } catch (const std::invalid_argument& e) {
    odom_input_.reject(e.what());  // the last good pose stays
  }
  if (work_.participant()) work_.participant()->received(odom_sub_.getTopic(), event);
}

void NormaControllerRos::control(const sensor_msgs::JointState& msg) {
  const ros::Time now = msg.header.stamp;
  norma::ControlOutput output;
  norma::NormaMeasurement measured;
  try {
    // The loop validates the state before it changes anything; the stamp is checked against
    // the clock first, so a state stamped in the future cannot move the path clock.
    const std::string stamp_problem = stampProblem(now, this->now(), parameters_.max_stamp_skew);
    if (!stamp_problem.empty()) throw std::invalid_argument("joint_states " + stamp_problem);
    if (!pose_ || !odom_input_.fresh(this->now()))
      throw std::invalid_argument("no fresh odom for the pose");
    measured = conversions::withNormaJoints(*pose_, msg);
    output = loop_.step(now.toSec(), measured);
  } catch (const std::invalid_argument& e) {
    input_.reject(e.what());  // nothing commanded: the hardware keeps the last good efforts
    return;
  }
  input_.accept(this->now());
  if (!path_start_kept_ && !run_id_.empty()) keepPathStart();
  command_pub_.publish(conversions::normaEffortCommand(output.torque, output.force, now));
  const double age = (this->now() - now).toSec();
  max_state_age_ = std::max(max_state_age_, age);
  if (age > kLateAge) {
    ++late_commands_;
    ROS_WARN_STREAM_THROTTLE(1.0, "Norma controller is late: a command left "
                                      << age * 1e3 << " ms (ROS time) after its state; the loop "
                                                      "is built for <= 2 ms (lower the speed-up)");
  }

  if (publication_.take(nanosecondsOf(now))) {
    const norma::PathPoint reference = loop_.reference(now.toSec());
    const double zeta = norma::kinematicLayer(controller().gains().kinematic, robot_.R, measured.x,
                                              measured.y, measured.psi, reference).zeta;
    error_pub_.publish(
        conversions::toNormaTrackingErrorMsg(reference, measured.x, measured.y, output.error, zeta,
                                             parameters_.odom_frame, now));
    target_pub_.publish(conversions::toPointStamped({reference.x, reference.y, 0.0},
                                                    parameters_.odom_frame, now));
  }
}

void NormaControllerRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "controlling");
  const norma::ControlOutput& output = loop_.lastOutput();
  status.add("controller", norma::toString(controller().kind()));
  status.add("|e| [m]", output.error);
  status.add("T [N m]", output.torque);
  status.add("F [N]", output.force);
  status.add("theta_dot_d [rad/s]", output.theta_dot_d);
  status.add("delta_d [m]", output.delta_d);
  status.add("integrals held (actuators stopped)", loop_.actuatorsStopped());
  status.add("max state age at command [ms]", max_state_age_ * 1e3);
  status.add("late commands (> 2 ms)", late_commands_);
  status.add("last refused reconfiguration",
             reconfigure_problem_.empty() ? std::string("none") : reconfigure_problem_);
  if (max_state_age_ > kLateAge)
    status.mergeSummary(diagnostic_msgs::DiagnosticStatus::WARN, "commands late: lower the speed-up");
  max_state_age_ = 0.0;
  input_.report(status, now());
  odom_input_.report(status, now());
  actuator_input_.reportRejections(status);
}

}  // namespace spherical_robots
