// IK of a FreeBOT chain (service) and goals driven through the trolleys' wheels.
#include "spherical_robots/ros/freebot_ik_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::FreebotIkRos>(argc, argv, "freebot_ik");
}
