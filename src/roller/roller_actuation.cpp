#include "spherical_robots/roller/roller_actuation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::roller {

terrain::DriveRates rollingRates(const Eigen::Vector3d& omega) {
  requireFinite(omega.x(), "sphere angular velocity omega_x [rad/s]");
  requireFinite(omega.y(), "sphere angular velocity omega_y [rad/s]");
  terrain::DriveRates rates;
  rates.roll_rate = omega.y();
  rates.lateral_rate = omega.x();
  return rates;
}

RollerActuation::RollerActuation(const FrictionDrive& drive, double roller_radius)
    : drive_(drive), roller_radius_(roller_radius) {
  requirePositive(roller_radius, "roller radius [m]");
}

std::array<double, 2> RollerActuation::motorRates(const terrain::DriveRates& rates) const {
  requireFinite(rates.roll_rate, "roll rate theta_dot [rad/s]");
  requireFinite(rates.lateral_rate, "lateral rate phi_dot [rad/s]");
  const double r = drive_.geometry().radius();
  // V = ω × r z with ω = (φ̇, θ̇, ·): V = r (θ̇, −φ̇, 0) (eq 13).
  const double vx = r * rates.roll_rate;
  const double vy = -r * rates.lateral_rate;
  // V = 0 gives speeds 0, 0 whatever the direction.
  const RollerSpeeds speeds = drive_.inverse(std::hypot(vx, vy), std::atan2(vy, vx)).speeds;
  return {speeds.v1 / roller_radius_, speeds.v2 / roller_radius_};
}

DriveState RollerActuation::driveState(const std::array<double, 2>& motor_rates) const {
  DriveState state;
  state.speeds = {roller_radius_ * motor_rates[0], roller_radius_ * motor_rates[1]};
  state.omega = drive_.angularVelocity(state.speeds);  // eq 11; checks finiteness
  state.slip = drive_.slipSpeeds(state.omega, state.speeds);  // eq 28
  const Eigen::Vector3d omega = state.omega;
  if (std::hypot(omega.x(), omega.y()) > kDegenerateTolerance * omega.norm())
    state.motion = sphereMotion(omega, drive_.geometry().radius());  // eq 14
  return state;
}

std::vector<std::string> RollerActuation::actuatorNames() const {
  return {kMotorNames.begin(), kMotorNames.end()};
}

std::vector<double> RollerActuation::setpoints(const terrain::DriveRates& command) const {
  const std::array<double, 2> rates =
      motorRates(terrain::keepActuated(terrain::RobotType::TwoAxisRolling, command));
  return {rates[0], rates[1]};
}

terrain::DriveRates RollerActuation::driveRates(const std::vector<double>& measured) const {
  if (measured.size() != kMotorNames.size())
    throw std::invalid_argument("the friction drive has 2 motors, got " +
                                std::to_string(measured.size()) + " rates");
  return terrain::keepActuated(terrain::RobotType::TwoAxisRolling,
                               rollingRates(driveState({measured[0], measured[1]}).omega));
}

}  // namespace spherical_robots::roller
