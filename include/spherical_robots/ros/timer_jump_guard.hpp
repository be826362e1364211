#pragma once
// roscpp's ros::Timer can stay asleep after ROS time jumps back: a timer whose callback was
// scheduled at the jumped time gets its next expiry computed from that time after the callback
// returns, and fires only when the clock gets there again. One stray /clock message 1,000 s
// ahead stopped a hardware interface's actuators/state, or a controller's commands, for 1,000 s
// of simulated time that way (the robot stood while the reference went on). This guard notes
// every reading of ROS time it is shown (the timer events' scheduled times, which carry the jump
// even when the callback runs after it, and its own 10 ms wall poll) and, after a step of more
// than max_clock_step either way, resets the timers it was given to fire one period from now on
// its next three polls: after the callbacks in flight, whose bookkeeping would undo a reset made
// inside them.

#include <ros/node_handle.h>
#include <ros/timer.h>
#include <ros/wall_timer.h>

#include <utility>
#include <vector>

namespace spherical_robots {

class TimerJumpGuard {
 public:
  /// @param timers the node's ROS-time timers with their periods [s]; they must outlive the guard.
  /// @param max_clock_step [s] > 0: a longer step of ROS time, either way, is a jump.
  TimerJumpGuard(ros::NodeHandle nh, std::vector<std::pair<ros::Timer*, double>> timers,
                 double max_clock_step);

  /// Call first in each guarded timer's callback.
  void observe(const ros::TimerEvent& event);
  /// The node saw ROS time jump: reset the timers.
  void reset() { pending_resets_ = kResetPolls; }
  unsigned long resets() const { return resets_; }

 private:
  static constexpr int kResetPolls = 3;
  void note(double t);
  void watch();

  std::vector<std::pair<ros::Timer*, double>> timers_;
  double max_clock_step_;
  double latest_ = 0.0;
  bool started_ = false;
  int pending_resets_ = 0;
  ros::WallTimer watch_timer_;
  unsigned long resets_ = 0;
};

}  // namespace spherical_robots
