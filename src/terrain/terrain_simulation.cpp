#include "spherical_robots/terrain/terrain_simulation.hpp"
#include "spherical_robots/core/validation.hpp"

#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace spherical_robots::terrain {
namespace {

using OdeState = std::array<double, 4>;  // x, y, psi, phi
using Stepper = boost::numeric::odeint::runge_kutta4<OdeState>;

TerrainState fromOde(const OdeState& x) { return {x[0], x[1], x[2], x[3]}; }
OdeState toOde(const TerrainState& s) { return {s.x, s.y, s.psi, s.phi}; }
OdeState toOde(const TerrainStateRate& r) { return {r.x_dot, r.y_dot, r.psi_dot, r.phi_dot}; }


TerrainState checkedResult(const TerrainKinematics& kinematics, const OdeState& x, double t) {
  for (double value : x) {
    if (!std::isfinite(value)) {
      throw std::runtime_error("terrain state became non-finite at t = " + std::to_string(t) +
                               " s");
    }
  }
  return kinematics.constrain(fromOde(x));
}

}  // namespace

TerrainSimulation::TerrainSimulation(const TerrainKinematics& kinematics,
                                     const PursuitController& controller,
                                     const ReferencePath& path, const TerrainState& initial)
    : kinematics_(kinematics), controller_(controller),
      smooth_controller_(dynamic_cast<const SmoothPursuitController*>(&controller)), path_(path),
      velocity_window_(controller.velocityWindow()), reads_zeta_(controller.readsZeta()),
      state_(kinematics.constrain(initial)) {
  if (controller.type() != kinematics.type()) {
    throw std::invalid_argument("controller is for robot type " + toString(controller.type()) +
                                " but the kinematics are " + toString(kinematics.type()));
  }
  kinematics_.geometry(state_);  // validates the initial state
}

TerrainSample TerrainSimulation::evaluate(const TerrainState& state, double t) const {
  TerrainSample sample{t, state, kinematics_.geometry(state), desiredAt(t), {}, {}};
  sample.error = trackingError(sample.geometry, sample.desired.position);
  sample.rates = kinematics_.realisedRates(
      state, controller_.command(sample.geometry, state.phi, sample.error,
                                 sample.desired.velocity));
  return sample;
}

const DesiredPoint& TerrainSimulation::desiredAt(double t) const {
  for (std::size_t i = 0; i < desired_cache_used_; ++i) {
    if (desired_cache_[i].first == t) return desired_cache_[i].second;
  }
  desired_cache_used_ = std::min(desired_cache_used_ + 1, desired_cache_.size());
  auto& slot = desired_cache_[desired_cache_next_];
  desired_cache_next_ = (desired_cache_next_ + 1) % desired_cache_.size();
  slot = {t, liftOntoSurface(path_, kinematics_.surface(), t, velocity_window_)};
  return slot.second;
}

void TerrainSimulation::step(double dt) {
  requirePositive(dt, "integration step dt [s]");
  if (smooth_controller_ != nullptr) {
    advance(*smooth_controller_, dt);
  } else {
    advance(controller_, dt);
  }
}

// Boost.Odeint's classical RK4 with the step's three desired points looked up before its four
// stages, which are then straight-line arithmetic without a call: flattened, GCC inlines into
// this function everything they call that it can see (its size limits otherwise leave the
// heading frame and the smooth law out of line), so their inputs and results stay in registers
// along the serial chain of operations from one stage to the next. Before, a desired point not
// yet cached was computed inside a stage, and every value live across that call went through
// memory.
template <typename Controller>
void TerrainSimulation::advance(const Controller& controller, double dt) {
  const double half_dt = 0.5 * dt;
  // Copies: the cache holds two points, the step needs three.
  const DesiredPoint start = desiredAt(t_);
  const DesiredPoint middle = desiredAt(t_ + half_dt);
  const DesiredPoint end = desiredAt(t_ + dt);
  // The controller runs inside the vector field, so it is evaluated at every RK stage: evaluate()
  // without assembling the whole sample, which 160,000 stages a run do not need.
  const auto closed_loop = [this, &controller](const TerrainState& state,
                                               const DesiredPoint& desired) {
    const ContactGeometry geometry = kinematics_.geometry(state);
    const TrackingError error = trackingError(geometry, desired.position, reads_zeta_);
    const DriveRates rates = kinematics_.realisedRates(
        state, controller.command(geometry, state.phi, error, desired.velocity));
    return kinematics_.realisedStateRate(state, geometry, rates);
  };
  // odeint asks for the field at t_, at t_ + dt/2 twice and at t_ + dt: the same doubles (any
  // other time would be looked up as before).
  const auto field = [&](const OdeState& x, OdeState& dxdt, double t) {
    const DesiredPoint& desired = t == t_             ? start
                                  : t == t_ + half_dt ? middle
                                  : t == t_ + dt      ? end
                                                      : desiredAt(t);
    dxdt = toOde(closed_loop(fromOde(x), desired));
  };
  OdeState next = toOde(state_);
  Stepper().do_step(field, next, t_, dt);
  const double increment = dt - t_compensation_;
  const double next_t = t_ + increment;
  t_compensation_ = (next_t - t_) - increment;
  t_ = next_t;
  state_ = checkedResult(kinematics_, next, t_);
}

TerrainSample TerrainSimulation::sample() const { return evaluate(state_, t_); }

TerrainState stepWithHeldRates(const TerrainKinematics& kinematics, const TerrainState& state,
                               const DriveRates& rates, double dt) {
  requirePositive(dt, "integration step dt [s]");
  const auto open_loop = [&kinematics, &rates](const OdeState& x, OdeState& dxdt, double) {
    dxdt = toOde(kinematics.stateRate(fromOde(x), rates));
  };
  OdeState x = toOde(state);
  Stepper().do_step(open_loop, x, 0.0, dt);
  return checkedResult(kinematics, x, dt);
}

RollingState advanceWithHeldRates(const TerrainKinematics& kinematics, const RollingState& start,
                                  const DriveRates& rates, double elapsed, double max_step) {
  requirePositive(elapsed, "elapsed time [s]");
  requirePositive(max_step, "largest integration step [s]");
  const int steps = std::max(1, static_cast<int>(std::ceil(elapsed / max_step - 1e-9)));
  const double dt = elapsed / steps;
  RollingState result = start;
  Eigen::Vector3d omega = kinematics.shellAngularVelocity(result.state, rates);
  for (int i = 0; i < steps; ++i) {
    result.state = stepWithHeldRates(kinematics, result.state, rates, dt);
    const Eigen::Vector3d omega_end = kinematics.shellAngularVelocity(result.state, rates);
    result.orientation = advanceOrientation(result.orientation, 0.5 * (omega + omega_end), dt);
    omega = omega_end;
  }
  return result;
}

Eigen::Quaterniond advanceOrientation(const Eigen::Quaterniond& orientation,
                                      const Eigen::Vector3d& omega, double dt) {
  requirePositive(dt, "orientation step dt [s]");
  if (!omega.allFinite()) throw std::invalid_argument("angular velocity is not finite");
  const double angle = omega.norm() * dt;
  if (angle == 0.0) return orientation;
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle, omega / omega.norm()));
  return (turn * orientation).normalized();
}

TrackingSummary::TrackingSummary(double threshold, double settle_time)
    : threshold_(threshold), settle_time_(settle_time) {}

void TrackingSummary::add(double t, double error_norm) {
  if (!converged_ && error_norm < threshold_) {
    converged_ = true;
    time_to_converge_ = t;
  }
  if (t >= settle_time_) {
    sum_after_ += error_norm;
    max_after_ = count_after_ == 0 ? error_norm : std::max(max_after_, error_norm);
    ++count_after_;
  }
}

double TrackingSummary::meanAfterSettling() const {
  return count_after_ == 0 ? std::numeric_limits<double>::quiet_NaN() : sum_after_ / count_after_;
}

double TrackingSummary::maxAfterSettling() const {
  return count_after_ == 0 ? std::numeric_limits<double>::quiet_NaN() : max_after_;
}

}  // namespace spherical_robots::terrain
