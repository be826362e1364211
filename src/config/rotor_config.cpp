#include "spherical_robots/config/rotor_config.hpp"

namespace spherical_robots::config {

rotor::ManoeuvreExecutive::Parameters rotorExecutiveParameters(const ParameterSource& stack,
                                                               const ParameterSource& node,
                                                               const std::string& prefix) {
  rotor::ManoeuvreExecutive::Parameters e;
  const auto key = [&prefix](const char* name) { return prefix + name; };
  e.radius = positiveNumber(node, key("sphere_radius"), e.radius);
  e.inertia_scale = positiveNumber(stack, "rotor_inertia_scale", e.inertia_scale);
  e.curve_rate = positiveNumber(node, key("curve_rate"), e.curve_rate);
  e.ramp_time = nonNegativeNumber(node, key("ramp_time"), e.ramp_time);
  e.command_period = 1.0 / positiveNumber(node, key("command_rate"), 1.0 / e.command_period);
  e.max_rotor_speed = nonNegativeNumber(node, key("max_rotor_speed"), e.max_rotor_speed);
  e.settle = nonNegativeNumber(node, key("settle"), e.settle);
  e.actuator_time_constant =
      nonNegativeNumber(node, key("actuator_time_constant"), e.actuator_time_constant);
  e.corrections = wholeNumber(node, key("corrections"), e.corrections, 0);
  e.correction_tolerance = positiveNumber(node, key("correction_tolerance"), e.correction_tolerance);
  e.correction_heading_tolerance =
      positiveNumber(node, key("correction_heading_tolerance"), e.correction_heading_tolerance);
  e.correction_tilt_tolerance =
      positiveNumber(node, key("correction_tilt_tolerance"), e.correction_tilt_tolerance);
  e.correction_steps = wholeNumber(node, key("correction_steps"), e.correction_steps, 1);
  e.max_clock_step = positiveNumber(node, key("max_clock_step"), e.max_clock_step);
  return e;
}

RotorManoeuvre rotorManoeuvre(const ParameterSource& source, const std::string& prefix,
                              const RotorManoeuvre& fallback) {
  RotorManoeuvre m;
  m.k = positiveNumber(source, prefix + "k", fallback.k);
  m.steps = wholeNumber(source, prefix + "steps", fallback.steps, 1);
  m.u = finiteNumber(source, prefix + "u", fallback.u);
  m.v = finiteNumber(source, prefix + "v", fallback.v);
  m.psi = finiteNumber(source, prefix + "psi", fallback.psi);
  return m;
}

}  // namespace spherical_robots::config
