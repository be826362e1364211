#include "spherical_robots/core/stamp.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace spherical_robots {

constexpr Nanoseconds kNanosecondsPerSecond = 1000000000;

double stampSeconds(Nanoseconds ns) {
  Nanoseconds sec = ns / kNanosecondsPerSecond;
  Nanoseconds nsec = ns % kNanosecondsPerSecond;
  if (nsec < 0) {  // ros::Duration keeps 0 <= nsec < 1e9 with sec negative
    nsec += kNanosecondsPerSecond;
    --sec;
  }
  return static_cast<double>(sec) + 1e-9 * static_cast<double>(nsec);
}

Nanoseconds durationNanoseconds(double seconds) {
  const double whole = std::floor(seconds);
  if (!std::isfinite(seconds) || whole < std::numeric_limits<std::int32_t>::min() ||
      whole > std::numeric_limits<std::int32_t>::max()) {
    std::ostringstream what;
    what << "duration " << seconds << " s is not finite or beyond 2^31 s";
    throw std::invalid_argument(what.str());
  }
  const auto sec = static_cast<Nanoseconds>(whole);
  // boost::math::round in roscpp: halves away from zero, as std::round.
  const auto nsec = static_cast<Nanoseconds>(std::round((seconds - static_cast<double>(sec)) * 1e9));
  return sec * kNanosecondsPerSecond + nsec;
}

bool withinTimeout(Nanoseconds accepted, Nanoseconds now, double timeout) {
  const double age = stampSeconds(now - accepted);
  return age >= 0.0 && age <= timeout;
}

}  // namespace spherical_robots
