#pragma once
// Time as the stacks carry it: whole nanoseconds (ros::Time, ros::Duration), turned into seconds
// the way roscpp turns them. A batch run that replays a stack's loop computes with these, so that
// it uses the very doubles the nodes compute with (bit-identical results, issue 19 item 4).

#include <cstdint>

namespace spherical_robots {

using Nanoseconds = std::int64_t;

/// Seconds as ros::Time::toSec() and ros::Duration::toSec() give them for this many nanoseconds:
/// whole seconds (rounded down) plus 1e-9 times the nanoseconds left, not ns * 1e-9.
double stampSeconds(Nanoseconds ns);

/// Nanoseconds of ros::Duration(seconds) (ros::Duration::fromSec: whole seconds rounded down, the
/// rest rounded to the nearest nanosecond). @throw std::invalid_argument if not finite or beyond
/// a 32-bit count of seconds.
Nanoseconds durationNanoseconds(double seconds);

/// Whether an input accepted at `accepted` is still fresh at `now`: 0 <= age <= timeout [s].
bool withinTimeout(Nanoseconds accepted, Nanoseconds now, double timeout);

}  // namespace spherical_robots
