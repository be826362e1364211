#include "spherical_robots/terrain/height_map_surface.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::terrain {
namespace {

// Evaluation points a hair beyond an edge (rounding in x0 + (n - 1) h) count as on it [cells].
constexpr double kEdgeSlack = 1e-9;

/// The fourth-order one-sided difference 12 h f'(z_0) = -25 z0 + 48 z1 - 36 z2 + 16 z3 - 3 z4
/// (error h^4 f^(5) / 5), from z_0 inwards: its weights.
constexpr std::array<double, 5> kEndSlopeStencil = {-25.0, 48.0, -36.0, 16.0, -3.0};

/// Cubic B-spline interpolation along the rows of `samples` (n >= 5 of them): the n + 2
/// coefficients c_-1 .. c_n of each column, from the n equations (c_k-1 + 4 c_k + c_k+1) / 6 = z_k
/// and the two end slopes (c_1 - c_-1) / 2h = s'(x_0), (c_n - c_n-2) / 2h = s'(x_n-1), each
/// estimated with kEndSlopeStencil. The system is banded; Eigen's sparse LU factorises it once
/// for every column.
Eigen::MatrixXd prefilter(const Eigen::MatrixXd& samples) {
  const Eigen::Index n = samples.rows();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(3 * n + 4));
  Eigen::MatrixXd rhs(n + 2, samples.cols());
  entries.emplace_back(0, 0, -1.0);
  entries.emplace_back(0, 2, 1.0);
  rhs.row(0).setZero();
  rhs.row(n + 1).setZero();
  for (Eigen::Index k = 0; k < 5; ++k) {
    // 2 h s' = 2 h (stencil . z) / 12 h
    rhs.row(0) += kEndSlopeStencil[static_cast<std::size_t>(k)] / 6.0 * samples.row(k);
    rhs.row(n + 1) -= kEndSlopeStencil[static_cast<std::size_t>(k)] / 6.0 * samples.row(n - 1 - k);
  }
  for (Eigen::Index k = 0; k < n; ++k) {
    entries.emplace_back(k + 1, k, 1.0);
    entries.emplace_back(k + 1, k + 1, 4.0);
    entries.emplace_back(k + 1, k + 2, 1.0);
    rhs.row(k + 1) = 6.0 * samples.row(k);
  }
  entries.emplace_back(n + 1, n - 1, -1.0);
  entries.emplace_back(n + 1, n + 1, 1.0);
  Eigen::SparseMatrix<double> system(n + 2, n + 2);
  system.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(system);
  if (solver.info() != Eigen::Success) {
    throw std::logic_error("height map: the spline's banded system did not factorise");
  }
  return solver.solve(rhs);
}

/// The uniform cubic B-spline's four weights on a cell at t in [0, 1], and their first and
/// second derivatives in t.
struct Weights {
  Eigen::Vector4d value, first, second;
};

Weights weightsAt(double t) {
  const double s = 1.0 - t;
  const double t2 = t * t;
  Weights w;
  w.value << s * s * s / 6.0, (3.0 * t2 * t - 6.0 * t2 + 4.0) / 6.0,
      (-3.0 * t2 * t + 3.0 * t2 + 3.0 * t + 1.0) / 6.0, t2 * t / 6.0;
  w.first << -0.5 * s * s, 0.5 * (3.0 * t2 - 4.0 * t), 0.5 * (-3.0 * t2 + 2.0 * t + 1.0), 0.5 * t2;
  w.second << s, 3.0 * t - 2.0, 1.0 - 3.0 * t, t;
  return w;
}

/// A cell's B-spline coefficients (4 along x by 4 along y) into the Bernstein (Bezier)
/// coefficients of the cell's polynomial [value], its first derivative [per cell] and its second
/// [per cell^2], along one axis.
const Eigen::Matrix4d kToBezier = (Eigen::Matrix4d() << 1, 4, 1, 0,  //
                                   0, 4, 2, 0,                       //
                                   0, 2, 4, 0,                       //
                                   0, 1, 4, 1)
                                      .finished() /
                                  6.0;
const Eigen::Matrix<double, 3, 4> kFirstToBezier =
    (Eigen::Matrix<double, 3, 4>() << -0.5, 0, 0.5, 0,  //
     0, -1, 1, 0,                                       //
     0, -0.5, 0, 0.5)
        .finished();
const Eigen::Matrix<double, 2, 4> kSecondToBezier =
    (Eigen::Matrix<double, 2, 4>() << 1, -2, 1, 0,  //
     0, 1, -2, 1)
        .finished();

/// [lo, hi] enclosing a polynomial's values on its cell: its Bernstein coefficients' range.
struct Range {
  double lo, hi;
  template <typename Derived>
  explicit Range(const Eigen::MatrixBase<Derived>& bernstein) {
    const auto coefficients = bernstein.eval();
    lo = coefficients.minCoeff();
    hi = coefficients.maxCoeff();
  }
  double magnitude() const { return std::max(std::abs(lo), std::abs(hi)); }
  double distanceFromZero() const { return lo > 0.0 ? lo : hi < 0.0 ? -hi : 0.0; }
};

/// An upper bound [1/m] of the largest principal curvature over a cell whose 4 x 4 B-spline
/// coefficients are `c`, spacing h.
double cellCurvatureBound(const Eigen::Matrix4d& c, double h) {
  const Range f_xx(kSecondToBezier * c * kToBezier.transpose() / (h * h));
  const Range f_yy(kToBezier * c * kSecondToBezier.transpose() / (h * h));
  const Range f_xy(kFirstToBezier * c * kFirstToBezier.transpose() / (h * h));
  const Range f_x(kFirstToBezier * c * kToBezier.transpose() / h);
  const Range f_y(kToBezier * c * kFirstToBezier.transpose() / h);
  // lambda_max = (a + c) / 2 + sqrt(((a - c) / 2)^2 + b^2), each term at its worst on the cell.
  const double spread = std::max(std::abs(f_xx.hi - f_yy.lo), std::abs(f_xx.lo - f_yy.hi));
  const double largest_eigenvalue =
      0.5 * (f_xx.hi + f_yy.hi) + std::hypot(0.5 * spread, f_xy.magnitude());
  // The shape operator's eigenvalues are those of H / W against I = 1 + grad grad^T >= 1.
  const double least_slope = std::hypot(f_x.distanceFromZero(), f_y.distanceFromZero());
  return std::max(largest_eigenvalue, 0.0) / std::sqrt(1.0 + least_slope * least_slope);
}

void validate(const HeightGrid& grid) {
  requirePositive(grid.spacing, grid.source + ": resolution [m]");
  requireFinite(grid.first_sample.x(), grid.source + ": first sample x [m]");
  requireFinite(grid.first_sample.y(), grid.source + ": first sample y [m]");
  const Eigen::Index nx = grid.heights.rows();
  const Eigen::Index ny = grid.heights.cols();
  if (std::min(nx, ny) < HeightMapSurface::kMinSamples ||
      std::max(nx, ny) > HeightMapSurface::kMaxSamples) {
    std::ostringstream message;
    message << grid.source << ": a height map needs " << HeightMapSurface::kMinSamples << " to "
            << HeightMapSurface::kMaxSamples << " samples a side, got " << nx << " x " << ny;
    throw std::invalid_argument(message.str());
  }
  for (Eigen::Index j = 0; j < ny; ++j) {
    for (Eigen::Index i = 0; i < nx; ++i) {
      if (!std::isfinite(grid.heights(i, j))) {
        std::ostringstream message;
        message << grid.source << ": the height of sample (" << i << ", " << j << ") along (x, y) is "
                << grid.heights(i, j) << ", expected finite";
        throw std::invalid_argument(message.str());
      }
    }
  }
}

}  // namespace

HeightMapSurface::HeightMapSurface(HeightGrid grid) : grid_(std::move(grid)) {
  validate(grid_);
  const Eigen::Index nx = grid_.heights.rows();
  const Eigen::Index ny = grid_.heights.cols();
  last_sample_ = grid_.first_sample +
                 grid_.spacing * Eigen::Vector2d(static_cast<double>(nx - 1), static_cast<double>(ny - 1));
  coefficients_ = prefilter(prefilter(grid_.heights).transpose()).transpose();
  worst_.curvature = -1.0;
  for (Eigen::Index j = 0; j + 1 < ny; ++j) {
    for (Eigen::Index i = 0; i + 1 < nx; ++i) {
      const double bound =
          cellCurvatureBound(coefficients_.block<4, 4>(i, j), grid_.spacing);
      if (bound > worst_.curvature) {
        worst_.i = i;
        worst_.j = j;
        worst_.curvature = bound;
      }
    }
  }
  worst_.centre = grid_.first_sample +
                  grid_.spacing * Eigen::Vector2d(static_cast<double>(worst_.i) + 0.5,
                                                  static_cast<double>(worst_.j) + 0.5);
}

SurfacePoint HeightMapSurface::evaluate(double x, double y) const {
  const double h = grid_.spacing;
  const double u = (x - grid_.first_sample.x()) / h;
  const double v = (y - grid_.first_sample.y()) / h;
  const auto nx = static_cast<double>(grid_.heights.rows());
  const auto ny = static_cast<double>(grid_.heights.cols());
  if (!(u >= -kEdgeSlack && u <= nx - 1.0 + kEdgeSlack && v >= -kEdgeSlack &&
        v <= ny - 1.0 + kEdgeSlack)) {
    std::ostringstream message;
    message << "(" << x << ", " << y << ") m is off the height map " << grid_.source
            << ", which covers x in [" << grid_.first_sample.x() << ", " << last_sample_.x()
            << "] m, y in [" << grid_.first_sample.y() << ", " << last_sample_.y() << "] m";
    throw OffMapError(message.str());
  }
  // The cell holding (u, v); its far edges belong to it, so the map's last row and column do.
  const double i = std::clamp(std::floor(u), 0.0, nx - 2.0);
  const double j = std::clamp(std::floor(v), 0.0, ny - 2.0);
  const Weights wx = weightsAt(u - i);
  const Weights wy = weightsAt(v - j);
  const auto block = coefficients_.block<4, 4>(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  const Eigen::Vector4d along_y = block * wy.value;
  const Eigen::Vector4d along_y_first = block * wy.first;
  SurfacePoint point;
  point.height = wx.value.dot(along_y);
  point.gradient << wx.first.dot(along_y) / h, wx.value.dot(along_y_first) / h;
  const double h2 = h * h;
  point.hessian(0, 0) = wx.second.dot(along_y) / h2;
  point.hessian(0, 1) = point.hessian(1, 0) = wx.first.dot(along_y_first) / h2;
  point.hessian(1, 1) = wx.value.dot(block * wy.second) / h2;
  return point;
}

double HeightMapSurface::maxPrincipalCurvature() const { return worst_.curvature; }

std::string HeightMapSurface::describe() const {
  std::ostringstream text;
  text << "height map " << grid_.source << " (" << grid_.heights.rows() << " x "
       << grid_.heights.cols() << " samples " << grid_.spacing << " m apart, x in ["
       << grid_.first_sample.x() << ", " << last_sample_.x() << "] m, y in ["
       << grid_.first_sample.y() << ", " << last_sample_.y() << "] m)";
  return text.str();
}

std::optional<Eigen::AlignedBox2d> HeightMapSurface::domain() const {
  return Eigen::AlignedBox2d(grid_.first_sample, last_sample_);
}

std::string HeightMapSurface::maxCurvatureLocation() const {
  std::ostringstream text;
  text << "cell (" << worst_.i << ", " << worst_.j << ") along (x, y), centred at ("
       << worst_.centre.x() << ", " << worst_.centre.y() << ") m";
  return text.str();
}

}  // namespace spherical_robots::terrain
