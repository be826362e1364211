// sphere_sim: batch runs of the spherical_robots models from the command line.
#include <iostream>

#include "sphere_sim_cli.hpp"
#include "sphere_sim_commands.hpp"

int main(int argc, char** argv) {
  using namespace spherical_robots::sphere_sim;
  return runSphereSim(sphereSimCommands(), std::vector<std::string>(argv + 1, argv + argc),
                      std::cout, std::cerr);
}
