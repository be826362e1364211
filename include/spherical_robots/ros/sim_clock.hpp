#pragma once
// The free-running and ROS-time clock modes of a plant (plant_clock.hpp).

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/timer.h>
#include <ros/wall_timer.h>

#include <memory>

#include "spherical_robots/ros/plant_clock.hpp"
#include "spherical_robots/ros/timer_jump_guard.hpp"

namespace spherical_robots {

/// With speedup > 0 it owns simulated time (there must be exactly one such clock per master, and
/// /use_sim_time must be true): a wall timer advances /clock by `step` every step / speedup wall
/// seconds and then calls tick with the new time, so a slow tick lowers the speed-up but never
/// changes the steps. With speedup <= 0 it publishes nothing: a ros::Timer calls tick every
/// `step` of ROS time, which is wall time (hardware in the loop) or a clock someone else
/// publishes (rosbag play --clock). Ticks run on the node handle's callback queue.
class SimClock : public PlantClock {
 public:
  /// @param step [s] > 0, @param speedup [-] finite. @throw std::invalid_argument on a bad step or
  /// speedup, or on speedup > 0 while /use_sim_time is false.
  /// When it owns the clock, time does not start until `ready` holds or `ready_timeout` wall
  /// seconds have passed, after which it starts anyway with a warning.
  SimClock(ros::NodeHandle nh, double step, double speedup, Tick tick,
           Ready ready = [] { return true; }, double ready_timeout = 0.0);

  bool ownsClock() const { return speedup_ > 0.0; }
  ros::Time now() const override;
  void resumeAt(const ros::Time& t) override {
    if (ownsClock()) now_ = t;
  }
  double realTimeFactor() const override;

 protected:
  const char* mode() const override { return ownsClock() ? "free" : "ros"; }

 private:
  void onTick(const ros::Time& now);
  /// Whether simulated time may start now; logs once when it does.
  bool hasStarted();

  double step_;
  double speedup_;
  Tick tick_;
  Ready ready_;
  double ready_timeout_;
  ros::WallTime created_wall_;
  bool started_ = false;
  ros::Publisher clock_pub_;
  ros::WallTimer wall_timer_;
  ros::Timer timer_;
  std::unique_ptr<TimerJumpGuard> timer_guard_;  ///< restarts timer_ after a clock jump
  ros::Time now_;
  ros::Time first_tick_;
  ros::WallTime first_tick_wall_;
};

}  // namespace spherical_robots
