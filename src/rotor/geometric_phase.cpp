#include "spherical_robots/rotor/geometric_phase.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <complex>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::rotor {
namespace {

namespace odeint = boost::numeric::odeint;
using State = std::array<double, 3>;  // u_a, v_a, ψ

constexpr double kInitialStep = 0.05;

/// Eqs 28-30 along curve(θ) from θ0 to θ1 (the curve must be smooth on the interval).
template <typename Curve>
PlaneState integrateSmooth(double k, const Curve& curve, double theta0, double theta1,
                           const PlaneState& start, double tolerance = kIntegrationTolerance) {
  State x{start.u_a, start.v_a, start.psi};
  if (theta1 > theta0) {
    const auto rhs = [&](const State& s, State& dxdt, double theta) {
      const PlaneState rates = realizableCurveRates(k, curve(theta), s[2]);
      dxdt = {rates.u_a, rates.v_a, rates.psi};
    };
    odeint::integrate_adaptive(
        odeint::make_controlled(tolerance, tolerance, odeint::runge_kutta_fehlberg78<State>()),
        rhs, x, theta0, theta1, std::min(kInitialStep, theta1 - theta0));
  }
  return {x[0], x[1], x[2]};
}

void requireStart(const PlaneState& start) {
  requireFinite(start.u_a, "start u_a [R]");
  requireFinite(start.v_a, "start v_a [R]");
  requireFinite(start.psi, "start psi [rad]");
}

void requireInterval(double theta0, double theta1) {
  requireFinite(theta0, "theta0 [rad]");
  requireFinite(theta1, "theta1 [rad]");
  if (theta0 < 0.0 || theta1 > 2.0 * M_PI || theta0 > theta1) {
    std::ostringstream message;
    message << "theta interval [" << theta0 << ", " << theta1
            << "] must satisfy 0 <= theta0 <= theta1 <= 2 pi";
    throw std::invalid_argument(message.str());
  }
}

}  // namespace

PlaneState integrateFigureEight(double k, const FigureEight& curve, double theta0, double theta1,
                                const PlaneState& start) {
  requireInterval(theta0, theta1);
  requireStart(start);
  // The tangent jumps at the pole between the leaves (θ = π): each leaf is integrated with its
  // own parameterization so no stage of the step control evaluates the other leaf.
  const auto first = [&curve](double theta) { return curve.onLeaf(false, theta); };
  const auto second = [&curve](double theta) { return curve.onLeaf(true, theta); };
  PlaneState state = start;
  if (theta0 < M_PI) state = integrateSmooth(k, first, theta0, std::min(theta1, M_PI), state);
  if (theta1 > M_PI) state = integrateSmooth(k, second, std::max(theta0, M_PI), theta1, state);
  return state;
}

StepResult rotorStep(double k, const FigureEight& curve) {
  StepResult result;
  result.half = integrateFigureEight(k, curve, 0.0, M_PI, PlaneState{});
  result.full = integrateFigureEight(k, curve, M_PI, 2.0 * M_PI, result.half);
  return result;
}

PlaneState integrateSteps(double k, const FigureEight& curve, int steps) {
  if (steps < 1) {
    throw std::invalid_argument("number of steps n must be >= 1, got " + std::to_string(steps));
  }
  PlaneState state;
  for (int i = 0; i < steps; ++i) state = integrateFigureEight(k, curve, 0.0, 2.0 * M_PI, state);
  return state;
}

std::vector<ContactCoordinates> samplePath(double k, const FigureEight& curve, int steps,
                                           int samples_per_step) {
  if (steps < 1 || samples_per_step < 1) {
    throw std::invalid_argument("steps and samples per step must be >= 1, got " +
                                std::to_string(steps) + " and " +
                                std::to_string(samples_per_step));
  }
  const auto coordinates = [&curve](const PlaneState& state, double theta) {
    const Eigen::Vector2d angles = contactAngles(curve.at(theta).point);
    return ContactCoordinates{state.u_a, state.v_a, angles.x(), angles.y(), state.psi};
  };
  std::vector<ContactCoordinates> path;
  path.reserve(static_cast<std::size_t>(steps) * samples_per_step + 1);
  PlaneState state;
  path.push_back(coordinates(state, 0.0));
  for (int step = 0; step < steps; ++step) {
    double theta = 0.0;
    for (int i = 1; i <= samples_per_step; ++i) {
      const double next = i == samples_per_step ? 2.0 * M_PI : 2.0 * M_PI * i / samples_per_step;
      state = integrateFigureEight(k, curve, theta, next, state);
      theta = next;
      path.push_back(coordinates(state, theta));
    }
  }
  return path;
}

LeafPhase leafPhase(double k, double r, double tolerance) {
  requirePositive(tolerance, "integration tolerance");
  const FigureEight curve(r, r);  // validates r; its first leaf at θ is the circle at angle 2θ
  const auto circle = [&curve](double theta) { return curve.onLeaf(false, theta); };
  const PlaneState half = integrateSmooth(k, circle, 0.0, 0.5 * M_PI, PlaneState{}, tolerance);
  // The second half circle is the first one mirrored in x and traced backwards: along it eq 30
  // gives the same heading increments in reverse order, so ψ(2π − s) = η − ψ(s) with η = 2ψ(π),
  // and eqs 28-29 then make its shift e^{−iη} conj(first half's shift) in u + iv.
  const double eta = 2.0 * half.psi;
  const std::complex<double> first(half.u_a, half.v_a);
  const std::complex<double> shift = first + std::polar(1.0, -eta) * std::conj(first);
  return {Eigen::Vector2d(shift.real(), shift.imag()), eta};
}

StepPhase composeLeaves(const LeafPhase& first, const LeafPhase& second) {
  const Eigen::Vector2d mirrored(second.shift.x(), -second.shift.y());
  StepPhase phase;
  phase.shift = first.shift + Eigen::Rotation2Dd(-first.holonomy) * mirrored;
  phase.h = phase.shift.norm();
  phase.eta = first.holonomy - second.holonomy;
  return phase;
}

StepPhase stepPhase(double k, double a, double b) {
  return composeLeaves(leafPhase(k, a), leafPhase(k, b));
}

}  // namespace spherical_robots::rotor
