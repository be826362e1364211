#pragma once
// A height map as a terrain surface: the C2 tensor-product cubic B-spline through its samples
// (docs/conventions.md, "Height maps").

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <stdexcept>
#include <string>

#include "spherical_robots/terrain/height_grid.hpp"
#include "spherical_robots/terrain/surface.hpp"

namespace spherical_robots::terrain {

/// Thrown for a point off a height map: there are no heights there, and the surface is not
/// continued (a made-up continuation would be a terrain nobody surveyed). A runtime_error, as a
/// run that leaves the map has failed; a plant holds its last state on it.
class OffMapError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The tensor-product cubic B-spline s(x, y) = sum_kl c_kl B((x - x0)/h - k) B((y - y0)/h - l)
/// that passes through every sample of a HeightGrid (interpolating: the coefficients are the
/// samples prefiltered, one banded solve per axis). It is C2 everywhere, so the Hessian the
/// kinematics needs is continuous; its end conditions are the slopes at the map's edges,
/// estimated from the five samples nearest each edge to fourth order. The map covers the
/// rectangle of the samples' positions; evaluate() refuses any point off it.
class HeightMapSurface final : public Surface {
 public:
  /// The cell with the map's largest principal-curvature bound.
  struct CurvatureCell {
    Eigen::Index i = 0;  ///< the cell [x_i, x_i+1] x [y_j, y_j+1], x_i = x0 + i h
    Eigen::Index j = 0;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< [m]
    double curvature = 0.0;                            ///< bound [1/m] over the cell
  };

  /// The fewest and the most samples a side: five for the end slopes' stencil; the most keeps a
  /// map's coefficients to tens of MB.
  static constexpr Eigen::Index kMinSamples = 5;
  static constexpr Eigen::Index kMaxSamples = 2048;

  /// Solves for the coefficients and bounds the curvature of every cell.
  /// @throw std::invalid_argument naming grid.source and the limit: spacing not finite and > 0,
  /// a position not finite, fewer than kMinSamples or more than kMaxSamples a side, a height
  /// that is not finite (naming its sample).
  explicit HeightMapSurface(HeightGrid grid);

  /// @throw OffMapError naming the point and the map's extent if (x, y) is off the map.
  SurfacePoint evaluate(double x, double y) const override;
  /// The largest over the cells of a bound on each cell (see worstCell()).
  double maxPrincipalCurvature() const override;
  std::string describe() const override;
  std::optional<Eigen::AlignedBox2d> domain() const override;
  std::string maxCurvatureLocation() const override;

  /// The cell whose bound is largest. A cell's bound comes from the spline's pieces: on a cell
  /// f_xx, f_xy, f_yy, f_x and f_y are polynomials whose Bernstein coefficients enclose their
  /// ranges; those ranges bound the Hessian's largest eigenvalue from above and the slope from
  /// below, and k_max <= max(lambda_max(H), 0) / sqrt(1 + |grad f|^2). It exceeds the true
  /// maximum by O(h) (the ranges' width).
  const CurvatureCell& worstCell() const { return worst_; }
  const HeightGrid& grid() const { return grid_; }

 private:
  HeightGrid grid_;
  Eigen::Vector2d last_sample_;
  /// c_kl at (k + 1, l + 1), k = -1 .. nx, l = -1 .. ny.
  Eigen::MatrixXd coefficients_;
  CurvatureCell worst_;
};

}  // namespace spherical_robots::terrain
