#pragma once
// Drives a fixed-step simulation, either owning simulated time or following ROS time.

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/timer.h>
#include <ros/wall_timer.h>

#include <functional>
#include <memory>

#include <ros/subscriber.h>

#include "spherical_robots/ros/timer_jump_guard.hpp"

namespace spherical_robots {

/// Whether a periodic action last done at `last` (zero: never) is due again at `now`, also after
/// ROS time jumped back (a replayed or restarted clock).
bool periodDue(const ros::Time& last, const ros::Time& now, double period);

/// With speedup > 0 it owns simulated time (there must be exactly one such clock per master, and
/// /use_sim_time must be true): a wall timer advances /clock by `step` every step / speedup wall
/// seconds and then calls tick with the new time, so a slow tick lowers the speed-up but never
/// changes the steps. With speedup <= 0 it publishes nothing: a ros::Timer calls tick every
/// `step` of ROS time, which is wall time (hardware in the loop) or a clock someone else
/// publishes (rosbag play --clock). Ticks run on the node handle's callback queue.
class SimClock {
 public:
  using Tick = std::function<void(const ros::Time& now)>;
  using Ready = std::function<bool()>;

  /// @param step [s] > 0, @param speedup [-] finite. @throw std::invalid_argument on a bad step or
  /// speedup, or on speedup > 0 while /use_sim_time is false.
  /// When it owns the clock, time does not start until `ready` holds (e.g. the controller and a
  /// bag recorder have subscribed, so no simulated second goes unseen) or `ready_timeout` wall
  /// seconds have passed, after which it starts anyway with a warning.
  SimClock(ros::NodeHandle nh, double step, double speedup, Tick tick,
           Ready ready = [] { return true; }, double ready_timeout = 0.0);

  bool ownsClock() const { return speedup_ > 0.0; }
  /// The time of the latest tick when it owns the clock (a stray /clock message, which moves
  /// ros::Time::now() of every node, cannot move it), else ros::Time::now().
  ros::Time now() const;
  /// ROS seconds per wall second since the first tick [-]; NaN before the second tick.
  double realTimeFactor() const;

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

/// A plant's clock from its private parameters (pnh): publish_clock (false) and speedup
/// (default_speedup) choose whether it owns simulated time; if it does, time starts once
/// wait_for_subscribers (1) nodes read `state` and something publishes on `actuators`, or after
/// start_timeout [s] (10). @throw std::invalid_argument as SimClock, or on a bad parameter.
std::unique_ptr<SimClock> makePlantClock(ros::NodeHandle nh, const ros::NodeHandle& pnh,
                                         double step, double default_speedup, SimClock::Tick tick,
                                         const ros::Publisher& state,
                                         const ros::Subscriber& actuators);

}  // namespace spherical_robots
