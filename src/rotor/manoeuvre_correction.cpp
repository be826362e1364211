#include "spherical_robots/rotor/manoeuvre_correction.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::rotor {
namespace {

std::string describe(const Eigen::Quaterniond& q) {
  std::ostringstream text;
  text << "attitude quaternion (w " << q.w() << ", x " << q.x() << ", y " << q.y() << ", z "
       << q.z() << ")";
  return text.str();
}

/// A usable measured attitude: finite and of norm 1 within 1e-3 (a message's quaternion is unit
/// to its float or printing precision; an unset one is all zero).
void requireAttitude(const Eigen::Quaterniond& attitude) {
  const double norm = attitude.coeffs().norm();
  if (!attitude.coeffs().allFinite() || !(std::abs(norm - 1.0) <= 1e-3)) {
    std::ostringstream text;
    text << describe(attitude) << " must be finite with norm 1 within 1e-3, norm " << norm;
    throw std::invalid_argument(text.str());
  }
}

void requireFinitePose(double u_a, double v_a, double psi, const std::string& what) {
  requireFinite(u_a, what + " u_a [R]");
  requireFinite(v_a, what + " v_a [R]");
  requireFinite(psi, what + " psi [rad]");
}

}  // namespace

RestPose planEnd(const RestPose& start, const PlanTarget& target) {
  requireFinitePose(start.u_a, start.v_a, start.psi, "start");
  requireFinitePose(target.u_a, target.v_a, target.psi, "plan target");
  // R_zᵀ(ψ_0) applied to the zero-state displacement (eqs 6-7 with ω turned by eq 11).
  const double c = std::cos(start.psi);
  const double s = std::sin(start.psi);
  return {start.u_a + c * target.u_a + s * target.v_a,
          start.v_a - s * target.u_a + c * target.v_a, start.psi + target.psi};
}

PlanTarget correctionTarget(const RestPose& from, const RestPose& to) {
  requireFinitePose(from.u_a, from.v_a, from.psi, "from");
  requireFinitePose(to.u_a, to.v_a, to.psi, "to");
  const double du = to.u_a - from.u_a;
  const double dv = to.v_a - from.v_a;
  const double c = std::cos(from.psi);
  const double s = std::sin(from.psi);
  return {c * du - s * dv, s * du + c * dv, wrapToPi(to.psi - from.psi)};
}

RestPose measuredRestPose(double centre_x, double centre_y, double radius,
                          const Eigen::Quaterniond& attitude) {
  requireFinite(centre_x, "centre x [m]");
  requireFinite(centre_y, "centre y [m]");
  requirePositive(radius, "sphere radius [m]");
  requireAttitude(attitude);
  const Eigen::Vector4d q = attitude.coeffs();  // x, y, z, w
  // The twist about z of q = (x, y, z, w) is (0, 0, z, w) normalised; R_zᵀ(ψ) is a turn by −ψ.
  if (std::hypot(q.z(), q.w()) < 1e-9) {
    throw std::invalid_argument(describe(attitude) +
                                " turns the vertical upside down: no rest with the contact at the "
                                "south pole");
  }
  return {centre_x / radius, centre_y / radius, wrapToPi(-2.0 * std::atan2(q.z(), q.w()))};
}

Eigen::Vector2d measuredContactAngles(const Eigen::Quaterniond& attitude) {
  requireAttitude(attitude);
  const Eigen::Matrix3d rotation = attitude.normalized().toRotationMatrix();
  const Eigen::Vector3d contact = rotation.transpose() * Eigen::Vector3d(0.0, 0.0, -1.0);
  if (!(contact.z() < 0.0)) {
    throw std::invalid_argument(describe(attitude) + " puts the contact on or above the sphere's "
                                "equator (z " + std::to_string(contact.z()) + " in the sphere's "
                                "frame, must be < 0)");
  }
  return contactAngles(contact);  // eqs 24-25
}

PoleReturnArc::PoleReturnArc(double u_o, double v_o)
    : start_(contactPoint(u_o, v_o)), axis_(Eigen::Vector3d::UnitX()), angle_(0.0) {
  if (!(std::cos(u_o) * std::cos(v_o) > 0.0)) {
    throw std::invalid_argument("contact (u_o, v_o) = (" + std::to_string(u_o) + ", " +
                                std::to_string(v_o) + ") rad is not below the sphere's equator");
  }
  const Eigen::Vector3d pole(0.0, 0.0, -1.0);
  const Eigen::Vector3d normal = start_.cross(pole);
  angle_ = std::atan2(normal.norm(), start_.dot(pole));
  if (normal.norm() > 0.0) axis_ = normal.normalized();
}

CurvePoint PoleReturnArc::at(double theta) const {
  requireFinite(theta, "arc parameter theta [rad]");
  const double fraction = std::clamp(theta, 0.0, 2.0 * M_PI) / (2.0 * M_PI);
  CurvePoint c;
  c.point = Eigen::AngleAxisd(fraction * angle_, axis_) * start_;
  // Outside [0, 2π] the clamped curve stands still.
  if (theta >= 0.0 && theta <= 2.0 * M_PI) c.tangent = angle_ / (2.0 * M_PI) * axis_.cross(c.point);
  return c;
}

RotorSpeeds arcSetPointAt(double k, double inertia_scale, const PoleReturnArc& arc,
                          const CurveTiming& timing, double t) {
  if (timing.steps() != 1) {
    throw std::invalid_argument("a pole-return arc is traced in one step, not " +
                                std::to_string(timing.steps()));
  }
  return arcSetPoint(k, inertia_scale, arc, timing.theta(t), timing.rate(t));
}

RotorSpeeds arcSetPoint(double k, double inertia_scale, const PoleReturnArc& arc, double theta,
                        double theta_rate) {
  const CurvePoint c = arc.at(theta);
  const Eigen::Vector2d angles = contactAngles(c.point);
  // ψ = 0 and the origin: the speeds are the same at every heading and place (eq 11).
  const ContactCoordinates at{0.0, 0.0, angles.x(), angles.y(), 0.0};
  return rotorSpeeds(k, inertia_scale, at, curveAngularVelocity(k, c, 0.0, theta_rate));
}

}  // namespace spherical_robots::rotor
