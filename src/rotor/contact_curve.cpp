#include "spherical_robots/rotor/contact_curve.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::rotor {
namespace {

// The rejections are out of line so that the checks, made at every stage of the integrations,
// stay a few compares.
[[noreturn]] void rejectAboveEquator(const Eigen::Vector3d& point) {
  std::ostringstream message;
  message << "curve point (" << point.x() << ", " << point.y() << ", " << point.z()
          << ") must lie below the sphere's equator (z < 0, |y| < 1): eq 30 divides by z";
  throw std::invalid_argument(message.str());
}

[[noreturn]] void rejectRatio(double k) {
  std::ostringstream message;
  message << "inertia ratio k must be in [0, " << kMaxInertiaRatio << "], got " << k;
  throw std::invalid_argument(message.str());
}

/// √(1 − y²) = cos v_o of a checked point (eq 24).
double checkedCosV(const Eigen::Vector3d& point) {
  requireFinite(point.x(), "curve point x [R]");
  requireFinite(point.y(), "curve point y [R]");
  requireFinite(point.z(), "curve point z [R]");
  const double w2 = 1.0 - point.y() * point.y();
  if (!(point.z() < 0.0) || !(w2 > 0.0)) rejectAboveEquator(point);
  return std::sqrt(w2);
}

void requireFiniteTangent(const Eigen::Vector3d& tangent) {
  requireFinite(tangent.x(), "curve tangent x [R]");
  requireFinite(tangent.y(), "curve tangent y [R]");
  requireFinite(tangent.z(), "curve tangent z [R]");
}

/// c_uᵀ c_θ and c_vᵀ c_θ (eq 26) for unit R.
Eigen::Vector2d projections(const CurvePoint& curve, double w) {
  const Eigen::Vector3d& c = curve.point;
  const Eigen::Vector3d c_u(c.z(), 0.0, -c.x());
  const Eigen::Vector3d c_v(-c.x() * c.y() / w, w, -c.y() * c.z() / w);
  return {c_u.dot(curve.tangent), c_v.dot(curve.tangent)};
}

}  // namespace

Eigen::Vector2d contactAngles(const Eigen::Vector3d& point) {
  checkedCosV(point);
  return {std::atan2(-point.x(), -point.z()), std::asin(point.y())};  // eqs 24-25
}

Eigen::Vector2d contactAngleRates(const CurvePoint& curve) {
  const double w = checkedCosV(curve.point);
  requireFiniteTangent(curve.tangent);
  const Eigen::Vector2d p = projections(curve, w);
  return {p.x() / (w * w), p.y()};  // eq 27
}

PlaneState realizableCurveRates(double k, const CurvePoint& curve, double psi) {
  if (!(k >= 0.0 && k <= kMaxInertiaRatio)) rejectRatio(k);
  requireFinite(psi, "psi [rad]");
  const double w = checkedCosV(curve.point);
  requireFiniteTangent(curve.tangent);
  const Eigen::Vector2d p = projections(curve, w);
  const double cp = std::cos(psi), sp = std::sin(psi);
  const Eigen::Vector3d& c = curve.point;
  PlaneState rates;
  rates.u_a = -cp / w * p.x() + sp * p.y();                                          // eq 28
  rates.v_a = sp / w * p.x() + cp * p.y();                                           // eq 29
  rates.psi = (1.0 - k) * c.y() * p.x() / (w * w) + k * c.x() * p.y() / (c.z() * w);  // eq 30
  return rates;
}

}  // namespace spherical_robots::rotor
