// The simulated actuators behind the hardware seam (docs/hardware_interface.md).
#include <exception>
#include <optional>

#include <ros/ros.h>

#include "spherical_robots/ros/hardware_interface_sim_ros.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "hardware_interface_sim");
  // Outside the try: destroying the last handle shuts ROS (and rosconsole) down before ROS_FATAL.
  ros::NodeHandle nh, pnh("~");
  std::optional<spherical_robots::HardwareInterfaceSimRos> node;
  try {
    node.emplace(nh, pnh);
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("hardware_interface_sim cannot start: " << e.what());
    return 1;
  }
  ros::spin();  // outside the try: a runtime error is not a start-up failure
  return 0;
}
