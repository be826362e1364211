#include "sphere_sim_commands.hpp"

#include "freebot_command.hpp"
#include "norma_command.hpp"
#include "roller_command.hpp"
#include "rotor_command.hpp"
#include "terrain_command.hpp"

namespace spherical_robots::sphere_sim {

std::vector<Subcommand> sphereSimCommands() {
  return {terrainCommand(),    rollerCommand(),      normaCommand(),
          rotorStepCommand(),  rotorPlanCommand(),   rotorExecuteCommand(),
          freebotFkCommand(),  freebotIkCommand(),   freebotWheelsCommand()};
}

}  // namespace spherical_robots::sphere_sim
