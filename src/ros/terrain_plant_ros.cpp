#include "spherical_robots/ros/terrain_plant_ros.hpp"

#include "spherical_robots/ros/diagnostics_timer.hpp"
#include "spherical_robots/ros/loop_publishers.hpp"

#include <nav_msgs/Odometry.h>
#include <visualization_msgs/Marker.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/TerrainState.h"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/terrain/terrain_simulation.hpp"

namespace spherical_robots {
namespace {

const std::string kWorldFrame = "world";
constexpr std::size_t kMaxTrailPoints = 2000;


}  // namespace

TerrainPlantRos::TerrainPlantRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : type_(parsedParam(pnh, "robot_type", "3R", terrain::robotTypeFromString)),
      base_frame_(stringParam(pnh, "frame_prefix", "") + "base_link"),
      heading_frame_(stringParam(pnh, "frame_prefix", "") + "heading"),
      step_(positiveParam(pnh, "step", 0.01)),
      timeline_(pnh),
      publish_period_(1.0 / positiveParam(pnh, "publish_rate", 50.0)),
      trail_(nh, "trail", kWorldFrame, positiveParam(pnh, "trail_period", 0.5), kMaxTrailPoints),
      max_actuator_rate_(positiveParam(pnh, "max_actuator_rate", 1000.0)),
      actuator_input_(nh.resolveName("actuators/state"), positiveParam(pnh, "state_timeout", 0.5)),
      updater_(nh, pnh) {
  const config::TerrainConfig terrain_config = config::loadTerrainConfig(RosParameterSource(nh));
  const double radius = radiusFromRobotDescription(nh);
  const auto model = parsedParam(pnh, "contact_model", "paper", terrain::contactModelFromString);
  surface_ = config::makeSurface(terrain_config.surface);
  kinematics_ = std::make_unique<terrain::TerrainKinematics>(*surface_, type_, radius, model,
                                                              terrain_config.tilt_limit);
  state_.x = numberParam(pnh, "initial_x", 0.0);
  state_.y = numberParam(pnh, "initial_y", 0.0);
  state_.psi = numberParam(pnh, "initial_psi", 0.0);
  orientation_ = Eigen::Quaterniond(kinematics_->geometry(state_).heading_frame);

  actuator_sub_ = nh.subscribe("actuators/state", 10, &TerrainPlantRos::onActuatorState, this);
  odom_pub_ = nh.advertise<nav_msgs::Odometry>("odom", kLoopQueueSize);
  state_pub_ = nh.advertise<spherical_robots::TerrainState>("terrain_state", kLoopQueueSize);
  marker_pub_ = nh.advertise<visualization_msgs::Marker>("terrain_marker", 1, true);
  marker_pub_.publish(conversions::surfaceMesh(*surface_, positiveParam(pnh, "marker_half_extent", 3.0),
                                               positiveParam(pnh, "marker_resolution", 0.1),
                                               kWorldFrame, ros::Time::now()));

  updater_.setHardwareID(terrain::toString(type_) + " sphere");
  updater_.add("terrain plant", this, &TerrainPlantRos::diagnose);
  diagnostics_timer_ = startDiagnostics(nh, updater_);

  ROS_INFO_STREAM(terrain::toString(type_) << " sphere, R = " << radius << " m, "
                                           << terrain::toString(model) << " contact model, on "
                                           << surface_->describe() << "; frames " << base_frame_
                                           << ", " << heading_frame_);
  clock_ = makePlantClock(nh, pnh, step_, 10.0, [this](const ros::Time& now) { return tick(now); },
                          state_pub_, actuator_sub_);
}

void TerrainPlantRos::onActuatorState(const sensor_msgs::JointState& msg) {
  try {
    measured_ = conversions::ratesFromJointState(type_, msg, max_actuator_rate_);
    actuator_input_.accept(clock_ ? clock_->now() : ros::Time::now());
  } catch (const std::invalid_argument& e) {
    actuator_input_.reject(e.what());
  }
  if (clock_) clock_->received(actuator_sub_.getTopic(), msg.header.stamp);
}

std::vector<std::string> TerrainPlantRos::tick(const ros::Time& now) {
  if (timeline_.finished()) return {};
  const terrain::DriveRates rates =
      actuator_input_.fresh(now) ? measured_ : terrain::DriveRates{};
  timeline_.tick(now, [&](double elapsed) { integrate(elapsed, rates); });

  std::vector<std::string> published;
  if (periodDue(last_publish_, now, publish_period_)) {
    publishState(now, rates);
    published = {odom_pub_.getTopic(), state_pub_.getTopic(), "/tf"};
  }
  if (trail_.due(now)) {
    const terrain::ContactGeometry geometry = kinematics_->geometry(state_);
    trail_.add(now, geometry.contact_point, Eigen::Quaterniond(geometry.heading_frame));
  }

  if (timeline_.complete(now)) {
    ROS_INFO_STREAM("scenario complete after " << timeline_.duration()
                                                << " s, contact point at (" << state_.x << ", "
                                                << state_.y << ") m");
    clock_->finish();
  }
  return published;
}

void TerrainPlantRos::integrate(double elapsed, const terrain::DriveRates& rates) {
  const terrain::RollingState next =
      terrain::advanceWithHeldRates(*kinematics_, {state_, orientation_}, rates, elapsed, step_);
  // Nothing non-finite is published: a step that would produce it is a failed step.
  if (!std::isfinite(next.state.x) || !std::isfinite(next.state.y) ||
      !std::isfinite(next.state.psi) || !std::isfinite(next.state.phi) ||
      !next.orientation.coeffs().allFinite())
    throw std::runtime_error("the step produced a non-finite state");
  state_ = next.state;
  orientation_ = next.orientation;
}

void TerrainPlantRos::publishState(const ros::Time& now, const terrain::DriveRates& rates) {
  last_publish_ = now;
  const terrain::ContactGeometry geometry = kinematics_->geometry(state_);
  const Eigen::Quaterniond heading(geometry.heading_frame);
  odom_pub_.publish(conversions::toOdometry(geometry.centre, orientation_,
                                            kinematics_->centreVelocity(state_, rates),
                                            kinematics_->shellAngularVelocity(state_, rates),
                                            kWorldFrame, base_frame_, now));
  tf_broadcaster_.sendTransform(
      {conversions::toTransform(geometry.centre, orientation_, kWorldFrame, base_frame_, now),
       conversions::toTransform(geometry.contact_point, heading, kWorldFrame, heading_frame_, now)});
  state_pub_.publish(conversions::toTerrainStateMsg(type_, kinematics_->model(), state_, geometry,
                                                    kinematics_->realisedRates(state_, rates), now));
}

void TerrainPlantRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const ros::Time now = ros::Time::now();
  status.summary(diagnostic_msgs::DiagnosticStatus::OK, "rolling");
  status.add("robot type", terrain::toString(type_));
  status.add("contact model", terrain::toString(kinematics_->model()));
  status.add("x [m]", state_.x);
  status.add("y [m]", state_.y);
  status.add("psi [rad]", state_.psi);
  status.add("phi [rad]", state_.phi);
  reportPlantHealth(status, now, *clock_, timeline_, actuator_input_);
}

}  // namespace spherical_robots
