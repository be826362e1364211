#include "spherical_robots/core/periodic_schedule.hpp"

namespace spherical_robots {

PeriodicSchedule::PeriodicSchedule(double period)
    : period_(period), period_ns_(durationNanoseconds(period)) {}

bool PeriodicSchedule::take(Nanoseconds now) {
  if (!periodDue(scheduled_, now, period_)) return false;
  const bool on_schedule = scheduled_ != 0 && now >= scheduled_ && now - scheduled_ < 2 * period_ns_;
  scheduled_ = on_schedule ? scheduled_ + period_ns_ : now;
  return true;
}

}  // namespace spherical_robots
