// The terrain plant: a sphere rolling over z = f(x, y), driven by measured actuator rates.
#include <ros/ros.h>

#include "spherical_robots/ros/terrain_plant_ros.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "terrain_kinematics");
  try {
    spherical_robots::TerrainPlantRos plant(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL_STREAM("terrain_kinematics cannot start: " << e.what());
    return 1;
  }
  return 0;
}
