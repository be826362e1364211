#include "spherical_robots/config/hardware_interface_config.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace spherical_robots::config {
namespace {

std::invalid_argument badNames(const ParameterSource& source, const std::string& problem) {
  return std::invalid_argument(source.origin() + ": parameter 'actuator_names' " + problem);
}

std::vector<std::string> actuatorNames(const ParameterSource& source) {
  const auto names = source.texts("actuator_names");
  if (!names)
    throw badNames(source, "is required: the list of actuator names, e.g. [theta, phi, psi]");
  if (names->empty()) throw badNames(source, "must not be empty");
  if (std::set<std::string>(names->begin(), names->end()).size() != names->size())
    throw badNames(source, "must not name an actuator twice");
  return *names;
}

}  // namespace

HardwareInterfaceSimParameters loadHardwareInterfaceSimParameters(const ParameterSource& source) {
  HardwareInterfaceSimParameters p;
  p.actuator_names = actuatorNames(source);
  hardware::ActuatorLimits velocity;
  velocity.max_velocity = positiveNumber(source, "max_velocity", 20.0);
  velocity.max_acceleration = positiveNumber(source, "max_acceleration", 50.0);
  p.limits.assign(p.actuator_names.size(), velocity);
  for (const std::string& name : source.keys("effort_limits").value_or(std::vector<std::string>{})) {
    const auto it = std::find(p.actuator_names.begin(), p.actuator_names.end(), name);
    if (it == p.actuator_names.end())
      throw std::invalid_argument(source.origin() + ": parameter 'effort_limits/" + name +
                                  "' names no actuator in actuator_names");
    hardware::ActuatorLimits& limits = p.limits[it - p.actuator_names.begin()];
    limits.kind = hardware::ActuatorKind::Effort;
    limits.max_effort = positiveNumber(source, "effort_limits/" + name, 0.0);
  }
  p.command_timeout = positiveNumber(source, "command_timeout", p.command_timeout);
  p.models = loadActuatorModels(source, p.actuator_names);
  p.rate = positiveNumber(source, "rate", p.rate);
  p.max_clock_step = positiveNumber(source, "max_clock_step", p.max_clock_step);
  p.max_stamp_skew = positiveNumber(source, "max_stamp_skew", p.max_stamp_skew);
  return p;
}

hardware::SimulatedActuators makeSimulatedActuators(const HardwareInterfaceSimParameters& parameters) {
  return hardware::SimulatedActuators(parameters.actuator_names, parameters.limits,
                                      parameters.command_timeout, parameters.models.models,
                                      parameters.models.noise_seed);
}

}  // namespace spherical_robots::config
