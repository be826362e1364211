#pragma once
// What real velocity-controlled actuators do to their set-points, without ROS: velocity and
// acceleration limits, and a command-timeout watchdog that brings them to rest when commands stop.

#include <string>
#include <vector>

namespace spherical_robots::hardware {

struct ActuatorLimits {
  double max_velocity = 10.0;      ///< |rate| limit [rad/s] > 0
  double max_acceleration = 20.0;  ///< |d rate/dt| limit [rad/s^2] > 0
};

class SimulatedActuators {
 public:
  /// @param command_timeout [s] > 0: with no accepted command for this long, set-points become 0.
  /// @throw std::invalid_argument on empty names, a size mismatch, or non-positive/non-finite limits.
  SimulatedActuators(std::vector<std::string> names, std::vector<ActuatorLimits> limits,
                     double command_timeout);

  /// Accepts set-points [rad/s] by actuator name at time t [s]. Returns an empty string if
  /// accepted, else the reason (unknown name, non-finite value, names/values size mismatch); a
  /// rejected command changes nothing. Names not mentioned keep their set-point.
  std::string command(const std::vector<std::string>& names, const std::vector<double>& velocities,
                      double t);

  /// Advances the measured state to time t [s] (t never goes back; an earlier t is ignored):
  /// velocities ramp towards the clamped set-points under the acceleration limit and positions
  /// integrate them.
  void update(double t);

  /// Stops everything now (e-stop): set-points and velocities become 0 until the next command.
  void stop();

  const std::vector<std::string>& names() const { return names_; }
  const std::vector<double>& velocities() const { return velocities_; }
  const std::vector<double>& positions() const { return positions_; }
  const std::vector<double>& setpoints() const { return setpoints_; }
  bool timedOut() const { return timed_out_; }

 private:
  std::vector<std::string> names_;
  std::vector<ActuatorLimits> limits_;
  double command_timeout_;
  std::vector<double> setpoints_;
  std::vector<double> velocities_;
  std::vector<double> positions_;
  double last_command_time_ = 0.0;
  double last_update_time_ = 0.0;
  bool has_command_ = false;
  bool timed_out_ = false;
};

}  // namespace spherical_robots::hardware
