#pragma once
// What drives a plant's steps, in one of the three clock modes (docs/lockstep.md):
// * lockstep: the plant owns /clock and advances one step only when every participant of its
//   loop has answered for the current one (LockstepClock);
// * free: the plant owns /clock and advances it at a fixed pace of wall time (SimClock);
// * ros: the plant follows ROS time, which is wall time (hardware in the loop) or a /clock that
//   someone else publishes (rosbag play --clock, another stack's plant) (SimClock).

#include <diagnostic_updater/DiagnosticStatusWrapper.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/subscriber.h>
#include <ros/time.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "spherical_robots/config/plant_loop_parameters.hpp"

namespace spherical_robots {

class PlantClock {
 public:
  /// One step of the plant at `now`; returns the resolved names of the topics it published
  /// (every message stamped `now`), which lock-step passes on to the participants.
  using Tick = std::function<std::vector<std::string>(const ros::Time& now)>;
  /// Whether simulated time may start (e.g. the controller and a recorder have subscribed).
  using Ready = std::function<bool()>;

  virtual ~PlantClock() = default;
  /// The time of the latest step when the plant owns the clock (a stray /clock message, which
  /// moves ros::Time::now() of every node, cannot move it), else ros::Time::now().
  virtual ros::Time now() const = 0;
  /// ROS seconds per wall second since the first step [-]; NaN before the second.
  virtual double realTimeFactor() const = 0;
  /// A message the plant reads arrived on `topic` from `publisher` (its caller id; lock-step waits
  /// for those it is told of).
  virtual void received(const std::string& /*topic*/, const ros::Time& /*stamp*/,
                        const std::string& /*publisher*/) {}
  /// Adds the clock's figures ("clock mode", "real-time factor", lock-step participants) and may
  /// raise the status.
  virtual void report(diagnostic_updater::DiagnosticStatusWrapper& status);
  /// The scenario is over: stop stepping and shut the node down (in lock-step after a second of
  /// wall time, so that observers such as a recorder receive the last messages first).
  virtual void finish();
  /// Before time starts: the clock goes on from `t` (a restarted plant's checkpoint), so that
  /// its first step is t + step and /clock never goes back. Only a clock the plant owns moves.
  virtual void resumeAt(const ros::Time& /*t*/) {}

 protected:
  virtual const char* mode() const = 0;
};

/// Whether a periodic action last done at `last` (zero: never) is due again at `now`, also after
/// ROS time jumped back (a replayed or restarted clock).
bool periodDue(const ros::Time& last, const ros::Time& now, double period);

/// The clock `parameters` choose for the plant whose private handle is pnh (its namespace names
/// it in lock-step). The participants are <ns>/lockstep/participants. Time starts once
/// wait_for_subscribers nodes read `state`, something publishes on `actuators` and every listed
/// participant has joined, or after start_timeout with a warning.
/// @throw std::invalid_argument on a bad participants list, naming it.
std::unique_ptr<PlantClock> makePlantClock(ros::NodeHandle nh, const ros::NodeHandle& pnh,
                                           const config::PlantLoopParameters& parameters,
                                           PlantClock::Tick tick, const ros::Publisher& state,
                                           const ros::Subscriber& actuators);

}  // namespace spherical_robots
