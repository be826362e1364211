#pragma once
// roscpp's ros::Timer can stay asleep after ROS time jumps back: a timer whose callback was in
// flight across the jump keeps its next expiry on the far side of it and fires only when the
// clock gets there again. One stray /clock message 1,000 s ahead stopped a hardware interface's
// actuators/state for 1,000 s of simulated time that way (the robot stood while the reference
// went on). This guard resets the timers it was given to fire one period from now whenever ROS
// time jumps (core/clock_jump.hpp): when the node's callbacks see a jump and call reset(), and
// when its own wall timer sees one (a stray /clock lasts a millisecond of wall time, so the
// callbacks, which run at the jumped time, see it more often).

#include <ros/node_handle.h>
#include <ros/timer.h>
#include <ros/wall_timer.h>

#include <utility>
#include <vector>

#include "spherical_robots/core/clock_jump.hpp"

namespace spherical_robots {

class TimerJumpGuard {
 public:
  /// @param timers the node's ROS-time timers with their periods [s]; they must outlive the guard.
  /// @param max_clock_step [s] > 0: a longer forward step of ROS time is a jump.
  TimerJumpGuard(ros::NodeHandle nh, std::vector<std::pair<ros::Timer*, double>> timers,
                 double max_clock_step);

  /// ROS time jumped: every timer fires next one period from now.
  void reset();
  unsigned long resets() const { return resets_; }

 private:
  void watch();

  std::vector<std::pair<ros::Timer*, double>> timers_;
  ClockJumpDetector clock_;
  ros::WallTimer watch_timer_;
  unsigned long resets_ = 0;
};

}  // namespace spherical_robots
