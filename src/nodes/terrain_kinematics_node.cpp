// The terrain plant: a sphere rolling over z = f(x, y), driven by measured actuator rates.
#include <exception>
#include <optional>

#include <ros/ros.h>

#include "spherical_robots/ros/terrain_plant_ros.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "terrain_kinematics");
  // Outside the try: destroying the last handle shuts ROS (and rosconsole) down before ROS_FATAL.
  ros::NodeHandle nh, pnh("~");
  std::optional<spherical_robots::TerrainPlantRos> plant;
  try {
    plant.emplace(nh, pnh);
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("terrain_kinematics cannot start: " << e.what());
    return 1;
  }
  ros::spin();  // outside the try: a runtime error is not a start-up failure
  return 0;
}
