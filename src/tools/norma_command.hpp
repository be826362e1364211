#pragma once
// `sphere_sim norma`: Norma, the slider-and-pendulum robot of Moazami et al. 2019, closed loop on
// the path of eq 52 (the paper's controller or the tracking one) or open loop from a given state,
// written as CSV.

#include "sphere_sim_cli.hpp"

namespace spherical_robots::sphere_sim {

/// The subcommand's option table and run function, for runSphereSim.
Subcommand normaCommand();

}  // namespace spherical_robots::sphere_sim
