#pragma once
// The rotor stack's parameters (config/rotor.yaml) that rotor_planner, rotor_plant and
// `sphere_sim rotor-execute` share: one reader of the manoeuvre executive's parameters for the
// planner (its private namespace, prefix "") and sphere_sim (config/rotor.yaml, prefix
// kRotorPlannerKeys), and of the start-up manoeuvre.

#include <string>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/rotor/manoeuvre_executive.hpp"

namespace spherical_robots::config {

/// rotor_planner's block of config/rotor.yaml.
inline const std::string kRotorPlannerKeys = "rotor_planner/";

/// The executive's parameters (ManoeuvreExecutive::Parameters' defaults when absent): from
/// `stack` rotor_inertia_scale (> 0); from `node`, each key prefixed: sphere_radius, curve_rate,
/// command_rate [Hz], correction_tolerance, correction_heading_tolerance,
/// correction_tilt_tolerance, max_clock_step (> 0); ramp_time, max_rotor_speed, settle,
/// actuator_time_constant (>= 0); corrections (integer >= 0), correction_steps (integer >= 1).
/// @throw std::invalid_argument naming the key, its value and the source on a bad value.
rotor::ManoeuvreExecutive::Parameters rotorExecutiveParameters(const ParameterSource& stack,
                                                               const ParameterSource& node,
                                                               const std::string& prefix = "");

/// A manoeuvre planned from the zero state: the inertia ratio of the plan, the figure eights and
/// the target [m, m, rad].
struct RotorManoeuvre {
  double k = 2.5;
  int steps = 2;
  double u = 0.0;    ///< [m]
  double v = 0.0;    ///< [m]
  double psi = 0.0;  ///< [rad]
};

/// Keys prefix + k (> 0), steps (integer >= 1), u, v, psi (finite); absent: `fallback`'s.
/// @throw std::invalid_argument naming the key, its value and the source on a bad value.
RotorManoeuvre rotorManoeuvre(const ParameterSource& source, const std::string& prefix,
                              const RotorManoeuvre& fallback = {});

}  // namespace spherical_robots::config
