#include "spherical_robots/ros/rotor_planner_parameters.hpp"

#include <sstream>
#include <stdexcept>

#include "spherical_robots/config/rotor_config.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"

namespace spherical_robots {
namespace {

constexpr double kDefaultMaxRadius = 0.7;  // [R], the default limit

}  // namespace

RotorPlannerParameters loadRotorPlannerParameters(const config::ParameterSource& stack,
                                                  const config::ParameterSource& node) {
  using config::positiveNumber;
  using config::wholeNumber;
  RotorPlannerParameters p;
  p.executive = config::rotorExecutiveParameters(stack, node);
  const rotor::ManoeuvreExecutive::Parameters& e = p.executive;
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

  if (node.keys("manoeuvre")) {
    RotorPlannerParameters::StartUpManoeuvre m;
    const config::RotorManoeuvre planned =
        config::rotorManoeuvre(node, "manoeuvre/", {m.k, m.steps, m.u, m.v, m.psi});
    m.k = planned.k;
    m.steps = planned.steps;
    m.u = planned.u;
    m.v = planned.v;
    m.psi = planned.psi;
    m.index = wholeNumber(node, "manoeuvre/index", m.index, 0);
    p.manoeuvre = m;
  }
  return p;
}

}  // namespace spherical_robots
