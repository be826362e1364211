#pragma once
// What real actuators do to their set-points, without ROS. A velocity actuator follows a rate
// set-point within velocity and acceleration limits; an effort actuator (a torque- or
// force-controlled motor) applies an effort set-point within its effort limit. A command-timeout
// watchdog brings them to a safe state (rest, zero effort) when commands stop, and an e-stop latch; optionally (ActuatorModel, all off by default) a first-order lag, a dead
// time, encoder quantisation and velocity measurement noise. The true state is advanced exactly
// (closed form between events), so it does not depend on how often update() is called; the
// reported measurement (quantisation, noise) is derived from it and never fed back.

#include <cstdint>
#include <deque>
#include <random>
#include <string>
#include <vector>

namespace spherical_robots::hardware {

/// What an actuator's set-point is.
enum class ActuatorKind {
  Velocity,  ///< a rate [rad/s or m/s]; the actuator integrates its position
  Effort,    ///< an effort [N m or N]; its motion is the load's (the plant's), not known here
};

struct ActuatorLimits {
  double max_velocity = 10.0;      ///< velocity actuators: |rate| limit [rad/s], finite and > 0
  double max_acceleration = 20.0;  ///< velocity actuators: |d rate/dt| limit [rad/s^2], finite, > 0
  double max_effort = 10.0;        ///< effort actuators: |effort| limit [N m or N], finite and > 0
  ActuatorKind kind = ActuatorKind::Velocity;
};

/// Non-ideal behaviour of one actuator. Every field is finite and >= 0; 0 switches it off, and all
/// of them 0 (the default) is the ideal actuator (only ActuatorLimits and the watchdog act).
struct ActuatorModel {
  /// First-order lag [s]: dv/dt = clamp((u - v) / time_constant, ±max_acceleration), u the active
  /// set-point. 0: v ramps to u at exactly max_acceleration (the lag's limit as tau -> 0).
  /// For an effort actuator the applied effort lags: de/dt = (u - e) / time_constant; 0: e = u.
  double time_constant = 0.0;
  /// [s] an accepted set-point becomes active this long after it was commanded (the watchdog and
  /// the e-stop are not delayed).
  double dead_time = 0.0;
  /// [rad] the reported position is the true one rounded to a multiple of this.
  double position_resolution = 0.0;
  /// [rad/s] standard deviation of the Gaussian noise added to the reported velocity.
  double velocity_noise = 0.0;
};

/// A set-point beyond this many times its actuator's limit is not clamped but rejected: it is no
/// set-point a controller meant (an overflow, a unit error, a hostile sender).
constexpr double kImplausibleFactor = 100.0;

/// A set of velocity-controlled actuators. Times are in seconds on any monotonic clock (the node
/// passes ROS time); the first time seen starts the clock. A time earlier than the latest one seen
/// is treated as that latest time: the state never runs backwards.
class SimulatedActuators {
 public:
  /// @param names actuator names, non-empty, unique, none empty.
  /// @param limits one entry per name.
  /// @param command_timeout [s], finite and > 0: with no accepted command for this long the
  ///        set-points become 0: velocity actuators ramp to rest under their acceleration limits,
  ///        effort actuators drop to zero effort at once (whatever their lag).
  /// @param models one entry per name, or empty: every actuator ideal.
  /// @param noise_seed seeds the std::mt19937 of the velocity noise: the same seed and the same
  ///        sequence of calls give the same measurements.
  /// @throw std::invalid_argument naming the offending argument and value: empty or duplicate
  ///        names, a size mismatch, non-positive or non-finite limits or timeout, negative or
  ///        non-finite model fields (naming actuator and field).
  SimulatedActuators(std::vector<std::string> names, std::vector<ActuatorLimits> limits,
                     double command_timeout, std::vector<ActuatorModel> models = {},
                     std::uint32_t noise_seed = 0);

  /// Accepts set-points by actuator name at time t [s]: rates [rad/s] for velocity actuators,
  /// efforts [N m or N] for effort actuators. The state is first advanced to t with the previous
  /// set-points; each set-point is then clamped to ±max_velocity or ±max_effort and the watchdog
  /// restarts at t. Names not mentioned keep their set-point. With a dead time the
  /// set-point becomes active dead_time after t (activeSetpoints()); setpoints() shows it at once.
  /// @return an empty string if accepted, else the reason (e-stop engaged, no names, names/values
  ///         size mismatch, unknown or duplicate name, non-finite value or time, a value beyond
  ///         kImplausibleFactor times its limit). A rejected
  ///         command changes nothing, not even the watchdog or the clock.
  std::string command(const std::vector<std::string>& names, const std::vector<double>& setpoints,
                      double t);

  /// Advances the state to time t [s]: velocities ramp towards the active set-points at exactly
  /// max_acceleration (or follow them through the lag), positions [rad] integrate the velocities,
  /// delayed set-points become active at their time, and at the watchdog deadline (last accepted
  /// command + command_timeout) every set-point, active and pending, becomes 0. A new measurement
  /// is taken when the clock starts or advances. A non-finite t or one not later than the latest
  /// time seen is ignored.
  void update(double t);

  /// Brings everything to rest now (after advancing to t [s], if t is later than the latest time
  /// seen): set-points (pending ones too), velocities and efforts become 0 at once, positions
  /// hold, until the next command. A new measurement is taken.
  void stop(double t);

  /// The clock jumped to t [s] (core/clock_jump.hpp: a stray /clock, a replay looping back):
  /// continues from t with the state as it is and no time elapsed. The watchdog keeps the age of
  /// the last command and delayed set-points their delay, so neither fires early nor freezes
  /// until the clock catches up with a time it jumped to. A new measurement is taken. A
  /// non-finite t is ignored; before the first time seen it starts the clock, as update().
  void rebase(double t);

  /// Replaces the limits and the watchdog's timeout at time t [s] (after advancing to t), as
  /// dynamic_reconfigure asks: set-points beyond a lowered limit are clamped to it, and a velocity
  /// beyond it ramps down at the new acceleration limit, never jumps. The watchdog deadline moves
  /// with the timeout (last accepted command + the new timeout).
  /// @throw std::invalid_argument, with nothing changed, as the constructor for limits and timeout,
  ///        or if an actuator's kind would change.
  void setLimits(const std::vector<ActuatorLimits>& limits, double command_timeout, double t);

  /// Engages (stop(t), then every command is rejected) or releases the e-stop latch. Releasing
  /// leaves the actuators at rest; they move again on the next accepted command.
  void setEStop(bool engaged, double t);

  const std::vector<std::string>& names() const { return names_; }
  const std::vector<ActuatorLimits>& limits() const { return limits_; }
  const std::vector<ActuatorModel>& models() const { return models_; }
  double commandTimeout() const { return command_timeout_; }
  /// The latest time seen [s] (0 before the first).
  double now() const { return now_; }
  /// True state, used for the integration.
  const std::vector<double>& velocities() const { return velocities_; }  ///< [rad/s]
  const std::vector<double>& positions() const { return positions_; }    ///< [rad], from 0
  /// Applied efforts [N m or N]: the (lagged) set-points of effort actuators, 0 for velocity ones.
  const std::vector<double>& efforts() const { return efforts_; }
  /// Velocities and positions of effort actuators stay 0: the load's motion is the plant's.
  /// The reported measurement, taken at the latest update() or stop(): the true position rounded
  /// to position_resolution, the true velocity plus noise (not differenced from the quantised
  /// positions, so it does not depend on the update rate). Equal to the true state when the
  /// model is off.
  const std::vector<double>& measuredVelocities() const { return measured_velocities_; }
  const std::vector<double>& measuredPositions() const { return measured_positions_; }
  /// Latest accepted set-points, clamped [rad/s or N m, N].
  const std::vector<double>& setpoints() const { return setpoints_; }
  /// The set-points the actuators follow now: setpoints() delayed by the dead time [rad/s].
  const std::vector<double>& activeSetpoints() const { return active_setpoints_; }
  /// How many accepted set-points of each actuator were clamped to its limit.
  const std::vector<unsigned long>& saturations() const { return saturations_; }
  /// Time [s] since the last accepted command, at the latest time seen; NaN before the first.
  double commandAge() const;
  /// True from the watchdog deadline until the next accepted command.
  bool timedOut() const { return timed_out_; }
  /// timedOut(), with every set-point already 0 at the deadline: the last command asked for
  /// rest, so the watchdog stopped nothing. A controller that has finished and falls silent is
  /// idle, not lost.
  bool timedOutAtRest() const { return timed_out_ && timed_out_at_rest_; }
  bool eStopped() const { return e_stopped_; }
  /// True once any command has been accepted.
  bool hasCommand() const { return has_command_; }

 private:
  struct Pending {
    double time;   ///< [s] when it becomes active
    double value;  ///< clamped set-point [rad/s]
  };

  /// @throw std::invalid_argument naming the actuator and the value unless there is one entry
  ///        per actuator, of its kind, with every limit and the timeout finite and > 0.
  void requireValidLimits(const std::vector<ActuatorLimits>& limits, double command_timeout) const;
  /// Advances velocities and positions by dt [s] >= 0 towards the active set-points.
  void integrate(double dt);
  /// Effort actuators without lag apply their active set-point at once.
  void applyInstantEfforts();
  /// Sets every set-point, active and pending, to 0, and every effort.
  void zeroSetpoints();
  /// Recomputes the measurement from the true state, drawing fresh noise.
  void measure();

  std::vector<std::string> names_;
  std::vector<ActuatorLimits> limits_;
  double command_timeout_;
  std::vector<ActuatorModel> models_;
  std::vector<double> setpoints_;
  std::vector<double> active_setpoints_;
  std::vector<std::deque<Pending>> pending_;  ///< per actuator, in time order
  std::vector<double> velocities_;
  std::vector<double> positions_;
  std::vector<double> efforts_;
  std::vector<unsigned long> saturations_;
  std::vector<double> measured_velocities_;
  std::vector<double> measured_positions_;
  std::mt19937 noise_engine_;
  std::normal_distribution<double> unit_normal_{0.0, 1.0};
  double last_command_time_ = 0.0;
  double now_ = 0.0;  ///< latest time seen [s]; meaningless until clock_started_
  bool clock_started_ = false;
  bool has_command_ = false;
  bool timed_out_ = false;
  bool timed_out_at_rest_ = false;
  bool e_stopped_ = false;
};

}  // namespace spherical_robots::hardware
