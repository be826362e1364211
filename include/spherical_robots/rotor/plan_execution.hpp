#pragma once
// Executing a figure-eight plan through the two rotors (Svinin et al., eq 11) and the plant that
// rolls the sphere from measured rotor speeds (eqs 6-10 with eq 11 solved for ω). No ROS.
//
// The rotor speeds that realize the curve do not depend on the heading ψ nor on the contact
// point on the plane: ω turns with R_zᵀ(ψ) and diag(k, k, 1) commutes with it (eq 11), so a
// set-point is a function of the curve parameter θ and its rate only. Tracing is
// reparameterisation invariant (eqs 28-30), so any θ(t) from 0 to 2πn reaches the plan's end;
// CurveTiming starts and ends at rest so that rate-limited rotors can follow.
// Lengths in units of R, times in s, rotor speeds in rad/s.

#include <functional>

#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/dynamic_realizability.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"

namespace spherical_robots::rotor {

/// θ(t) over n steps: θ̇ rises from 0 to max_rate along sin² over ramp_time, holds, and falls
/// back to 0 along sin² over ramp_time, reaching θ = 2πn at duration() (θ̇ and θ̈ continuous at
/// the ends of the cruise; θ̈ ≤ π max_rate / (2 ramp_time)).
class CurveTiming {
 public:
  /// @throw std::invalid_argument unless steps >= 1, max_rate > 0, ramp_time >= 0 (finite), and
  ///        the ramps fit: max_rate ramp_time <= 2πn.
  CurveTiming(int steps, double max_rate, double ramp_time);

  int steps() const { return steps_; }
  double maxRate() const { return max_rate_; }
  /// 2πn / max_rate + ramp_time [s].
  double duration() const;
  /// θ(t) [rad] for any finite t, clamped to [0, 2πn] outside [0, duration()].
  double theta(double t) const;
  /// θ̇(t) [rad/s], 0 outside [0, duration()].
  double rate(double t) const;

 private:
  int steps_;
  double max_rate_;
  double ramp_time_;
};

/// The plan's rotor set-point [rad/s] at execution parameter θ ∈ [0, 2πn] advancing at rate θ̇
/// [rad/s]: eq 11 (rotorSpeeds) on curveAngularVelocity. Within a step (θ mod 2π; θ = 2πj for
/// j >= 1 is the end of step j) the first leaf takes θ ∈ [0, 2πa/(a + b)] and the second the
/// rest, each mapped linearly onto its FigureEight interval, so the contact moves at (a + b) θ̇
/// on both leaves and the set-points are continuous at the pole (the FigureEight's own θ,
/// circle angle 2θ on each leaf, would step them by the ratio b/a there).
/// @throw std::invalid_argument as rotorSpeeds(), or if θ is outside [0, 2πn] or steps < 1.
RotorSpeeds planSetPoint(double k, double inertia_scale, const FigureEight& curve, int steps,
                         double theta, double theta_rate);

/// The set-point at time t [s] of executing the plan with a timing.
RotorSpeeds planSetPointAt(double k, double inertia_scale, const FigureEight& curve,
                           const CurveTiming& timing, double t);

/// Rotor set-points [rad/s] against execution time t [s]: a plan's (planSetPointAt) or another
/// manoeuvre's (manoeuvre_correction.hpp's arcSetPointAt), bound to its curve and timing.
using SetPointSchedule = std::function<RotorSpeeds(double t)>;

/// The set-point at time t that makes rotors with a first-order lag of time_constant τ [s] >= 0
/// follow a schedule: the lag's inverse u = φ̇ + τ φ̈, φ̈ by a forward difference over h [s] > 0
/// (the command period: u held over [t, t + h] brings the lagged speed to φ̇(t + h)). Dead time
/// needs nothing: a delay only reparameterises the curve. τ = 0: the schedule itself.
/// @throw std::invalid_argument as the schedule or on a bad τ or h.
RotorSpeeds lagCompensatedSetPoint(const SetPointSchedule& schedule, double t,
                                   double time_constant, double h);

/// The largest |φ̇_i| [rad/s] of a manoeuvre traced at θ̇ = 1 rad/s (speeds scale with θ̇):
/// at_unit_rate(θ) gives the set-point at θ ∈ [0, 2π], sampled at 4001 θ.
double peakRotorSpeed(const std::function<RotorSpeeds(double theta)>& at_unit_rate);

/// peakRotorSpeed of one step of a figure eight (2000 θ per leaf).
double peakRotorSpeed(double k, double inertia_scale, const FigureEight& curve);

/// The plant: contact-coordinate rates for measured rotor speeds (eq 11 solved for ω, then
/// eqs 6-10). @throw std::invalid_argument as rotorAngularVelocity() and contactRates().
ContactRates plantRates(double k, double inertia_scale, const ContactCoordinates& coordinates,
                        const RotorSpeeds& speeds);

/// Rolls the plant for duration [s] >= 0 with the rotor speeds held, by fixed RK4 steps of at
/// most step [s] > 0. @throw std::invalid_argument on a bad duration or step, as plantRates(),
/// or if the state leaves the band |v_o| < π/2.
ContactCoordinates advancePlant(double k, double inertia_scale, const ContactCoordinates& start,
                                const RotorSpeeds& speeds, double duration, double step);

/// Open-loop execution from the zero state: the plant driven by the plan's set-points over
/// timing.duration() plus settle [s] >= 0 of rest. period = 0: the set-point follows θ(t)
/// continuously (Dormand-Prince 5(4), tolerance 1e-12); period > 0: it is sampled every period
/// and held (zero-order hold, as a ROS loop streams it), the plant integrated by RK4 at
/// min(period, 1 ms) per hold. @throw std::invalid_argument on bad arguments.
ContactCoordinates executePlan(double k, double inertia_scale, const FigureEight& curve,
                               const CurveTiming& timing, double period, double settle = 0.0);

}  // namespace spherical_robots::rotor
