#include "spherical_robots/ros/timer_jump_guard.hpp"

#include <ros/console.h>

namespace spherical_robots {
namespace {

// [s] of wall time between looks at ROS time: at 10x real time, 0.1 s of simulated time.
constexpr double kWatchPeriod = 0.01;

}  // namespace

TimerJumpGuard::TimerJumpGuard(ros::NodeHandle nh,
                               std::vector<std::pair<ros::Timer*, double>> timers,
                               double max_clock_step)
    : timers_(std::move(timers)), clock_(max_clock_step) {
  watch_timer_ = nh.createWallTimer(ros::WallDuration(kWatchPeriod),
                                    [this](const ros::WallTimerEvent&) { watch(); });
}

void TimerJumpGuard::watch() {
  if (clock_.jumpOver(ros::Time::now().toSec()) != 0.0) reset();
}

void TimerJumpGuard::reset() {
  // setPeriod(..., reset) sets the next expiry to now + period and re-sorts roscpp's queue of
  // waiting timers; a stopped timer is left alone.
  for (const auto& [timer, period] : timers_) timer->setPeriod(ros::Duration(period), true);
  ++resets_;
  ROS_WARN_STREAM_THROTTLE(1.0, "ROS time jumped to " << ros::Time::now()
                                                      << " s: the node's timers restart from it");
}

}  // namespace spherical_robots
