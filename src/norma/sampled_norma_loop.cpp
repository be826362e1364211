#include "spherical_robots/norma/sampled_norma_loop.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::norma {
namespace {

// The hardware interface's actuators in launch/norma_stack.launch, the order of Efforts.
const std::vector<std::string> kActuators = {"pendulum_motor", "slider_motor"};

hardware::SimulatedActuators idealEffortActuators(const EffortLimits& limits,
                                                  double command_timeout) {
  hardware::ActuatorLimits torque, force;
  torque.kind = force.kind = hardware::ActuatorKind::Effort;
  torque.max_effort = limits.max_torque;
  force.max_effort = limits.max_force;
  return hardware::SimulatedActuators(kActuators, {torque, force}, command_timeout);
}

const SampledLoopConfig& validated(const SampledLoopConfig& config) {
  requirePositive(config.step, "step [s]");
  if (config.step > kDefaultMaxClockStep) {
    std::ostringstream what;
    what << "step [s] " << config.step << " is longer than a node's max_clock_step ("
         << kDefaultMaxClockStep << " s): the stack would take each step for a clock jump";
    throw std::invalid_argument(what.str());
  }
  requirePositive(config.state_timeout, "state_timeout [s]");
  requireFinite(config.duration, "duration [s]");
  if (config.duration < 0.0) throw std::invalid_argument("duration [s] must be >= 0");
  // Bounded before anything runs: 1e300 s is a request, not a run.
  if (!(config.duration / config.step <= kMaxLoggedSamples)) {
    std::ostringstream what;
    what << "duration " << config.duration << " s is " << config.duration / config.step
         << " steps of " << config.step << " s, more than the " << kMaxLoggedSamples
         << " a run allows";
    throw std::invalid_argument(what.str());
  }
  requireFinite(config.initial_psi, "initial psi [rad]");
  return config;
}

/// The step as the lock-step clock takes it (ros::Duration(step)).
Nanoseconds checkedStepNanoseconds(double step) {
  const Nanoseconds ns = durationNanoseconds(step);
  if (ns <= 0) {
    std::ostringstream what;
    what << "step [s] " << step << " is under 1 ns";
    throw std::invalid_argument(what.str());
  }
  return ns;
}

/// The state as the controller reads it from joint_states (q, q̇) and odom: X, Y, and ψ as the
/// heading of the orientation the plant publishes (yawRotation, read back by yawOf: in (−π, π]).
NormaMeasurement measurementOf(const NormaState& state) {
  NormaMeasurement m;
  m.q = state.q;
  m.qd = state.qd;
  m.x = state.x;
  m.y = state.y;
  m.psi = yawOf(yawRotation(state.psi));
  return m;
}

}  // namespace

SampledNormaLoop::SampledNormaLoop(const NormaParameters& parameters,
                                   const SampledLoopConfig& config)
    : dynamics_(parameters, config.variant),
      config_(validated(config)),
      step_ns_(checkedStepNanoseconds(config.step)),
      timeline_(config.duration, kDefaultMaxClockStep),
      control_(NormaController(parameters, config.controller, config.gains), config.limits),
      actuators_(idealEffortActuators(config.limits, config.command_timeout)) {
  state_.psi = config.initial_psi;
}

bool SampledNormaLoop::complete() const {
  return config_.duration == 0.0 ? timeline_.started() : timeline_.finished();
}

const SampledStep& SampledNormaLoop::step() {
  if (complete()) throw std::logic_error("SampledNormaLoop::step after the last step");
  const Nanoseconds now = latest_.time + step_ns_;
  const double t = stampSeconds(now);  // ros::Time::toSec(), as every node passes its time on

  // norma_plant (plant_loop.cpp, tick): freshness first, then the timeline.
  const bool fresh = accepted_at_ && withinTimeout(*accepted_at_, now, config_.state_timeout);
  const Efforts driving = drivingEfforts(measured_, fresh);
  const LoopTimeline::Tick tick = timeline_.tick(now);
  if (tick.advances())
    state_ = advanceWithHeldInputs(dynamics_, state_, driving.torque, driving.force, tick.elapsed,
                                   config_.step);
  timeline_.complete(now);

  // norma_controller (norma_controller_ros.cpp, control): a rejected state commands nothing.
  std::optional<ControlOutput> command;
  try {
    command = control_.step(t, measurementOf(state_));
  } catch (const std::invalid_argument&) {
    ++rejected_states_;
  }

  // hardware_interface (hardware_interface_sim_ros.cpp): the command at its stamp, then update.
  if (command && !actuators_.command(kActuators, {command->torque, command->force}, t).empty())
    ++rejected_commands_;
  actuators_.update(t);
  const Efforts applied{actuators_.efforts()[0], actuators_.efforts()[1]};

  // actuators/state reaches the plant (taken in at its clock's time, this step's) and the
  // controller before the next step.
  measured_ = applied;
  accepted_at_ = now;
  control_.actuatorsApplied(applied.torque, applied.force);

  latest_ = {now, state_, driving, command, applied};
  return latest_;
}

std::vector<NormaSample> runSampledLoop(const NormaParameters& parameters,
                                        const SampledLoopConfig& config, long steps_per_row) {
  if (steps_per_row < 1) {
    std::ostringstream what;
    what << "steps per logged row " << steps_per_row << " must be >= 1";
    throw std::invalid_argument(what.str());
  }
  SampledNormaLoop loop(parameters, config);
  std::vector<NormaSample> samples;
  Nanoseconds first = 0;
  for (long index = 0; !loop.complete(); ++index) {
    const SampledStep& step = loop.step();
    if (index == 0) first = step.time;
    if (index % steps_per_row != 0) continue;
    NormaSample s;
    s.t = stampSeconds(step.time - first);
    s.q = step.state.q;
    s.qd = step.state.qd;
    s.x = step.state.x;
    s.y = step.state.y;
    s.psi = step.state.psi;
    const PathPoint reference = loop.reference();
    s.x_d = reference.x;
    s.y_d = reference.y;
    s.error = std::hypot(s.x - reference.x, s.y - reference.y);
    s.torque = step.applied.torque;
    s.force = step.applied.force;
    s.energy = loop.dynamics().totalEnergy(s.q, s.qd);
    samples.push_back(s);
  }
  return samples;
}

}  // namespace spherical_robots::norma
