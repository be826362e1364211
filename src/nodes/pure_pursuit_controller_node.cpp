// Pure-pursuit path tracking (or teleoperation) of a sphere rolling over terrain.
#include "spherical_robots/ros/pure_pursuit_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::PurePursuitRos>(argc, argv,
                                                                      "pure_pursuit_controller");
}
