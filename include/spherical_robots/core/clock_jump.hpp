#pragma once
// Tells a clock's jumps from its steps, with time as a number (no ROS). A simulated /clock can be
// jumped by a stray message (1,000 s ahead, then back), a replayed bag loops back to its start,
// a restarted plant starts again at 0: a node that integrates, times out or schedules from the
// clock must handle each of these as a jump, not as 1,000 s of elapsed time or a frozen clock.

namespace spherical_robots {

enum class ClockStep {
  kStart,        ///< the first reading
  kAdvance,      ///< forward by at most max_step: time elapsed
  kHold,         ///< the same reading again
  kJumpForward,  ///< forward by more than max_step: no time is to be taken as elapsed
  kJumpBack,     ///< backwards by any amount
};

const char* toString(ClockStep step);

/// [s] the default largest forward step taken as elapsed time: every node's ~max_clock_step.
constexpr double kDefaultMaxClockStep = 5.0;

class ClockJumpDetector {
 public:
  /// @param max_step [s], finite and > 0: the largest forward step taken as elapsed time.
  /// @throw std::invalid_argument naming max_step if it is not.
  explicit ClockJumpDetector(double max_step);

  /// Classifies t [s] against the previous reading and makes it the latest. A non-finite t is
  /// ignored and classified kHold.
  ClockStep observe(double t);
  /// observe(t), and the size of the jump [s] (t minus the previous reading) if it was one, else
  /// 0: what a schedule timed from the clock shifts its start by to go on where it was.
  double jumpOver(double t);

  bool started() const { return started_; }
  double latest() const { return latest_; }  ///< [s]; 0 before the first reading
  double maxStep() const { return max_step_; }
  /// Jumps seen so far, either way.
  unsigned long jumps() const { return jumps_; }

 private:
  double max_step_;
  double latest_ = 0.0;
  bool started_ = false;
  unsigned long jumps_ = 0;
};

}  // namespace spherical_robots
