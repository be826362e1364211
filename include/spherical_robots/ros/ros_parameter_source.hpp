#pragma once
// Parameters from the ROS parameter server, read through the same config::ParameterSource
// interface as the YAML files, so a node parses config/terrain.yaml (loaded by the launch file
// with rosparam) with the very parser sphere_sim uses.

#include <ros/node_handle.h>

#include <stdexcept>
#include <string>

#include "spherical_robots/config/parameter_source.hpp"

namespace spherical_robots {

/// Keys are '/'-separated names relative to the node handle's namespace, e.g.
/// "terrain/gains/3R/k_theta". Integers count as numbers.
class RosParameterSource final : public config::ParameterSource {
 public:
  explicit RosParameterSource(const ros::NodeHandle& nh);
  std::optional<double> number(const std::string& key) const override;
  std::optional<std::string> text(const std::string& key) const override;
  std::optional<std::vector<double>> numbers(const std::string& key) const override;
  std::optional<std::vector<std::string>> texts(const std::string& key) const override;
  std::optional<std::vector<std::string>> keys(const std::string& key) const override;
  /// The namespace, e.g. "/sphere" or "/sphere/terrain_plant".
  std::string origin() const override;
  /// ROS_WARN: on the console and /rosout.
  void warn(const std::string& message) const override;

  /// The fully resolved name of key, for error messages.
  std::string resolve(const std::string& key) const;

 private:
  ros::NodeHandle nh_;
};

/// The URDF in parameter `robot_description` of nh. @throw std::invalid_argument if it is not set.
std::string robotDescription(const ros::NodeHandle& nh);

/// read(the URDF in parameter `robot_description` of nh), read being a config:: reader of URDF
/// text, its errors prefixed with the parameter's name: how every node reads its robot.
template <typename Read>
auto fromRobotDescription(const ros::NodeHandle& nh, Read read) {
  const std::string urdf = robotDescription(nh);
  try {
    return read(urdf);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("parameter " + nh.resolveName("robot_description") + ": " +
                                e.what());
  }
}

/// The sphere radius [m] from the URDF in parameter `robot_description` of nh (the collision
/// sphere of link `shell`, urdf/terrain_robot.urdf). @throw std::invalid_argument if the parameter is missing or the URDF bad.
double radiusFromRobotDescription(const ros::NodeHandle& nh);

}  // namespace spherical_robots
