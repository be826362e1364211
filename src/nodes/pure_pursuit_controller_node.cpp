// Pure-pursuit path tracking (or teleoperation) of a sphere rolling over terrain.
#include <exception>
#include <optional>

#include <ros/ros.h>

#include "spherical_robots/ros/pure_pursuit_ros.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "pure_pursuit_controller");
  // Outside the try: destroying the last handle shuts ROS (and rosconsole) down before ROS_FATAL.
  ros::NodeHandle nh, pnh("~");
  std::optional<spherical_robots::PurePursuitRos> controller;
  try {
    controller.emplace(nh, pnh);
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("pure_pursuit_controller cannot start: " << e.what());
    return 1;
  }
  ros::spin();  // outside the try: a runtime error is not a start-up failure
  return 0;
}
