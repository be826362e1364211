#include "spherical_robots/ros/rotor_planner_parameters.hpp"

#include <sstream>
#include <stdexcept>

#include "spherical_robots/rotor/figure_eight.hpp"

namespace spherical_robots {
namespace {

constexpr double kDefaultMaxRadius = 0.7;  // [R], the default limit

}  // namespace

RotorPlannerParameters loadRotorPlannerParameters(const config::ParameterSource& stack,
                                                  const config::ParameterSource& node) {
  using config::finiteNumber;
  using config::nonNegativeNumber;
  using config::positiveNumber;
  using config::wholeNumber;
  RotorPlannerParameters p;
  rotor::ManoeuvreExecutive::Parameters& e = p.executive;
  e.radius = positiveNumber(node, "sphere_radius", e.radius);
  p.max_radius = positiveNumber(node, "max_radius", kDefaultMaxRadius * e.radius);
  if (p.max_radius / e.radius >= rotor::kMaxCircleRadius) {
    std::ostringstream what;
    what << node.origin() << ": parameter 'max_radius' = " << p.max_radius
         << " m must be < R / sqrt(2) = " << rotor::kMaxCircleRadius * e.radius << " m";
    throw std::invalid_argument(what.str());
  }
  p.max_position = positiveNumber(node, "max_position", p.max_position);
  p.max_stamp_skew = positiveNumber(node, "max_stamp_skew", p.max_stamp_skew);
  p.frame_id = node.text("frame_id").value_or(p.frame_id);
  p.sphere_frame = node.text("sphere_frame").value_or(p.sphere_frame);
  p.samples_per_step = wholeNumber(node, "samples_per_step", p.samples_per_step, 1);
  p.path_period = positiveNumber(node, "path_period", p.path_period);
  p.odom_timeout = positiveNumber(node, "odom_timeout", p.odom_timeout);
  if (stack.number("inertia_ratio")) p.robot_inertia_ratio = positiveNumber(stack, "inertia_ratio", 0.0);

  e.inertia_scale = positiveNumber(stack, "rotor_inertia_scale", e.inertia_scale);
  e.curve_rate = positiveNumber(node, "curve_rate", e.curve_rate);
  e.ramp_time = nonNegativeNumber(node, "ramp_time", e.ramp_time);
  e.command_period = 1.0 / positiveNumber(node, "command_rate", 1.0 / e.command_period);
  e.max_rotor_speed = nonNegativeNumber(node, "max_rotor_speed", e.max_rotor_speed);
  e.settle = nonNegativeNumber(node, "settle", e.settle);
  e.actuator_time_constant = nonNegativeNumber(node, "actuator_time_constant", 0.0);
  e.corrections = wholeNumber(node, "corrections", e.corrections, 0);
  e.correction_tolerance = positiveNumber(node, "correction_tolerance", e.correction_tolerance);
  e.correction_heading_tolerance =
      positiveNumber(node, "correction_heading_tolerance", e.correction_heading_tolerance);
  e.correction_tilt_tolerance =
      positiveNumber(node, "correction_tilt_tolerance", e.correction_tilt_tolerance);
  e.correction_steps = wholeNumber(node, "correction_steps", e.correction_steps, 1);
  e.max_clock_step = positiveNumber(node, "max_clock_step", e.max_clock_step);

  if (node.keys("manoeuvre")) {
    RotorPlannerParameters::StartUpManoeuvre m;
    m.k = positiveNumber(node, "manoeuvre/k", m.k);
    m.steps = wholeNumber(node, "manoeuvre/steps", m.steps, 1);
    m.u = finiteNumber(node, "manoeuvre/u", m.u);
    m.v = finiteNumber(node, "manoeuvre/v", m.v);
    m.psi = finiteNumber(node, "manoeuvre/psi", m.psi);
    m.index = wholeNumber(node, "manoeuvre/index", m.index, 0);
    p.manoeuvre = m;
  }
  return p;
}

}  // namespace spherical_robots
