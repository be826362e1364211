#pragma once
// The simulated hardware interface's parameters (hardware_interface_sim; docs/hardware_interface.md,
// docs/nodes.md): one loader over ParameterSource for the node, the tests and any batch run.

#include <string>
#include <vector>

#include "spherical_robots/config/actuator_models.hpp"
#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/core/clock_jump.hpp"
#include "spherical_robots/hardware/simulated_actuators.hpp"

namespace spherical_robots::config {

struct HardwareInterfaceSimParameters {
  std::vector<std::string> actuator_names;       ///< required, non-empty, distinct
  std::vector<hardware::ActuatorLimits> limits;  ///< one per name, in their order
  double command_timeout = 0.5;                  ///< [s] the watchdog
  ActuatorModels models;                         ///< all ideal by default
  double rate = 100.0;                           ///< [Hz] of the state, on a timer (not in lock-step)
  double max_clock_step = kDefaultMaxClockStep;  ///< [s] a larger step of ROS time is a jump
  double max_stamp_skew = 1.0;                   ///< [s] in lock-step, how far ahead a command may be
};

/// Keys: actuator_names (list of strings); max_velocity [rad/s] (20), max_acceleration [rad/s²]
/// (50) for the velocity actuators; effort_limits {name: max effort [N m or N]}, whose actuators
/// are effort actuators; command_timeout [s], rate [Hz], max_clock_step [s], max_stamp_skew [s];
/// the actuator models of loadActuatorModels.
/// @throw std::invalid_argument naming the origin, the key and the value: a missing or empty
/// name list, duplicate names, a number not finite and > 0, an effort limit naming no actuator.
HardwareInterfaceSimParameters loadHardwareInterfaceSimParameters(const ParameterSource& source);

/// The actuators these parameters describe.
hardware::SimulatedActuators makeSimulatedActuators(const HardwareInterfaceSimParameters& parameters);

}  // namespace spherical_robots::config
