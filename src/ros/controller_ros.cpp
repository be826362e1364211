#include "spherical_robots/ros/controller_ros.hpp"

#include <string>

namespace spherical_robots {

ControllerRos::ControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh) {
  std::string robot_type;
  pnh.param<std::string>("robot_type", robot_type, "3R");
  if (robot_type == "norma")
    controller_.emplace<NormaControllerRos>(nh, pnh);
  else
    controller_.emplace<PurePursuitRos>(nh, pnh);
}

}  // namespace spherical_robots
