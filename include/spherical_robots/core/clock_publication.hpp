#pragma once
// When a lock-step clock publishes /clock (docs/lockstep.md, "/clock"), with time as numbers and
// no ROS. The participants take their time from their requests, so /clock serves the observers
// (robot_state_publisher, rosout, rosbag, rviz), each woken by every /clock message: at 33 x real
// time the terrain stack's robot_state_publisher and rosout spent 59 us of CPU per 10 ms step on
// it. At most `rate` messages per second of wall time are sent, as Gazebo caps its /clock with
// pub_clock_frequency; a step's time not sent then is sent once time waits (a paced or paused
// clock, a participant late to answer, the end), so an observer is never left behind a clock
// that stands still. Simulated step times are integer nanoseconds; wall time is seconds.

#include <cstdint>
#include <optional>

namespace spherical_robots {

class ClockPublication {
 public:
  /// @param rate [Hz] of wall time, finite >= 0; 0: every step.
  /// @throw std::invalid_argument naming the value that is out of its domain.
  explicit ClockPublication(double rate);

  /// Whether to publish the step at `step` [ns] now, at wall time `wall` [s]: at once if
  /// `waiting` (time stands still after it), else once 1 / rate has passed since the last.
  /// Never the same step twice.
  bool due(std::int64_t step, double wall, bool waiting) const;
  /// The step at `step` [ns] was published at wall time `wall` [s].
  void published(std::int64_t step, double wall);

 private:
  double period_;  ///< [s] of wall time
  std::optional<std::int64_t> last_step_;
  double last_wall_ = 0.0;
};

}  // namespace spherical_robots
