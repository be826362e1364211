#include "spherical_robots/ros/rotor_planner_ros.hpp"

#include <nav_msgs/Path.h>
#include <visualization_msgs/Marker.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/ros/conversions.hpp"
#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "spherical_robots/rotor/geometric_phase.hpp"
#include "spherical_robots/rotor/motion_planner.hpp"

namespace spherical_robots {
namespace {

constexpr double kDefaultRadius = 0.1;        // [m]
constexpr double kDefaultMaxRadius = 0.7;     // [R], the default limit
constexpr int kMarkerSamples = 400;

}  // namespace

RotorPlannerRos::RotorPlannerRos(ros::NodeHandle nh, ros::NodeHandle pnh)
    : radius_(positiveParam(pnh, "sphere_radius", kDefaultRadius)),
      max_radius_(positiveParam(pnh, "max_radius", kDefaultMaxRadius * radius_)),
      frame_id_(stringParam(pnh, "frame_id", "odom")),
      sphere_frame_(stringParam(pnh, "sphere_frame", "base_link")),
      samples_per_step_(static_cast<int>(positiveParam(pnh, "samples_per_step", 200))) {
  if (samples_per_step_ < 1) {
    throw std::invalid_argument("parameter " + pnh.resolveName("samples_per_step") +
                                " must be >= 1");
  }
  if (max_radius_ / radius_ >= rotor::kMaxCircleRadius) {
    throw std::invalid_argument("parameter " + pnh.resolveName("max_radius") + " = " +
                                std::to_string(max_radius_) + " m must be < R / sqrt(2) = " +
                                std::to_string(rotor::kMaxCircleRadius * radius_) + " m");
  }
  path_pub_ = nh.advertise<nav_msgs::Path>("planned_path", 1, true);
  marker_pub_ = nh.advertise<visualization_msgs::Marker>("contact_curve", 1, true);
  service_ = pnh.advertiseService("plan", &RotorPlannerRos::onPlan, this);
  ROS_INFO_STREAM("rotor_planner: R = " << radius_ << " m, circle radii up to " << max_radius_
                                        << " m; service " << service_.getService());
}

bool RotorPlannerRos::onPlan(spherical_robots::PlanRotorMotion::Request& request,
                             spherical_robots::PlanRotorMotion::Response& response) {
  rotor::PlanRequest plan;
  plan.k = request.k;
  plan.steps = request.steps;
  plan.u_a = request.u_a / radius_;
  plan.v_a = request.v_a / radius_;
  plan.psi = request.psi;
  plan.max_radius = (request.max_radius > 0.0 ? request.max_radius : max_radius_) / radius_;
  plan.heading_turns = request.heading_turns;
  rotor::PlanResult result;
  try {
    result = rotor::planRotorMotion(plan);
  } catch (const std::invalid_argument& error) {
    response.success = false;
    response.reason = std::string("invalid request: ") + error.what();
    ROS_WARN_STREAM("rotor_planner: " << response.reason);
    return true;
  }
  response.success = !result.solutions.empty();
  response.reason = result.reason;
  for (const rotor::RotorPlan& solution : result.solutions) {
    response.a.push_back(solution.a * radius_);
    response.b.push_back(solution.b * radius_);
    response.gamma.push_back(solution.gamma);
    response.psi.push_back(solution.psi);
    response.length.push_back(solution.length * radius_);
    response.final_error.push_back(solution.final_error);
  }
  if (!response.success) {
    ROS_WARN_STREAM("rotor_planner: " << result.reason);
    return true;
  }
  const rotor::RotorPlan& best = result.solutions.front();
  ROS_INFO_STREAM("rotor_planner: " << result.solutions.size() << " plan(s); shortest a = "
                                    << best.a * radius_ << " m, b = " << best.b * radius_
                                    << " m, gamma = " << best.gamma << " rad, final error "
                                    << best.final_error);
  publishPlan(plan.k, plan.steps, best.a, best.b, best.gamma);
  return true;
}

void RotorPlannerRos::publishPlan(double k, int steps, double a, double b, double gamma) {
  const rotor::FigureEight curve(a, b, gamma);
  const ros::Time stamp = ros::Time::now();
  nav_msgs::Path path;
  path.header.frame_id = frame_id_;
  path.header.stamp = stamp;
  for (const rotor::ContactCoordinates& c : rotor::samplePath(k, curve, steps, samples_per_step_)) {
    const Eigen::Quaterniond orientation(rotor::orientation(c.u_o, c.v_o, c.psi));
    path.poses.push_back(conversions::toPoseStamped(
        Eigen::Vector3d(c.u_a * radius_, c.v_a * radius_, radius_), orientation, frame_id_, stamp));
  }
  path_pub_.publish(path);

  visualization_msgs::Marker marker;
  marker.header.frame_id = sphere_frame_;
  marker.header.stamp = stamp;
  marker.ns = "contact_curve";
  marker.type = visualization_msgs::Marker::LINE_STRIP;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = 0.02 * radius_;
  marker.color.r = 1.0;
  marker.color.g = 0.6;
  marker.color.a = 1.0;
  for (int i = 0; i <= kMarkerSamples; ++i) {
    marker.points.push_back(
        conversions::toPoint(radius_ * curve.at(2.0 * M_PI * i / kMarkerSamples).point));
  }
  marker_pub_.publish(marker);
}

}  // namespace spherical_robots
