#pragma once
// What real velocity-controlled actuators do to their set-points, without ROS: velocity and
// acceleration limits, a command-timeout watchdog that brings them to rest when commands stop,
// and an e-stop latch. The state is advanced exactly (piecewise-constant acceleration), so the
// result does not depend on how often update() is called.

#include <string>
#include <vector>

namespace spherical_robots::hardware {

struct ActuatorLimits {
  double max_velocity = 10.0;      ///< |rate| limit [rad/s], finite and > 0
  double max_acceleration = 20.0;  ///< |d rate/dt| limit [rad/s^2], finite and > 0
};

/// A set of velocity-controlled actuators. Times are in seconds on any monotonic clock (the node
/// passes ROS time); the first time seen starts the clock. A time earlier than the latest one seen
/// is treated as that latest time: the state never runs backwards.
class SimulatedActuators {
 public:
  /// @param names actuator names, non-empty, unique, none empty.
  /// @param limits one entry per name.
  /// @param command_timeout [s], finite and > 0: with no accepted command for this long the
  ///        set-points become 0 and the actuators ramp to rest under their acceleration limits.
  /// @throw std::invalid_argument naming the offending argument and value: empty or duplicate
  ///        names, a size mismatch, non-positive or non-finite limits or timeout.
  SimulatedActuators(std::vector<std::string> names, std::vector<ActuatorLimits> limits,
                     double command_timeout);

  /// Accepts rate set-points [rad/s] by actuator name at time t [s]. The state is first advanced
  /// to t with the previous set-points; each set-point is then clamped to ±max_velocity and the
  /// watchdog restarts at t. Names not mentioned keep their set-point.
  /// @return an empty string if accepted, else the reason (e-stop engaged, no names, names/values
  ///         size mismatch, unknown or duplicate name, non-finite value or time). A rejected
  ///         command changes nothing, not even the watchdog or the clock.
  std::string command(const std::vector<std::string>& names, const std::vector<double>& velocities,
                      double t);

  /// Advances the measured state to time t [s]: velocities ramp towards the set-points at exactly
  /// max_acceleration, positions [rad] integrate the velocities, and at the watchdog deadline
  /// (last accepted command + command_timeout) the set-points become 0. A non-finite t or one
  /// earlier than the latest time seen is ignored.
  void update(double t);

  /// Brings everything to rest now (after advancing to t [s], if t is later than the latest time
  /// seen): set-points and velocities become 0 at once, positions hold, until the next command.
  void stop(double t);

  /// Engages (stop(t), then every command is rejected) or releases the e-stop latch. Releasing
  /// leaves the actuators at rest; they move again on the next accepted command.
  void setEStop(bool engaged, double t);

  const std::vector<std::string>& names() const { return names_; }
  const std::vector<ActuatorLimits>& limits() const { return limits_; }
  double commandTimeout() const { return command_timeout_; }
  const std::vector<double>& velocities() const { return velocities_; }  ///< [rad/s]
  const std::vector<double>& positions() const { return positions_; }    ///< [rad], from 0
  const std::vector<double>& setpoints() const { return setpoints_; }    ///< clamped [rad/s]
  /// True from the watchdog deadline until the next accepted command.
  bool timedOut() const { return timed_out_; }
  bool eStopped() const { return e_stopped_; }
  /// True once any command has been accepted.
  bool hasCommand() const { return has_command_; }

 private:
  /// Advances velocities and positions by dt [s] >= 0 towards the current set-points.
  void integrate(double dt);

  std::vector<std::string> names_;
  std::vector<ActuatorLimits> limits_;
  double command_timeout_;
  std::vector<double> setpoints_;
  std::vector<double> velocities_;
  std::vector<double> positions_;
  double last_command_time_ = 0.0;
  double now_ = 0.0;  ///< latest time seen [s]; meaningless until clock_started_
  bool clock_started_ = false;
  bool has_command_ = false;
  bool timed_out_ = false;
  bool e_stopped_ = false;
};

}  // namespace spherical_robots::hardware
