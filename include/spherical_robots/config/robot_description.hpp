#pragma once
// Geometry read from the URDF, the one source of truth for rviz and the models (urdfdom).

#include <string>

namespace spherical_robots::config {

/// The radius [m] of the sphere that is the collision (else visual) geometry of `link`.
/// @throw std::invalid_argument if the XML does not parse, the link is missing, or its geometry is
/// not a sphere of positive, finite radius.
double sphereRadiusFromUrdf(const std::string& urdf_xml, const std::string& link);

/// Reads a whole file. @throw std::invalid_argument naming the path if it cannot be read.
std::string readTextFile(const std::string& path);

/// The package's share directory (config/, urdf/, launch/): the installed one next to the running
/// executable, else the one compiled in. Works without a sourced ROS environment.
std::string packageShareDirectory();

}  // namespace spherical_robots::config
