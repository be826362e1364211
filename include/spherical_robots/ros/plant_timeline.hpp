#pragma once
// The time bookkeeping every plant node shares (terrain, Norma, rotor sphere, FreeBOT chain): the
// first tick starts the scenario; each later tick advances the model by the ROS time elapsed since
// the previous one, never backwards and never by a jump (a step back, or forward by more than
// max_clock_step, holds the state: core/clock_jump.hpp); a model that throws (also when a step
// would produce a non-finite state) keeps its last good state and the failure is counted; after
// `duration` the scenario is complete. The decisions are core/loop_timeline's (which the batch
// runs that replay a stack share); this class adds the logs, the failure count and diagnostics.

#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <ros/time.h>

#include <functional>

#include "spherical_robots/core/loop_timeline.hpp"

namespace spherical_robots {

class PlantTimeline {
 public:
  /// @param duration [s] of ROS time after the first tick; 0 (or less): forever.
  /// @param max_clock_step [s] > 0: a longer forward step of ROS time is a jump, not elapsed time.
  PlantTimeline(double duration, double max_clock_step);

  /// Calls advance(elapsed [s]) when ROS time moved forward since the previous tick (not on the
  /// first); logs a jump back, and an exception from advance, at most once a second.
  void tick(const ros::Time& now, const std::function<void(double elapsed)>& advance);

  /// True once the duration has passed (the node logs and shuts down then); later ticks are to
  /// be ignored.
  bool complete(const ros::Time& now);
  bool finished() const { return timeline_.finished(); }
  /// As LoopTimeline::resume: from a checkpoint's start and time.
  void resume(const ros::Time& start, const ros::Time& last_tick);
  /// [ns] the first tick; 0 before it.
  Nanoseconds start() const { return timeline_.start(); }
  double duration() const { return timeline_.duration(); }

  /// Adds "time since start [s]", "clock jumps" and "integration failures", and raises ERROR if the model
  /// failed since the last report.
  void report(diagnostic_updater::DiagnosticStatusWrapper& status, const ros::Time& now);

 private:
  LoopTimeline timeline_;
  unsigned long failures_ = 0;
  unsigned long failures_at_last_report_ = 0;
};

}  // namespace spherical_robots
