#include "spherical_robots/rotor/contact_curve.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "spherical_robots/core/sin_cos.hpp"
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

/// c_uᵀ c_θ and c_vᵀ c_θ (eq 26) for unit R, with w = cos v_o and inverse_w = 1 / w.
Eigen::Vector2d projections(const CurvePoint& curve, double w, double inverse_w) {
  const Eigen::Vector3d& c = curve.point;
  const Eigen::Vector3d c_u(c.z(), 0.0, -c.x());
  const Eigen::Vector3d c_v(-c.x() * c.y() * inverse_w, w, -c.y() * c.z() * inverse_w);
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
  const double inverse_w = 1.0 / w;
  const Eigen::Vector2d p = projections(curve, w, inverse_w);
  return {p.x() * inverse_w * inverse_w, p.y()};  // eq 27
}

PlaneState realizableCurveRates(double k, const CurvePoint& curve, double psi) {
  if (!(k >= 0.0 && k <= kMaxInertiaRatio)) rejectRatio(k);
  requireFinite(psi, "psi [rad]");
  const double w = checkedCosV(curve.point);
  requireFiniteTangent(curve.tangent);
  const Eigen::Vector3d& c = curve.point;
  // One division for the three of eqs 28-30 (1/w, 1/w², 1/(z w)): this runs at every stage of
  // the planner's integrations.
  const double inverse_zw = 1.0 / (c.z() * w);
  const double inverse_w = c.z() * inverse_zw;
  const Eigen::Vector2d p = projections(curve, w, inverse_w);
  const auto [sp, cp] = sinCos(psi);
  const double u_rate = p.x() * inverse_w;  // u_o' cos v_o (eq 27)
  PlaneState rates;
  rates.u_a = -cp * u_rate + sp * p.y();                                           // eq 28
  rates.v_a = sp * u_rate + cp * p.y();                                            // eq 29
  rates.psi = (1.0 - k) * c.y() * u_rate * inverse_w + k * c.x() * p.y() * inverse_zw;  // eq 30
  return rates;
}

}  // namespace spherical_robots::rotor
