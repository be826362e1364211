#pragma once
// `sphere_sim rotor-step`, `rotor-plan` and `rotor-execute`: one figure eight of the two-rotor
// sphere integrated from the zero state and the n-step geometric-phase planner (Svinin et al.),
// both written as JSON, and the rotor stack's run of a plan through its rotors, written as CSV.

#include "sphere_sim_cli.hpp"

namespace spherical_robots::sphere_sim {

/// The subcommands' option tables and run functions, for runSphereSim.
Subcommand rotorStepCommand();
Subcommand rotorPlanCommand();
Subcommand rotorExecuteCommand();

}  // namespace spherical_robots::sphere_sim
