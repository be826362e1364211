#include "spherical_robots/core/lockstep_pace.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace spherical_robots {

LockstepPace::LockstepPace(double step, double speedup) : step_(step), speedup_(speedup) {
  std::ostringstream what;
  if (!(step > 0.0) || !std::isfinite(step))
    what << "lock-step pace: step = " << step << " s must be finite and > 0";
  else if (!(speedup >= 0.0) || !std::isfinite(speedup))
    what << "lock-step pace: speedup = " << speedup << " must be finite and >= 0 (0: no cap)";
  if (!what.str().empty()) throw std::invalid_argument(what.str());
}

std::string LockstepPace::describe() const {
  std::ostringstream text;
  text << step_ << " s per step, ";
  if (speedup_ > 0.0)
    text << "at most " << speedup_ << "x real time";
  else
    text << "as fast as the participants answer";
  return text.str();
}

std::optional<double> LockstepPace::delayBefore(std::int64_t step, double wall) {
  if (paused_) {
    if (single_steps_ == 0) return std::nullopt;
    --single_steps_;
  }
  if (speedup_ == 0.0 || !anchor_step_) return 0.0;
  const double ahead = dueAfterAnchor(step) - (wall - anchor_wall_);
  return ahead > 0.0 ? ahead : 0.0;
}

double LockstepPace::dueAfterAnchor(std::int64_t step) const {
  // The step at t is due t - t_anchor of simulated time after the anchor, divided by the cap.
  return 1e-9 * static_cast<double>(step - *anchor_step_) / speedup_;
}

void LockstepPace::started(std::int64_t step, double wall) {
  if (!first_step_) {
    first_step_ = step;
    first_wall_ = wall;
  }
  if (speedup_ == 0.0) return;
  if (!anchor_step_ || wall - anchor_wall_ - dueAfterAnchor(step) > kMaxLag) {
    anchor_step_ = step;
    anchor_wall_ = wall;
  }
}

void LockstepPace::pause() {
  paused_ = true;
  single_steps_ = 0;
}

void LockstepPace::resume() {
  paused_ = false;
  anchor_step_.reset();
}

std::string LockstepPace::stepOnce() {
  if (!paused_) return "not paused: call lockstep/pause first";
  ++single_steps_;
  return "";
}

void LockstepPace::finished(double wall) {
  if (!finished_wall_) finished_wall_ = wall;
}

double LockstepPace::realTimeFactor(std::int64_t latest_step, double wall) const {
  const double elapsed_wall = finished_wall_.value_or(wall) - first_wall_;
  if (!first_step_ || !(elapsed_wall > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return 1e-9 * static_cast<double>(latest_step - *first_step_) / elapsed_wall;
}

}  // namespace spherical_robots
