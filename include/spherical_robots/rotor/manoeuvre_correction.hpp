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
// Lengths in units of R.

#include <Eigen/Geometry>

namespace spherical_robots::rotor {

/// The sphere at rest with its contact at the south pole: the contact point (u_a, v_a) [R] on
/// the plane and the contact angle ψ [rad]; the attitude is R_zᵀ(ψ).
struct RestPose {
  double u_a = 0.0;
  double v_a = 0.0;
  double psi = 0.0;
};

/// What a plan is asked to do from the zero state (PlanRequest's u_a, v_a [R], ψ [rad]).
struct PlanTarget {
  double u_a = 0.0;
  double v_a = 0.0;
  double psi = 0.0;
};

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
/// @throw std::invalid_argument on a non-finite input, radius <= 0, or an attitude whose
///        vertical axis is turned upside down (no twist to take: |q_w|, |q_z| both ~0).
RestPose measuredRestPose(double centre_x, double centre_y, double radius,
                          const Eigen::Quaterniond& attitude);

}  // namespace spherical_robots::rotor
