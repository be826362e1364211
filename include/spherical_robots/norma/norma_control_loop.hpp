#pragma once
// Norma's controller run as a sampled loop over time, with time as a number (no ROS): the path
// clock of eq 52 (from the first state, or from a start kept across a restart of the
// controller, so that a respawned one follows the run's path, not a new one), the three PID integrals (Fig. 5) advanced by the time
// between states, and the rules that keep them sane when the input or the actuators misbehave.
//
// * Validate before update: a state that is non-finite, implausible or would give a non-finite
//   command changes nothing (path clock, integrals, last output), so a burst of bad states
//   cannot push the loop off its path.
// * Anti-windup (conditional integration): an integral is held while its effort is saturated at
//   the actuator's limit and its integrand pushes further into the limit, and all of them while
//   the actuators report that they apply nothing of a non-zero command (e-stop, watchdog), so
//   releasing an e-stop resumes tracking instead of firing a wound-up effort.

#include <Eigen/Core>
#include <optional>

#include "spherical_robots/norma/norma_controller.hpp"

namespace spherical_robots::norma {

/// The efforts the actuators can apply: |T| <= max_torque [N m], |F| <= max_force [N].
struct EffortLimits {
  double max_torque = 20.0;
  double max_force = 200.0;
};

/// What the loop is fed at each sample: the plant's generalised coordinates and rates and the
/// contact point and heading.
struct NormaMeasurement {
  Vector4 q = Vector4::Zero();   ///< θ, α [rad], φ [rad], δ [m]
  Vector4 qd = Vector4::Zero();  ///< their rates [rad/s, m/s]
  double x = 0.0, y = 0.0;       ///< contact point [m]
  double psi = 0.0;              ///< heading [rad]
};

/// Plausibility bounds of a measurement: beyond them it is no state of this robot.
struct NormaStateBounds {
  double position = 1e3;  ///< |X|, |Y| [m]
  double angle = 1e6;     ///< |θ|, |α|, |ψ| [rad] (they wind up over a run)
  double rate = 1e3;      ///< |q̇_i| [rad/s, m/s]
};

class NormaControlLoop {
 public:
  /// @param max_gap [s] > 0: a longer gap between two states is not integrated.
  /// @param jump_back [s] > 0: a state earlier than the last one by more than this comes from a
  ///        clock that went back (a replay looping, a restarted plant); by less, it is out of order.
  /// @throw std::invalid_argument on non-positive or non-finite limits, gap or jump, naming them.
  NormaControlLoop(NormaController controller, EffortLimits limits, double max_gap = 0.1,
                   double jump_back = 1.0, NormaStateBounds bounds = {});

  /// The command for the state measured at t [s]. The first state, or one more than jump_back
  /// earlier than the last accepted one, restarts the integrals, and the path clock from t
  /// unless it was given (startPathAt).
  /// @throw std::invalid_argument naming the problem (non-finite or implausible t or state, a
  ///        state not later than the last one but within jump_back of it, or a non-finite
  ///        command); nothing changes then.
  ControlOutput step(double t, const NormaMeasurement& state);

  /// The efforts the actuators report applying [N m, N]; non-finite reports are ignored.
  void actuatorsApplied(double torque, double force);

  /// True while the actuators apply nothing of the last non-zero command (the integrals hold).
  bool actuatorsStopped() const;
  /// Integral i is held for the next step (saturation or stopped actuators).
  bool integralHeld(int i) const;

  /// The desired point of eq 52 at t [s] on this loop's path clock (t − the path's start).
  PathPoint reference(double t) const;
  /// The path of eq 52 starts at t0 [s] (the run's, which a respawned controller was given),
  /// whatever the time of the first state. @throw std::invalid_argument if t0 is not finite.
  void startPathAt(double t0);
  /// [s] when the path started; none before the first state unless startPathAt was called.
  std::optional<double> pathStart() const;
  const Eigen::Vector3d& integrals() const { return integrals_; }
  const ControlOutput& lastOutput() const { return last_output_; }
  const NormaController& controller() const { return controller_; }
  /// New gains from the next step on; the integrals and the path clock go on.
  /// @throw std::invalid_argument as norma::validate(), with the gains unchanged.
  void setGains(const ControllerGains& gains) { controller_.setGains(gains); }
  const EffortLimits& limits() const { return limits_; }
  bool started() const { return started_; }

 private:
  void validate(double t, const NormaMeasurement& state) const;

  NormaController controller_;
  EffortLimits limits_;
  double max_gap_;
  double jump_back_;
  NormaStateBounds bounds_;
  bool started_ = false;
  double path_start_ = 0.0;
  bool path_start_given_ = false;
  double last_t_ = 0.0;
  Eigen::Vector3d integrals_ = Eigen::Vector3d::Zero();
  ControlOutput last_output_;
  double applied_torque_ = 0.0;
  double applied_force_ = 0.0;
  bool applied_known_ = false;
};

}  // namespace spherical_robots::norma
