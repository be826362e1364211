#pragma once
// Something a loop does every `period` (a plant's publication), at steps whose times may come
// late: a wall timer fires a little after each of its times.

#include "spherical_robots/core/stamp.hpp"

namespace spherical_robots {

/// Due at the first step at or after its scheduled time (periodDue); the next time is scheduled one
/// period after the scheduled one, not after the step that was late, so a loop whose steps come
/// late still does it at its rate (a 50 Hz publication on a 200 Hz wall timer, rescheduled from
/// each late step, came at 38 Hz). After a gap longer than a period, or when time goes back, it
/// starts again from the step. On a loop whose step divides the period (lock-step, batch runs) the
/// scheduled time is the step's.
class PeriodicSchedule {
 public:
  /// @param period [s] > 0.
  explicit PeriodicSchedule(double period);

  /// Whether it is due at now; if so, it counts as done.
  bool take(Nanoseconds now);

 private:
  double period_;
  Nanoseconds period_ns_;
  Nanoseconds scheduled_ = 0;  ///< the time the last one was due, 0: never
};

}  // namespace spherical_robots
