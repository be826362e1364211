#include "spherical_robots/roller/friction_drive.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::roller {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

void requireFiniteOmega(const Eigen::Vector3d& omega) {
  requireFinite(omega.x(), "omega_x [rad/s]");
  requireFinite(omega.y(), "omega_y [rad/s]");
  requireFinite(omega.z(), "omega_z [rad/s]");
}

void requireFiniteSpeeds(const RollerSpeeds& speeds) {
  requireFinite(speeds.v1, "roller speed v1 [m/s]");
  requireFinite(speeds.v2, "roller speed v2 [m/s]");
}

}  // namespace

FrictionDrive::FrictionDrive(const RollerGeometry& geometry) : geometry_(geometry) {
  const double r = geometry_.radius();
  const double n = geometry_.crossNorm();
  const Eigen::Vector3d& e = geometry_.normal();
  const RollerContact& first = geometry_.rollers()[0];
  const RollerContact& second = geometry_.rollers()[1];
  // Eq 11 sorted by speed (eqs 16, 17): v1 moves ω along −P2 in the plane (ω_t) and along e by
  // half of its line's height −v1 sin α1 / r (ω_s); v2 likewise with P1.
  omega_per_speed_[0] =
      -std::cos(first.alpha) / n * second.point - std::sin(first.alpha) / (2 * r) * e;
  omega_per_speed_[1] =
      std::cos(second.alpha) / n * first.point - std::sin(second.alpha) / (2 * r) * e;
  // The paper's X × Y with X = ∂ω/∂v2 and Y = ∂ω/∂v1. Never zero: X and Y are independent
  // whenever cos α_i != 0 and P1, P2 are, which RollerGeometry guarantees.
  plane_normal_ = omega_per_speed_[1].cross(omega_per_speed_[0]).normalized();
}

const RollerContact& FrictionDrive::contact(std::size_t roller) const {
  if (roller > 1) {
    throw std::out_of_range("roller index " + std::to_string(roller) +
                            ": the drive has rollers 0 (paper's 1) and 1 (paper's 2)");
  }
  return geometry_.rollers()[roller];
}

const Eigen::Vector3d& FrictionDrive::omegaPerSpeed(std::size_t roller) const {
  contact(roller);  // range check
  return omega_per_speed_[roller];
}

Eigen::Vector3d FrictionDrive::angularVelocity(const RollerSpeeds& speeds) const {
  requireFiniteSpeeds(speeds);
  return speeds.v1 * omega_per_speed_[0] + speeds.v2 * omega_per_speed_[1];  // eqs 11, 16
}

RollerSpeeds FrictionDrive::rollerSpeeds(const Eigen::Vector3d& omega) const {
  requireFiniteOmega(omega);
  const Eigen::Vector3d& e = geometry_.normal();
  const auto speed = [&](const RollerContact& c) {
    return e.dot(omega.cross(c.point)) / std::cos(c.alpha);  // eq 22
  };
  return {speed(geometry_.rollers()[0]), speed(geometry_.rollers()[1])};
}

double FrictionDrive::rho(double direction) const { return std::atan(tanRho(direction)); }

double FrictionDrive::tanRho(double direction) const {
  requireFinite(direction, "direction phi [rad]");
  const Eigen::Vector3d& n = plane_normal_;
  if (std::abs(n.z()) <= kDegenerateTolerance) {
    std::ostringstream message;
    message << "span{X, Y} of eq 17 is vertical ((X x Y)_z = " << n.z()
            << " of a unit normal, <= " << kDegenerateTolerance
            << "): eq 18 divides by it; the rollers can drive the sphere only along phi = "
            // ω ⊥ n with n horizontal gives V = r (ω_y, −ω_x) ∥ (n_x, n_y).
            << wrapToPeriod(std::atan2(n.y(), n.x()), M_PI) << " rad and that + pi";
    throw std::invalid_argument(message.str());
  }
  // ⟨ω, X × Y⟩ = 0 with ω ∝ (−sin φ, cos φ, tan ρ) (eqs 15, 18).
  return (n.x() * std::sin(direction) - n.y() * std::cos(direction)) / n.z();
}

Eigen::Vector3d FrictionDrive::angularVelocityFor(double speed, double direction) const {
  requireFinite(speed, "speed [m/s]");
  if (speed < 0.0) {
    std::ostringstream message;
    message << "speed [m/s] must be >= 0 (it is the norm |V| of eq 13), got " << speed
            << "; reverse the direction instead";
    throw std::invalid_argument(message.str());
  }
  const double tan_rho = tanRho(direction);
  return speed / geometry_.radius() *
         Eigen::Vector3d(-std::sin(direction), std::cos(direction), tan_rho);  // eq 19
}

Eigen::Vector3d FrictionDrive::slipVelocity(const Eigen::Vector3d& omega,
                                            const RollerSpeeds& speeds, std::size_t roller) const {
  const RollerContact& c = contact(roller);
  requireFiniteOmega(omega);
  requireFiniteSpeeds(speeds);
  const double v = roller == 0 ? speeds.v1 : speeds.v2;
  return omega.cross(c.point) - v * c.rolling_direction;  // eq 25
}

std::array<double, 2> FrictionDrive::slipSpeeds(const Eigen::Vector3d& omega,
                                                const RollerSpeeds& speeds) const {
  return {slipVelocity(omega, speeds, 0).dot(contact(0).tangent),  // eq 28
          slipVelocity(omega, speeds, 1).dot(contact(1).tangent)};
}

double FrictionDrive::squaredSlip(const Eigen::Vector3d& omega, const RollerSpeeds& speeds) const {
  return slipVelocity(omega, speeds, 0).squaredNorm() +
         slipVelocity(omega, speeds, 1).squaredNorm();
}

double FrictionDrive::constraintLineDistance(const Eigen::Vector3d& omega,
                                             const RollerSpeeds& speeds, std::size_t roller) const {
  const RollerContact& c = contact(roller);
  requireFiniteOmega(omega);
  requireFiniteSpeeds(speeds);
  const double v = roller == 0 ? speeds.v1 : speeds.v2;
  // l_i passes through −(v_i / r) η_i along P_i (eq 4): drop the P_i component of the offset.
  const Eigen::Vector3d offset = omega + v / geometry_.radius() * c.axis;
  const Eigen::Vector3d along = c.point.normalized();
  return (offset - offset.dot(along) * along).norm();
}

double FrictionDrive::constraintLineGap(const RollerSpeeds& speeds) const {
  requireFiniteSpeeds(speeds);
  // Both lines run parallel to span{P1, P2}, at heights −v_i sin α_i / r above it (eq 9), and
  // their projections onto it always meet (eq 7, appendix B).
  return std::abs(speeds.v1 * std::sin(contact(0).alpha) - speeds.v2 * std::sin(contact(1).alpha)) /
         geometry_.radius();
}

DriveState FrictionDrive::forward(const RollerSpeeds& speeds) const {
  DriveState state;
  state.speeds = speeds;
  state.omega = angularVelocity(speeds);
  try {
    state.motion = sphereMotion(state.omega, geometry_.radius());
  } catch (const std::invalid_argument& error) {
    std::ostringstream message;
    message << "roller speeds v1 = " << speeds.v1 << ", v2 = " << speeds.v2
            << " m/s: " << error.what();
    throw std::invalid_argument(message.str());
  }
  state.slip = slipSpeeds(state.omega, speeds);
  return state;
}

DriveState FrictionDrive::inverse(double speed, double direction) const {
  DriveState state;
  state.omega = angularVelocityFor(speed, direction);
  state.motion = {speed, wrapToPeriod(direction, kTwoPi), rho(direction)};
  state.speeds = rollerSpeeds(state.omega);
  state.slip = slipSpeeds(state.omega, state.speeds);
  return state;
}

SphereMotion sphereMotion(const Eigen::Vector3d& omega, double radius) {
  requirePositive(radius, "sphere radius r [m]");
  requireFiniteOmega(omega);
  const double horizontal = std::hypot(omega.x(), omega.y());
  if (!(horizontal > kDegenerateTolerance * omega.norm())) {
    std::ostringstream message;
    message << "omega = (" << omega.x() + 0.0 << ", " << omega.y() + 0.0 << ", " << omega.z() + 0.0
            << ") rad/s has no horizontal component (|omega_xy| = " << horizontal
            << " <= " << kDegenerateTolerance
            << " |omega|): the sphere does not move over the floor, so its direction phi "
               "(eq 14) is undefined";
    throw std::invalid_argument(message.str());
  }
  SphereMotion motion;
  motion.speed = radius * horizontal;  // eq 14
  // V = r (ω_y, −ω_x) (eq 15), so φ = atan2(−ω_x, ω_y): the printed case split of eq 14 gives
  // 360° instead of 0° at ω_x = 0, ω_y > 0.
  motion.direction = wrapToPeriod(std::atan2(-omega.x(), omega.y()), kTwoPi);
  motion.rho = std::atan2(omega.z(), horizontal);
  return motion;
}

}  // namespace spherical_robots::roller
