#pragma once
// Terrain surfaces z = f(x, y) (paper eq 3) with the derivatives the rolling kinematics need.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <optional>
#include <string>

#include "spherical_robots/core/sin_cos.hpp"

namespace spherical_robots::terrain {

/// f, its gradient and its Hessian at one point.
struct SurfacePoint {
  double height = 0.0;                                    ///< f(x, y) [m]
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();     ///< (f_x, f_y) [-]
  Eigen::Matrix2d hessian = Eigen::Matrix2d::Zero();      ///< [[f_xx, f_xy], [f_xy, f_yy]] [1/m]
};

/// A smooth terrain z = f(x, y), heights in [m], in the world frame.
class Surface {
 public:
  virtual ~Surface() = default;
  /// Height, gradient and Hessian together: they share their trigonometry, and the closed loop
  /// needs them at every RK stage.
  virtual SurfacePoint evaluate(double x, double y) const = 0;
  double height(double x, double y) const { return evaluate(x, y).height; }
  Eigen::Vector2d gradient(double x, double y) const { return evaluate(x, y).gradient; }
  Eigen::Matrix2d hessian(double x, double y) const { return evaluate(x, y).hessian; }
  /// An upper bound [1/m] over the whole surface of the largest principal curvature, measured
  /// positive where the surface is concave up (a valley that a sphere resting on top sits in).
  virtual double maxPrincipalCurvature() const = 0;
  /// A short human-readable description, e.g. "cosine a=0.2 m w=2 rad/m".
  virtual std::string describe() const = 0;
  /// The rectangle [m] the surface is defined on; nullopt where it is defined everywhere.
  virtual std::optional<Eigen::AlignedBox2d> domain() const { return std::nullopt; }
  /// Where maxPrincipalCurvature() is reached, for messages; empty if nowhere in particular.
  virtual std::string maxCurvatureLocation() const { return {}; }
};

/// Paper eq 59: z = a (cos(w x) + cos(w y) - 2).
class CosineSurface final : public Surface {
 public:
  /// @param amplitude a [m], @param frequency w [rad/m] > 0. @throw std::invalid_argument
  CosineSurface(double amplitude, double frequency);
  /// Inline (below): called on a CosineSurface itself, as TerrainKinematics does at every RK
  /// stage, it is inlined instead of returning its point through memory. (Declared inline here,
  /// so that maxPrincipalCurvature stays the key function that places the vtable.)
  inline SurfacePoint evaluate(double x, double y) const override;
  double maxPrincipalCurvature() const override;
  std::string describe() const override;

 private:
  double amplitude_;
  double frequency_;
};

// Eq 59 and its derivatives.
inline SurfacePoint CosineSurface::evaluate(double x, double y) const {
  const auto [along_x, along_y] = sinCos(frequency_ * x, frequency_ * y);
  const double slope = -amplitude_ * frequency_;
  const double curvature = slope * frequency_;
  SurfacePoint point;
  point.height = amplitude_ * (along_x.cos + along_y.cos - 2.0);
  point.gradient = slope * Eigen::Vector2d(along_x.sin, along_y.sin);
  point.hessian(0, 0) = curvature * along_x.cos;
  point.hessian(1, 1) = curvature * along_y.cos;
  return point;
}

/// z = z0 + g_x x + g_y y: a horizontal plane (g = 0) or a tilted one.
class PlaneSurface final : public Surface {
 public:
  /// @param slope_x g_x [-], @param slope_y g_y [-], @param offset z0 [m]. @throw std::invalid_argument
  PlaneSurface(double slope_x, double slope_y, double offset);
  SurfacePoint evaluate(double x, double y) const override;
  double maxPrincipalCurvature() const override;
  std::string describe() const override;

 private:
  Eigen::Vector2d slope_;
  double offset_;
};

/// Principal curvatures (k_min, k_max) [1/m] of z = f(x, y) at (x, y), positive where concave up,
/// from the shape operator I^-1 II with I, II the first and second fundamental forms.
Eigen::Vector2d principalCurvatures(const Surface& surface, double x, double y);

/// Throws std::invalid_argument unless a sphere of radius [m] keeps single-point contact
/// everywhere on the surface (paper assumption 3): radius * maxPrincipalCurvature() < 1.
void requireSinglePointContact(const Surface& surface, double radius);

}  // namespace spherical_robots::terrain
