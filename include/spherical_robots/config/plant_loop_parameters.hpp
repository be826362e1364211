#pragma once
// The parameters every plant node's loop shares (PlantLoop, its timeline and its clock; the table
// is docs/nodes.md, "Plant loop and clock"), loaded and checked in one place.

#include <string>

#include "spherical_robots/config/parameter_source.hpp"
#include "spherical_robots/core/clock_jump.hpp"
#include "spherical_robots/core/loop_cpu.hpp"

namespace spherical_robots::config {

/// What drives a plant's steps (docs/lockstep.md).
enum class ClockMode { kLockstep, kFree, kRos };

/// @throw std::invalid_argument unless name is lockstep, free or ros.
ClockMode clockModeFromString(const std::string& name);

struct PlantLoopParameters {
  double step = 0.01;           ///< [s] the tick and the integration step
  double publish_rate = 50.0;   ///< [Hz] of what the plant publishes periodically
  double state_timeout = 0.5;   ///< [s] older actuator states count as stale
  double trail_period = 0.0;    ///< [s] between trail points; 0: the plant has no trail
  double duration = 0.0;        ///< [s] of ROS time after the first tick; 0 (or less): forever
  double max_clock_step = kDefaultMaxClockStep;  ///< [s] a longer forward step is a jump
  ClockMode clock = ClockMode::kRos;
  /// lockstep: a cap on the pace [x real time], 0 = none; free: the pace, > 0.
  double speedup = 0.0;
  /// lockstep only: "" this plant owns /clock, else the absolute namespace of the stack that does.
  std::string lockstep_leader;
  double lockstep_timeout = 2.0;  ///< [s] of wall time (lockstep): a silent participant is dropped
  /// lockstep: /clock messages per second of wall time at most (core/clock_publication.hpp);
  /// 0: one every step.
  double clock_rate = 1000.0;
  /// lockstep: the CPU the loop runs on (core/loop_cpu.hpp): auto, none or a CPU number.
  LoopCpuSetting loop_cpu;
  int wait_for_subscribers = 1;   ///< time starts once this many nodes read the plant's state
  double start_timeout = 10.0;    ///< [s] of wall time: time starts anyway, with a warning
  /// Where the stack's root frame (<ns>/odom; the FreeBOT's base) is in map: several robots on
  /// one master side by side.
  double origin_x = 0.0;    ///< [m]
  double origin_y = 0.0;    ///< [m]
  double origin_yaw = 0.0;  ///< [rad]
  /// Where the plant keeps the checkpoint a restarted plant resumes from: "none" (it keeps
  /// none), "ros_home" ($ROS_HOME/checkpoints) or an absolute directory.
  std::string checkpoint = "none";
};

/// The plant's private parameters over `defaults` (each plant's: step, state_timeout,
/// trail_period, and speedup as the pace of clock free). Keys: step, publish_rate,
/// state_timeout, trail_period (only if the default has a trail), duration, max_clock_step,
/// clock (lockstep | free | ros, "ros"), speedup (lockstep: default 0, >= 0; free: > 0),
/// lockstep_leader, lockstep_timeout (default 2 s, 1 s with a leader: a follower drops its own
/// silent participant before the leader would drop the follower), clock_rate (>= 0, default
/// 1000 Hz) and loop_cpu (auto, none or a CPU number; default auto), read in lockstep only,
/// wait_for_subscribers
/// (integer >= 0), start_timeout, origin_x, origin_y, origin_yaw (finite), checkpoint (none,
/// ros_home or an absolute directory).
/// @throw std::invalid_argument naming the origin, the key, the value and the limit.
PlantLoopParameters loadPlantLoopParameters(const ParameterSource& source,
                                            const PlantLoopParameters& defaults);

}  // namespace spherical_robots::config
