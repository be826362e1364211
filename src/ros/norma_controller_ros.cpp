#include "spherical_robots/ros/norma_controller_ros.hpp"

#include <geometry_msgs/PointStamped.h>
#include <nav_msgs/Path.h>
#include <sensor_msgs/JointState.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/TrackingError.h"
#include "spherical_robots/config/norma_description.hpp"
#include "spherical_robots/norma/norma_simulation.hpp"
#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/ros/sim_clock.hpp"

namespace spherical_robots {
namespace {

const std::string kWorldFrame = "world";
constexpr double kPathPeriod = 200.0 * M_PI;  // [s] eq 52 repeats after 2π / 0.01
constexpr int kDesiredPathSamples = 2000;
constexpr double kMaxIntegrationGap = 0.1;  // [s] a longer gap between states is not integrated
constexpr double kLateAge = 0.002;           // [s] two 1 ms ticks: the delay the 1 kHz loop is built for

norma::ControllerKind controllerFromString(const std::string& name) {
  if (name == "paper") return norma::ControllerKind::kPaper;
  if (name == "tracking") return norma::ControllerKind::kTracking;
  throw std::invalid_argument("unknown controller (paper | tracking)");
}

norma::NormaParameters parametersOf(const ros::NodeHandle& nh) {
  std::string urdf;
  if (!nh.getParam("robot_description", urdf))
    throw std::invalid_argument("parameter " + nh.resolveName("robot_description") +
                                " (urdf/norma.urdf) is required");
  return config::normaParametersFromUrdf(urdf);
}

nav_msgs::Path desiredPath(const ros::Time& stamp) {
  nav_msgs::Path path;
  path.header.frame_id = kWorldFrame;
  path.header.stamp = stamp;
  for (int k = 0; k <= kDesiredPathSamples; ++k) {
    const norma::PathPoint p = norma::lissajousPath(kPathPeriod * k / kDesiredPathSamples);
    path.poses.push_back(conversions::toPoseStamped({p.x, p.y, 0.0}, Eigen::Quaterniond::Identity(),
                                                    kWorldFrame, stamp));
  }
  return path;
}

}  // namespace

NormaControllerRos::NormaControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : parameters_(parametersOf(nh)),
      controller_(parameters_, parsedParam(pnh, "controller", "paper", controllerFromString)),
      publish_period_(1.0 / positiveParam(pnh, "publish_rate", 50.0)),
      input_(nh.resolveName("norma_state"), positiveParam(pnh, "input_timeout", 0.05)),
      updater_(nh, pnh) {
  command_pub_ = nh.advertise<sensor_msgs::JointState>("actuators/command", 10);
  error_pub_ = nh.advertise<spherical_robots::TrackingError>("tracking_error", 10);
  target_pub_ = nh.advertise<geometry_msgs::PointStamped>("target", 10);
  desired_path_pub_ = nh.advertise<nav_msgs::Path>("desired_path", 1, true);
  desired_path_pub_.publish(desiredPath(ros::Time::now()));
  state_sub_ = nh.subscribe("norma_state", 10, &NormaControllerRos::onState, this);
  updater_.setHardwareID("Norma");
  updater_.add("norma controller", this, &NormaControllerRos::diagnose);
  ROS_INFO_STREAM("Norma controller: "
                  << (controller_.kind() == norma::ControllerKind::kPaper ? "paper (eqs 48-51, Table 1)"
                                                                          : "tracking")
                  << ", path eq 52 from the first state on " << input_.topic());
}

void NormaControllerRos::onState(const spherical_robots::NormaState& msg) {
  const ros::Time now = msg.header.stamp;
  if (path_start_.isZero() || now < last_state_) {  // first state, or ROS time jumped back
    path_start_ = now;
    integrals_.setZero();
  } else {
    const double gap = (now - last_state_).toSec();
    if (gap > 0.0 && gap <= kMaxIntegrationGap) integrals_ += last_output_.integrand * gap;
  }
  last_state_ = now;
  const double t = (now - path_start_).toSec();
  const norma::PathPoint reference = norma::lissajousPath(t);
  try {
    const norma::Vector4 q(msg.q[0], msg.q[1], msg.q[2], msg.q[3]);
    const norma::Vector4 qd(msg.qd[0], msg.qd[1], msg.qd[2], msg.qd[3]);
    last_output_ = controller_.compute(q, qd, msg.x, msg.y, msg.psi, integrals_, reference);
  } catch (const std::invalid_argument& e) {
    last_output_.integrand.setZero();
    input_.reject(e.what());  // nothing commanded: the hardware keeps the last good efforts
    return;
  }
  input_.accept(ros::Time::now());
  sensor_msgs::JointState command;
  command.header.stamp = now;
  command.name = {"pendulum_motor", "slider_motor"};
  command.effort = {last_output_.torque, last_output_.force};
  command_pub_.publish(command);
  const double age = (ros::Time::now() - now).toSec();
  max_state_age_ = std::max(max_state_age_, age);
  if (age > kLateAge) {
    ++late_commands_;
    ROS_WARN_STREAM_THROTTLE(1.0, "Norma controller is late: a command left "
                                      << age * 1e3 << " ms (ROS time) after its state; the loop "
                                                      "is built for <= 2 ms (lower the speed-up)");
  }

  if (periodDue(last_publish_, now, publish_period_)) {
    last_publish_ = now;
    spherical_robots::TrackingError error;
    error.header.stamp = now;
    error.header.frame_id = kWorldFrame;
    error.desired = conversions::toPoint({reference.x, reference.y, 0.0});
    error.desired_velocity = conversions::toVector3({reference.x_dot, reference.y_dot, 0.0});
    error.error = conversions::toVector3({reference.x - msg.x, reference.y - msg.y, 0.0});
    error.error_norm = last_output_.error;
    error.zeta = norma::kinematicLayer(controller_.gains().kinematic,
                                       parameters_.R, msg.x, msg.y, msg.psi,
                                       reference).zeta;
    error_pub_.publish(error);
    geometry_msgs::PointStamped target;
    target.header = error.header;
    target.point = error.desired;
    target_pub_.publish(target);
  }
  updater_.update();
}

void NormaControllerRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "controlling");
  status.add("controller", controller_.kind() == norma::ControllerKind::kPaper ? "paper" : "tracking");
  status.add("|e| [m]", last_output_.error);
  status.add("T [N m]", last_output_.torque);
  status.add("F [N]", last_output_.force);
  status.add("theta_dot_d [rad/s]", last_output_.theta_dot_d);
  status.add("delta_d [m]", last_output_.delta_d);
  status.add("max state age at command [ms]", max_state_age_ * 1e3);
  status.add("late commands (> 2 ms)", late_commands_);
  if (max_state_age_ > kLateAge)
    status.mergeSummary(diagnostic_msgs::DiagnosticStatus::WARN, "commands late: lower the speed-up");
  max_state_age_ = 0.0;
  input_.report(status, ros::Time::now());
}

}  // namespace spherical_robots
