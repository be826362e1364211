#include "spherical_robots/ros/rotor_planner_parameters.hpp"

#include <sstream>
#include <stdexcept>

#include "spherical_robots/ros/ros_parameter_source.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"

namespace spherical_robots {
namespace {

constexpr double kDefaultMaxRadius = 0.7;  // [R], the default limit

/// A finite number >= 0.
double nonNegativeParam(const ros::NodeHandle& nh, const std::string& name, double fallback) {
  const double value = numberParam(nh, name, fallback);
  if (value < 0.0) {
    std::ostringstream what;
    what << "parameter " << nh.resolveName(name) << " = " << value << " must be >= 0";
    throw std::invalid_argument(what.str());
  }
  return value;
}

}  // namespace

RotorPlannerParameters loadRotorPlannerParameters(const ros::NodeHandle& nh,
                                                  const ros::NodeHandle& pnh) {
  RotorPlannerParameters p;
  rotor::ManoeuvreExecutive::Parameters& e = p.executive;
  e.radius = positiveParam(pnh, "sphere_radius", e.radius);
  p.max_radius = positiveParam(pnh, "max_radius", kDefaultMaxRadius * e.radius);
  if (p.max_radius / e.radius >= rotor::kMaxCircleRadius) {
    std::ostringstream what;
    what << "parameter " << pnh.resolveName("max_radius") << " = " << p.max_radius
         << " m must be < R / sqrt(2) = " << rotor::kMaxCircleRadius * e.radius << " m";
    throw std::invalid_argument(what.str());
  }
  p.max_position = positiveParam(pnh, "max_position", p.max_position);
  p.max_stamp_skew = positiveParam(pnh, "max_stamp_skew", p.max_stamp_skew);
  p.frame_id = stringParam(pnh, "frame_id", p.frame_id);
  p.sphere_frame = stringParam(pnh, "sphere_frame", p.sphere_frame);
  p.samples_per_step = countParam(pnh, "samples_per_step", p.samples_per_step, 1);
  p.path_period = positiveParam(pnh, "path_period", p.path_period);
  p.odom_timeout = positiveParam(pnh, "odom_timeout", p.odom_timeout);
  double robot_k = 0.0;
  if (nh.getParam("inertia_ratio", robot_k)) p.robot_inertia_ratio = robot_k;

  e.inertia_scale = positiveParam(nh, "rotor_inertia_scale", e.inertia_scale);
  e.curve_rate = positiveParam(pnh, "curve_rate", e.curve_rate);
  e.ramp_time = nonNegativeParam(pnh, "ramp_time", e.ramp_time);
  e.command_period = 1.0 / positiveParam(pnh, "command_rate", 1.0 / e.command_period);
  e.max_rotor_speed = nonNegativeParam(pnh, "max_rotor_speed", e.max_rotor_speed);
  e.settle = nonNegativeParam(pnh, "settle", e.settle);
  e.actuator_time_constant = nonNegativeParam(pnh, "actuator_time_constant", 0.0);
  e.corrections = countParam(pnh, "corrections", e.corrections, 0);
  e.correction_tolerance = positiveParam(pnh, "correction_tolerance", e.correction_tolerance);
  e.correction_heading_tolerance =
      positiveParam(pnh, "correction_heading_tolerance", e.correction_heading_tolerance);
  e.correction_tilt_tolerance =
      positiveParam(pnh, "correction_tilt_tolerance", e.correction_tilt_tolerance);
  e.correction_steps = countParam(pnh, "correction_steps", e.correction_steps, 1);
  e.max_clock_step = positiveParam(pnh, "max_clock_step", e.max_clock_step);

  if (pnh.hasParam("manoeuvre")) {
    RotorPlannerParameters::StartUpManoeuvre m;
    m.k = positiveParam(pnh, "manoeuvre/k", m.k);
    m.steps = countParam(pnh, "manoeuvre/steps", m.steps, 1);
    m.u = numberParam(pnh, "manoeuvre/u", m.u);
    m.v = numberParam(pnh, "manoeuvre/v", m.v);
    m.psi = numberParam(pnh, "manoeuvre/psi", m.psi);
    m.index = countParam(pnh, "manoeuvre/index", m.index, 0);
    p.manoeuvre = m;
  }
  return p;
}

}  // namespace spherical_robots
