#include "spherical_robots/norma/norma_control_loop.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "spherical_robots/core/validation.hpp"
#include "spherical_robots/norma/norma_simulation.hpp"

namespace spherical_robots::norma {
namespace {

// An effort this small next to its limit is "nothing applied"; a command this large is "something".
constexpr double kAppliedNothing = 1e-9;
constexpr double kCommandedSomething = 1e-3;

bool saturatedFurther(double effort, double limit, double integrand) {
  return std::abs(effort) >= limit && effort * integrand > 0.0;
}

}  // namespace

NormaControlLoop::NormaControlLoop(NormaController controller, EffortLimits limits, double max_gap,
                                   double jump_back, NormaStateBounds bounds)
    : controller_(std::move(controller)),
      limits_(limits),
      max_gap_(max_gap),
      jump_back_(jump_back),
      bounds_(bounds) {
  requirePositive(jump_back_, "jump-back threshold [s]");
  requirePositive(limits_.max_torque, "max_torque [N m]");
  requirePositive(limits_.max_force, "max_force [N]");
  requirePositive(max_gap_, "max integration gap [s]");
  requirePositive(bounds_.position, "position bound [m]");
  requirePositive(bounds_.angle, "angle bound [rad]");
  requirePositive(bounds_.rate, "rate bound");
}

void NormaControlLoop::validate(double t, const NormaMeasurement& state) const {
  requireFinite(t, "state time [s]");
  static const char* const kCoordinates[4] = {"theta [rad]", "alpha [rad]", "phi [rad]",
                                              "delta [m]"};
  static const char* const kRates[4] = {"theta_dot [rad/s]", "alpha_dot [rad/s]",
                                        "phi_dot [rad/s]", "delta_dot [m/s]"};
  for (int i = 0; i < 4; ++i) {
    requireMagnitudeAtMost(state.q(i), bounds_.angle, kCoordinates[i]);
    requireMagnitudeAtMost(state.qd(i), bounds_.rate, kRates[i]);
  }
  // The slider moves along a shaft of 0.4 m; the model has no end stops, so a slider dropped by
  // an e-stop may pass them, but not by metres.
  requireMagnitudeAtMost(state.q(3), 10.0, "delta [m]");
  requireMagnitudeAtMost(state.x, bounds_.position, "X [m]");
  requireMagnitudeAtMost(state.y, bounds_.position, "Y [m]");
  requireMagnitudeAtMost(state.psi, bounds_.angle, "psi [rad]");
}

bool NormaControlLoop::actuatorsStopped() const {
  if (!applied_known_) return false;
  const bool nothing_applied = std::abs(applied_torque_) <= kAppliedNothing * limits_.max_torque &&
                               std::abs(applied_force_) <= kAppliedNothing * limits_.max_force;
  const bool something_commanded =
      std::abs(last_output_.torque) > kCommandedSomething * limits_.max_torque ||
      std::abs(last_output_.force) > kCommandedSomething * limits_.max_force;
  return nothing_applied && something_commanded;
}

bool NormaControlLoop::integralHeld(int i) const {
  if (actuatorsStopped()) return true;
  // Integrals 0 and 1 feed the torque through PID1 and PID2, integral 2 the force (PID3).
  return i < 2 ? saturatedFurther(last_output_.torque, limits_.max_torque, last_output_.integrand(i))
               : saturatedFurther(last_output_.force, limits_.max_force, last_output_.integrand(i));
}

void NormaControlLoop::actuatorsApplied(double torque, double force) {
  if (!std::isfinite(torque) || !std::isfinite(force)) return;
  applied_torque_ = torque;
  applied_force_ = force;
  applied_known_ = true;
}

void NormaControlLoop::startPathAt(double t0) {
  requireFinite(t0, "path start [s]");
  path_start_ = t0;
  path_start_given_ = true;
}

std::optional<double> NormaControlLoop::pathStart() const {
  if (started_ || path_start_given_) return path_start_;
  return std::nullopt;
}

PathPoint NormaControlLoop::reference(double t) const { return lissajousPath(t - path_start_); }

ControlOutput NormaControlLoop::step(double t, const NormaMeasurement& state) {
  validate(t, state);
  const bool restart = !started_ || t < last_t_ - jump_back_;
  if (!restart && t <= last_t_) {
    std::ostringstream problem;
    problem << "state at t = " << t << " s is not later than the last one (" << last_t_
            << " s): out of order or repeated";
    throw std::invalid_argument(problem.str());
  }
  const double path_start = restart && !path_start_given_ ? t : path_start_;
  Eigen::Vector3d integrals = restart ? Eigen::Vector3d::Zero() : integrals_;
  if (!restart) {
    const double gap = t - last_t_;
    if (gap > 0.0 && gap <= max_gap_) {
      for (int i = 0; i < 3; ++i)
        if (!integralHeld(i)) integrals(i) += last_output_.integrand(i) * gap;
    }
  }
  const ControlOutput output = controller_.compute(state.q, state.qd, state.x, state.y, state.psi,
                                                   integrals, lissajousPath(t - path_start));
  requireFinite(output.torque, "commanded torque T [N m]");
  requireFinite(output.force, "commanded force F [N]");
  for (int i = 0; i < 3; ++i) requireFinite(output.integrand(i), "controller integrand");
  started_ = true;
  path_start_ = path_start;
  last_t_ = t;
  integrals_ = integrals;
  last_output_ = output;
  return output;
}

}  // namespace spherical_robots::norma
