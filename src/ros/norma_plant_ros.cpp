#include "spherical_robots/ros/norma_plant_ros.hpp"


#include <Eigen/Geometry>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "spherical_robots/config/norma_config.hpp"
#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/config/norma_description.hpp"
#include "spherical_robots/ros/norma_conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"

namespace spherical_robots {
namespace {

PlantLoop::Defaults loopDefaults(const std::string& odom_frame) {
  PlantLoop::Defaults defaults;
  defaults.root_frame = odom_frame;
  defaults.task = "norma plant";
  defaults.hardware_id = "Norma";
  defaults.parameters.step = 0.001;
  defaults.parameters.speedup = 1.0;
  defaults.parameters.state_timeout = 0.05;
  defaults.parameters.trail_period = 0.5;
  defaults.max_trail_points = 4000;
  return defaults;
}

}  // namespace

NormaPlantParameters loadNormaPlantParameters(const config::ParameterSource& node) {
  NormaPlantParameters p;
  const config::NormaModelParameters model = config::normaModelParameters(node);
  p.variant = model.variant;
  p.initial_psi = model.initial_psi;
  p.frame_prefix = node.text("frame_prefix").value_or("");
  p.max_actuator_effort = config::positiveNumber(node, "max_actuator_effort", p.max_actuator_effort);
  p.odometry = config::loadOdometryParameters(node);
  return p;
}

NormaPlantRos::NormaPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : parameters_(loadNormaPlantParameters(RosParameterSource(pnh))),
      dynamics_(fromRobotDescription(nh, config::normaParametersFromUrdf), parameters_.variant),
      odom_frame_(parameters_.frame_prefix + "odom"),
      base_frame_(parameters_.frame_prefix + "base_link"),
      loop_(nh, pnh, loopDefaults(odom_frame_)) {
  state_.psi = parameters_.initial_psi;
  state_pub_ = loop_.advertise<spherical_robots::NormaState>("norma_state");
  odometry_.emplace(loop_, parameters_.odometry, odom_frame_, base_frame_);
  joint_pub_ = loop_.advertise<sensor_msgs::JointState>("joint_states");
  const auto& p = dynamics_.parameters();
  ROS_INFO_STREAM("Norma: R = " << p.R << " m, L = " << p.L << " m, L0 = " << p.L0
                                << " m, delta0 = " << p.delta0 << " m, masses shell "
                                << p.m_shell << ", shaft " << p.m_shaft << ", pendulum "
                                << p.m_pendulum << ", slider " << p.m_slider << " kg; step "
                                << loop_.step() << " s");
  loop_.start(*this, odometry_->odom(), 1.0 / loop_.step());  // every step
}

void NormaPlantRos::read(const sensor_msgs::JointState& actuators) {
  const std::vector<double> efforts =
      conversions::effortsByName(actuators, conversions::normaActuatorNames(), parameters_.max_actuator_effort);
  measured_ = {efforts[0], efforts[1]};
}

void NormaPlantRos::advance(double elapsed, bool actuators_fresh) {
  const norma::Efforts driving = norma::drivingEfforts(measured_, actuators_fresh);
  state_ = norma::advanceWithHeldInputs(dynamics_, state_, driving.torque, driving.force, elapsed,
                                        loop_.step());
}

// The controller's feedback, odom and joint_states, at every step: the paper's inner loop needs
// the 1 kHz (docs/conventions.md).
void NormaPlantRos::publishEveryStep(const ros::Time& now, bool actuators_fresh) {
  const norma::PlanarRates rates = dynamics_.planarRates(state_.q, state_.qd, state_.psi);
  const BodyMotion motion = bodyMotion(centre(), yawRotation(state_.psi), {rates.x_dot, rates.y_dot, 0.0},
                                       {0.0, 0.0, rates.psi_dot});
  odometry_->publish(now, motion);
  if (odometry_->imuDue(now)) odometry_->publishImu(now, motion);
  joint_pub_.publish(conversions::normaJointState(state_, now));
  state_pub_.publish(conversions::toNormaStateMsg(
      state_, norma::drivingEfforts(measured_, actuators_fresh),
      dynamics_.totalEnergy(state_.q, state_.qd), now));
}

void NormaPlantRos::publishPeriodic(const ros::Time& now, bool /*actuators_fresh*/) {
  loop_.tf().sendTransform(
      conversions::toTransform(centre(), yawRotation(state_.psi), odom_frame_, base_frame_, now));
}

Eigen::Vector3d NormaPlantRos::centre() const {
  return {state_.x, state_.y, dynamics_.parameters().R};
}

std::optional<PlantModel::Pose> NormaPlantRos::trailPose() const {
  return Pose{{state_.x, state_.y, 0.0}, yawRotation(state_.psi)};
}

void NormaPlantRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "rolling");
  status.add("variant", norma::toString(dynamics_.variant()));
  status.add("X [m]", state_.x);
  status.add("Y [m]", state_.y);
  status.add("psi [rad]", state_.psi);
  status.add("phi [rad]", state_.q(2));
  status.add("delta [m]", state_.q(3));
  // The slider leaves the shaft's ends (|delta0 + delta| > R): the model no longer holds.
  const auto& p = dynamics_.parameters();
  if (std::abs(p.delta0 + state_.q(3)) > p.R)
    status.mergeSummary(diagnostic_msgs::DiagnosticStatus::WARN, "slider beyond the shaft's end");
}

std::optional<std::vector<double>> NormaPlantRos::checkpointState() const {
  std::vector<double> numbers(state_.q.data(), state_.q.data() + 4);
  numbers.insert(numbers.end(), state_.qd.data(), state_.qd.data() + 4);
  numbers.insert(numbers.end(), {state_.x, state_.y, state_.psi});
  return numbers;
}

void NormaPlantRos::resumeState(const std::vector<double>& numbers) {
  requireStateSize(numbers, 11, "Norma (q, q_dot, X, Y, psi)");
  state_.q = norma::Vector4(numbers.data());
  state_.qd = norma::Vector4(numbers.data() + 4);
  state_.x = numbers[8];
  state_.y = numbers[9];
  state_.psi = numbers[10];
}

std::string NormaPlantRos::describeState() const {
  std::ostringstream text;
  text << "centre at (" << state_.x << ", " << state_.y << ") m";
  return text.str();
}

}  // namespace spherical_robots
