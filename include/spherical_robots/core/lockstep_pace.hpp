#pragma once
// When a lock-step clock may take its next step (docs/lockstep.md, "Pace"), with time as numbers
// and no ROS: the cap of `speedup` times real time, measured from the first step, and the pause,
// resume and single-step services. Simulated step times are integer nanoseconds; wall time, which
// only paces, is seconds.

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
  /// The step at `step` [ns] started at wall time `wall` [s]; the first one anchors the pace.
  void started(std::int64_t step, double wall);

  void pause();
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
  std::optional<std::int64_t> first_step_;
  double first_wall_ = 0.0;
  std::optional<double> finished_wall_;
};

}  // namespace spherical_robots
