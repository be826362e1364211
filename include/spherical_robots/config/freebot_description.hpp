#pragma once
// FreeBOT's robot description, generated from the radii its nodes use (config/freebot.yaml's
// freebot/radii): there is no xacro in Debian 12, and a file would repeat the radii.

#include <string>
#include <vector>

namespace spherical_robots::config {

/// A URDF of the chain: link<i> is sphere B_i (i = 0 the fixed base), a sphere of radius l_i [m]
/// at its origin (visual and collision). An SRC joint is no URDF joint type, so B_i hangs under
/// B_{i-1} by a floating joint: freebot_plant publishes link<i-1> -> link<i> on tf itself and no
/// robot_state_publisher runs (it would publish a floating joint as a fixed one).
/// @throw std::invalid_argument unless there are at least two radii, each finite and > 0.
std::string freebotRobotDescription(const std::vector<double>& radii);

}  // namespace spherical_robots::config
