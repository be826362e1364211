#pragma once
// `sphere_sim freebot-fk`, `freebot-ik`, `freebot-wheels`: the SRC-joint manipulator of Zong,
// Liang, Lam 2022 (forward kinematics with J_{B_n}, inverse kinematics) and the FreeBOT
// trolley's wheel speeds, for one set of inputs, written as JSON.

#include "sphere_sim_cli.hpp"

namespace spherical_robots::sphere_sim {

/// The subcommands' option tables and run functions, for runSphereSim.
Subcommand freebotFkCommand();
Subcommand freebotIkCommand();
Subcommand freebotWheelsCommand();

}  // namespace spherical_robots::sphere_sim
