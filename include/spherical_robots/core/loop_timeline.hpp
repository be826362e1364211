#pragma once
// The plant loop's timeline with time as whole nanoseconds (no ROS): the first tick starts the
// scenario; each later tick says by how much to advance the model, the time elapsed since the
// previous tick, unless the clock held or jumped (core/clock_jump.hpp); after `duration` the
// scenario is complete. Every plant node (ros/plant_timeline) and the batch runs that replay a
// stack's loop (norma/sampled_norma_loop) decide with this one class, so that they advance their
// models by the very same doubles.

#include "spherical_robots/core/clock_jump.hpp"
#include "spherical_robots/core/stamp.hpp"

namespace spherical_robots {

class LoopTimeline {
 public:
  /// What one tick means for the model.
  struct Tick {
    bool starts = false;                ///< the first tick: the scenario starts, nothing elapsed
    ClockStep clock = ClockStep::kStart;  ///< how the clock moved since the previous tick
    double elapsed = 0.0;  ///< [s] now - previous tick as ros::Duration::toSec() gives it
    /// Whether the model is to advance by `elapsed`: a later tick on a clock that moved forward
    /// by at most max_clock_step (a hold or a jump holds the state).
    bool advances() const { return !starts && clock == ClockStep::kAdvance; }
  };

  /// @param duration [s] after the first tick; 0 (or less): forever.
  /// @param max_clock_step [s] > 0: a longer forward step of the clock is a jump, not elapsed time.
  /// @throw std::invalid_argument naming max_clock_step if it is not finite and > 0.
  LoopTimeline(double duration, double max_clock_step);

  /// A tick at `now` [ns]. A tick at 0 (no clock yet) does not start the scenario.
  Tick tick(Nanoseconds now);
  /// Goes on from a checkpoint (core/plant_checkpoint) of a timeline that started at `start` and
  /// last ticked at `last_tick` [ns]: the next tick advances by the time since last_tick.
  void resume(Nanoseconds start, Nanoseconds last_tick);
  /// True from the first tick at least duration - 1 ns after the start (the node logs and shuts
  /// down then; later ticks are to be ignored).
  bool complete(Nanoseconds now);
  bool finished() const { return finished_; }
  bool started() const { return start_ != 0; }
  Nanoseconds start() const { return start_; }          ///< [ns] the first tick; 0 before it
  Nanoseconds lastTick() const { return last_tick_; }  ///< [ns] 0 before the first
  double duration() const { return duration_; }
  const ClockJumpDetector& clock() const { return clock_; }

 private:
  double duration_;
  ClockJumpDetector clock_;
  Nanoseconds start_ = 0;
  Nanoseconds last_tick_ = 0;
  bool finished_ = false;
};

}  // namespace spherical_robots
