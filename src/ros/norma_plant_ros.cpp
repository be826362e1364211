#include "spherical_robots/ros/norma_plant_ros.hpp"

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

#include <nav_msgs/Odometry.h>

#include <Eigen/Geometry>
#include <stdexcept>
#include <vector>

#include "spherical_robots/NormaState.h"
#include "spherical_robots/config/norma_description.hpp"
#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {
namespace {

const std::string kWorldFrame = "world";
const std::vector<std::string> kActuators = {"pendulum_motor", "slider_motor"};
const std::vector<std::string> kJoints = {"tilt_joint", "shell_joint", "pendulum_joint",
                                          "slider_joint"};
constexpr std::size_t kMaxTrailPoints = 4000;

norma::LagrangianVariant variantFromString(const std::string& name) {
  if (name == "text") return norma::LagrangianVariant::kText;
  if (name == "appendix") return norma::LagrangianVariant::kAppendix;
  throw std::invalid_argument("unknown variant (text | appendix)");
}

norma::NormaParameters parametersFromRobotDescription(const ros::NodeHandle& nh) {
  std::string urdf;
  if (!nh.getParam("robot_description", urdf))
    throw std::invalid_argument("parameter " + nh.resolveName("robot_description") +
                                " (urdf/norma.urdf) is required");
  return config::normaParametersFromUrdf(urdf);
}

}  // namespace

NormaPlantRos::NormaPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : dynamics_(parametersFromRobotDescription(nh),
                parsedParam(pnh, "variant", "text", variantFromString)),
      base_frame_(stringParam(pnh, "frame_prefix", "") + "base_link"),
      step_(positiveParam(pnh, "step", 0.001)),
      timeline_(pnh),
      max_actuator_effort_(positiveParam(pnh, "max_actuator_effort", 1e4)),
      publish_period_(1.0 / positiveParam(pnh, "publish_rate", 50.0)),
      trail_(nh, "trail", kWorldFrame, positiveParam(pnh, "trail_period", 0.5), kMaxTrailPoints),
      actuator_input_(nh.resolveName("actuators/state"), positiveParam(pnh, "state_timeout", 0.05)),
      updater_(nh, pnh) {
  state_.psi = numberParam(pnh, "initial_psi", 0.0);
  actuator_sub_ = nh.subscribe("actuators/state", 10, &NormaPlantRos::onActuatorState, this);
  state_pub_ = nh.advertise<spherical_robots::NormaState>("norma_state", kLoopQueueSize);
  odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", kLoopQueueSize);
  joint_pub_ = nh.advertise<sensor_msgs::JointState>("joint_states", kLoopQueueSize);

  updater_.setHardwareID("Norma");
  updater_.add("norma plant", this, &NormaPlantRos::diagnose);
  diagnostics_timer_ = startDiagnostics(nh, updater_);

  const auto& p = dynamics_.parameters();
  ROS_INFO_STREAM("Norma: R = " << p.R << " m, L = " << p.L << " m, L0 = " << p.L0
                                << " m, delta0 = " << p.delta0 << " m, masses shell "
                                << p.m_shell << ", shaft " << p.m_shaft << ", pendulum "
                                << p.m_pendulum << ", slider " << p.m_slider << " kg; step "
                                << step_ << " s");
  clock_ = makePlantClock(nh, pnh, step_, 1.0, [this](const ros::Time& now) { return tick(now); },
                          state_pub_, actuator_sub_);
}

void NormaPlantRos::onActuatorState(const sensor_msgs::JointState& msg) {
  try {
    const std::vector<double> efforts = conversions::effortsByName(msg, kActuators, max_actuator_effort_);
    torque_ = efforts[0];
    force_ = efforts[1];
    actuator_input_.accept(clock_ ? clock_->now() : ros::Time::now());
  } catch (const std::invalid_argument& e) {
    actuator_input_.reject(e.what());
  }
  if (clock_) clock_->received(actuator_sub_.getTopic(), msg.header.stamp);
}

std::vector<std::string> NormaPlantRos::tick(const ros::Time& now) {
  if (timeline_.finished()) return {};
  const bool fresh = actuator_input_.fresh(now);
  timeline_.tick(now, [&](double elapsed) {
    state_ = norma::advanceWithHeldInputs(dynamics_, state_, fresh ? torque_ : 0.0,
                                          fresh ? force_ : 0.0, elapsed, step_);
  });
  publishState(now);
  std::vector<std::string> published = {state_pub_.getTopic()};
  if (periodDue(last_publish_, now, publish_period_)) {
    publishPose(now);
    published.insert(published.end(), {odom_pub_.getTopic(), joint_pub_.getTopic(), "/tf"});
  }

  if (timeline_.complete(now)) {
    ROS_INFO_STREAM("scenario complete after " << timeline_.duration() << " s, centre at ("
                                               << state_.x << ", " << state_.y << ") m");
    clock_->finish();
  }
  return published;
}

void NormaPlantRos::publishState(const ros::Time& now) {
  spherical_robots::NormaState msg;
  msg.header.stamp = now;
  for (int i = 0; i < 4; ++i) {
    msg.q[i] = state_.q(i);
    msg.qd[i] = state_.qd(i);
  }
  msg.x = state_.x;
  msg.y = state_.y;
  msg.psi = state_.psi;
  const bool fresh = actuator_input_.fresh(now);
  msg.torque = fresh ? torque_ : 0.0;
  msg.force = fresh ? force_ : 0.0;
  msg.energy = dynamics_.totalEnergy(state_.q, state_.qd);
  state_pub_.publish(msg);
}

void NormaPlantRos::publishPose(const ros::Time& now) {
  last_publish_ = now;
  const Eigen::Vector3d centre(state_.x, state_.y, dynamics_.parameters().R);
  const Eigen::Quaterniond heading(Eigen::AngleAxisd(state_.psi, Eigen::Vector3d::UnitZ()));
  const norma::PlanarRates rates = dynamics_.planarRates(state_.q, state_.qd, state_.psi);
  odom_pub_.publish(conversions::toOdometry(centre, heading, {rates.x_dot, rates.y_dot, 0.0},
                                            {0.0, 0.0, rates.psi_dot}, kWorldFrame, base_frame_,
                                            now));
  tf_broadcaster_.sendTransform(
      conversions::toTransform(centre, heading, kWorldFrame, base_frame_, now));
  // URDF joints (urdf/norma.urdf): phi, theta, alpha (relative to the shell), delta.
  const norma::Vector4& q = state_.q;
  const norma::Vector4& qd = state_.qd;
  sensor_msgs::JointState joints;
  joints.header.stamp = now;
  joints.name = kJoints;
  joints.position = {q(2), q(0), q(1), q(3)};
  joints.velocity = {qd(2), qd(0), qd(1), qd(3)};
  joint_pub_.publish(joints);

  if (trail_.due(now)) trail_.add(now, {state_.x, state_.y, 0.0}, heading);
}

void NormaPlantRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const ros::Time now = ros::Time::now();
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "rolling");
  status.add("variant", dynamics_.variant() == norma::LagrangianVariant::kText ? "text" : "appendix");
  status.add("X [m]", state_.x);
  status.add("Y [m]", state_.y);
  status.add("psi [rad]", state_.psi);
  status.add("phi [rad]", state_.q(2));
  status.add("delta [m]", state_.q(3));
  reportPlantHealth(status, now, *clock_, timeline_, actuator_input_);
  // The slider leaves the shaft's ends (|delta0 + delta| > R): the model no longer holds.
  const auto& p = dynamics_.parameters();
  if (std::abs(p.delta0 + state_.q(3)) > p.R)
    status.mergeSummary(diagnostic_msgs::DiagnosticStatus::WARN, "slider beyond the shaft's end");
}

}  // namespace spherical_robots
