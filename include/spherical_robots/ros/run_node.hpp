#pragma once
// The one main() every node of the package shares (node_nodelet.hpp runs the same classes as
// nodelets).

#include <ros/ros.h>

#include <exception>
#include <optional>

namespace spherical_robots {

/// Initialises ROS as `name`, constructs Node(nh, private nh) and spins. A construction error is
/// a start-up failure: ROS_FATAL "<name> cannot start: <what>" and exit status 1.
template <typename Node>
int runNode(int argc, char** argv, const char* name) {
  ros::init(argc, argv, name);
  // Outside the try: destroying the last handle shuts ROS (and rosconsole) down before ROS_FATAL.
  ros::NodeHandle nh, pnh("~");
  std::optional<Node> node;
  try {
    node.emplace(nh, pnh);
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM(name << " cannot start: " << e.what());
    return 1;
  }
  ros::spin();  // outside the try: a runtime error is not a start-up failure
  return 0;
}

}  // namespace spherical_robots
