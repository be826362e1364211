#include "spherical_robots/hardware/simulated_actuators.hpp"

#include "spherical_robots/core/validation.hpp"

#include <algorithm>
#include <cmath>
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


}  // namespace

SimulatedActuators::SimulatedActuators(std::vector<std::string> names,
                                       std::vector<ActuatorLimits> limits, double command_timeout)
    : names_(std::move(names)), limits_(std::move(limits)), command_timeout_(command_timeout) {
  if (names_.empty()) throw std::invalid_argument("SimulatedActuators: no actuator names given");
  if (limits_.size() != names_.size()) {
    std::ostringstream msg;
    msg << "SimulatedActuators: " << names_.size() << " actuator names (" << joined(names_)
        << ") but " << limits_.size() << " limit entries";
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
    requirePositive(limits_[i].max_velocity, "SimulatedActuators: max_velocity" + of + " [rad/s]");
    requirePositive(limits_[i].max_acceleration,
                    "SimulatedActuators: max_acceleration" + of + " [rad/s^2]");
  }
  requirePositive(command_timeout_, "SimulatedActuators: command_timeout [s]");
  setpoints_.assign(names_.size(), 0.0);
  velocities_.assign(names_.size(), 0.0);
  positions_.assign(names_.size(), 0.0);
}

std::string SimulatedActuators::command(const std::vector<std::string>& names,
                                        const std::vector<double>& velocities, double t) {
  if (e_stopped_) return "e-stop engaged: commands are rejected until it is released";
  if (!std::isfinite(t)) return "non-finite command time " + std::to_string(t);
  if (names.empty()) return "command names no actuator";
  if (names.size() != velocities.size()) {
    std::ostringstream msg;
    msg << "command has " << names.size() << " names but " << velocities.size() << " velocities";
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
    if (!std::isfinite(velocities[k])) {
      std::ostringstream msg;
      msg << "non-finite velocity " << velocities[k] << " for actuator '" << names[k] << "'";
      return msg.str();
    }
  }

  update(t);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const double limit = limits_[index[k]].max_velocity;
    setpoints_[index[k]] = std::clamp(velocities[k], -limit, limit);
  }
  // now_ rather than t: a late-arriving command restarts the watchdog at the latest time seen.
  last_command_time_ = now_;
  has_command_ = true;
  timed_out_ = false;
  return {};
}

void SimulatedActuators::update(double t) {
  if (!std::isfinite(t)) return;
  if (!clock_started_) {
    now_ = t;
    clock_started_ = true;
    return;
  }
  if (t <= now_) return;
  if (has_command_ && !timed_out_) {
    // The watchdog fires at its deadline, not at the next update, so the travel does not depend
    // on the update rate. A command always restarts it at now_, hence deadline > now_ here.
    const double deadline = last_command_time_ + command_timeout_;
    if (deadline <= t) {
      integrate(deadline - now_);
      now_ = deadline;
      std::fill(setpoints_.begin(), setpoints_.end(), 0.0);
      timed_out_ = true;
    }
  }
  integrate(t - now_);
  now_ = t;
}

void SimulatedActuators::stop(double t) {
  update(t);
  std::fill(setpoints_.begin(), setpoints_.end(), 0.0);
  std::fill(velocities_.begin(), velocities_.end(), 0.0);
}

void SimulatedActuators::setEStop(bool engaged, double t) {
  if (engaged) stop(t);
  e_stopped_ = engaged;
}

void SimulatedActuators::integrate(double dt) {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    const double v0 = velocities_[i];
    const double target = setpoints_[i];
    const double a = limits_[i].max_acceleration;
    const double dv = target - v0;
    if (std::abs(dv) <= a * dt) {
      // Reaches the set-point after tau, then holds it: a trapezoid, then a rectangle.
      const double tau = std::abs(dv) / a;
      positions_[i] += 0.5 * (v0 + target) * tau + target * (dt - tau);
      velocities_[i] = target;
    } else {
      const double v1 = v0 + std::copysign(a * dt, dv);
      positions_[i] += 0.5 * (v0 + v1) * dt;
      velocities_[i] = v1;
    }
  }
}

}  // namespace spherical_robots::hardware
