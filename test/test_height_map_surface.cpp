// The height map surface (terrain::HeightMapSurface): eq 59 sampled on a grid against its closed
// form within the error bound of cubic spline interpolation, the bound's order by halving the
// spacing, C2 continuity across cells, exactness on cubics, the curvature bound and the
// single-point-contact check naming the worst cell, the edges; and the Gaussian smoothing
// against the Gaussian's Fourier transform.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/terrain/height_grid.hpp"
#include "spherical_robots/terrain/height_map_surface.hpp"
#include "spherical_robots/terrain/surface.hpp"

namespace {

namespace terrain = spherical_robots::terrain;
using terrain::HeightGrid;
using terrain::HeightMapSurface;

constexpr double kA = 0.2;  // eq 59 as config/terrain.yaml has it: a [m], w [rad/m]
constexpr double kW = 2.0;
constexpr double kRadius = 0.2;  // urdf/terrain_robot.urdf [m]

/// f sampled at x0 + i h, y0 + j h on n_x x n_y samples.
template <typename F>
HeightGrid sampled(F f, double x0, double y0, double h, Eigen::Index nx, Eigen::Index ny) {
  HeightGrid grid;
  grid.spacing = h;
  grid.first_sample = {x0, y0};
  grid.source = "test grid";
  grid.heights.resize(nx, ny);
  for (Eigen::Index i = 0; i < nx; ++i)
    for (Eigen::Index j = 0; j < ny; ++j) grid.heights(i, j) = f(x0 + i * h, y0 + j * h);
  return grid;
}

const terrain::CosineSurface kEq59(kA, kW);

/// Eq 59 sampled every h over [-3, 3.4] m along both axes (not symmetric about an extremum).
HeightMapSurface eq59Map(double h) {
  const auto n = static_cast<Eigen::Index>(std::lround(6.4 / h)) + 1;
  return HeightMapSurface(
      sampled([](double x, double y) { return kEq59.height(x, y); }, -3.0, -3.0, h, n, n));
}

/// Largest errors of the map against eq 59 over every cell at a quarter-cell lattice.
struct Errors {
  double height = 0.0, gradient = 0.0, hessian_diagonal = 0.0, hessian_mixed = 0.0;
};

/// ... at least `margin` [m] inside the map's edges.
Errors eq59Errors(const HeightMapSurface& map, double margin = 0.0) {
  Errors e;
  const Eigen::AlignedBox2d box = *map.domain();
  const double step = map.grid().spacing / 4.0;
  const auto n = static_cast<int>(std::lround((box.sizes().x() - 2.0 * margin) / step));
  for (int a = 0; a <= n; ++a) {
    for (int b = 0; b <= n; ++b) {
      const double x = box.min().x() + margin + a * step;
      const double y = box.min().y() + margin + b * step;
      const terrain::SurfacePoint got = map.evaluate(x, y);
      const terrain::SurfacePoint truth = kEq59.evaluate(x, y);
      e.height = std::max(e.height, std::abs(got.height - truth.height));
      e.gradient = std::max(e.gradient, (got.gradient - truth.gradient).cwiseAbs().maxCoeff());
      e.hessian_diagonal = std::max(
          e.hessian_diagonal, (got.hessian - truth.hessian).diagonal().cwiseAbs().maxCoeff());
      e.hessian_mixed = std::max(e.hessian_mixed, std::abs(got.hessian(0, 1) - truth.hessian(0, 1)));
    }
  }
  return e;
}

// The bound. Eq 59 is g(x) + g(y) - 2a, g(x) = a cos(w x), and the tensor-product interpolant
// reproduces constants along each axis, so its error is e(x) + e(y) with e the error of the 1D
// spline through g's samples: the cross derivative f_xy has none. That 1D spline is the complete
// cubic spline s_c (exact end slopes) plus the spline z through zero data whose end slopes are
// the stencil's errors |delta| <= h^4 max|g^(5)| / 5.
//  * s_c (Hall & Meyer 1976, J. Approx. Theory 16, optimal constants for r = 0, 1):
//    |g^(r) - s_c^(r)| <= C_r h^(4-r) max|g''''|, C = 5/384, 1/24, 3/8.
//  * z: its knot second derivatives M solve the clamped moment system, rows (2 1 | 1 4 1 | 1 2)
//    with right-hand side 0 but -+6 delta / h at the ends; the system is diagonally dominant by
//    at least 1, so |M| <= 6 |delta| / h, and s'' is linear between knots. z vanishes at the
//    knots, so |z| <= h^2 / 8 |M| = 3/4 h |delta| and |z'| <= h / 2 |M| = 3 |delta|.
struct Bound {
  double height, gradient, hessian;
};

Bound eq59Bound(double h) {
  const double m4 = kA * std::pow(kW, 4);
  const double delta = std::pow(h, 4) * kA * std::pow(kW, 5) / 5.0;
  const double e0 = 5.0 / 384.0 * std::pow(h, 4) * m4 + 0.75 * h * delta;
  const double e1 = 1.0 / 24.0 * std::pow(h, 3) * m4 + 3.0 * delta;
  const double e2 = 3.0 / 8.0 * h * h * m4 + 6.0 * delta / h;
  return {2.0 * e0, e1, e2};
}

TEST(HeightMapSurface, Eq59WithinTheInterpolationBoundAtTheShippedResolution) {
  for (const double h : {0.1, 0.05}) {  // maps/hills.yaml's; the example
    const Errors e = eq59Errors(eq59Map(h));
    const Bound bound = eq59Bound(h);
    SCOPED_TRACE("h = " + std::to_string(h));
    EXPECT_LE(e.height, bound.height);
    EXPECT_LE(e.gradient, bound.gradient);
    EXPECT_LE(e.hessian_diagonal, bound.hessian);
    EXPECT_LE(e.hessian_mixed, 1e-9);  // rounding only
    // The bound is not vacuous: at 0.05 m, 3e-3 1/m of eq 59's 0.8 1/m curvature.
    EXPECT_LE(bound.hessian, 0.01 * kA * kW * kW / h);
  }
}

TEST(HeightMapSurface, Eq59ErrorsConvergeAtOrdersFourThreeTwo) {
  // Halving h divides the interpolation's errors by 2^4, 2^3, 2^2. Measured a metre inside the
  // edges (10 cells or more, over which the end slopes' influence decays by (2 - sqrt 3)^10):
  // near an edge the end slopes' own error, h^4 max|g^(5)| / 5, adds terms of higher order.
  const Errors coarse = eq59Errors(eq59Map(0.1), 1.0);
  const Errors fine = eq59Errors(eq59Map(0.05), 1.0);
  EXPECT_NEAR(coarse.height / fine.height, 16.0, 1.5);
  EXPECT_NEAR(coarse.gradient / fine.gradient, 8.0, 0.8);
  EXPECT_NEAR(coarse.hessian_diagonal / fine.hessian_diagonal, 4.0, 0.4);
}

HeightGrid randomGrid(unsigned seed, Eigen::Index nx, Eigen::Index ny) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> height(-0.05, 0.05);
  HeightGrid grid = sampled([](double, double) { return 0.0; }, -0.3, 0.2, 0.1, nx, ny);
  for (Eigen::Index i = 0; i < nx; ++i)
    for (Eigen::Index j = 0; j < ny; ++j) grid.heights(i, j) = height(generator);
  return grid;
}

TEST(HeightMapSurface, PassesThroughEverySample) {
  const HeightGrid grid = randomGrid(7, 9, 6);
  const HeightMapSurface map(grid);
  for (Eigen::Index i = 0; i < 9; ++i) {
    for (Eigen::Index j = 0; j < 6; ++j) {
      EXPECT_NEAR(map.height(-0.3 + i * 0.1, 0.2 + j * 0.1), grid.heights(i, j), 1e-14);
    }
  }
}

TEST(HeightMapSurface, CubicsAreReproducedExactly) {
  // The end slopes' stencil is exact on quartics and a complete cubic spline reproduces cubics.
  const auto cubic = [](double x, double y) {
    return 0.1 * x * x * x - 0.2 * x * x * y + 0.05 * x * y * y * y - 0.3 * y * y + 0.4 * x - 1.0;
  };
  const HeightMapSurface map(sampled(cubic, -1.0, -0.5, 0.25, 9, 7));
  for (const auto& [x, y] : {std::pair{-0.93, -0.41}, {0.1, 0.2}, {0.99, 0.99}, {-1.0, 1.0}}) {
    const terrain::SurfacePoint p = map.evaluate(x, y);
    EXPECT_NEAR(p.height, cubic(x, y), 1e-13);
    EXPECT_NEAR(p.gradient.x(), 0.3 * x * x - 0.4 * x * y + 0.05 * y * y * y + 0.4, 1e-12);
    EXPECT_NEAR(p.gradient.y(), -0.2 * x * x + 0.15 * x * y * y - 0.6 * y, 1e-12);
    EXPECT_NEAR(p.hessian(0, 0), 0.6 * x - 0.4 * y, 1e-11);
    EXPECT_NEAR(p.hessian(0, 1), -0.4 * x + 0.15 * y * y, 1e-11);
    EXPECT_NEAR(p.hessian(1, 1), 0.3 * x * y - 0.6, 1e-11);
  }
}

TEST(HeightMapSurface, DerivativesAreThoseOfTheHeight) {
  const HeightMapSurface map(randomGrid(11, 8, 8));
  const double d = 1e-6;
  for (const auto& [x, y] : {std::pair{-0.17, 0.33}, {0.05, 0.61}, {0.31, 0.44}}) {
    const terrain::SurfacePoint p = map.evaluate(x, y);
    EXPECT_NEAR(p.gradient.x(), (map.height(x + d, y) - map.height(x - d, y)) / (2 * d), 1e-7);
    EXPECT_NEAR(p.gradient.y(), (map.height(x, y + d) - map.height(x, y - d)) / (2 * d), 1e-7);
    const Eigen::Matrix2d fd_hessian =
        (Eigen::Matrix2d() << (map.gradient(x + d, y) - map.gradient(x - d, y)) / (2 * d),
         (map.gradient(x, y + d) - map.gradient(x, y - d)) / (2 * d))
            .finished();
    EXPECT_LE((p.hessian - fd_hessian).cwiseAbs().maxCoeff(), 1e-6);
  }
}

TEST(HeightMapSurface, HessianIsContinuousAcrossCellBoundaries) {
  // Random samples: every boundary of an interpolating C1-only scheme (local bicubic) would show
  // a jump here. One-sided limits at the boundary x = x_4 (and y = y_3) agree to O(epsilon);
  // the third derivative, which a cubic spline does not keep continuous, does jump: the check
  // can tell.
  const HeightMapSurface map(randomGrid(3, 9, 9));
  const double x_knot = -0.3 + 4 * 0.1;
  const double y_knot = 0.2 + 3 * 0.1;
  const double eps = 1e-9;
  for (const double y : {0.27, 0.36, y_knot}) {
    const Eigen::Matrix2d left = map.hessian(x_knot - eps, y);
    const Eigen::Matrix2d right = map.hessian(x_knot + eps, y);
    EXPECT_LE((left - right).cwiseAbs().maxCoeff(), 1e-5) << "y = " << y;
  }
  for (const double x : {0.02, x_knot}) {
    EXPECT_LE((map.hessian(x, y_knot - eps) - map.hessian(x, y_knot + eps)).cwiseAbs().maxCoeff(),
              1e-5);
  }
  const double d = 1e-4;
  const double third_left = (map.hessian(x_knot - d, 0.27)(0, 0) - map.hessian(x_knot - 2 * d, 0.27)(0, 0)) / d;
  const double third_right = (map.hessian(x_knot + 2 * d, 0.27)(0, 0) - map.hessian(x_knot + d, 0.27)(0, 0)) / d;
  EXPECT_GT(std::abs(third_left - third_right), 1.0);
}

TEST(HeightMapSurface, CurvatureBoundHoldsEverywhereAndIsTight) {
  const HeightMapSurface map = eq59Map(0.05);
  const double bound = map.maxPrincipalCurvature();
  const Eigen::AlignedBox2d box = *map.domain();
  double sampled_max = 0.0;
  for (double x = box.min().x(); x <= box.max().x(); x += 0.0123) {
    for (double y = box.min().y(); y <= box.max().y(); y += 0.0123) {
      sampled_max = std::max(sampled_max, terrain::principalCurvatures(map, x, y).y());
    }
  }
  EXPECT_LE(sampled_max, bound);
  // Eq 59's own maximum a w^2 = 0.8 1/m is reached at its valleys' bottoms, which the map
  // holds; the bound exceeds it by O(h) (the Bernstein ranges' width, h max|f'''| ~ 0.08 1/m).
  EXPECT_GE(bound, kA * kW * kW - eq59Bound(0.05).hessian);
  EXPECT_LE(bound, kA * kW * kW + 0.05 * kA * std::pow(kW, 3) * 1.5);
  EXPECT_NO_THROW(terrain::requireSinglePointContact(map, kRadius));
}

TEST(HeightMapSurface, ContactCheckNamesTheWorstCell) {
  // A level 2 m x 2 m map with one pit: the sample (12, 7) is 2 cm deeper. The spline's
  // valley there is curved far beyond 1/R; the worst cell is one of the four around the pit.
  HeightGrid grid = sampled([](double, double) { return 0.0; }, -1.0, -1.0, 0.1, 21, 21);
  grid.heights(12, 7) = -0.02;
  grid.source = "pit.yaml";
  const HeightMapSurface map(grid);
  const HeightMapSurface::CurvatureCell& worst = map.worstCell();
  EXPECT_TRUE(worst.i == 11 || worst.i == 12) << worst.i;
  EXPECT_TRUE(worst.j == 6 || worst.j == 7) << worst.j;
  EXPECT_NEAR(worst.centre.x(), -1.0 + (worst.i + 0.5) * 0.1, 1e-12);
  EXPECT_NEAR(worst.centre.y(), -1.0 + (worst.j + 0.5) * 0.1, 1e-12);
  // At the pit itself the spline's curvature (truth: principalCurvatures) already breaks R k < 1.
  EXPECT_GT(kRadius * terrain::principalCurvatures(map, 0.2, -0.3).y(), 1.0);
  std::ostringstream cell, where;
  cell << "cell (" << worst.i << ", " << worst.j << ")";
  where << "(" << worst.centre.x() << ", " << worst.centre.y() << ") m";
  EXPECT_INVALID_ARGUMENT(terrain::requireSinglePointContact(map, kRadius), "pit.yaml",
                          cell.str(), where.str(), "R * max principal curvature", ">= 1");
}

TEST(HeightMapSurface, OffTheMapIsRefusedOnItsEdgesIsNot) {
  const HeightMapSurface map = eq59Map(0.1);
  EXPECT_NO_THROW(map.evaluate(-3.0, -3.0));
  EXPECT_NO_THROW(map.evaluate(3.4, 3.4));
  EXPECT_NEAR(map.height(3.4, -3.0), kEq59.height(3.4, -3.0), 1e-12);  // the samples there
  for (const auto& [x, y] : {std::pair{-3.001, 0.0}, {0.0, 3.401}, {5.0, 5.0},
                             {std::numeric_limits<double>::quiet_NaN(), 0.0}}) {
    try {
      map.evaluate(x, y);
      ADD_FAILURE() << "(" << x << ", " << y << ") was accepted";
    } catch (const terrain::OffMapError& error) {
      EXPECT_NE(std::string(error.what()).find("off the height map test grid"), std::string::npos)
          << error.what();
      EXPECT_NE(std::string(error.what()).find("x in [-3, 3.4] m"), std::string::npos) << error.what();
    }
  }
}

TEST(HeightMapSurface, RejectsBadGridsNamingTheLimit) {
  const auto flat = [](double, double) { return 0.0; };
  EXPECT_INVALID_ARGUMENT(HeightMapSurface(sampled(flat, 0, 0, 0.1, 4, 10)), "test grid", "5 to 2048",
                          "4 x 10");
  EXPECT_INVALID_ARGUMENT(HeightMapSurface(sampled(flat, 0, 0, 0.1, 5, 2049)), "2049");
  EXPECT_INVALID_ARGUMENT(HeightMapSurface(sampled(flat, 0, 0, 0.0, 5, 5)), "resolution");
  HeightGrid hole = sampled(flat, 0, 0, 0.1, 6, 6);
  hole.heights(2, 3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_INVALID_ARGUMENT(HeightMapSurface(hole), "sample (2, 3)", "finite");
}

TEST(GaussianSmoothed, LeavesPlanesAndAttenuatesACosineAsItsTransform) {
  const auto plane = [](double x, double y) { return 0.3 - 0.2 * x + 0.1 * y; };
  const HeightGrid tilted = sampled(plane, -1.0, -1.0, 0.1, 21, 25);
  EXPECT_LE((terrain::gaussianSmoothed(tilted, 2.0).heights - tilted.heights).cwiseAbs().maxCoeff(),
            1e-12);
  // cos(w x) sampled every h: a normalised Gaussian of sigma samples multiplies it by
  // exp(-(w h sigma)^2 / 2) (its Fourier transform; the sampled kernel's aliasing is below 1e-8),
  // give or take twice the weight cut off beyond 4 sigma, erfc(4 / sqrt 2) = 6.3e-5.
  const double h = 0.05, sigma = 2.0;
  const double truncation = 2.0 * std::erfc(4.0 / std::sqrt(2.0));
  const HeightGrid wave = sampled([](double x, double) { return std::cos(kW * x); }, -3.0, 0.0, h, 121, 20);
  const HeightGrid smoothed = terrain::gaussianSmoothed(wave, sigma);
  const double gain = std::exp(-0.5 * std::pow(kW * h * sigma, 2));
  for (Eigen::Index i = 10; i < 111; ++i) {  // beyond 4 sigma of the ends
    EXPECT_NEAR(smoothed.heights(i, 9), gain * wave.heights(i, 9), truncation);
  }
  EXPECT_EQ(terrain::gaussianSmoothed(wave, 0.0).heights, wave.heights);
  EXPECT_INVALID_ARGUMENT(terrain::gaussianSmoothed(wave, 5.0), "sigma 5", "20");
  EXPECT_INVALID_ARGUMENT(terrain::gaussianSmoothed(wave, -1.0), "sigma");
}

// fuzz_height_map_surface's finding (test/fuzz/corpus/fuzz_height_map_surface/huge_sigma): a sigma
// whose 4-sigma reach exceeds every index was converted to one, undefined behaviour, before the
// check against the map's size.
TEST(GaussianSmoothed, RejectsASigmaBeyondAnyIndexNamingTheMapsSize) {
  const HeightGrid flat = sampled([](double, double) { return 0.0; }, 0.0, 0.0, 0.1, 7, 5);
  for (const double sigma : {1e19, 1e300, std::numeric_limits<double>::max()}) {
    EXPECT_INVALID_ARGUMENT(terrain::gaussianSmoothed(flat, sigma), "smoothing sigma", "7 x 5")
        << sigma;
  }
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
