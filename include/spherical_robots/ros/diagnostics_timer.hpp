#pragma once
// Reports a node's diagnostics on a wall timer. diagnostic_updater::Updater::update() waits for
// ROS time to reach its next report, so after one stray /clock message 1,000 s ahead a node would
// say nothing on /diagnostics for 1,000 s of simulated time: the silence an operator's monitor
// must never show while bad input arrives. Every node reports through this instead.

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/node_handle.h>
#include <ros/wall_timer.h>

namespace spherical_robots {

/// A wall timer that publishes `updater`'s report every updater.getPeriod() wall seconds
/// (~diagnostic_period, default 1 s). Keep the timer as long as the updater. Construct the
/// updater as Updater(nh, pnh, pnh.getNamespace()): its default name, ros::this_node::getName(),
/// would name every status of a nodelet after its manager.
ros::WallTimer startDiagnostics(ros::NodeHandle& nh, diagnostic_updater::Updater& updater);

}  // namespace spherical_robots
