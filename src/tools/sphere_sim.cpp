// sphere_sim: batch runs of the spherical_robots models from the command line.
#include <iostream>

#include "freebot_command.hpp"
#include "norma_command.hpp"
#include "roller_command.hpp"
#include "rotor_command.hpp"
#include "sphere_sim_cli.hpp"
#include "terrain_command.hpp"

int main(int argc, char** argv) {
  using namespace spherical_robots::sphere_sim;
  return runSphereSim({terrainCommand(), rollerCommand(), normaCommand(), rotorStepCommand(),
                       rotorPlanCommand(), rotorExecuteCommand(), freebotFkCommand(),
                       freebotIkCommand(), freebotWheelsCommand()},
                      std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
