// A FreeBOT chain integrated from the measured wheel speeds, with tf and markers.
#include "spherical_robots/ros/freebot_plant_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::FreebotPlantRos>(argc, argv, "freebot_plant");
}
