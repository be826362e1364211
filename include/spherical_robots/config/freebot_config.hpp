#pragma once
// FreeBOT's parameters under freebot/ (config/freebot.yaml): the chain that freebot_plant
// integrates and freebot_ik drives, and the goal executive's solver, gains, drive limits,
// tolerances and timeout. One reader for both FreeBOT nodes and `sphere_sim freebot-*`.

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/freebot/freebot_chain.hpp"
#include "spherical_robots/freebot/goal_executive.hpp"

namespace spherical_robots::config {

/// Keys freebot/radii (required: l_0 the fixed base's, then l_1 … l_n [m], at least two) and
/// freebot/trolley/{wheel_radius, wheel_interval, shell_thickness} [m], > 0 (TrolleyGeometry's
/// defaults, Table II).
/// @throw std::invalid_argument naming the key, its value and the source if one is missing or bad.
freebot::FreebotChain freebotChain(const ParameterSource& source);

/// Keys, each optional (GoalExecutiveParameters' default) and > 0 unless said otherwise:
/// freebot/ik/{position_tolerance [m], orientation_tolerance [rad], restarts (integer >= 0),
/// max_iterations (integer >= 1)}; freebot/gains/{forward, steering, alignment} (k_s, k_φ1, k_φ2);
/// freebot/drive/{max_forward_speed, max_steering_speed, max_wheel_speed, heading_tolerance,
/// contact_tolerance, steering_distance} (DriveLimits); freebot/goal/{position_tolerance [m],
/// orientation_tolerance [rad], max_replans (integer >= 0), timeout [s]}.
/// @throw std::invalid_argument naming the key, its value and the source on a bad value.
freebot::GoalExecutiveParameters freebotGoalExecutive(const ParameterSource& source);

}  // namespace spherical_robots::config
