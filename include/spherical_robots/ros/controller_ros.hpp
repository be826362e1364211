#pragma once
// The pure_pursuit_controller node: with ~robot_type norma, Norma's two-layer controller
// (norma_controller_ros.hpp); with a terrain robot type (3R, the default, 2R, RT, RS), pure
// pursuit or teleoperation of a sphere rolling over terrain (pure_pursuit_ros.hpp).

#include <ros/node_handle.h>

#include <variant>

#include "spherical_robots/ros/norma_controller_ros.hpp"
#include "spherical_robots/ros/pure_pursuit_ros.hpp"

namespace spherical_robots {

class ControllerRos {
 public:
  /// @throw what the chosen controller's constructor throws.
  ControllerRos(ros::NodeHandle nh, ros::NodeHandle pnh);

 private:
  std::variant<std::monostate, PurePursuitRos, NormaControllerRos> controller_;
};

}  // namespace spherical_robots
