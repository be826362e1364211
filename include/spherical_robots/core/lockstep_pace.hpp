#pragma once
// When a lock-step clock may take its next step (docs/lockstep.md, "Pace"), with time as numbers
// and no ROS: the cap of `speedup` times real time, and the pause, resume and single-step
// services. Simulated step times are integer nanoseconds; wall time, which only paces, is seconds.
//
// The cap counts from an anchor step: the first, and again the first after a resume or after the
// loop fell more than kMaxLag of wall time behind the cap's schedule (a participant silent until
// dropped, a descheduled plant). Up to kMaxLag the loop makes up lost time, so the average pace
// stays at the cap despite a late timer; beyond it, it does not race: without a new anchor, 2 s
// of wall time waiting for a silent participant at 10x would be made up by 20 s of simulated
// time at full speed.

#include <cstdint>
#include <optional>
#include <string>

namespace spherical_robots {

class LockstepPace {
 public:
  /// @param step [s] of simulated time per step, finite > 0.
  /// @param speedup cap on the pace [-], 0: none, else finite > 0.
  /// @throw std::invalid_argument naming the value that is out of its domain.
  LockstepPace(double step, double speedup);

  /// "0.001 s per step, at most 10x real time" or "..., as fast as the participants answer".
  std::string describe() const;

  /// The wall time [s] to wait before the step at `step` [ns] may start, at wall time `wall`
  /// [s]: 0 now, nullopt while paused (a single step asked for is consumed here).
  std::optional<double> delayBefore(std::int64_t step, double wall);
  /// The step at `step` [ns] started at wall time `wall` [s]; it anchors the pace if it is the
  /// first, the first after a resume, or more than kMaxLag behind the schedule.
  void started(std::int64_t step, double wall);

  /// [s] of wall time the loop may fall behind the cap's schedule and still make up.
  static constexpr double kMaxLag = 0.1;

  void pause();
  /// Ends a pause; the next step anchors the pace, so the paused time is not made up.
  void resume();
  /// Allows one step while paused. @return the reason it is refused ("" if allowed): not paused.
  std::string stepOnce();
  bool paused() const { return paused_; }

  /// The last step has been taken, at wall time `wall` [s]: the real-time factor keeps its value
  /// from then on (a run's figure, not diluted by the wall time that passes after its end).
  void finished(double wall);

  /// Simulated over wall time since the first step (up to `wall`, or to the end once finished);
  /// NaN before the first step.
  double realTimeFactor(std::int64_t latest_step, double wall) const;

 private:
  double step_;
  double speedup_;
  bool paused_ = false;
  int single_steps_ = 0;
  /// Seconds of wall time after the anchor that the step at `step` [ns] is due.
  double dueAfterAnchor(std::int64_t step) const;

  std::optional<std::int64_t> first_step_;  // the real-time factor counts from the first step
  double first_wall_ = 0.0;
  std::optional<std::int64_t> anchor_step_;  // the cap counts from the anchor
  double anchor_wall_ = 0.0;
  std::optional<double> finished_wall_;
};

}  // namespace spherical_robots
