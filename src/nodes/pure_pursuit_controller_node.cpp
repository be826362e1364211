// Path tracking: pure pursuit (or teleoperation) of a sphere rolling over terrain, or, with
// ~robot_type: norma, Norma's two-layer controller (eqs 48-51 and the PID cascade).
#include "spherical_robots/ros/controller_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  return spherical_robots::runNode<spherical_robots::ControllerRos>(argc, argv,
                                                                    "pure_pursuit_controller");
}
