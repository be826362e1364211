#include <exception>

#include <ros/ros.h>

#include "spherical_robots/ros/hardware_interface_sim_ros.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "hardware_interface_sim");
  // Outside the try: destroying the last handle shuts ROS (and rosconsole) down before ROS_FATAL.
  ros::NodeHandle nh, pnh("~");
  try {
    spherical_robots::HardwareInterfaceSimRos node(nh, pnh);
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("hardware_interface_sim: %s", e.what());
    return 1;
  }
  return 0;
}
