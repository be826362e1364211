// Path tracking of a sphere rolling over terrain: pure pursuit (paper or smooth law) or
// teleoperation, for the 3R, 2R, RT and RS robots.
#include "spherical_robots/ros/pure_pursuit_controller_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::PurePursuitControllerRos>(
      argc, argv, "pure_pursuit_controller");
}
