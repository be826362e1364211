#include "spherical_robots/hardware/simulated_actuators.hpp"

#include "spherical_robots/core/validation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unordered_set>
#include <utility>

namespace spherical_robots::hardware {

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

double limitOf(const ActuatorLimits& limits) {
  return limits.kind == ActuatorKind::Effort ? limits.max_effort : limits.max_velocity;
}

}  // namespace

SimulatedActuators::SimulatedActuators(std::vector<std::string> names,
                                       std::vector<ActuatorLimits> limits, double command_timeout,
                                       std::vector<ActuatorModel> models,
                                       std::uint32_t noise_seed)
    : names_(std::move(names)),
      limits_(std::move(limits)),
      command_timeout_(command_timeout),
      models_(std::move(models)),
      noise_engine_(noise_seed) {
  if (names_.empty()) throw std::invalid_argument("SimulatedActuators: no actuator names given");
  if (models_.empty()) models_.assign(names_.size(), ActuatorModel{});
  if (models_.size() != names_.size()) {
    std::ostringstream msg;
    msg << "SimulatedActuators: " << names_.size() << " actuator names (" << joined(names_)
        << ") but " << models_.size() << " model entries";
    throw std::invalid_argument(msg.str());
  }
  std::unordered_set<std::string> seen;
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i].empty())
      throw std::invalid_argument("SimulatedActuators: actuator name #" + std::to_string(i) +
                                  " is empty");
    if (!seen.insert(names_[i]).second)
      throw std::invalid_argument("SimulatedActuators: actuator name '" + names_[i] +
                                  "' appears twice");
    const std::string of = " of '" + names_[i] + "'";
    requireNonNegative(models_[i].time_constant, "SimulatedActuators: time_constant" + of + " [s]");
    requireNonNegative(models_[i].dead_time, "SimulatedActuators: dead_time" + of + " [s]");
    requireNonNegative(models_[i].position_resolution,
                       "SimulatedActuators: position_resolution" + of + " [rad]");
    requireNonNegative(models_[i].velocity_noise,
                       "SimulatedActuators: velocity_noise" + of + " [rad/s]");
  }
  requireValidLimits(limits_, command_timeout_);
  setpoints_.assign(names_.size(), 0.0);
  active_setpoints_.assign(names_.size(), 0.0);
  pending_.assign(names_.size(), {});
  velocities_.assign(names_.size(), 0.0);
  positions_.assign(names_.size(), 0.0);
  efforts_.assign(names_.size(), 0.0);
  saturations_.assign(names_.size(), 0);
  measured_velocities_.assign(names_.size(), 0.0);
  measured_positions_.assign(names_.size(), 0.0);
}

void SimulatedActuators::requireValidLimits(const std::vector<ActuatorLimits>& limits,
                                            double command_timeout) const {
  if (limits.size() != names_.size()) {
    std::ostringstream msg;
    msg << "SimulatedActuators: " << names_.size() << " actuator names (" << joined(names_)
        << ") but " << limits.size() << " limit entries";
    throw std::invalid_argument(msg.str());
  }
  for (std::size_t i = 0; i < names_.size(); ++i) {
    const std::string of = " of '" + names_[i] + "'";
    requirePositive(limits[i].max_velocity, "SimulatedActuators: max_velocity" + of + " [rad/s]");
    requirePositive(limits[i].max_acceleration,
                    "SimulatedActuators: max_acceleration" + of + " [rad/s^2]");
    requirePositive(limits[i].max_effort, "SimulatedActuators: max_effort" + of + " [N m or N]");
    if (limits[i].kind != limits_[i].kind)
      throw std::invalid_argument("SimulatedActuators: actuator '" + names_[i] +
                                  "' cannot change between velocity and effort");
  }
  requirePositive(command_timeout, "SimulatedActuators: command_timeout [s]");
}

void SimulatedActuators::setLimits(const std::vector<ActuatorLimits>& limits,
                                   double command_timeout, double t) {
  requireValidLimits(limits, command_timeout);
  // Before the clock starts there is nothing to integrate, and starting it here would draw the
  // measurement noise once more than a run without the change.
  if (clock_started_) update(t);
  limits_ = limits;
  command_timeout_ = command_timeout;
  // Set-points beyond a lowered limit are clamped as a new command would be; a velocity above
  // it then ramps down at the acceleration limit, as after any other set-point change.
  for (std::size_t i = 0; i < names_.size(); ++i) {
    const double limit = limitOf(limits_[i]);
    setpoints_[i] = std::clamp(setpoints_[i], -limit, limit);
    active_setpoints_[i] = std::clamp(active_setpoints_[i], -limit, limit);
    for (Pending& pending : pending_[i]) pending.value = std::clamp(pending.value, -limit, limit);
  }
  applyInstantEfforts();
}

std::string SimulatedActuators::command(const std::vector<std::string>& names,
                                        const std::vector<double>& setpoints, double t) {
  if (e_stopped_) return "e-stop engaged: commands are rejected until it is released";
  if (!std::isfinite(t)) return "non-finite command time " + std::to_string(t);
  if (names.empty()) return "command names no actuator";
  if (names.size() != setpoints.size()) {
    std::ostringstream msg;
    msg << "command has " << names.size() << " names but " << setpoints.size() << " set-points";
    return msg.str();
  }
  // Validate everything before touching anything, so a rejected command changes nothing.
  std::vector<std::size_t> index(names.size());
  std::vector<bool> mentioned(names_.size(), false);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto it = std::find(names_.begin(), names_.end(), names[k]);
    if (it == names_.end())
      return "unknown actuator '" + names[k] + "' (known: " + joined(names_) + ")";
    index[k] = static_cast<std::size_t>(it - names_.begin());
    if (mentioned[index[k]]) return "actuator '" + names[k] + "' named twice in one command";
    mentioned[index[k]] = true;
    if (!std::isfinite(setpoints[k])) {
      std::ostringstream msg;
      msg << "non-finite "
          << (limits_[index[k]].kind == ActuatorKind::Effort ? "effort " : "velocity ")
          << setpoints[k] << " for actuator '" << names[k] << "'";
      return msg.str();
    }
    const double limit = limitOf(limits_[index[k]]);
    if (std::abs(setpoints[k]) > kImplausibleFactor * limit) {
      std::ostringstream msg;
      msg << (limits_[index[k]].kind == ActuatorKind::Effort ? "effort " : "velocity ")
          << setpoints[k] << " for actuator '" << names[k] << "' is beyond " << kImplausibleFactor
          << " times its limit " << limit << ": not a set-point";
      return msg.str();
    }
  }

  update(t);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::size_t i = index[k];
    const double limit = limitOf(limits_[i]);
    setpoints_[i] = std::clamp(setpoints[k], -limit, limit);
    if (std::abs(setpoints[k]) > limit) ++saturations_[i];
    if (models_[i].dead_time > 0.0)
      pending_[i].push_back({now_ + models_[i].dead_time, setpoints_[i]});
    else
      active_setpoints_[i] = setpoints_[i];
  }
  // now_ rather than t: a late-arriving command restarts the watchdog at the latest time seen.
  applyInstantEfforts();
  last_command_time_ = now_;
  has_command_ = true;
  timed_out_ = false;
  return {};
}

double SimulatedActuators::commandAge() const {
  return has_command_ ? now_ - last_command_time_ : std::numeric_limits<double>::quiet_NaN();
}

void SimulatedActuators::update(double t) {
  if (!std::isfinite(t)) return;
  if (!clock_started_) {
    now_ = t;
    clock_started_ = true;
    measure();
    return;
  }
  if (t <= now_) return;
  // From event to event (a delayed set-point becoming active, the watchdog deadline), so that
  // each takes effect at its own time, not at the next update, and the result does not depend on
  // the update rate.
  for (;;) {
    double next = t;
    // A command always restarts the watchdog at now_, hence deadline > now_ while it is armed.
    const bool armed = has_command_ && !timed_out_;
    const double deadline = last_command_time_ + command_timeout_;
    if (armed) next = std::min(next, deadline);
    for (const auto& queue : pending_)
      if (!queue.empty()) next = std::min(next, queue.front().time);
    integrate(next - now_);
    now_ = next;
    for (std::size_t i = 0; i < names_.size(); ++i) {
      while (!pending_[i].empty() && pending_[i].front().time <= now_) {
        active_setpoints_[i] = pending_[i].front().value;
        pending_[i].pop_front();
      }
    }
    if (armed && deadline <= now_) {
      timed_out_at_rest_ = std::all_of(setpoints_.begin(), setpoints_.end(),
                                       [](double setpoint) { return setpoint == 0.0; });
      zeroSetpoints();
      timed_out_ = true;
    }
    applyInstantEfforts();
    if (now_ >= t) break;
  }
  measure();
}

void SimulatedActuators::rebase(double t) {
  if (!std::isfinite(t)) return;
  if (!clock_started_) {
    update(t);
    return;
  }
  const double shift = t - now_;
  last_command_time_ += shift;
  for (auto& queue : pending_)
    for (auto& pending : queue) pending.time += shift;
  now_ = t;
  measure();
}

void SimulatedActuators::stop(double t) {
  update(t);
  zeroSetpoints();
  std::fill(velocities_.begin(), velocities_.end(), 0.0);
  measure();
}

void SimulatedActuators::applyInstantEfforts() {
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (limits_[i].kind == ActuatorKind::Effort && models_[i].time_constant <= 0.0)
      efforts_[i] = active_setpoints_[i];
}

void SimulatedActuators::zeroSetpoints() {
  std::fill(setpoints_.begin(), setpoints_.end(), 0.0);
  std::fill(active_setpoints_.begin(), active_setpoints_.end(), 0.0);
  for (auto& queue : pending_) queue.clear();
  // The safe state of a torque or force actuator is no effort, at once, not through its lag.
  std::fill(efforts_.begin(), efforts_.end(), 0.0);
}

void SimulatedActuators::measure() {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    const ActuatorModel& model = models_[i];
    const double resolution = model.position_resolution;
    measured_positions_[i] =
        resolution > 0.0 ? resolution * std::round(positions_[i] / resolution) : positions_[i];
    // Drawn only for noisy actuators, in index order: a fixed seed gives a fixed sequence.
    measured_velocities_[i] =
        model.velocity_noise > 0.0
            ? velocities_[i] + model.velocity_noise * unit_normal_(noise_engine_)
            : velocities_[i];
  }
}

void SimulatedActuators::setEStop(bool engaged, double t) {
  if (engaged) stop(t);
  e_stopped_ = engaged;
}

void SimulatedActuators::integrate(double dt) {
  if (dt <= 0.0) return;
  for (std::size_t i = 0; i < names_.size(); ++i) {
    const double target = active_setpoints_[i];
    const double tau = models_[i].time_constant;
    if (limits_[i].kind == ActuatorKind::Effort) {
      // e(s) = u + (e - u) e^{-s/tau}; without a lag applyInstantEfforts() holds e = u.
      if (tau > 0.0) efforts_[i] = target + (efforts_[i] - target) * std::exp(-dt / tau);
      continue;
    }
    const double v0 = velocities_[i];
    const double a = limits_[i].max_acceleration;
    const double dv = target - v0;
    if (tau <= 0.0) {
      if (std::abs(dv) <= a * dt) {
        // Reaches the set-point after t_reach, then holds it: a trapezoid, then a rectangle.
        const double t_reach = std::abs(dv) / a;
        positions_[i] += 0.5 * (v0 + target) * t_reach + target * (dt - t_reach);
        velocities_[i] = target;
      } else {
        const double v1 = v0 + std::copysign(a * dt, dv);
        positions_[i] += 0.5 * (v0 + v1) * dt;
        velocities_[i] = v1;
      }
      continue;
    }
    // dv/dt = clamp((u - v) / tau, ±a): a constant-acceleration ramp while |u - v| > a tau, then
    // the exponential approach, which never saturates again for a constant u.
    double v = v0;
    double rest = dt;
    if (std::abs(dv) > a * tau) {
      const double t_sat = (std::abs(dv) - a * tau) / a;
      if (t_sat >= rest) {
        const double v1 = v0 + std::copysign(a * rest, dv);
        positions_[i] += 0.5 * (v0 + v1) * rest;
        velocities_[i] = v1;
        continue;
      }
      const double v1 = target - std::copysign(a * tau, dv);
      positions_[i] += 0.5 * (v0 + v1) * t_sat;
      v = v1;
      rest -= t_sat;
    }
    // v(s) = u + (v - u) e^{-s/tau}; its integral is u s + (v - u) tau (1 - e^{-s/tau}).
    const double one_minus_e = -std::expm1(-rest / tau);
    positions_[i] += target * rest + (v - target) * tau * one_minus_e;
    velocities_[i] = target + (v - target) * (1.0 - one_minus_e);
  }
}

}  // namespace spherical_robots::hardware
