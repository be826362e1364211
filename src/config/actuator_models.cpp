#include "spherical_robots/config/actuator_models.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spherical_robots::config {
namespace {

using Field = double hardware::ActuatorModel::*;
const std::pair<const char*, Field> kFields[] = {
    {"time_constant", &hardware::ActuatorModel::time_constant},
    {"dead_time", &hardware::ActuatorModel::dead_time},
    {"position_resolution", &hardware::ActuatorModel::position_resolution},
    {"velocity_noise", &hardware::ActuatorModel::velocity_noise}};

std::invalid_argument badKey(const ParameterSource& source, const std::string& key,
                             const std::string& problem) {
  return std::invalid_argument(source.origin() + ": parameter '" + key + "' " + problem);
}

/// The model at prefix ("default_model", "models/theta"), fields absent there kept from fallback.
hardware::ActuatorModel readModel(const ParameterSource& source, const std::string& prefix,
                                  const hardware::ActuatorModel& fallback) {
  for (const std::string& key : source.keys(prefix).value_or(std::vector<std::string>{})) {
    const bool known = std::any_of(std::begin(kFields), std::end(kFields),
                                   [&key](const auto& field) { return key == field.first; });
    if (!known)
      throw badKey(source, prefix + "/" + key,
                   "is not a model field (time_constant, dead_time, position_resolution, "
                   "velocity_noise)");
  }
  hardware::ActuatorModel model = fallback;
  for (const auto& [name, member] : kFields) {
    const std::string key = prefix + "/" + name;
    const double value = finiteNumber(source, key, fallback.*member);
    if (value < 0.0) {
      std::ostringstream problem;
      problem << "must be >= 0, got " << value;
      throw badKey(source, key, problem.str());
    }
    model.*member = value;
  }
  return model;
}

std::uint32_t readSeed(const ParameterSource& source) {
  const double seed = finiteNumber(source, "noise_seed", 0.0);
  if (seed < 0.0 || seed != std::floor(seed) || seed > 4294967295.0) {
    std::ostringstream problem;
    problem << "must be an integer in [0, 2^32), got " << seed;
    throw badKey(source, "noise_seed", problem.str());
  }
  return static_cast<std::uint32_t>(seed);
}

}  // namespace

ActuatorModels loadActuatorModels(const ParameterSource& source,
                                  const std::vector<std::string>& actuator_names) {
  for (const std::string& name : source.keys("models").value_or(std::vector<std::string>{})) {
    if (std::find(actuator_names.begin(), actuator_names.end(), name) == actuator_names.end())
      throw badKey(source, "models/" + name, "names no actuator in actuator_names");
  }
  const hardware::ActuatorModel default_model = readModel(source, "default_model", {});
  ActuatorModels result;
  for (const std::string& name : actuator_names)
    result.models.push_back(readModel(source, "models/" + name, default_model));
  result.noise_seed = readSeed(source);
  return result;
}

}  // namespace spherical_robots::config
