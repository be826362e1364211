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

[[noreturn]] void rejectInput(double tilt, const TrackingError& error,
                              const Eigen::Vector3d& desired_velocity) {
  std::ostringstream message;
  message << "smooth pursuit: input not finite (|e_t| " << error.norm << " m, e_t ("
          << error.error.transpose() << ") m, desired velocity (" << desired_velocity.transpose()
          << ") m/s, tilt " << tilt << " rad)";
  throw std::invalid_argument(message.str());
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

// Linear in e_t near p_d (stiffer along the path, where only the speed responds, than across,
// where types that must turn respond through their heading), never faster than v_c far from it.
// Inline: command() calls it at every RK stage.
inline SmoothPursuitController::Correction SmoothPursuitController::correction(
    const TrackingError& error, const Eigen::Vector3d& desired_velocity) const {
  const Eigen::Vector3d along =
      desired_velocity *
      (1.0 / std::sqrt(desired_velocity.squaredNorm() + gains_.min_speed * gains_.min_speed));
  const Eigen::Vector3d linear = gains_.cross_gain * error.error +
                                 (gains_.along_gain - gains_.cross_gain) *
                                     error.error.dot(along) * along;
  return {linear, gains_.approach_speed + linear.norm()};
}

Eigen::Vector3d SmoothPursuitController::desiredVelocity(
    const TrackingError& error, const Eigen::Vector3d& desired_velocity) const {
  const Correction c = correction(error, desired_velocity);
  return desired_velocity + (gains_.approach_speed / c.denominator) * c.linear;
}

DriveRates SmoothPursuitController::command(const ContactGeometry& geometry, double tilt,
                                            const TrackingError& error,
                                            const Eigen::Vector3d& desired_velocity) const {
  const Eigen::Vector3d& e = error.error;
  const Eigen::Vector3d& w = desired_velocity;
  if (!allFinite(error.norm, e.x(), e.y(), e.z(), w.x(), w.y(), w.z(), tilt)) {
    rejectInput(tilt, error, desired_velocity);
  }
  // The robot moves in the tangent plane: u's components along h and l. With D = v_c + |k|,
  // D u = D w + v_c k has u's direction without a division by D, which the turn, at the end of
  // the chain of operations from one RK stage to the next, then does not wait for.
  const Correction c = correction(error, desired_velocity);
  const Eigen::Vector3d& h = geometry.heading_frame.col(0);
  const Eigen::Vector3d& l = geometry.heading_frame.col(1);
  const double approach_speed = gains_.approach_speed;
  const double forward_times_d =
      c.denominator * desired_velocity.dot(h) + approach_speed * c.linear.dot(h);
  const double leftward_times_d =
      c.denominator * desired_velocity.dot(l) + approach_speed * c.linear.dot(l);
  const double inverse_d = 1.0 / c.denominator;
  const double forward = forward_times_d * inverse_d;
  const double leftward = leftward_times_d * inverse_d;
  // Turn towards u: k_h times the sine of the angle from h to u, u_l / sqrt(u_h^2 + u_l^2 + v_e^2)
  // (|u| in the plane regularised: u's direction means nothing where |u| < v_e), all times D.
  const double floor_times_d = gains_.min_speed * c.denominator;
  const double turn =
      gains_.heading_gain * leftward_times_d /
      std::sqrt(forward_times_d * forward_times_d + leftward_times_d * leftward_times_d +
                floor_times_d * floor_times_d);
  DriveRates rates;
  switch (type_) {
    case RobotType::ThreeAxisRolling:  // the contact point moves with R theta' h - R phi' l (eq 33)
      rates.roll_rate = forward * inverse_radius_;
      rates.lateral_rate = -leftward * inverse_radius_;
      rates.turn_rate = turn;
      break;
    case RobotType::TwoAxisRolling:
      rates.roll_rate = forward * inverse_radius_;
      rates.lateral_rate = -leftward * inverse_radius_;
      break;
    case RobotType::RollingAndTurning:  // R theta' h only (eq 38): u's sideways part by turning
      rates.roll_rate = forward * inverse_radius_;
      rates.turn_rate = turn;
      break;
    case RobotType::RollingAndSteering: {
      // RS turns only while it rolls (eq 44), so it rolls forward at the cardioid speed
      // (|u| + u.h) / 2: u.h when heading along u, |u| / 2 with u abeam, 0 only with u straight
      // behind; at R alpha' cos(phi) (eq 48). The turn comes from the tilt: eq 44 inverted,
      // sin(phi*) = -turn / alpha', regularised where alpha' -> 0 and bounded smoothly by
      // max_tilt; the tilt rate servos phi towards phi*, smoothly bounded by max_tilt_rate.
      // |u| by sqrt, not hypot: speeds of metres per second neither overflow nor underflow.
      const double planar_speed = std::sqrt(forward * forward + leftward * leftward);
      rates.roll_rate = 0.5 * (planar_speed + forward) * inverse_radius_ / std::cos(tilt);
      const double roll_floor = gains_.min_speed * inverse_radius_;
      const double sine = -turn * rates.roll_rate /
                          (rates.roll_rate * rates.roll_rate + roll_floor * roll_floor);
      const double target_tilt =
          std::asin(max_tilt_sine_ * std::tanh(sine / max_tilt_sine_));
      rates.lateral_rate =
          gains_.max_tilt_rate *
          std::tanh(gains_.tilt_gain * (target_tilt - tilt) / gains_.max_tilt_rate);
      break;
    }
  }
  return rates;
}

}  // namespace spherical_robots::terrain
