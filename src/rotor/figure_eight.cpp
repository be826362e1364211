#include "spherical_robots/rotor/figure_eight.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "spherical_robots/core/sin_cos.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::rotor {
namespace {

void requireRadius(double r, std::string_view what) {
  requirePositive(r, what);
  if (r >= kMaxCircleRadius) {
    std::ostringstream message;
    message << what << " must be < " << kMaxCircleRadius
            << " (sqrt(2)/2: a larger circle through the pole reaches the equator, where eq 30 "
               "is singular), got "
            << r;
    throw std::invalid_argument(message.str());
  }
}

/// Out of line so that the check, made at every stage of the integrations, stays two compares.
[[noreturn]] void rejectTheta(double theta, double lo, bool second) {
  std::ostringstream message;
  message << "theta [rad] must be in [" << lo << ", " << lo + M_PI << "] on leaf "
          << (second ? 2 : 1) << ", got " << theta;
  throw std::invalid_argument(message.str());
}

/// Eq 35 for a checked radius a with d = √(1 − a²) (= cos α; sin α = a).
CurvePoint circlePoint(double a, double d, double phi, bool mirrored) {
  const auto [s, c] = sinCos(phi);
  const double y_sign = mirrored ? -1.0 : 1.0;
  CurvePoint out;
  out.point = {a * s, y_sign * (-a * d * c + d * a), -a * a * c - d * d};
  out.tangent = {a * c, y_sign * a * d * s, a * a * s};
  return out;
}

}  // namespace

CurvePoint sphericalCircle(double a, double phi, bool mirrored) {
  requireRadius(a, "circle radius a [R]");
  requireFinite(phi, "circle angle [rad]");
  return circlePoint(a, std::sqrt(1.0 - a * a), phi, mirrored);
}

double arcRadius(double a) {
  requirePositive(a, "Euclidean radius a [R]");
  if (a > 1.0) {
    std::ostringstream message;
    message << "Euclidean radius a [R] must be <= 1, got " << a;
    throw std::invalid_argument(message.str());
  }
  return std::asin(a);
}

double euclideanRadius(double arc_radius) {
  requirePositive(arc_radius, "geodesic radius [R]");
  if (arc_radius > M_PI / 2) {
    std::ostringstream message;
    message << "geodesic radius [R] must be <= pi/2, got " << arc_radius;
    throw std::invalid_argument(message.str());
  }
  return std::sin(arc_radius);
}

FigureEight::FigureEight(double a, double b, double gamma) : a_(a), b_(b), gamma_(gamma) {
  requireRadius(a, "first circle radius a [R]");
  requireRadius(b, "second circle radius b [R]");
  requireFinite(gamma, "orientation gamma [rad]");
  d_a_ = std::sqrt(1.0 - a * a);
  d_b_ = std::sqrt(1.0 - b * b);
  cos_gamma_ = std::cos(gamma);
  sin_gamma_ = std::sin(gamma);
}

CurvePoint FigureEight::at(double theta) const { return onLeaf(theta > M_PI, theta); }

CurvePoint FigureEight::onLeaf(bool second, double theta) const {
  requireFinite(theta, "theta [rad]");
  const double lo = second ? M_PI : 0.0;
  if (theta < lo || theta > lo + M_PI) rejectTheta(theta, lo, second);
  const CurvePoint leaf = second ? circlePoint(b_, d_b_, 2.0 * theta - 2.0 * M_PI, true)
                                 : circlePoint(a_, d_a_, 2.0 * theta, false);
  const auto turn = [this](const Eigen::Vector3d& v) {  // R_z(γ) of eq 31
    return Eigen::Vector3d(cos_gamma_ * v.x() - sin_gamma_ * v.y(),
                           sin_gamma_ * v.x() + cos_gamma_ * v.y(), v.z());
  };
  return {turn(leaf.point), 2.0 * turn(leaf.tangent)};
}

double FigureEight::length() const { return 2.0 * M_PI * (a_ + b_); }

}  // namespace spherical_robots::rotor
