#include "spherical_robots/terrain/smooth_pursuit.hpp"
#include "spherical_robots/core/validation.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace spherical_robots::terrain {
namespace {

void requireGain(double value, const char* name, const char* unit, bool zero_allowed) {
  if (std::isfinite(value) && (value > 0.0 || (zero_allowed && value == 0.0))) return;
  rejectNumber(value, std::string("smooth pursuit gain ") + name + " [" + unit + "]",
               zero_allowed ? "finite and >= 0" : "finite and > 0");
}

}  // namespace

SmoothPursuitGains defaultSmoothGains(RobotType type) {
  SmoothPursuitGains gains;
  if (type == RobotType::RollingAndTurning) {
    gains.window = 1.0;
    gains.lead = 0.25;
    gains.heading_gain = 4.0;
  } else if (type == RobotType::RollingAndSteering) {
    gains.window = 1.0;
    gains.lead = 0.5;
    gains.approach_speed = 0.2;
    gains.cross_gain = 1.5;
    gains.heading_gain = 2.0;
    gains.min_speed = 0.05;
  }
  return gains;
}

void validate(const SmoothPursuitGains& gains) {
  requireGain(gains.window, "window", "s", true);
  requireGain(gains.lead, "lead", "s", true);
  requireGain(gains.approach_speed, "approach_speed", "m/s", false);
  requireGain(gains.along_gain, "along_gain", "1/s", false);
  requireGain(gains.cross_gain, "cross_gain", "1/s", false);
  requireGain(gains.heading_gain, "heading_gain", "1/s", true);
  requireGain(gains.tilt_gain, "tilt_gain", "1/s", false);
  requireGain(gains.max_tilt_rate, "max_tilt_rate", "rad/s", false);
  requireGain(gains.max_tilt, "max_tilt", "rad", false);
  requireGain(gains.min_speed, "min_speed", "m/s", false);
}

SmoothPursuitController::SmoothPursuitController(RobotType type, const SmoothPursuitGains& gains,
                                                 double radius, double tilt_limit)
    : type_(type), gains_(gains), inverse_radius_(1.0 / radius),
      max_tilt_sine_(std::sin(gains.max_tilt)) {
  validate(gains);
  requirePositive(radius, "smooth pursuit: radius [m]");
  requirePositive(tilt_limit, "smooth pursuit: RS tilt limit [rad]");
  if (type == RobotType::RollingAndSteering && !(gains.max_tilt < tilt_limit)) {
    std::ostringstream message;
    message << "smooth pursuit gain max_tilt [rad] must be below the RS tilt limit " << tilt_limit
            << " rad, got " << gains.max_tilt;
    throw std::invalid_argument(message.str());
  }
}

void SmoothPursuitController::rejectInput(double tilt, const TrackingError& error,
                                          const Eigen::Vector3d& desired_velocity) {
  std::ostringstream message;
  message << "smooth pursuit: input not finite (|e_t| " << error.norm << " m, e_t ("
          << error.error.transpose() << ") m, desired velocity (" << desired_velocity.transpose()
          << ") m/s, tilt " << tilt << " rad)";
  throw std::invalid_argument(message.str());
}

Eigen::Vector3d SmoothPursuitController::desiredVelocity(
    const TrackingError& error, const Eigen::Vector3d& desired_velocity) const {
  const Correction c = correction(error, desired_velocity);
  return desired_velocity + (gains_.approach_speed / c.denominator) * c.linear;
}

}  // namespace spherical_robots::terrain
