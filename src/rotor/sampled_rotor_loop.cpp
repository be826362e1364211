#include "spherical_robots/rotor/sampled_rotor_loop.hpp"

#include <Eigen/Geometry>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::rotor {
namespace {

// The rotors on actuators/command and actuators/state, in RotorSpeeds order.
const std::vector<std::string> kRotors = {"rotor_1", "rotor_2"};

hardware::SimulatedActuators rotorActuators(const RotorStackSampling& sampling) {
  hardware::ActuatorLimits limits;
  limits.max_velocity = sampling.max_velocity;
  limits.max_acceleration = sampling.max_acceleration;
  return hardware::SimulatedActuators(kRotors, {limits, limits}, sampling.command_timeout,
                                      sampling.actuator_models, sampling.noise_seed);
}

/// The period of a node's timer or lock-step `next`, as ros::Duration(period) holds it.
Nanoseconds periodNanoseconds(double period, const char* what) {
  const Nanoseconds ns = durationNanoseconds(period);
  if (ns <= 0) throw std::invalid_argument(std::string(what) + " is below one nanosecond");
  return ns;
}

}  // namespace

void validate(const RotorStackSampling& sampling) {
  requireAllPositive({{sampling.k, "inertia ratio k"},
                      {sampling.plant_step, "plant step [s]"},
                      {sampling.publish_rate, "plant publish rate [Hz]"},
                      {sampling.state_timeout, "plant state timeout [s]"},
                      {sampling.odom_timeout, "planner odom timeout [s]"},
                      {sampling.hardware_rate, "hardware interface rate [Hz]"},
                      {sampling.max_velocity, "actuator velocity limit [rad/s]"},
                      {sampling.max_acceleration, "actuator acceleration limit [rad/s^2]"},
                      {sampling.command_timeout, "hardware command timeout [s]"}});
}

SampledRotorLoop::SampledRotorLoop(const RotorStackSampling& sampling,
                                   const ManoeuvreExecutive::Parameters& parameters,
                                   const PlanRequest& request, const PlanResult& plans,
                                   std::uint32_t index)
    : sampling_((validate(sampling), sampling)),
      executive_(parameters),
      actuators_(rotorActuators(sampling)),
      step_(periodNanoseconds(sampling.plant_step, "plant step [s]")),
      command_period_(periodNanoseconds(parameters.command_period, "command period [s]")),
      hardware_period_(periodNanoseconds(1.0 / sampling.hardware_rate, "hardware period [s]")),
      timeline_(0.0, kDefaultMaxClockStep) {
  executive_.offerPlans(request, plans);
  const std::string refused = executive_.execute(index);
  if (!refused.empty()) throw std::invalid_argument(refused);
}

void SampledRotorLoop::step() {
  now_ += step_;
  const double t = stampSeconds(now_);  // ros::Time::toSec(), as the nodes pass their time on
  const double radius = executive_.parameters().radius;
  const double inertia_scale = executive_.parameters().inertia_scale;
  // 1. The plant (PlantLoop::tick, RotorPlantRos).
  const bool measured_fresh =
      measured_at_ != 0 && withinTimeout(measured_at_, now_, sampling_.state_timeout);
  driving_ = measured_fresh ? measured_ : RotorSpeeds{};
  const LoopTimeline::Tick tick = timeline_.tick(now_);
  if (tick.advances()) {
    state_ = advancePlant(sampling_.k, inertia_scale, state_, driving_, tick.elapsed,
                          sampling_.plant_step);
  }
  if (publication_.take(now_)) {
    // odom carries the attitude normalised (rotor_plant); the planner normalises
    // what it reads again (conversions::fromQuaternion).
    const Eigen::Quaterniond sent =
        Eigen::Quaterniond(orientation(state_.u_o, state_.v_o, state_.psi)).normalized();
    rest_ = measureRest(radius * state_.u_a, radius * state_.v_a, radius, sent.normalized());
    rest_at_ = now_;
  }
  // 2. The planner (RotorPlannerRos::command), asked every command period.
  if (now_ >= planner_due_) {
    planner_due_ = now_ + command_period_;
    if (rest_) rest_->fresh = withinTimeout(rest_at_, now_, sampling_.odom_timeout);
    const ManoeuvreExecutive::Output out = executive_.step(now_, rest_);
    if (out.set_point) {
      command_ = *out.set_point;
      const std::string refused = actuators_.command(kRotors, {command_.phi1, command_.phi2}, t);
      if (!refused.empty()) throw std::runtime_error("the actuators refused a set-point: " + refused);
    }
  }
  // 3. The hardware interface, when it is due; the plant reads what it reports.
  if (now_ >= hardware_due_) {
    hardware_due_ = now_ + hardware_period_;
    actuators_.update(t);
    measured_ = {actuators_.measuredVelocities()[0], actuators_.measuredVelocities()[1]};
    measured_at_ = now_;
  }
}

SampledRotorSample SampledRotorLoop::sample() const {
  SampledRotorSample sample;
  sample.t = timeline_.started() ? stampSeconds(now_ - timeline_.start()) : 0.0;
  sample.state = state_;
  sample.command = command_;
  sample.measured = driving_;
  sample.executive = executive_.state();
  return sample;
}

}  // namespace spherical_robots::rotor
