#include "spherical_robots/ros/diagnostics_timer.hpp"

namespace spherical_robots {

ros::WallTimer startDiagnostics(ros::NodeHandle& nh, diagnostic_updater::Updater& updater) {
  return nh.createWallTimer(ros::WallDuration(updater.getPeriod()),
                            [&updater](const ros::WallTimerEvent&) { updater.force_update(); });
}

}  // namespace spherical_robots
