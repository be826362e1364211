// Norma's two-layer controller: the paper's (eqs 48-51 and the PID cascade) or the tracking one.
#include "spherical_robots/ros/norma_controller_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::NormaControllerRos>(argc, argv,
                                                                         "norma_controller");
}
