#pragma once
// One step of the geometric-phase strategy (Svinin et al., section III-B): tracing a figure eight
// once moves the contact point on the plane by the non-holonomic shift h and turns the heading by
// the holonomy angle η. Integrated with Boost.Odeint (Runge-Kutta-Fehlberg 7(8), adaptive,
// absolute and relative tolerance 1e-12). Lengths in units of R. No ROS.

#include <Eigen/Core>
#include <vector>

#include "spherical_robots/rotor/contact_curve.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"

namespace spherical_robots::rotor {

/// Eqs 28-30 integrated along the figure eight from θ0 to θ1 (0 <= θ0 <= θ1 <= 2π).
/// @throw std::invalid_argument on a non-finite or negative k, θ outside [0, 2π] or θ0 > θ1, or
///        a non-finite start.
PlaneState integrateFigureEight(double k, const FigureEight& curve, double theta0, double theta1,
                                const PlaneState& start);

/// The state after half (θ = π) and all (θ = 2π) of one step from the zero state.
struct StepResult {
  PlaneState half;
  PlaneState full;
};
StepResult rotorStep(double k, const FigureEight& curve);

/// The state after tracing the figure eight n >= 1 times from the zero state.
/// @throw std::invalid_argument as integrateFigureEight(), or if steps < 1.
PlaneState integrateSteps(double k, const FigureEight& curve, int steps);

/// The contact coordinates along n >= 1 steps from the zero state, at samples_per_step >= 1
/// equally spaced θ per step (θ = 0 first, the end of the last step last): for plots, paths and
/// self-intersection counts. @throw std::invalid_argument as integrateSteps() or on bad counts.
std::vector<ContactCoordinates> samplePath(double k, const FigureEight& curve, int steps,
                                           int samples_per_step);

/// One leaf (circle of Euclidean radius r, first-leaf orientation, γ = 0) from the zero state:
/// its plane displacement and heading change. Integrates half the circle and uses its mirror
/// symmetry for the other half.
struct LeafPhase {
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
  double holonomy = 0.0;
};
/// Absolute and relative tolerance of every integration unless a caller asks for less.
constexpr double kIntegrationTolerance = 1e-12;

/// tolerance: of the integration (the planner's leaf table uses a looser one for its start).
/// @throw std::invalid_argument unless 0 < r < kMaxCircleRadius, tolerance > 0, or on a bad k.
LeafPhase leafPhase(double k, double r, double tolerance = kIntegrationTolerance);

/// One step's phase for γ = 0: shift vector, h = |shift| and η = ψ(2π).
struct StepPhase {
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
  double h = 0.0;
  double eta = 0.0;
};
/// Composes two leaves: the mirrored leaf of radius b maps (u, v, ψ) to (u, −v, −ψ), and a leaf
/// started at heading ψ0 has its shift turned by −ψ0 (eqs 28-29), so
/// shift = s(a) + Rot(−η(a)) diag(1, −1) s(b) and η = η(a) − η(b).
StepPhase composeLeaves(const LeafPhase& first, const LeafPhase& second);

/// h(a, b), η(a, b) from two leaf integrations.
StepPhase stepPhase(double k, double a, double b);

}  // namespace spherical_robots::rotor
