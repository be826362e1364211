#pragma once
// The rotor_planner node: the two-rotor sphere's geometric-phase planner (Svinin et al.) as a
// service, with the chosen plan published for rviz.

#include <ros/ros.h>

#include <string>

#include "spherical_robots/PlanRotorMotion.h"

namespace spherical_robots {

/// Parameters (private, ~): sphere_radius R [m] (0.1); max_radius [m] (0.07 = 0.7 R unless set),
/// the default limit of a request's circle radii; frame_id ("odom"), the plane frame of the
/// predicted path; sphere_frame ("base_link"), the sphere's frame for the contact-curve marker;
/// samples_per_step (200).
///
/// Service ~plan (spherical_robots/PlanRotorMotion): plans with rotor::planRotorMotion; a bad
/// request is answered with success = false and the reason (logged), never a dead node. On
/// success it publishes, latched, for the shortest plan: planned_path (nav_msgs/Path in
/// frame_id: the sphere's centre and orientation along all n steps from the origin) and
/// contact_curve (visualization_msgs/Marker LINE_STRIP in sphere_frame: the figure eight on the
/// sphere's surface).
class RotorPlannerRos {
 public:
  /// @throw std::invalid_argument on a bad parameter.
  RotorPlannerRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  bool onPlan(spherical_robots::PlanRotorMotion::Request& request,
              spherical_robots::PlanRotorMotion::Response& response);
  /// Publishes the path and marker of the plan (a, b, γ in units of R) for inertia ratio k.
  void publishPlan(double k, int steps, double a, double b, double gamma);

  double radius_;
  double max_radius_;
  std::string frame_id_;
  std::string sphere_frame_;
  int samples_per_step_;
  ros::ServiceServer service_;
  ros::Publisher path_pub_;
  ros::Publisher marker_pub_;
};

}  // namespace spherical_robots
