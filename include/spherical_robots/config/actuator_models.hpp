#pragma once
// The actuator models of the simulated hardware interface (docs/hardware_interface.md), from the
// file a stack takes as actuator_models:= (config/actuators_realistic.yaml) or from
// hardware_interface_sim's private parameters, where that file is loaded: one reader for the node,
// sphere_sim and the tests.

#include <cstdint>
#include <string>
#include <vector>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/hardware/simulated_actuators.hpp"

namespace spherical_robots::config {

struct ActuatorModels {
  std::vector<hardware::ActuatorModel> models;  ///< one per actuator name, in their order
  std::uint32_t noise_seed = 0;
};

/// Keys default_model/<field> for every actuator, overridden field by field by
/// models/<name>/<field>, with fields time_constant, dead_time, position_resolution and
/// velocity_noise, each optional (0: off); noise_seed, an integer >= 0 (default 0).
/// @throw std::invalid_argument naming the origin, the key and the value: a field that is not a
/// model field (a typo would silently do nothing), a key under models/ that names no actuator,
/// a negative or non-finite field, a seed that is no integer in [0, 2^32).
ActuatorModels loadActuatorModels(const ParameterSource& source,
                                  const std::vector<std::string>& actuator_names);

}  // namespace spherical_robots::config
