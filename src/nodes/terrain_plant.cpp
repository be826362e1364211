// The terrain plant: a sphere rolling over z = f(x, y), driven by measured actuator rates.
#include "spherical_robots/ros/run_node.hpp"
#include "spherical_robots/ros/terrain_plant_ros.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::TerrainPlantRos>(argc, argv, "terrain_plant");
}
