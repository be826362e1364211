#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/core/validation.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace spherical_robots::terrain {
CosineSurface::CosineSurface(double amplitude, double frequency)
    : amplitude_(amplitude), frequency_(frequency) {
  requireFinite(amplitude, "cosine surface: amplitude [m]");
  requirePositive(frequency, "cosine surface: frequency [rad/m]");
}

// The Hessian's largest eigenvalue, |a| w^2, is reached where the gradient vanishes, so it is
// also the largest normal curvature: a non-zero gradient only divides it by (1 + |grad f|^2)^k.
double CosineSurface::maxPrincipalCurvature() const {
  return std::abs(amplitude_) * frequency_ * frequency_;
}

std::string CosineSurface::describe() const {
  std::ostringstream text;
  text << "cosine a=" << amplitude_ << " m w=" << frequency_ << " rad/m";
  return text.str();
}

PlaneSurface::PlaneSurface(double slope_x, double slope_y, double offset)
    : slope_(slope_x, slope_y), offset_(offset) {
  requireFinite(slope_x, "plane: slope_x");
  requireFinite(slope_y, "plane: slope_y");
  requireFinite(offset, "plane: offset [m]");
}

SurfacePoint PlaneSurface::evaluate(double x, double y) const {
  SurfacePoint point;
  point.height = offset_ + slope_.dot(Eigen::Vector2d(x, y));
  point.gradient = slope_;
  return point;
}

double PlaneSurface::maxPrincipalCurvature() const { return 0.0; }

std::string PlaneSurface::describe() const {
  std::ostringstream text;
  text << "plane z=" << offset_ << "+" << slope_.x() << "x+" << slope_.y() << "y";
  return text.str();
}

Eigen::Vector2d principalCurvatures(const Surface& surface, double x, double y) {
  const SurfacePoint point = surface.evaluate(x, y);
  const Eigen::Vector2d& g = point.gradient;
  const double w = std::sqrt(1.0 + g.squaredNorm());
  const Eigen::Matrix2d first_form = Eigen::Matrix2d::Identity() + g * g.transpose();
  const Eigen::Matrix2d second_form = point.hessian / w;
  // The eigenvalues of the shape operator S = I^-1 II, H -+ sqrt(H^2 - K), with the discriminant
  // written from S's entries, ((s00 - s11) / 2)^2 + s01 s10, which does not cancel at umbilics.
  const Eigen::Matrix2d shape = first_form.inverse() * second_form;
  const double mean = 0.5 * shape.trace();
  const double half_difference = 0.5 * (shape(0, 0) - shape(1, 1));
  const double spread =
      std::sqrt(std::max(0.0, half_difference * half_difference + shape(0, 1) * shape(1, 0)));
  return {mean - spread, mean + spread};
}

void requireSinglePointContact(const Surface& surface, double radius) {
  requirePositive(radius, "sphere radius [m]");
  const double curvature = surface.maxPrincipalCurvature();
  if (radius * curvature >= 1.0) {
    std::ostringstream message;
    message << "radius " << radius << " m on surface '" << surface.describe()
            << "' breaks single-point contact: R * max principal curvature = " << radius << " * "
            << curvature << " 1/m = " << radius * curvature << " >= 1 (paper assumption 3)";
    const std::string location = surface.maxCurvatureLocation();
    if (!location.empty()) message << "; the curvature is largest in " << location;
    throw std::invalid_argument(message.str());
  }
}

}  // namespace spherical_robots::terrain
