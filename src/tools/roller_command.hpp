#pragma once
// `sphere_sim roller`: the friction drive of Kimura et al. 2019 (two constraint rollers on a
// sphere, with slip), inverse or forward, for one set of inputs, written as JSON.

#include "sphere_sim_cli.hpp"

namespace spherical_robots::sphere_sim {

/// The subcommand's option table and run function, for runSphereSim.
Subcommand rollerCommand();

}  // namespace spherical_robots::sphere_sim
