#pragma once
// The friction drive as a robot's actuation (launch/roller_stack.launch): motors turn the two
// rollers at angular rates [rad/s] (what actuators/command and actuators/state carry), the rollers'
// peripheral speeds drive the sphere (friction_drive.hpp), and the sphere rolls on the level floor
// below it. The rest of the stack speaks the terrain plant's 2R drive rates: on a level floor with
// heading ψ = 0 the heading frame is Σ-xyz itself (h = x, l = y, n = z), so θ̇ (about l) = ω_y and
// φ̇ (about h) = ω_x. Conventions: docs/conventions.md, "Friction drive".

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "spherical_robots/roller/friction_drive.hpp"
#include "spherical_robots/terrain/robot_type.hpp"
#include "spherical_robots/terrain/sampled_terrain_loop.hpp"

namespace spherical_robots::roller {

/// The horizontal part of ω [rad/s] as 2R drive rates. The spin ω_z is dropped: on a level floor it
/// turns the sphere about the vertical through the contact point and does not move the centre.
terrain::DriveRates rollingRates(const Eigen::Vector3d& omega);

/// The motors' names on actuators/command and actuators/state: the paper's roller 1 and 2.
inline const std::array<std::string, 2> kMotorNames = {"roller_1", "roller_2"};

/// Also the roller stack's drive between the 2R controller and the motors, as its friction drive
/// nodes convert (terrain::ActuatorDrive, for the batch run that replays the stack).
class RollerActuation final : public terrain::ActuatorDrive {
 public:
  /// @param roller_radius radius of both rollers [m], finite and > 0: peripheral speed
  ///        v_i = roller_radius · motor rate_i.
  /// @throw std::invalid_argument on a bad roller radius.
  RollerActuation(const FrictionDrive& drive, double roller_radius);

  const FrictionDrive& drive() const { return drive_; }
  double rollerRadius() const { return roller_radius_; }

  /// The motor rates [rad/s] for which the drive rolls the sphere's centre as the 2R rates
  /// (θ̇, φ̇) [rad/s] would (V = r (θ̇, −φ̇, 0)): the inverse kinematics (eqs 15, 18, 19, 22) for
  /// that speed and direction (0, 0 for V = 0). roll_rate and lateral_rate only: 2R never turns.
  /// @throw std::invalid_argument on a non-finite rate.
  std::array<double, 2> motorRates(const terrain::DriveRates& rates) const;

  /// What the drive does with measured motor rates [rad/s]: ω of eq 11 and the slip of eq 28,
  /// defined for every pair of rates (0, 0 included: ω = 0, no slip). `motion` is eq 14's where ω
  /// has a horizontal part, and zero otherwise.
  /// @throw std::invalid_argument on a non-finite rate.
  DriveState driveState(const std::array<double, 2>& motor_rates) const;

  /// kMotorNames.
  std::vector<std::string> actuatorNames() const override;
  /// motorRates() of the command's 2R rates (friction_drive_controller).
  std::vector<double> setpoints(const terrain::DriveRates& command) const override;
  /// The 2R rates of driveState(measured)'s ω (friction_drive_sim). @throw std::invalid_argument
  /// unless two finite rates.
  terrain::DriveRates driveRates(const std::vector<double>& measured) const override;

 private:
  FrictionDrive drive_;
  double roller_radius_;
};

}  // namespace spherical_robots::roller
