// Norma's dynamics (Moazami et al. 2019) as the plant behind the hardware interface.
#include "spherical_robots/ros/norma_plant_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::NormaPlantRos>(argc, argv, "norma_plant");
}
