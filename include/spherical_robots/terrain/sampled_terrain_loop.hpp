#pragma once
// The terrain stack's loop as a batch run (docs/lockstep.md, "Equal to the batch run"): what one
// lock-step step of launch/terrain_stack.launch does, in its order, with its times as ros::Time
// carries them (whole nanoseconds, from the first step at one plant step) and its messages as
// float64 values. At each step t:
//   1. the plant (terrain_plant) advances from its last step to t with the rates it last
//      measured held (at rest if they are older than the state timeout), and every publish period
//      sends its odometry (the body's pose, BodyFrame::pose) and RS tilt;
//   2. the controller (pure_pursuit_controller), at its rate, commands from the last state it
//      received (at rest if older than its input timeout), the geometry recovered from the
//      body's pose through the terrain model (BodyFrame::state);
//   3. the hardware interface (hardware_interface_sim, ideal actuators) takes the command at t and,
//      at its rate, advances the actuators to t and reports their velocities, which the plant reads.
// Each part is the core code its node calls (advanceWithHeldRates, PathTracker,
// SimulatedActuators), so a run equals the stack's value for value (test/batch_equality.test).

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "spherical_robots/core/loop_timeline.hpp"
#include "spherical_robots/core/periodic_schedule.hpp"
#include "spherical_robots/core/stamp.hpp"
#include "spherical_robots/hardware/simulated_actuators.hpp"
#include "spherical_robots/terrain/body_frame.hpp"
#include "spherical_robots/terrain/path_tracker.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace spherical_robots::terrain {

/// What stands between the controller's drive rates and the actuators, both ways: in the terrain
/// stack nothing (the actuators are the drive rates, DirectDrive); in the roller stack the
/// friction drive's inverse (friction_drive_controller) and forward kinematics with slip
/// (friction_drive_sim), roller::RollerActuation.
class ActuatorDrive {
 public:
  virtual ~ActuatorDrive() = default;
  /// The actuators' names on actuators/command and actuators/state.
  virtual std::vector<std::string> actuatorNames() const = 0;
  /// Their set-points for the controller's command. @throw std::invalid_argument if non-finite.
  virtual std::vector<double> setpoints(const DriveRates& command) const = 0;
  /// The drive rates the plant reads for the actuators' measured rates, in actuatorNames() order.
  /// @throw std::invalid_argument if non-finite.
  virtual DriveRates driveRates(const std::vector<double>& measured) const = 0;
};

/// The terrain stack's actuators: one per actuated drive rate (terrain::actuatorNames).
class DirectDrive final : public ActuatorDrive {
 public:
  explicit DirectDrive(RobotType type) : type_(type) {}
  std::vector<std::string> actuatorNames() const override { return terrain::actuatorNames(type_); }
  std::vector<double> setpoints(const DriveRates& command) const override {
    return actuatedValues(type_, command);
  }
  DriveRates driveRates(const std::vector<double>& measured) const override {
    return ratesFromActuated(type_, measured);
  }

 private:
  RobotType type_;
};

/// How the stack samples its loop: the nodes' parameters as launch/terrain_stack.launch sets them
/// (launch/roller_stack.launch: max_velocity 60, max_acceleration 300).
struct StackSampling {
  double plant_step = 0.01;        ///< terrain_plant ~step [s]
  double publish_rate = 50.0;      ///< terrain_plant ~publish_rate [Hz]: odom, terrain_state
  double state_timeout = 0.5;      ///< terrain_plant ~state_timeout [s]: actuator states
  double control_rate = 50.0;      ///< pure_pursuit_controller ~rate [Hz]
  double controller_state_timeout = 0.5;  ///< pure_pursuit_controller ~state_timeout [s]: odom
  double hardware_rate = 100.0;    ///< hardware_interface ~rate [Hz]
  double max_velocity = 20.0;      ///< hardware_interface ~max_velocity [rad/s]
  double max_acceleration = 50.0;  ///< hardware_interface ~max_acceleration [rad/s^2]
  double command_timeout = 0.5;    ///< hardware_interface ~command_timeout [s]
  /// hardware_interface's actuator models (actuator_models:=FILE), one per actuator in
  /// ActuatorDrive::actuatorNames() order, and their noise seed; none: ideal actuators.
  std::vector<hardware::ActuatorModel> actuator_models;
  std::uint32_t noise_seed = 0;
};

/// @throw std::invalid_argument naming the first field that is not finite and > 0.
void validate(const StackSampling& sampling);

/// The loop after a step.
struct SampledTerrainSample {
  double t = 0.0;  ///< [s] since the first step
  TerrainState state;
  ContactGeometry geometry;  ///< the plant's, at state
  DriveRates realised;       ///< the rates the robot realises from the held measured ones
  TrackingCommand tracked;   ///< the controller's latest (held between its steps)
};

class SampledTerrainLoop {
 public:
  /// The kinematics, law, path and drive must outlive the loop; the law must be for the
  /// kinematics' robot type. drive null: DirectDrive (the terrain stack).
  /// @throw std::invalid_argument on a bad sampling or a type mismatch.
  SampledTerrainLoop(const TerrainKinematics& kinematics, const PursuitController& law,
                     const ReferencePath& path, const StackSampling& sampling = {},
                     const ActuatorDrive* drive = nullptr, const TerrainState& initial = {});

  /// One step of the stack, the first at t = one plant step. @throw std::runtime_error if the
  /// plant's state stops being finite or the actuators refuse a command (neither happens in a
  /// stack that runs on).
  void step();

  /// After the latest step; before the first, the initial state at t = 0.
  SampledTerrainSample sample() const;
  /// The latest step's time, as the stack stamps it [ns] (0 before the first).
  Nanoseconds now() const { return now_; }

 private:
  const TerrainKinematics& kinematics_;
  StackSampling sampling_;
  DirectDrive direct_drive_;
  const ActuatorDrive& drive_stage_;
  PathTracker tracker_;
  hardware::SimulatedActuators actuators_;
  std::vector<std::string> actuator_names_;
  Nanoseconds step_;
  Nanoseconds control_period_;
  Nanoseconds hardware_period_;

  Nanoseconds now_ = 0;
  LoopTimeline timeline_;  ///< the plant's (PlantLoop's): start, elapsed time
  BodyFrame body_frame_;   ///< odometry's pose to the state, as the controller recovers it
  // The plant (terrain_plant).
  TerrainState state_;
  Eigen::Quaterniond orientation_;
  DriveRates measured_;           ///< the last actuator state read
  Nanoseconds measured_at_ = 0;   ///< when it was read; 0: never
  DriveRates drive_;              ///< what moved the plant in the latest step
  PeriodicSchedule publication_{1.0 / sampling_.publish_rate};
  // The controller (pure_pursuit_controller).
  ContactGeometry received_;      ///< from the last odom
  double received_tilt_ = 0.0;
  Nanoseconds received_at_ = 0;   ///< 0: none yet
  Nanoseconds control_due_ = 0;
  TrackingCommand tracked_;
  // The hardware interface.
  Nanoseconds hardware_due_ = 0;
};

}  // namespace spherical_robots::terrain
