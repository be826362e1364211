#include "spherical_robots/core/loop_timeline.hpp"

namespace spherical_robots {

LoopTimeline::LoopTimeline(double duration, double max_clock_step)
    : duration_(duration), clock_(max_clock_step) {}

LoopTimeline::Tick LoopTimeline::tick(Nanoseconds now) {
  Tick tick;
  // Absolute seconds, as the nodes observe ros::Time::toSec(); the elapsed time is the difference
  // of the integer stamps, as ros::Time subtraction gives it.
  tick.clock = clock_.observe(stampSeconds(now));
  tick.starts = !started();
  if (tick.starts) start_ = now;
  else tick.elapsed = stampSeconds(now - last_tick_);
  last_tick_ = now;
  return tick;
}

void LoopTimeline::resume(Nanoseconds start, Nanoseconds last_tick) {
  clock_.observe(stampSeconds(last_tick));
  start_ = start;
  last_tick_ = last_tick;
}

bool LoopTimeline::complete(Nanoseconds now) {
  if (!finished_ && duration_ > 0.0 && started() && stampSeconds(now - start_) >= duration_ - 1e-9)
    finished_ = true;
  return finished_;
}

}  // namespace spherical_robots
