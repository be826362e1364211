#include "spherical_robots/ros/rotor_plant_ros.hpp"

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

#include <nav_msgs/Odometry.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/rotor/plan_execution.hpp"

namespace spherical_robots {
namespace {

const std::string kWorldFrame = "world";
const std::vector<std::string> kRotors = {"rotor_1", "rotor_2"};

}  // namespace

RotorPlantRos::RotorPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : k_(positiveParam(nh, "inertia_ratio", 2.5)),
      inertia_scale_(positiveParam(nh, "rotor_inertia_scale", 12.0)),
      radius_(positiveParam(pnh, "sphere_radius", 0.1)),
      base_frame_(stringParam(pnh, "frame_prefix", "") + "base_link"),
      step_(positiveParam(pnh, "step", 0.001)),
      timeline_(pnh),
      max_actuator_rate_(positiveParam(pnh, "max_actuator_rate", 1000.0)),
      publish_period_(1.0 / positiveParam(pnh, "publish_rate", 50.0)),
      actuator_input_(nh.resolveName("actuators/state"), positiveParam(pnh, "state_timeout", 0.5)),
      updater_(nh, pnh) {
  actuator_sub_ = nh.subscribe("actuators/state", 10, &RotorPlantRos::onActuatorState, this);
  odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", kLoopQueueSize);
  joint_pub_ = nh.advertise<sensor_msgs::JointState>("joint_states", kLoopQueueSize);
  updater_.setHardwareID("rotor sphere");
  updater_.add("rotor sphere plant", this, &RotorPlantRos::diagnose);
  diagnostics_timer_ = startDiagnostics(nh, updater_);
  ROS_INFO_STREAM("rotor sphere: R = " << radius_ << " m, k = " << k_ << ", J_zz/J_r = "
                                       << inertia_scale_ << "; step " << step_ << " s");
  clock_ = makePlantClock(nh, pnh, step_, 1.0, [this](const ros::Time& now) { return tick(now); },
                          odom_pub_, actuator_sub_);
}

void RotorPlantRos::onActuatorState(const sensor_msgs::JointState& msg) {
  try {
    const std::vector<double> velocities = conversions::velocitiesByName(msg, kRotors, max_actuator_rate_);
    speeds_ = {velocities[0], velocities[1]};
    // Positions only drive the URDF's joints; a state without them keeps the last ones.
    if (msg.position.size() == msg.name.size()) {
      for (std::size_t i = 0; i < msg.name.size(); ++i) {
        for (std::size_t j = 0; j < kRotors.size(); ++j) {
          if (msg.name[i] == kRotors[j] && std::isfinite(msg.position[i]))
            positions_[j] = msg.position[i];
        }
      }
    }
    actuator_input_.accept(clock_ ? clock_->now() : ros::Time::now());
  } catch (const std::invalid_argument& e) {
    actuator_input_.reject(e.what());
  }
  if (clock_) clock_->received(actuator_sub_.getTopic(), msg.header.stamp);
}

std::vector<std::string> RotorPlantRos::tick(const ros::Time& now) {
  if (timeline_.finished()) return {};
  const bool fresh = actuator_input_.fresh(now);
  timeline_.tick(now, [&](double elapsed) {
    const auto next = rotor::advancePlant(k_, inertia_scale_, state_,
                                          fresh ? speeds_ : rotor::RotorSpeeds{}, elapsed, step_);
    // Nothing non-finite is published: a step that would produce it is a failed step.
    if (!std::isfinite(next.u_a) || !std::isfinite(next.v_a) || !std::isfinite(next.u_o) ||
        !std::isfinite(next.v_o) || !std::isfinite(next.psi))
      throw std::runtime_error("the step produced a non-finite contact state");
    state_ = next;
  });
  std::vector<std::string> published;
  if (periodDue(last_publish_, now, publish_period_)) {
    publishPose(now);
    published = {odom_pub_.getTopic(), joint_pub_.getTopic(), "/tf"};
  }

  if (timeline_.complete(now)) {
    ROS_INFO_STREAM("scenario complete after " << timeline_.duration() << " s, centre at ("
                                               << radius_ * state_.u_a << ", "
                                               << radius_ * state_.v_a << ") m, psi "
                                               << state_.psi << " rad");
    clock_->finish();
  }
  return published;
}

void RotorPlantRos::publishPose(const ros::Time& now) {
  last_publish_ = now;
  const Eigen::Vector3d centre(radius_ * state_.u_a, radius_ * state_.v_a, radius_);
  const Eigen::Quaterniond attitude(rotor::orientation(state_.u_o, state_.v_o, state_.psi));
  const bool fresh = actuator_input_.fresh(now);
  const rotor::RotorSpeeds speeds = fresh ? speeds_ : rotor::RotorSpeeds{};
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  rotor::ContactRates rates;
  try {
    omega = rotor::rotorAngularVelocity(k_, inertia_scale_, state_, speeds);
    rates = rotor::contactRates(state_, omega);
  } catch (const std::invalid_argument&) {
    // Counted by tick(); the pose is still worth publishing.
  }
  odom_pub_.publish(conversions::toOdometry(centre, attitude,
                                            {radius_ * rates.u_a, radius_ * rates.v_a, 0.0}, omega,
                                            kWorldFrame, base_frame_, now));
  tf_broadcaster_.sendTransform(
      conversions::toTransform(centre, attitude, kWorldFrame, base_frame_, now));
  sensor_msgs::JointState joints;
  joints.header.stamp = now;
  joints.name = kRotors;
  joints.position = {positions_[0], positions_[1]};
  joints.velocity = {speeds.phi1, speeds.phi2};
  joint_pub_.publish(joints);
}

void RotorPlantRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const ros::Time now = ros::Time::now();
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "rolling");
  status.add("u_a [m]", radius_ * state_.u_a);
  status.add("v_a [m]", radius_ * state_.v_a);
  status.add("u_o [rad]", state_.u_o);
  status.add("v_o [rad]", state_.v_o);
  status.add("psi [rad]", state_.psi);
  reportPlantHealth(status, now, *clock_, timeline_, actuator_input_);
}

}  // namespace spherical_robots
