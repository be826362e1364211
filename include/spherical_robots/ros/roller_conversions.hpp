#pragma once
// The roller stack's own messages (the two-roller friction drive): RollerDrive and the rollers
// with their slip for rviz. Its rates and state are the terrain stack's (terrain_conversions.hpp).

#include <visualization_msgs/MarkerArray.h>

#include <string>

#include "spherical_robots/RollerDrive.h"
#include "spherical_robots/roller/friction_drive.hpp"
#include "spherical_robots/ros/conversions.hpp"

namespace spherical_robots::conversions {

/// ω, the rollers' speeds and slips and the sphere's motion (speed, direction, ρ).
spherical_robots::RollerDrive toRollerDriveMsg(const roller::DriveState& state,
                                               const ros::Time& stamp);

/// In `heading_frame` (at the floor contact, the centre O r above it): per roller a cylinder of
/// radius roller_radius on its axis, touching the sphere at its contact point, and an arrow of its
/// slip ζ_i = S_i X_i (eq 27) from that point, 1 m per m/s.
visualization_msgs::MarkerArray rollerMarkers(const roller::RollerGeometry& geometry,
                                              double roller_radius,
                                              const roller::DriveState& state,
                                              const std::string& heading_frame,
                                              const ros::Time& stamp);

}  // namespace spherical_robots::conversions
