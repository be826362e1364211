// Path tracking: pure pursuit (or teleoperation) of a sphere rolling over terrain, or, with
// ~robot_type: norma, Norma's two-layer controller (eqs 48-51 and the PID cascade).
#include <string>

#include "spherical_robots/ros/norma_controller_ros.hpp"
#include "spherical_robots/ros/pure_pursuit_ros.hpp"
#include "spherical_robots/ros/run_node.hpp"

int main(int argc, char** argv) {
  constexpr const char* kName = "pure_pursuit_controller";
  ros::init(argc, argv, kName);
  std::string robot_type;
  ros::param::param<std::string>("~robot_type", robot_type, "3R");
  if (robot_type == "norma") return spherical_robots::spinNode<spherical_robots::NormaControllerRos>(kName);
  return spherical_robots::spinNode<spherical_robots::PurePursuitRos>(kName);
}
