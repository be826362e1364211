#include "spherical_robots/core/clock_jump.hpp"

#include <cmath>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots {

const char* toString(ClockStep step) {
  switch (step) {
    case ClockStep::kStart: return "start";
    case ClockStep::kAdvance: return "advance";
    case ClockStep::kHold: return "hold";
    case ClockStep::kJumpForward: return "jump forward";
    case ClockStep::kJumpBack: return "jump back";
  }
  return "?";
}

ClockJumpDetector::ClockJumpDetector(double max_step) : max_step_(max_step) {
  requirePositive(max_step_, "max_clock_step [s]");
}

ClockStep ClockJumpDetector::observe(double t) {
  if (!std::isfinite(t)) return ClockStep::kHold;
  if (!started_) {
    started_ = true;
    latest_ = t;
    return ClockStep::kStart;
  }
  const double step = t - latest_;
  latest_ = t;
  if (step == 0.0) return ClockStep::kHold;
  if (step > 0.0 && step <= max_step_) return ClockStep::kAdvance;
  ++jumps_;
  return step > 0.0 ? ClockStep::kJumpForward : ClockStep::kJumpBack;
}

double ClockJumpDetector::jumpOver(double t) {
  const double previous = latest_;
  const ClockStep step = observe(t);
  return step == ClockStep::kJumpForward || step == ClockStep::kJumpBack ? t - previous : 0.0;
}

}  // namespace spherical_robots
