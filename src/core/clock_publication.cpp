#include "spherical_robots/core/clock_publication.hpp"

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots {

ClockPublication::ClockPublication(double rate) {
  requireNonNegative(rate, "/clock publication rate [Hz of wall time] (0: every step)");
  period_ = rate == 0.0 ? 0.0 : 1.0 / rate;
}

bool ClockPublication::due(std::int64_t step, double wall, bool waiting) const {
  if (last_step_ && *last_step_ == step) return false;
  return waiting || !last_step_ || wall - last_wall_ >= period_;
}

void ClockPublication::published(std::int64_t step, double wall) {
  last_step_ = step;
  last_wall_ = wall;
}

}  // namespace spherical_robots
