#pragma once
// Every sphere_sim subcommand, in the order `sphere_sim --help` lists them: for its main() and for
// the fuzz target of its option parser (test/fuzz/fuzz_parse_options.cpp).

#include <vector>

#include "sphere_sim_cli.hpp"

namespace spherical_robots::sphere_sim {

std::vector<Subcommand> sphereSimCommands();

}  // namespace spherical_robots::sphere_sim
