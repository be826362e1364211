#include "spherical_robots/rotor/dynamic_realizability.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::rotor {
namespace {

void requireRatio(double k) {
  if (!(k >= 0.0 && k <= kMaxInertiaRatio)) {
    std::ostringstream message;
    message << "inertia ratio k must be in [0, " << kMaxInertiaRatio << "], got " << k;
    throw std::invalid_argument(message.str());
  }
}

/// J_zz = 2/3 m_o R² + 2 J_p + J_r (eq 11's definitions), checked.
double centralInertia(const RotorSphereInertia& inertia) {
  requireAllPositive({{inertia.total_mass, "total mass M [kg]"},
                      {inertia.shell_mass, "shell mass m_o [kg]"},
                      {inertia.radius, "radius R [m]"},
                      {inertia.rotor_axial, "rotor axial inertia J_r [kg m^2]"}});
  requireNonNegative(inertia.rotor_diametral, "rotor diametral inertia J_p [kg m^2]");
  if (inertia.shell_mass > inertia.total_mass) {
    std::ostringstream message;
    message << "shell mass m_o [kg] must not exceed the total mass M = " << inertia.total_mass
            << ", got " << inertia.shell_mass;
    throw std::invalid_argument(message.str());
  }
  const double r = inertia.radius;
  return 2.0 / 3.0 * inertia.shell_mass * r * r + 2.0 * inertia.rotor_diametral +
         inertia.rotor_axial;
}

}  // namespace

double inertiaRatio(const RotorSphereInertia& inertia) {
  const double j_zz = centralInertia(inertia);
  return 1.0 + inertia.total_mass * inertia.radius * inertia.radius / j_zz;  // eq 14
}

double rotorInertiaScale(const RotorSphereInertia& inertia) {
  return centralInertia(inertia) / inertia.rotor_axial;
}

double realizabilityResidual(double k, const ContactCoordinates& coordinates,
                             const Eigen::Vector3d& omega) {
  requireRatio(k);
  requireFinite(omega.x(), "omega_x [rad/s]");
  requireFinite(omega.y(), "omega_y [rad/s]");
  requireFinite(omega.z(), "omega_z [rad/s]");
  const Eigen::Vector3d n3 = orientation(coordinates.u_o, coordinates.v_o, coordinates.psi).col(2);
  return k * (n3.x() * omega.x() + n3.y() * omega.y()) + n3.z() * omega.z();  // eq 13
}

double realizableHeadingRate(double k, const ContactCoordinates& coordinates, double u_o_rate,
                             double v_o_rate) {
  requireRatio(k);
  requireFinite(coordinates.u_o, "u_o [rad]");
  requireFinite(coordinates.v_o, "v_o [rad]");
  requireFinite(u_o_rate, "u_o rate [rad/s]");
  requireFinite(v_o_rate, "v_o rate [rad/s]");
  const double cv = std::cos(coordinates.v_o);
  const double n3z = std::cos(coordinates.u_o) * cv;
  if (cv <= 0.0 || n3z <= 0.0) {
    std::ostringstream message;
    message << "contact point (u_o, v_o) = (" << coordinates.u_o << ", " << coordinates.v_o
            << ") must lie below the sphere's equator (cos u_o cos v_o > 0): eq 13 cannot be "
               "solved for omega_z there";
    throw std::invalid_argument(message.str());
  }
  return (1.0 - k) * std::sin(coordinates.v_o) * u_o_rate +
         k * std::tan(coordinates.u_o) / cv * v_o_rate;  // eq 20
}

Eigen::Vector3d curveAngularVelocity(double k, const CurvePoint& curve, double psi,
                                     double theta_rate) {
  requireFinite(theta_rate, "theta rate [1/s]");
  const PlaneState rates = realizableCurveRates(k, curve, psi);  // eq 30
  const Eigen::Vector2d angles = contactAngles(curve.point);
  const Eigen::Vector2d angle_rates = contactAngleRates(curve);  // eq 27
  const ContactCoordinates at{0.0, 0.0, angles.x(), angles.y(), psi};
  return angularVelocity(at, angle_rates.x() * theta_rate, angle_rates.y() * theta_rate,
                         rates.psi * theta_rate);
}

RotorSpeeds rotorSpeeds(double k, double inertia_scale, const ContactCoordinates& coordinates,
                        const Eigen::Vector3d& omega) {
  requirePositive(inertia_scale, "rotor inertia scale J_zz/J_r");
  const double residual = realizabilityResidual(k, coordinates, omega);
  if (std::abs(residual) > 1e-9 * (omega.norm() + 1.0)) {
    std::ostringstream message;
    message << "omega is not dynamically realizable: eq 13 residual " << residual
            << " exceeds 1e-9 (|omega| + 1)";
    throw std::invalid_argument(message.str());
  }
  const Eigen::Matrix3d r = orientation(coordinates.u_o, coordinates.v_o, coordinates.psi);
  const Eigen::Vector3d momentum(k * omega.x(), k * omega.y(), omega.z());  // J_c ω / J_zz
  // Eq 11 projected on the orthonormal n1, n2: J_r φ̇_i = −n_i · J_c ω.
  return {-inertia_scale * r.col(0).dot(momentum), -inertia_scale * r.col(1).dot(momentum)};
}

Eigen::Vector3d rotorAngularVelocity(double k, double inertia_scale,
                                     const ContactCoordinates& coordinates,
                                     const RotorSpeeds& speeds) {
  requirePositive(k, "inertia ratio k");
  requirePositive(inertia_scale, "rotor inertia scale J_zz/J_r");
  requireFinite(speeds.phi1, "rotor speed phi1 [rad/s]");
  requireFinite(speeds.phi2, "rotor speed phi2 [rad/s]");
  const Eigen::Matrix3d r = orientation(coordinates.u_o, coordinates.v_o, coordinates.psi);
  const Eigen::Vector3d rotor_momentum = r.col(0) * speeds.phi1 + r.col(1) * speeds.phi2;
  // Eq 11: J_c ω = −J_r (n1 φ̇1 + n2 φ̇2), J_c = J_zz diag(k, k, 1).
  return -Eigen::Vector3d(rotor_momentum.x() / k, rotor_momentum.y() / k, rotor_momentum.z()) /
         inertia_scale;
}

}  // namespace spherical_robots::rotor
