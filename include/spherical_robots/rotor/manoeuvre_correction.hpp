#pragma once
// Closing the loop over whole manoeuvres of the two-rotor sphere: a plan (Svinin et al.) is open
// loop, so a run ends off its target by whatever the rotors did not do exactly; measuring where
// the sphere came to rest and planning again from there corrects it. No ROS.
//
// Every plan starts and ends at rest with the contact at the sphere's south pole
// (u_o = v_o = 0), where the attitude is R_zᵀ(ψ) (eq 2). The rotor speeds that trace a plan do
// not depend on the contact point on the plane nor on ψ (eq 11: ω turns with R_zᵀ(ψ)), and the
// plane displacement turns with ω (eqs 6-7), so a plan for (u, v, ψ) traced from a rest pose
// (u_0, v_0, ψ_0) ends at (u_0, v_0) + R_zᵀ(ψ_0) (u, v) with contact angle ψ_0 + ψ.
// A figure eight is a closed curve on the sphere: it returns the contact to the point of the
// sphere it started from. A run that ends with the contact off the south pole (u_o, v_o ≠ 0, a
// tilt) needs an open curve back to the pole first: PoleReturnArc.
// Lengths in units of R.

#include <Eigen/Geometry>

#include "spherical_robots/rotor/contact_curve.hpp"
#include "spherical_robots/rotor/dynamic_realizability.hpp"
#include "spherical_robots/rotor/plan_execution.hpp"

namespace spherical_robots::rotor {

/// The sphere at rest with its contact at the south pole: the contact point (u_a, v_a) [R] on
/// the plane and the contact angle ψ [rad]; the attitude is R_zᵀ(ψ).
using RestPose = PlaneState;

/// What a plan is asked to do (PlanRequest's u_a, v_a [R], ψ [rad]): the rest it reaches from
/// the zero state.
using PlanTarget = PlaneState;

/// Where a plan for `target`, traced from `start`, ends. @throw std::invalid_argument on a
/// non-finite input.
RestPose planEnd(const RestPose& start, const PlanTarget& target);

/// The plan target that takes the sphere from `from` to `to` (the inverse of planEnd), the turn
/// ψ wrapped into (−π, π]: the attitude at rest only fixes ψ modulo 2π.
/// @throw std::invalid_argument on a non-finite input.
PlanTarget correctionTarget(const RestPose& from, const RestPose& to);

/// The rest pose of a measured sphere: contact point (centre_x, centre_y) / R on the plane and
/// ψ from the attitude's twist about the vertical (the swing-twist decomposition; exact for an
/// attitude R_zᵀ(ψ), and for a small tilt off the south pole the nearest such attitude up to
/// second order in the tilt), in (−π, π].
/// @throw std::invalid_argument on a non-finite input, radius <= 0, an attitude not of norm 1
///        within 1e-3 (an unset, all-zero one), or one whose vertical axis is turned upside down
///        (no twist to take: |q_w|, |q_z| both ~0).
RestPose measuredRestPose(double centre_x, double centre_y, double radius,
                          const Eigen::Quaterniond& attitude);

/// (u_o, v_o) [rad] of the sphere's point touching the plane (eqs 24-25) for an attitude of Σ_o
/// in Σ_a: the plane's downward normal seen from Σ_o.
/// @throw std::invalid_argument on an attitude not finite and of norm 1 within 1e-3, or a contact
///        on or above the equator.
Eigen::Vector2d measuredContactAngles(const Eigen::Quaterniond& attitude);

/// The great-circle arc on the sphere from the contact point (u_o, v_o) back to the south pole,
/// at uniform speed over θ ∈ [0, 2π] (so CurveTiming with one step times it).
class PoleReturnArc {
 public:
  /// @throw std::invalid_argument unless (u_o, v_o) is finite with the contact below the
  ///        equator (cos u_o cos v_o > 0).
  PoleReturnArc(double u_o, double v_o);

  /// Length of the arc [rad] (its angle at the centre); 0 at the pole.
  double angle() const { return angle_; }
  /// c(θ) and c_θ for θ in [0, 2π]; outside, the end point with c_θ = 0.
  CurvePoint at(double theta) const;

 private:
  Eigen::Vector3d start_;
  Eigen::Vector3d axis_;  ///< start × south pole, normalised: the arc turns about it
  double angle_;
};

/// The rotor set-point [rad/s] at arc parameter θ ∈ [0, 2π] advancing at θ̇ [rad/s]: eq 11
/// (rotorSpeeds) on curveAngularVelocity, as planSetPoint does for a figure eight.
/// @throw std::invalid_argument as rotorSpeeds().
RotorSpeeds arcSetPoint(double k, double inertia_scale, const PoleReturnArc& arc, double theta,
                        double theta_rate);

/// arcSetPoint at time t of a one-step timing.
/// @throw std::invalid_argument as arcSetPoint(), or unless timing has one step.
RotorSpeeds arcSetPointAt(double k, double inertia_scale, const PoleReturnArc& arc,
                          const CurveTiming& timing, double t);

}  // namespace spherical_robots::rotor
