#pragma once
// Whether a node publishes at the rate it is configured for, with time as a number (no ROS).
// Counted as diagnostic_updater::FrequencyStatus counts (the events and the time since the report
// `reports` reports ago, WARN outside target x (1 -+ tolerance), ERROR without events), but at
// times the node gives: the time it works at. FrequencyStatus reads ros::Time::now(), the last
// /clock a node has taken in, which in lock-step paced at ~50 x real time on a loaded machine lags
// or leads the steps the node has worked by seconds of simulated time: a plant publishing exactly
// 50 Hz was reported at 38.7 and 62.7 Hz. It also calls a clock that stands still (lock-step
// before the start, paused, ended) an ERROR; here that, a clock that went back and a node with
// nothing to publish (a planner between manoeuvres) are OK with the reason, and the window
// starts afresh once time runs and publications are expected.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>

#include "spherical_robots/core/input_health.hpp"
#include "spherical_robots/core/stamp.hpp"

namespace spherical_robots {

class PublicationRate {
 public:
  struct Report {
    HealthLevel level = HealthLevel::kOk;
    std::string message;
    std::uint64_t events = 0;  ///< in the window
    std::uint64_t total = 0;   ///< since the window last started afresh
    double window = 0.0;       ///< [s]
    std::optional<double> frequency;  ///< [Hz] events / window; none without a window
  };

  /// @param target [Hz] > 0, @param tolerance in [0, 1), @param reports >= 1 the window spans.
  /// @throw std::invalid_argument naming the value that is out of range.
  PublicationRate(double target, double tolerance, std::size_t reports = 5);

  /// One publication.
  void tick() { ++total_; }
  /// The report at time `now` (the node's); `expected`: the node has publications to make.
  Report report(Nanoseconds now, bool expected);

  double target() const { return target_; }
  double tolerance() const { return tolerance_; }

 private:
  struct Mark {
    Nanoseconds time;
    std::uint64_t total;
  };
  /// Starts the window afresh at `now` (measure), or not until the next report that expects
  /// publications; the report says why.
  Report restart(Nanoseconds now, const std::string& why, bool measure);

  double target_;
  double tolerance_;
  std::size_t reports_;
  std::uint64_t total_ = 0;
  std::deque<Mark> marks_;  ///< the last `reports_` reports, oldest first; empty: not measuring
  std::optional<Nanoseconds> last_report_;
};

}  // namespace spherical_robots
