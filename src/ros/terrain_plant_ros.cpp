#include "spherical_robots/ros/terrain_plant_ros.hpp"

#include <sensor_msgs/JointState.h>
#include <visualization_msgs/Marker.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/TerrainState.h"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/ros/terrain_conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/terrain/terrain_simulation.hpp"

namespace spherical_robots {
namespace {

PlantLoop::Defaults loopDefaults(terrain::RobotType type, const std::string& odom_frame) {
  PlantLoop::Defaults defaults;
  defaults.root_frame = odom_frame;
  defaults.task = "terrain plant";
  defaults.hardware_id = terrain::toString(type) + " sphere";
  defaults.parameters.step = 0.01;
  defaults.parameters.speedup = 10.0;
  defaults.parameters.state_timeout = 0.5;
  defaults.parameters.trail_period = 0.5;
  defaults.max_trail_points = 2000;
  return defaults;
}

}  // namespace

TerrainPlantParameters loadTerrainPlantParameters(const config::ParameterSource& node) {
  TerrainPlantParameters p;
  p.robot_type = config::parsedText(node, "robot_type", "3R", terrain::robotTypeFromString);
  p.contact_model = config::parsedText(node, "contact_model", "paper", terrain::contactModelFromString);
  p.frame_prefix = node.text("frame_prefix").value_or("");
  p.max_actuator_rate = config::positiveNumber(node, "max_actuator_rate", p.max_actuator_rate);
  p.initial_x = config::finiteNumber(node, "initial_x", p.initial_x);
  p.initial_y = config::finiteNumber(node, "initial_y", p.initial_y);
  p.initial_psi = config::finiteNumber(node, "initial_psi", p.initial_psi);
  p.marker_half_extent = config::positiveNumber(node, "marker_half_extent", p.marker_half_extent);
  p.marker_resolution = config::positiveNumber(node, "marker_resolution", p.marker_resolution);
  p.odometry = config::loadOdometryParameters(node);
  return p;
}

TerrainPlantRos::TerrainPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : parameters_(loadTerrainPlantParameters(RosParameterSource(pnh))),
      odom_frame_(parameters_.frame_prefix + "odom"),
      base_frame_(parameters_.frame_prefix + "base_link"),
      shell_frame_(parameters_.frame_prefix + "shell"),
      heading_frame_(parameters_.frame_prefix + "heading"),
      loop_(nh, pnh, loopDefaults(parameters_.robot_type, odom_frame_)) {
  const config::TerrainConfig terrain_config = config::loadTerrainConfig(RosParameterSource(nh));
  const double radius = radiusFromRobotDescription(nh);
  const terrain::ContactModel model = parameters_.contact_model;
  config::SurfaceLoading loading;
  loading.warn = [](const std::string& warning) { ROS_WARN_STREAM(warning); };
  surface_ = config::makeSurface(terrain_config.surface, loading);
  kinematics_ = std::make_unique<terrain::TerrainKinematics>(
      *surface_, parameters_.robot_type, radius, model, terrain_config.tilt_limit);
  body_frame_ = std::make_unique<terrain::BodyFrame>(*surface_, radius);
  state_.x = parameters_.initial_x;
  state_.y = parameters_.initial_y;
  state_.psi = parameters_.initial_psi;
  orientation_ = Eigen::Quaterniond(kinematics_->geometry(state_).heading_frame);

  odometry_.emplace(loop_, parameters_.odometry, odom_frame_, base_frame_);
  if (parameters_.robot_type == terrain::RobotType::RollingAndSteering)
    joint_pub_ = loop_.advertise<sensor_msgs::JointState>("joint_states");
  state_pub_ = loop_.advertise<spherical_robots::TerrainState>("terrain_state");
  marker_pub_ = nh.advertise<visualization_msgs::Marker>("terrain_marker", 1, true);
  // A height map is drawn where it has heights; a surface defined everywhere, on a square.
  const Eigen::Vector2d corner = Eigen::Vector2d::Constant(parameters_.marker_half_extent);
  marker_pub_.publish(conversions::surfaceMesh(
      *surface_, surface_->domain().value_or(Eigen::AlignedBox2d(-corner, corner)),
      parameters_.marker_resolution, odom_frame_, ros::Time::now()));
  ROS_INFO_STREAM(terrain::toString(parameters_.robot_type) << " sphere, R = " << radius << " m, "
                                           << terrain::toString(model) << " contact model, on "
                                           << surface_->describe() << "; frames " << odom_frame_ << " -> "
                                           << base_frame_ << " -> " << shell_frame_ << ", " << heading_frame_);
  loop_.start(*this, odometry_->odom(), loop_.publishRate());
}

void TerrainPlantRos::read(const sensor_msgs::JointState& actuators) {
  measured_ = conversions::ratesFromJointState(parameters_.robot_type, actuators, parameters_.max_actuator_rate);
}

terrain::DriveRates TerrainPlantRos::rates(bool actuators_fresh) const {
  return actuators_fresh ? measured_ : terrain::DriveRates{};
}

void TerrainPlantRos::advance(double elapsed, bool actuators_fresh) {
  const terrain::RollingState next = terrain::advanceWithHeldRates(
      *kinematics_, {state_, orientation_}, rates(actuators_fresh), elapsed, loop_.step());
  // Nothing non-finite is published: a step that would produce it is a failed step.
  if (!std::isfinite(next.state.x) || !std::isfinite(next.state.y) ||
      !std::isfinite(next.state.psi) || !std::isfinite(next.state.phi) ||
      !next.orientation.coeffs().allFinite())
    throw std::runtime_error("the step produced a non-finite state");
  state_ = next.state;
  orientation_ = next.orientation;
}

BodyMotion TerrainPlantRos::exactMotion(const terrain::ContactGeometry& geometry,
                                       const terrain::DriveRates& realised) const {
  const terrain::BodyPose body = terrain::BodyFrame::pose(geometry);
  const terrain::BodyTwist twist =
      body_frame_->twist(geometry, kinematics_->realisedStateRate(state_, geometry, realised));
  return {body.centre, body.orientation, twist.linear, twist.angular};
}

void TerrainPlantRos::publishEveryStep(const ros::Time& now, bool actuators_fresh) {
  if (!odometry_->imuDue(now)) return;
  odometry_->publishImu(now, exactMotion(kinematics_->geometry(state_),
                                         kinematics_->realisedRates(state_, rates(actuators_fresh))));
}

void TerrainPlantRos::publishPeriodic(const ros::Time& now, bool actuators_fresh) {
  const terrain::ContactGeometry geometry = kinematics_->geometry(state_);
  const terrain::DriveRates realised = kinematics_->realisedRates(state_, rates(actuators_fresh));
  const BodyMotion motion = exactMotion(geometry, realised);
  odometry_->publish(now, motion);
  // tf is the simulated truth, also with noisy odometry. The shell and the heading frame (at P0)
  // under the body, which does not roll.
  const Eigen::Quaterniond body_from_odom = motion.orientation.conjugate();
  loop_.tf().sendTransform(
      {conversions::toTransform(motion.position, motion.orientation, odom_frame_, base_frame_, now),
       conversions::toTransform(Eigen::Vector3d::Zero(), body_from_odom * orientation_, base_frame_,
                                shell_frame_, now),
       conversions::toTransform(body_from_odom * (geometry.contact_point - geometry.centre),
                                body_from_odom * Eigen::Quaterniond(geometry.heading_frame),
                                base_frame_, heading_frame_, now)});
  if (parameters_.robot_type == terrain::RobotType::RollingAndSteering)
    joint_pub_.publish(conversions::tiltJointState(state_.phi, realised.lateral_rate, now));
  state_pub_.publish(conversions::toTerrainStateMsg(parameters_.robot_type, kinematics_->model(), state_,
                                                    geometry, realised, odom_frame_, now));
}

std::optional<PlantModel::Pose> TerrainPlantRos::trailPose() const {
  const terrain::ContactGeometry geometry = kinematics_->geometry(state_);
  return Pose{geometry.contact_point, Eigen::Quaterniond(geometry.heading_frame)};
}

void TerrainPlantRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "rolling");
  status.add("robot type", terrain::toString(parameters_.robot_type));
  status.add("contact model", terrain::toString(kinematics_->model()));
  status.add("surface", surface_->describe());
  status.add("x [m]", state_.x);
  status.add("y [m]", state_.y);
  status.add("psi [rad]", state_.psi);
  status.add("phi [rad]", state_.phi);
}

std::optional<std::vector<double>> TerrainPlantRos::checkpointState() const {
  return std::vector<double>{state_.x,         state_.y,         state_.psi,       state_.phi,
                             orientation_.w(), orientation_.x(), orientation_.y(), orientation_.z()};
}

void TerrainPlantRos::resumeState(const std::vector<double>& numbers) {
  requireStateSize(numbers, 8, "a terrain sphere (x, y, psi, phi, the shell's quaternion)");
  state_ = {numbers[0], numbers[1], numbers[2], numbers[3]};
  orientation_ = Eigen::Quaterniond(numbers[4], numbers[5], numbers[6], numbers[7]);
}

std::vector<std::string> TerrainPlantRos::sharedParameters() const {
  return {"robot_description", "terrain"};  // the surface and the tilt limit
}

std::string TerrainPlantRos::describeState() const {
  std::ostringstream text;
  text << "contact point at (" << state_.x << ", " << state_.y << ") m";
  return text.str();
}

}  // namespace spherical_robots
