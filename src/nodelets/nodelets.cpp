// Every node of the package as a nodelet (node_nodelet.hpp), named as in nodelet_plugins.xml:
// spherical_robots/<the node's executable name in CamelCase>.
#include <pluginlib/class_list_macros.hpp>

#include "spherical_robots/ros/freebot_ik_ros.hpp"
#include "spherical_robots/ros/freebot_plant_ros.hpp"
#include "spherical_robots/ros/friction_drive_controller_ros.hpp"
#include "spherical_robots/ros/friction_drive_sim_ros.hpp"
#include "spherical_robots/ros/hardware_interface_sim_ros.hpp"
#include "spherical_robots/ros/node_nodelet.hpp"
#include "spherical_robots/ros/norma_controller_ros.hpp"
#include "spherical_robots/ros/norma_plant_ros.hpp"
#include "spherical_robots/ros/pure_pursuit_controller_ros.hpp"
#include "spherical_robots/ros/rotor_planner_ros.hpp"
#include "spherical_robots/ros/rotor_plant_ros.hpp"
#include "spherical_robots/ros/terrain_plant_ros.hpp"

// class_loader knows a class by its name as spelled here, and nodelet_plugins.xml repeats that
// name: a plain alias per nodelet, not a template-id with angle brackets in XML.
#define SPHERICAL_ROBOTS_NODELET(Name, Node) \
  namespace spherical_robots {               \
  using Name = NodeNodelet<Node>;            \
  }                                          \
  PLUGINLIB_EXPORT_CLASS(spherical_robots::Name, nodelet::Nodelet)

SPHERICAL_ROBOTS_NODELET(TerrainPlantNodelet, TerrainPlantRos)
SPHERICAL_ROBOTS_NODELET(PurePursuitControllerNodelet, PurePursuitControllerRos)
SPHERICAL_ROBOTS_NODELET(NormaControllerNodelet, NormaControllerRos)
SPHERICAL_ROBOTS_NODELET(HardwareInterfaceSimNodelet, HardwareInterfaceSimRos)
SPHERICAL_ROBOTS_NODELET(FrictionDriveControllerNodelet, FrictionDriveControllerRos)
SPHERICAL_ROBOTS_NODELET(FrictionDriveSimNodelet, FrictionDriveSimRos)
SPHERICAL_ROBOTS_NODELET(NormaPlantNodelet, NormaPlantRos)
SPHERICAL_ROBOTS_NODELET(RotorPlannerNodelet, RotorPlannerRos)
SPHERICAL_ROBOTS_NODELET(RotorPlantNodelet, RotorPlantRos)
SPHERICAL_ROBOTS_NODELET(FreebotPlantNodelet, FreebotPlantRos)
SPHERICAL_ROBOTS_NODELET(FreebotIkNodelet, FreebotIkRos)
