#include "spherical_robots/terrain/pure_pursuit.hpp"
#include "spherical_robots/core/sin_cos.hpp"
#include "spherical_robots/core/validation.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace spherical_robots::terrain {

PursuitGains defaultGains(RobotType type) {
  PursuitGains gains;
  if (type == RobotType::TwoAxisRolling) gains.k_phi1 = 3.0;
  return gains;
}

void validate(const PursuitGains& gains) {
  const std::pair<const char*, double> all[] = {
      {"k_e", gains.k_e},           {"k_theta", gains.k_theta},   {"k_phi1", gains.k_phi1},
      {"k_phi2", gains.k_phi2},     {"k_psi", gains.k_psi},       {"k_theta1", gains.k_theta1},
      {"k_theta2", gains.k_theta2}, {"k_alpha", gains.k_alpha},   {"k_phi", gains.k_phi}};
  for (const auto& [name, value] : all) {
    if (!std::isfinite(value) || value < 0.0) {
      std::ostringstream message;
      message << "pure pursuit gain " << name << " must be finite and >= 0, got " << value;
      throw std::invalid_argument(message.str());
    }
  }
  if (gains.k_e <= 0.0) {
    throw std::invalid_argument("pure pursuit gain k_e must be > 0 m, got " +
                                std::to_string(gains.k_e));
  }
}

PurePursuitController::PurePursuitController(RobotType type, const PursuitGains& gains,
                                             double radius)
    : type_(type), gains_(gains), radius_(radius) {
  validate(gains);
  requirePositive(radius, "pure pursuit: radius [m]");
}

DriveRates PurePursuitController::command(const ContactGeometry&, double, const TrackingError& error,
                                          const Eigen::Vector3d& desired_velocity) const {
  return command(error, desired_velocity);
}

DriveRates PurePursuitController::command(const TrackingError& error,
                                          const Eigen::Vector3d& desired_velocity) const {
  const Eigen::Vector3d& w = desired_velocity;
  if (!allFinite(error.norm, error.zeta, w.x(), w.y(), w.z())) {
    throw std::invalid_argument("pure pursuit: tracking error or desired velocity not finite");
  }
  const double normalised = error.norm / (gains_.k_e + error.norm);
  const double feed_forward = desired_velocity.norm() / radius_;
  const auto [sin_zeta, cos_zeta] = sinCos(error.zeta);
  // Copied in, not captured by reference: a lambda may capture a structured binding only from
  // C++20 on (GCC accepts it in C++17, clang 14, which builds the fuzz targets, does not).
  const auto lateral = [&, sin_zeta = sin_zeta](double k_phi1, double k_phi2) {
    return -(k_phi1 * normalised + k_phi2) * sin_zeta;
  };
  DriveRates rates;
  switch (type_) {
    case RobotType::ThreeAxisRolling:  // eq 55
      rates.roll_rate = gains_.k_theta * normalised * cos_zeta + feed_forward;
      rates.lateral_rate = lateral(gains_.k_phi1, gains_.k_phi2);
      rates.turn_rate = gains_.k_psi * error.zeta;
      break;
    case RobotType::TwoAxisRolling:  // eq 56
      rates.roll_rate = (gains_.k_theta1 * normalised + gains_.k_theta2) * cos_zeta;
      rates.lateral_rate = lateral(gains_.k_phi1, gains_.k_phi2);
      break;
    case RobotType::RollingAndTurning:  // eq 57
      rates.roll_rate = gains_.k_theta * normalised * cos_zeta + feed_forward;
      rates.turn_rate = gains_.k_psi * error.zeta;
      break;
    case RobotType::RollingAndSteering:  // eq 58, tilt sign corrected (docs/conventions.md)
      rates.roll_rate = gains_.k_alpha * normalised * cos_zeta + feed_forward;
      rates.lateral_rate = -gains_.k_phi * error.zeta;
      break;
  }
  return rates;
}

}  // namespace spherical_robots::terrain
