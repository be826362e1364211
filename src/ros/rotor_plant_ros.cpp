#include "spherical_robots/ros/rotor_plant_ros.hpp"


#include <Eigen/Geometry>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/rotor/plan_execution.hpp"

namespace spherical_robots {
namespace {

const std::vector<std::string> kRotors = {"rotor_1", "rotor_2"};

PlantLoop::Defaults loopDefaults(const std::string& odom_frame) {
  PlantLoop::Defaults defaults;
  defaults.root_frame = odom_frame;
  defaults.task = "rotor sphere plant";
  defaults.hardware_id = "rotor sphere";
  defaults.parameters.step = 0.001;
  defaults.parameters.speedup = 1.0;
  defaults.parameters.state_timeout = 0.5;
  return defaults;
}

}  // namespace

RotorPlantParameters loadRotorPlantParameters(const config::ParameterSource& stack,
                                              const config::ParameterSource& node) {
  RotorPlantParameters p;
  p.inertia_ratio = config::positiveNumber(stack, "inertia_ratio", p.inertia_ratio);
  p.rotor_inertia_scale = config::positiveNumber(stack, "rotor_inertia_scale", p.rotor_inertia_scale);
  p.sphere_radius = config::positiveNumber(node, "sphere_radius", p.sphere_radius);
  p.frame_prefix = node.text("frame_prefix").value_or("");
  p.max_actuator_rate = config::positiveNumber(node, "max_actuator_rate", p.max_actuator_rate);
  p.odometry = config::loadOdometryParameters(node);
  return p;
}

RotorPlantRos::RotorPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : parameters_(loadRotorPlantParameters(RosParameterSource(nh), RosParameterSource(pnh))),
      odom_frame_(parameters_.frame_prefix + "odom"),
      base_frame_(parameters_.frame_prefix + "base_link"),
      loop_(nh, pnh, loopDefaults(odom_frame_)) {
  odometry_.emplace(loop_, parameters_.odometry, odom_frame_, base_frame_);
  joint_pub_ = loop_.advertise<sensor_msgs::JointState>("joint_states");
  ROS_INFO_STREAM("rotor sphere: R = " << parameters_.sphere_radius << " m, k = " << parameters_.inertia_ratio << ", J_zz/J_r = "
                                       << parameters_.rotor_inertia_scale << "; step " << loop_.step() << " s");
  loop_.start(*this, odometry_->odom(), loop_.publishRate());
}

void RotorPlantRos::read(const sensor_msgs::JointState& actuators) {
  const std::vector<double> velocities =
      conversions::velocitiesByName(actuators, kRotors, parameters_.max_actuator_rate);
  speeds_ = {velocities[0], velocities[1]};
  // Positions only drive the URDF's joints; a state without them keeps the last ones.
  if (actuators.position.size() == actuators.name.size()) {
    for (std::size_t i = 0; i < actuators.name.size(); ++i) {
      for (std::size_t j = 0; j < kRotors.size(); ++j) {
        if (actuators.name[i] == kRotors[j] && std::isfinite(actuators.position[i]))
          positions_[j] = actuators.position[i];
      }
    }
  }
}

void RotorPlantRos::advance(double elapsed, bool actuators_fresh) {
  const auto next = rotor::advancePlant(parameters_.inertia_ratio, parameters_.rotor_inertia_scale, state_,
                                        actuators_fresh ? speeds_ : rotor::RotorSpeeds{}, elapsed,
                                        loop_.step());
  // Nothing non-finite is published: a step that would produce it is a failed step.
  if (!std::isfinite(next.u_a) || !std::isfinite(next.v_a) || !std::isfinite(next.u_o) ||
      !std::isfinite(next.v_o) || !std::isfinite(next.psi))
    throw std::runtime_error("the step produced a non-finite contact state");
  state_ = next;
}

void RotorPlantRos::publishPeriodic(const ros::Time& now, bool actuators_fresh) {
  const Eigen::Vector3d centre(parameters_.sphere_radius * state_.u_a, parameters_.sphere_radius * state_.v_a, parameters_.sphere_radius);
  // Normalised once, as rotor::SampledRotorLoop measures it.
  const Eigen::Quaterniond attitude =
      Eigen::Quaterniond(rotor::orientation(state_.u_o, state_.v_o, state_.psi)).normalized();
  const rotor::RotorSpeeds speeds = actuators_fresh ? speeds_ : rotor::RotorSpeeds{};
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  rotor::ContactRates rates;
  try {
    omega = rotor::rotorAngularVelocity(parameters_.inertia_ratio, parameters_.rotor_inertia_scale, state_, speeds);
    rates = rotor::contactRates(state_, omega);
  } catch (const std::invalid_argument&) {
    // Counted by the loop's failed step; the pose is still worth publishing.
  }
  const BodyMotion motion = bodyMotion(
      centre, attitude, {parameters_.sphere_radius * rates.u_a, parameters_.sphere_radius * rates.v_a, 0.0},
      omega);
  odometry_->publish(now, motion);
  // The IMU at the odometry's rate at most (the plant computes its motion only then).
  if (odometry_->imuDue(now)) odometry_->publishImu(now, motion);
  loop_.tf().sendTransform(conversions::toTransform(centre, attitude, odom_frame_, base_frame_, now));
  joint_pub_.publish(conversions::jointState(kRotors, {positions_[0], positions_[1]},
                                             {speeds.phi1, speeds.phi2}, {}, now));
}

void RotorPlantRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "rolling");
  status.add("u_a [m]", parameters_.sphere_radius * state_.u_a);
  status.add("v_a [m]", parameters_.sphere_radius * state_.v_a);
  status.add("u_o [rad]", state_.u_o);
  status.add("v_o [rad]", state_.v_o);
  status.add("psi [rad]", state_.psi);
}

std::string RotorPlantRos::describeState() const {
  std::ostringstream text;
  text << "centre at (" << parameters_.sphere_radius * state_.u_a << ", " << parameters_.sphere_radius * state_.v_a << ") m, psi "
       << state_.psi << " rad";
  return text.str();
}

}  // namespace spherical_robots
