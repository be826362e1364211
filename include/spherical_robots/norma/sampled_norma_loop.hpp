#pragma once
// The Norma stack's loop as the stack samples it, without ROS: the plant, the controller with its
// command held over a step and the hardware interface with ideal effort actuators, in the order a
// lock-step run of launch/norma_stack.launch works (docs/lockstep.md), with time in whole
// nanoseconds converted to seconds where the nodes convert it (core/stamp.hpp). It calls the very
// functions the nodes call (LoopTimeline, withinTimeout, drivingEfforts, advanceWithHeldInputs,
// NormaControlLoop, SimulatedActuators), so its states equal the stack's bit for bit
// (test/norma_batch_equality.test).
//
// One step at time t (the first at t = step, as the lock-step clock's first step):
// 1. norma_plant: the first step starts the timeline; a later one advances the plant by t minus
//    the previous step with the last measured efforts held, or none if they are older than
//    state_timeout; it publishes the state (odom, joint_states) stamped t.
// 2. norma_controller: NormaControlLoop::step(t, state) on the state as odom and joint_states
//    carry it (ψ read back from odom's orientation: core/angles.hpp, yawOf(yawRotation(ψ))) and
//    the command stamped t; a state the loop rejects commands nothing.
// 3. hardware_interface: the command at t, then update(t); it publishes the applied efforts.
// 4. The plant and the controller take in the applied efforts (for the next step).

#include <optional>
#include <vector>

#include "spherical_robots/core/loop_timeline.hpp"
#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/hardware/simulated_actuators.hpp"
#include "spherical_robots/norma/norma_control_loop.hpp"
#include "spherical_robots/norma/norma_plant.hpp"
#include "spherical_robots/norma/norma_simulation.hpp"

namespace spherical_robots::norma {

/// The stack's parameters the loop depends on; the defaults are launch/norma_stack.launch's.
struct SampledLoopConfig {
  LagrangianVariant variant = LagrangianVariant::kText;
  ControllerKind controller = ControllerKind::kPaper;
  ControllerGains gains;  ///< the controller's (norma_controller's ~gains)
  /// [s] the plant's step (its ~step, and its RK4 step) and the hardware interface's period
  /// (1 / ~rate): the stack has both at 1 ms. > 0, at most kDefaultMaxClockStep.
  double step = 0.001;
  EffortLimits limits;           ///< the hardware interface's effort limits (and the controller's)
  double command_timeout = 0.1;  ///< [s] the hardware interface's watchdog, > 0
  double state_timeout = 0.05;   ///< [s] the plant: older measured efforts drive nothing, > 0
  /// [s] >= 0 after the first step: the run ends at the step at which the stack's plant ends its
  /// scenario; 0: the first step only (the stack takes 0 as forever).
  double duration = 60.0;
  double initial_psi = pathStartHeading();  ///< [rad] ψ at the first step (the plant's initial_psi)
};

/// What one step produced.
struct SampledStep {
  Nanoseconds time = 0;  ///< the step's stamp [ns]
  NormaState state;      ///< the plant's state at the step (norma_state)
  Efforts driving;       ///< the efforts that drove the plant into this step (norma_state's T, F)
  std::optional<ControlOutput> command;  ///< the controller's output; none if it rejected the state
  Efforts applied;       ///< the efforts the actuators apply from this step on (actuators/state)
};

class SampledNormaLoop {
 public:
  /// @throw std::invalid_argument naming the field of a bad config (non-finite, out of range)
  ///        or a bad parameter.
  SampledNormaLoop(const NormaParameters& parameters, const SampledLoopConfig& config);

  /// Runs the loop's next step. @throw std::logic_error once complete(); std::invalid_argument if
  /// the plant's state turns non-finite (the stack's plant would hold it; a batch run ends).
  const SampledStep& step();
  /// True once the step at which the stack's plant ends its scenario has run.
  bool complete() const;

  const SampledLoopConfig& config() const { return config_; }
  Nanoseconds stepNanoseconds() const { return step_ns_; }
  /// The latest step; time 0 before the first.
  const SampledStep& latest() const { return latest_; }
  /// The desired point of eq 52 at the latest step, on the controller's path clock.
  PathPoint reference() const { return control_.reference(stampSeconds(latest_.time)); }
  const NormaDynamics& dynamics() const { return dynamics_; }
  unsigned long rejectedStates() const { return rejected_states_; }
  unsigned long rejectedCommands() const { return rejected_commands_; }

 private:
  NormaDynamics dynamics_;
  SampledLoopConfig config_;
  Nanoseconds step_ns_;
  LoopTimeline timeline_;
  NormaControlLoop control_;
  hardware::SimulatedActuators actuators_;
  NormaState state_;
  Efforts measured_;                         ///< the plant's last actuator state
  std::optional<Nanoseconds> accepted_at_;  ///< when the plant took it in
  SampledStep latest_;
  unsigned long rejected_states_ = 0;
  unsigned long rejected_commands_ = 0;
};

/// The loop from its first step to its last, logged at every `steps_per_row`-th step from the
/// first (steps between rows are not logged, the last one either): t is the time since the first
/// step [s], as ros::Duration::toSec() gives it; T, F the efforts applied from that step on; x_d,
/// y_d the controller's desired point.
/// @throw std::invalid_argument as SampledNormaLoop, or if steps_per_row < 1.
std::vector<NormaSample> runSampledLoop(const NormaParameters& parameters,
                                        const SampledLoopConfig& config, long steps_per_row);

}  // namespace spherical_robots::norma
