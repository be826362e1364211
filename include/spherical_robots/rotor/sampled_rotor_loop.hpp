#pragma once
// The rotor stack's loop as a batch run (docs/lockstep.md, "Equal to the batch run"): what one
// lock-step step of launch/rotor_stack.launch (execute:=true) does, in its order, with its times
// as ros::Time carries them (whole nanoseconds, the first step at one plant step). At each step t:
//   1. the plant (rotor_plant) advances from its last step to t with the rotor speeds it
//      last measured held (at rest if older than its state timeout), and every publish period
//      sends its odometry;
//   2. the planner (rotor_planner), every command period, steps its ManoeuvreExecutive with the
//      rest measured from the last odometry and commands the set-point, if any, at t;
//   3. the hardware interface (hardware_interface_sim), at its rate, advances the actuators to t
//      and reports their measured speeds, which the plant reads.
// Each part is the core code its node calls (LoopTimeline, advancePlant, measureRest,
// ManoeuvreExecutive, SimulatedActuators). No ROS.

#include <cstdint>
#include <string>
#include <vector>

#include "spherical_robots/core/loop_timeline.hpp"
#include "spherical_robots/core/periodic_schedule.hpp"
#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/hardware/simulated_actuators.hpp"
#include "spherical_robots/rotor/manoeuvre_executive.hpp"

namespace spherical_robots::rotor {

/// The stack's parameters the loop depends on, as launch/rotor_stack.launch sets them.
struct RotorStackSampling {
  double k = 2.5;                  ///< the plant's inertia_ratio, > 0
  double plant_step = 0.001;       ///< rotor_plant ~step [s]
  double publish_rate = 50.0;      ///< rotor_plant ~publish_rate [Hz]: odom
  double state_timeout = 0.5;      ///< rotor_plant ~state_timeout [s]: actuator states
  double odom_timeout = 0.5;       ///< rotor_planner ~odom_timeout [s]
  double hardware_rate = 100.0;    ///< hardware_interface ~rate [Hz]
  double max_velocity = 30.0;      ///< hardware_interface ~max_velocity [rad/s]
  double max_acceleration = 300.0;  ///< hardware_interface ~max_acceleration [rad/s^2]
  double command_timeout = 0.5;    ///< hardware_interface ~command_timeout [s]
  /// hardware_interface's actuator models (rotor_1, rotor_2) and their noise seed; none: ideal.
  std::vector<hardware::ActuatorModel> actuator_models;
  std::uint32_t noise_seed = 0;
};

/// @throw std::invalid_argument naming the first field that is not finite and > 0.
void validate(const RotorStackSampling& sampling);

/// The loop after a step.
struct SampledRotorSample {
  double t = 0.0;               ///< [s] since the first step
  ContactCoordinates state;     ///< the plant's
  RotorSpeeds command;          ///< the latest set-point commanded [rad/s] (zero before any)
  RotorSpeeds measured;         ///< the speeds that moved the plant into this step [rad/s]
  ManoeuvreState executive = ManoeuvreState::kIdle;  ///< after its latest step
};

class SampledRotorLoop {
 public:
  /// Offers `plans` (solutions of `request`, in units of R) to an executive with `parameters` and
  /// asks it to execute solution `index` from the first step, as rotor_planner does with its
  /// ~manoeuvre. @throw std::invalid_argument on a bad sampling or parameter, or an index beyond
  /// the plans.
  SampledRotorLoop(const RotorStackSampling& sampling,
                   const ManoeuvreExecutive::Parameters& parameters, const PlanRequest& request,
                   const PlanResult& plans, std::uint32_t index = 0);

  /// One step of the stack, the first at t = one plant step. @throw std::runtime_error if the
  /// actuators refuse a set-point; std::invalid_argument if the plant leaves its domain.
  void step();

  SampledRotorSample sample() const;
  const ManoeuvreExecutive& executive() const { return executive_; }
  /// The latest step's time, as the stack stamps it [ns] (0 before the first).
  Nanoseconds now() const { return now_; }

 private:
  RotorStackSampling sampling_;
  ManoeuvreExecutive executive_;
  hardware::SimulatedActuators actuators_;
  Nanoseconds step_;
  Nanoseconds command_period_;
  Nanoseconds hardware_period_;

  Nanoseconds now_ = 0;
  LoopTimeline timeline_;  ///< the plant's: start, elapsed time
  // The plant (rotor_plant).
  ContactCoordinates state_;
  RotorSpeeds measured_;          ///< the last actuator state read
  Nanoseconds measured_at_ = 0;   ///< 0: never
  RotorSpeeds driving_;           ///< what moved the plant in the latest step
  PeriodicSchedule publication_{1.0 / sampling_.publish_rate};
  // The planner (rotor_planner).
  std::optional<RestMeasurement> rest_;  ///< from the last odometry
  Nanoseconds rest_at_ = 0;
  Nanoseconds planner_due_ = 0;
  RotorSpeeds command_;
  // The hardware interface.
  Nanoseconds hardware_due_ = 0;
};

}  // namespace spherical_robots::rotor
