#include "spherical_robots/ros/sim_clock.hpp"

#include "spherical_robots/core/clock_jump.hpp"
#include "spherical_robots/ros/timer_jump_guard.hpp"

#include <rosgraph_msgs/Clock.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace spherical_robots {
SimClock::SimClock(ros::NodeHandle nh, double step, double speedup, Tick tick, Ready ready,
                   double ready_timeout)
    : step_(step), speedup_(speedup), tick_(std::move(tick)), ready_(std::move(ready)),
      ready_timeout_(ready_timeout), created_wall_(ros::WallTime::now()) {
  if (!(step > 0.0) || !std::isfinite(step) || !std::isfinite(speedup)) {
    std::ostringstream what;
    what << "SimClock: step = " << step << " s must be positive and finite, speedup = " << speedup
         << " finite";
    throw std::invalid_argument(what.str());
  }
  if (!ownsClock()) {
    timer_ = nh.createTimer(ros::Duration(step_),
                            [this](const ros::TimerEvent& event) {
                              timer_guard_->observe(event);
                              onTick(event.current_real);
                            });
    timer_guard_ = std::make_unique<TimerJumpGuard>(
        nh, std::vector<std::pair<ros::Timer*, double>>{{&timer_, step_}}, kDefaultMaxClockStep);
    ROS_INFO_STREAM("Stepping every " << step_ << " s of ROS time ("
                                      << (ros::Time::isSimTime() ? "simulated" : "wall") << " clock)");
    return;
  }
  if (!ros::Time::isSimTime()) {
    std::ostringstream what;
    what << "SimClock: speedup " << speedup_ << " > 0 means publishing /clock, but /use_sim_time "
         << "is not true, so no node would follow it";
    throw std::invalid_argument(what.str());
  }
  clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
  wall_timer_ = nh.createWallTimer(ros::WallDuration(step_ / speedup_), [this](const ros::WallTimerEvent&) {
    if (started_ || hasStarted()) onTick(now_ + ros::Duration(step_));
  });
  ROS_INFO_STREAM("Publishing /clock: " << step_ << " s per tick at " << speedup_ << "x real time");
}

void SimClock::onTick(const ros::Time& now) {
  now_ = now;
  if (first_tick_.isZero()) {
    first_tick_ = now;
    first_tick_wall_ = ros::WallTime::now();
  }
  if (ownsClock()) {
    rosgraph_msgs::Clock clock;
    clock.clock = now;
    clock_pub_.publish(clock);
  }
  tick_(now);
}

bool SimClock::hasStarted() {
  const double waited = (ros::WallTime::now() - created_wall_).toSec();
  if (ready_()) {
    ROS_INFO_STREAM("Starting simulated time after " << waited << " s of wall time");
  } else if (waited >= ready_timeout_) {
    ROS_WARN_STREAM("Starting simulated time without all expected subscribers after waiting "
                    << ready_timeout_ << " s");
  } else {
    return false;
  }
  started_ = true;
  return true;
}

ros::Time SimClock::now() const { return ownsClock() ? now_ : ros::Time::now(); }

double SimClock::realTimeFactor() const {
  const double wall = (ros::WallTime::now() - first_tick_wall_).toSec();
  if (first_tick_.isZero() || !(wall > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return (now_ - first_tick_).toSec() / wall;
}

}  // namespace spherical_robots
