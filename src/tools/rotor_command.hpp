#pragma once
// `sphere_sim rotor-step` and `sphere_sim rotor-plan`: one figure eight of the two-rotor sphere
// integrated from the zero state, and the n-step geometric-phase planner (Svinin et al.), both
// written as JSON.

#include "sphere_sim_cli.hpp"

namespace spherical_robots::sphere_sim {

/// The subcommands' option tables and run functions, for runSphereSim.
Subcommand rotorStepCommand();
Subcommand rotorPlanCommand();

}  // namespace spherical_robots::sphere_sim
