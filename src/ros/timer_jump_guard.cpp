#include "spherical_robots/ros/timer_jump_guard.hpp"

#include <ros/console.h>

#include <cmath>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots {
namespace {

// [s] of wall time between looks at ROS time: at 10x real time, 0.1 s of simulated time.
constexpr double kWatchPeriod = 0.01;

}  // namespace

TimerJumpGuard::TimerJumpGuard(ros::NodeHandle nh,
                               std::vector<std::pair<ros::Timer*, double>> timers,
                               double max_clock_step)
    : timers_(std::move(timers)), max_clock_step_(max_clock_step) {
  requirePositive(max_clock_step_, "max_clock_step [s]");
  watch_timer_ = nh.createWallTimer(ros::WallDuration(kWatchPeriod),
                                    [this](const ros::WallTimerEvent&) { watch(); });
}

void TimerJumpGuard::observe(const ros::TimerEvent& event) {
  note(event.current_real.toSec());
  note(ros::Time::now().toSec());
}

void TimerJumpGuard::note(double t) {
  // Either way by more than max_clock_step: a timer event's scheduled time lags now a little,
  // which is no jump.
  if (started_ && std::abs(t - latest_) > max_clock_step_) reset();
  latest_ = t;
  started_ = true;
}

void TimerJumpGuard::watch() {
  note(ros::Time::now().toSec());
  if (pending_resets_ == 0) return;
  --pending_resets_;
  // setPeriod(..., reset) sets the next expiry to now + period and re-sorts roscpp's queue of
  // waiting timers; a stopped timer is left alone.
  for (const auto& [timer, period] : timers_) timer->setPeriod(ros::Duration(period), true);
  ++resets_;
  ROS_WARN_STREAM_THROTTLE(1.0, "ROS time jumped (now " << ros::Time::now()
                                                        << " s): the node's timers restart");
}

}  // namespace spherical_robots
