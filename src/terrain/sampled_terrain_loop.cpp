#include "spherical_robots/terrain/sampled_terrain_loop.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/validation.hpp"
#include "spherical_robots/terrain/terrain_simulation.hpp"

namespace spherical_robots::terrain {
namespace {

hardware::SimulatedActuators actuatorsOf(const ActuatorDrive& drive, const StackSampling& sampling) {
  hardware::ActuatorLimits limits;
  limits.max_velocity = sampling.max_velocity;
  limits.max_acceleration = sampling.max_acceleration;
  const std::vector<std::string> names = drive.actuatorNames();
  return hardware::SimulatedActuators(names, std::vector<hardware::ActuatorLimits>(names.size(), limits),
                                      sampling.command_timeout, sampling.actuator_models,
                                      sampling.noise_seed);
}

}  // namespace

void validate(const StackSampling& sampling) {
  requireAllPositive({{sampling.plant_step, "plant step [s]"},
                      {sampling.publish_rate, "plant publish rate [Hz]"},
                      {sampling.state_timeout, "plant state timeout [s]"},
                      {sampling.control_rate, "controller rate [Hz]"},
                      {sampling.controller_state_timeout, "controller state timeout [s]"},
                      {sampling.hardware_rate, "hardware interface rate [Hz]"},
                      {sampling.max_velocity, "actuator velocity limit [rad/s]"},
                      {sampling.max_acceleration, "actuator acceleration limit [rad/s^2]"},
                      {sampling.command_timeout, "hardware command timeout [s]"}});
}

SampledTerrainLoop::SampledTerrainLoop(const TerrainKinematics& kinematics,
                                       const PursuitController& law, const ReferencePath& path,
                                       const StackSampling& sampling, const ActuatorDrive* drive,
                                       const TerrainState& initial)
    : kinematics_(kinematics),
      sampling_((validate(sampling), sampling)),
      direct_drive_(kinematics.type()),
      drive_stage_(drive != nullptr ? *drive : direct_drive_),
      tracker_(law, path, kinematics.surface()),
      actuators_(actuatorsOf(drive_stage_, sampling)),
      actuator_names_(drive_stage_.actuatorNames()),
      // As the nodes turn their parameters into ros::Duration.
      step_(durationNanoseconds(sampling.plant_step)),
      control_period_(durationNanoseconds(1.0 / sampling.control_rate)),
      hardware_period_(durationNanoseconds(1.0 / sampling.hardware_rate)),
      timeline_(0.0, kDefaultMaxClockStep),
      body_frame_(kinematics.surface(), kinematics.radius()),
      state_(initial),
      orientation_(kinematics.geometry(initial).heading_frame) {
  if (law.type() != kinematics.type()) {
    throw std::invalid_argument("the law is for robot type " + toString(law.type()) +
                                " but the kinematics are " + toString(kinematics.type()));
  }
  if (step_ <= 0) throw std::invalid_argument("plant step [s] is below one nanosecond");
}

void SampledTerrainLoop::step() {
  now_ += step_;
  // 1. The plant (PlantLoop::tick, TerrainPlantRos).
  const bool measured_fresh =
      measured_at_ != 0 && withinTimeout(measured_at_, now_, sampling_.state_timeout);
  drive_ = measured_fresh ? measured_ : DriveRates{};
  const LoopTimeline::Tick tick = timeline_.tick(now_);
  if (tick.advances()) {
    const RollingState next = advanceWithHeldRates(kinematics_, {state_, orientation_}, drive_,
                                                   tick.elapsed, sampling_.plant_step);
    state_ = next.state;
    orientation_ = next.orientation;
  }
  if (publication_.take(now_)) {
    // The controller sees odom (the body's pose) and, for RS, joint_states (the tilt), and
    // recovers the contact geometry from them through the terrain model.
    received_tilt_ = state_.phi;
    received_ = contactGeometry(kinematics_.surface(), kinematics_.radius(),
                                body_frame_.state(BodyFrame::pose(kinematics_.geometry(state_)),
                                                  received_tilt_));
    received_at_ = now_;
  }
  // 2. The controller (PurePursuitControllerRos::control), which the sequencer asks when it is due.
  if (now_ >= control_due_) {
    control_due_ = now_ + control_period_;
    DriveRates command;
    if (received_at_ != 0 && withinTimeout(received_at_, now_, sampling_.controller_state_timeout)) {
      tracked_ = tracker_.command(now_, received_, received_tilt_);
      command = tracked_.rates;
    }
    // 3a. The hardware interface takes the command as it arrives, stamped with the step (in the
    // roller stack converted to motor rates by friction_drive_controller on the way).
    const std::string refused =
        actuators_.command(actuator_names_, drive_stage_.setpoints(command), stampSeconds(now_));
    if (!refused.empty()) throw std::runtime_error("the actuators refused a command: " + refused);
  }
  // 3b. The hardware interface's own work when it is due; the plant reads what it reports (in
  // the roller stack converted to drive rates by friction_drive_sim on the way).
  if (now_ >= hardware_due_) {
    hardware_due_ = now_ + hardware_period_;
    actuators_.update(stampSeconds(now_));
    measured_ = drive_stage_.driveRates(actuators_.measuredVelocities());
    measured_at_ = now_;
  }
}

SampledTerrainSample SampledTerrainLoop::sample() const {
  SampledTerrainSample sample;
  sample.t = timeline_.started() ? stampSeconds(now_ - timeline_.start()) : 0.0;
  sample.state = state_;
  sample.geometry = kinematics_.geometry(state_);
  sample.realised = kinematics_.realisedRates(state_, drive_);
  sample.tracked = tracked_;
  return sample;
}

}  // namespace spherical_robots::terrain
