#pragma once
// n-step motion planning of the two-rotor sphere with spherical figure eights (Svinin et al.,
// eqs 31-34): find every (a, b, γ) with radii up to a limit such that tracing the figure eight n
// times moves the contact point from the origin to (u_a, v_a)_des and the heading to ψ_des.
// Lengths in units of R. No ROS.
//
// After one step the contact is back at the south pole with heading η, so step j's shift is the
// first one turned by −jη (eqs 28-29) and P_0 … P_n lie on a circle (Fig. 4). Hence
//   η(a, b) = ψ_des / n                                              (eq 32)
//   h(a, b) = |sin(η/2) / sin(nη/2)| h_des                            (eq 33, corrected; errata S3)
// and rotating the curve by γ about the sphere's z axis turns the whole plane path by +γ, which
// points the total shift at the target.

#include <string>
#include <vector>

namespace spherical_robots::rotor {

struct PlanRequest {
  double k = 0.0;          ///< inertia ratio, >= 0
  int steps = 1;           ///< n >= 1
  double u_a = 0.0;        ///< target [R]
  double v_a = 0.0;        ///< target [R]
  double psi = 0.0;        ///< target heading [rad], accumulated (not reduced mod 2π)
  double max_radius = 0.7;  ///< largest circle radius a, b [R], in (0, kMaxCircleRadius)
  int heading_turns = 0;   ///< also plan for ψ + 2πm, |m| <= heading_turns (>= 0)
};

/// Upper bounds of a request, so that no request can block a planner for seconds (one plan costs
/// milliseconds per heading turn and step): n <= 20 steps, |m| <= 10 heading turns, k <=
/// kMaxInertiaRatio, |u_a|, |v_a| <= 1000 R, |ψ| <= 1000 rad.
constexpr int kMaxSteps = 20;
constexpr int kMaxHeadingTurns = 10;
constexpr double kMaxTargetDistance = 1000.0;
constexpr double kMaxTargetHeading = 1000.0;

struct RotorPlan {
  double a = 0.0;            ///< first circle's Euclidean radius [R]
  double b = 0.0;            ///< second circle's Euclidean radius [R]
  double gamma = 0.0;        ///< orientation of the figure eight [rad], in (−π, π]
  double psi = 0.0;          ///< heading the plan reaches [rad] (ψ_des + 2πm)
  double length = 0.0;       ///< contact path length on the sphere over n steps [R]
  double final_error = 0.0;  ///< max |target − reached| over (u_a, v_a, ψ), all n steps integrated
};

struct PlanResult {
  std::vector<RotorPlan> solutions;  ///< shortest first
  std::string reason;                ///< why there is none (empty when there are solutions)
};

/// The checks planRotorMotion makes before it plans, alone: a request is cheap to check and a
/// plan costs milliseconds (test/fuzz/fuzz_plan_request.cpp fuzzes these).
/// @throw std::invalid_argument as planRotorMotion, naming the field, its value and the bound.
void requireValid(const PlanRequest& request);

/// Solves eqs 32-33 on a grid of leaf integrations, refines every root by Newton's method on
/// integrated leaves, aims each with γ and verifies it by integrating all n steps. Circles
/// smaller than 0.01 R are not plans (they approach the null manoeuvre a = b = 0).
/// Solutions whose final_error exceeds 1e-6 are dropped (and counted in the reason if none remain).
/// @throw std::invalid_argument on a non-finite input, k < 0, steps < 1, max_radius outside
///        (0, kMaxCircleRadius), heading_turns < 0, or a value beyond the bounds above.
PlanResult planRotorMotion(const PlanRequest& request);

}  // namespace spherical_robots::rotor
