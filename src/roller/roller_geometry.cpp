#include "spherical_robots/roller/roller_geometry.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::roller {
namespace {

RollerContact makeContact(const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                          double radius, double alpha) {
  RollerContact contact;
  contact.alpha = alpha;
  contact.point = point;
  contact.tangent = normal.cross(point) / radius;                               // eq 6
  contact.axis = contact.tangent * std::cos(alpha) + normal * std::sin(alpha);  // eq 5
  // The roller turns about η_i, so its surface at P_i moves along P_i × η_i; this sign is the one
  // for which eq 2, ⟨ω × P_i, e_i⟩ = −r ⟨η_i, ω⟩, holds.
  contact.rolling_direction = point.cross(contact.axis) / radius;
  return contact;
}

void requireRollingAxisInPlane(double alpha, int roller) {
  const double cosine = std::cos(alpha);
  if (std::abs(cosine) <= kDegenerateTolerance) {
    std::ostringstream message;
    message << "cos(alpha" << roller << ") = " << cosine << " (alpha" << roller << " = " << alpha
            << " rad): roller " << roller
            << "'s axis is normal to span{P1, P2}, and eqs 8 and 22 divide by cos(alpha_i)";
    throw std::invalid_argument(message.str());
  }
}

}  // namespace

Eigen::Vector3d spherePoint(double radius, const SphericalDirection& direction) {
  requireLength(radius, "sphere radius r [m]");
  requireFinite(direction.azimuth, "contact azimuth [rad]");
  requireFinite(direction.elevation, "contact elevation [rad]");
  const double horizontal = std::cos(direction.elevation);
  return radius * Eigen::Vector3d(std::cos(direction.azimuth) * horizontal,
                                  std::sin(direction.azimuth) * horizontal,
                                  std::sin(direction.elevation));  // eq 12
}

double wrapToPeriod(double angle, double period) {
  requireFinite(angle, "angle");
  requirePositive(period, "period");
  double wrapped = std::fmod(angle, period);
  if (wrapped < 0.0) wrapped += period;
  // A tiny negative angle wraps to period − tiny, which can round to period itself.
  return wrapped >= period ? 0.0 : wrapped + 0.0;  // + 0.0: no −0
}

RollerGeometry::RollerGeometry(double radius, const SphericalDirection& contact1,
                               const SphericalDirection& contact2, double alpha1, double alpha2)
    : radius_(radius) {
  requireLength(radius, "sphere radius r [m]");
  requireFinite(contact1.azimuth, "azimuth of P1 [rad]");
  requireFinite(contact1.elevation, "elevation of P1 [rad]");
  requireFinite(contact2.azimuth, "azimuth of P2 [rad]");
  requireFinite(contact2.elevation, "elevation of P2 [rad]");
  requireFinite(alpha1, "alpha1 [rad]");
  requireFinite(alpha2, "alpha2 [rad]");

  const Eigen::Vector3d p1 = spherePoint(radius, contact1);
  const Eigen::Vector3d p2 = spherePoint(radius, contact2);
  const Eigen::Vector3d cross = p1.cross(p2);
  cross_norm_ = cross.norm();
  const double sine = cross_norm_ / (radius * radius);  // eq B.3
  if (!(sine > kDegenerateTolerance)) {
    std::ostringstream message;
    message << "contact points P1 and P2 are " << (p1.dot(p2) > 0.0 ? "parallel" : "antipodal")
            << " (sin of the angle between them " << sine << " <= " << kDegenerateTolerance
            << "): span{P1, P2} and its normal e (eq 6) are undefined";
    throw std::invalid_argument(message.str());
  }
  requireRollingAxisInPlane(alpha1, 1);
  requireRollingAxisInPlane(alpha2, 2);

  normal_ = cross / cross_norm_;  // eq 6
  rollers_ = {makeContact(p1, normal_, radius, alpha1), makeContact(p2, normal_, radius, alpha2)};
}

}  // namespace spherical_robots::roller
