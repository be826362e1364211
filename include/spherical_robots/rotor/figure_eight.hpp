#pragma once
// The spherical figure eight of Svinin et al. (eqs 31, 35): two circles on the unit sphere that
// touch at the south pole, each traced once, turned by γ about the sphere's z axis. No ROS.
//
// Conventions (docs/conventions.md, "Rotor sphere", fixed by reproducing section IV):
// * a and b are Euclidean radii of the circles (in units of R). The paper's "a ≈ 0.533681R" is
//   the geodesic radius R asin(a/R) (arcRadius()).
// * The circle of radius a (eq 35, centre towards +y) is traced first, on θ ∈ [0, π]; the circle
//   of radius b, its mirror image in y, second, on θ ∈ [π, 2π]. Both start at the pole heading
//   +x, so the curve is smooth there. Each leaf's circle angle is 2θ (resp. 2θ − 2π).

#include "spherical_robots/rotor/contact_curve.hpp"

namespace spherical_robots::rotor {

/// Radii must stay below this (√2/2): a circle through the pole of larger radius reaches the
/// equator, where n3z = 0 and the realizable kinematics (eqs 13, 20, 30) are singular.
constexpr double kMaxCircleRadius = 0.70710678118654752;

/// Eq 35 (unit sphere): a point of the circle of Euclidean radius a through the south pole at
/// circle angle φ; mirrored flips y. @throw std::invalid_argument unless 0 < a < kMaxCircleRadius
/// and φ is finite.
CurvePoint sphericalCircle(double a, double phi, bool mirrored);

/// Geodesic radius [R] of a circle of Euclidean radius a (asin a) and its inverse (sin s).
/// @throw std::invalid_argument if a is not in (0, 1] (resp. s not in (0, π/2]).
double arcRadius(double a);
double euclideanRadius(double arc_radius);

/// One step's contact curve c(θ) = R_z(γ) c̄(a, b, θ), θ ∈ [0, 2π] (eq 31).
class FigureEight {
 public:
  /// @throw std::invalid_argument unless 0 < a, b < kMaxCircleRadius and γ is finite.
  FigureEight(double a, double b, double gamma = 0.0);

  double a() const { return a_; }
  double b() const { return b_; }
  double gamma() const { return gamma_; }

  /// c(θ) and c_θ for θ ∈ [0, 2π]; θ = π is the pole between the leaves (tangent of leaf 1).
  /// @throw std::invalid_argument if θ is not finite or outside [0, 2π].
  CurvePoint at(double theta) const;
  /// c(θ) and c_θ of one leaf (second = false: θ ∈ [0, π], true: θ ∈ [π, 2π]); at θ = π the
  /// leaves meet at the pole with different tangents. @throw as at(), for the leaf's interval.
  CurvePoint onLeaf(bool second, double theta) const;

  /// Contact path length on the sphere for one step [R]: 2π (a + b).
  double length() const;

 private:
  double a_;
  double b_;
  double gamma_;
  double d_a_;  // √(1 − a²), √(1 − b²): eq 35's d
  double d_b_;
  double cos_gamma_;
  double sin_gamma_;
};

}  // namespace spherical_robots::rotor
