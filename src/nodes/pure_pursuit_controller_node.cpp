// Pure-pursuit path tracking (or teleoperation) of a sphere rolling over terrain.
#include <ros/ros.h>

#include "spherical_robots/ros/pure_pursuit_ros.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "pure_pursuit_controller");
  try {
    spherical_robots::PurePursuitRos controller(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("pure_pursuit_controller cannot start: " << e.what());
    return 1;
  }
  return 0;
}
