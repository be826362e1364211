// Terrain surfaces z = f(x, y) (paper eq 3, eq 59) and their curvature, checked against closed
// forms, central finite differences and the classical curvature formulas for a graph.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/terrain/surface.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using spherical_robots::terrain::CosineSurface;
using spherical_robots::terrain::PlaneSurface;
using spherical_robots::terrain::principalCurvatures;
using spherical_robots::terrain::requireSinglePointContact;
using spherical_robots::terrain::Surface;

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// The paper's section 6 terrain: a = 0.2 m, w = 2 rad/m.
constexpr double kA = 0.2;
constexpr double kW = 2.0;

struct Point {
  double x, y;
};

// Points spread over a period of eq 59, including the peak, a valley, saddles and generic points.
const std::vector<Point> kSamplePoints = {{0.0, 0.0},   {kPi / kW, kPi / kW}, {kPi / kW, 0.0},
                                          {0.3, -0.7},  {1.1, 0.4},           {-2.3, 2.9},
                                          {0.785, 0.2}, {4.0, -5.5},          {0.01, 1e-3}};

// Central differences of a scalar/vector function, step h (error O(h^2) ~ 1e-10 for h = 1e-5).
// The return type is spelled out so that an Eigen expression is evaluated, not left dangling.
template <typename F>
auto centralDx(F f, double x, double y, double h = 1e-5) -> decltype(f(x, y)) {
  return (f(x + h, y) - f(x - h, y)) / (2.0 * h);
}
template <typename F>
auto centralDy(F f, double x, double y, double h = 1e-5) -> decltype(f(x, y)) {
  return (f(x, y + h) - f(x, y - h)) / (2.0 * h);
}

// Principal curvatures of a graph from the textbook Gaussian and mean curvature (do Carmo 3.3),
// with the upward normal, so that a valley (f_xx, f_yy > 0) has positive curvature:
//   K = (f_xx f_yy - f_xy^2) / W^2,  H = ((1+f_y^2) f_xx - 2 f_x f_y f_xy + (1+f_x^2) f_yy) / (2 W^1.5),
//   W = 1 + f_x^2 + f_y^2,  k = H -/+ sqrt(H^2 - K).
Eigen::Vector2d graphCurvatures(double fx, double fy, double fxx, double fxy, double fyy) {
  const double w = 1.0 + fx * fx + fy * fy;
  const double k_gauss = (fxx * fyy - fxy * fxy) / (w * w);
  const double h_mean =
      ((1.0 + fy * fy) * fxx - 2.0 * fx * fy * fxy + (1.0 + fx * fx) * fyy) / (2.0 * std::pow(w, 1.5));
  const double root = std::sqrt(std::max(0.0, h_mean * h_mean - k_gauss));
  return {h_mean - root, h_mean + root};
}

// A test-only surface: the bowl z = c - sqrt(r^2 - x^2 - y^2), the lower half of a sphere of
// radius r. Both principal curvatures are 1/r everywhere (concave up).
class SphericalBowl final : public Surface {
 public:
  explicit SphericalBowl(double r, double sign = 1.0) : r_(r), sign_(sign) {}
  spherical_robots::terrain::SurfacePoint evaluate(double x, double y) const override {
    const double q = r_ * r_ - x * x - y * y, root = std::sqrt(q);
    spherical_robots::terrain::SurfacePoint p;
    p.height = -sign_ * root;
    p.gradient = sign_ * Eigen::Vector2d(x, y) / root;
    p.hessian << (r_ * r_ - y * y), x * y, x * y, (r_ * r_ - x * x);
    p.hessian *= sign_ / (q * root);
    return p;
  }
  double maxPrincipalCurvature() const override { return sign_ > 0 ? 1.0 / r_ : 0.0; }
  std::string describe() const override { return "test bowl"; }

 private:
  double r_;
  double sign_;  // +1: bowl (concave up), -1: dome (concave down)
};

// A test-only cylinder z = -sqrt(r^2 - x^2): curvature 1/r across it, 0 along it.
class CylindricalTrough final : public Surface {
 public:
  explicit CylindricalTrough(double r) : r_(r) {}
  spherical_robots::terrain::SurfacePoint evaluate(double x, double) const override {
    const double root = std::sqrt(r_ * r_ - x * x);
    spherical_robots::terrain::SurfacePoint p;
    p.height = -root;
    p.gradient = {x / root, 0.0};
    p.hessian = Eigen::Matrix2d::Zero();
    p.hessian(0, 0) = r_ * r_ / (root * root * root);
    return p;
  }
  double maxPrincipalCurvature() const override { return 1.0 / r_; }
  std::string describe() const override { return "test trough"; }

 private:
  double r_;
};

// ------------------------------------------------------------------------------------------
// CosineSurface, eq 59: z = a (cos wx + cos wy - 2).

TEST(CosineSurface, HeightGradientHessianMatchEq59ClosedForm) {
  const CosineSurface s(kA, kW);
  for (const auto& p : kSamplePoints) {
    SCOPED_TRACE("at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
    EXPECT_NEAR(s.height(p.x, p.y), kA * (std::cos(kW * p.x) + std::cos(kW * p.y) - 2.0), 1e-14);
    const Eigen::Vector2d g = s.gradient(p.x, p.y);
    EXPECT_NEAR(g.x(), -kA * kW * std::sin(kW * p.x), 1e-15);
    EXPECT_NEAR(g.y(), -kA * kW * std::sin(kW * p.y), 1e-15);
    const Eigen::Matrix2d h = s.hessian(p.x, p.y);
    EXPECT_NEAR(h(0, 0), -kA * kW * kW * std::cos(kW * p.x), 1e-15);
    EXPECT_NEAR(h(1, 1), -kA * kW * kW * std::cos(kW * p.y), 1e-15);
    EXPECT_EQ(h(0, 1), 0.0);  // separable: no mixed term
    EXPECT_EQ(h(1, 0), 0.0);
  }
}

TEST(CosineSurface, PeakIsAtOriginAndValleysAtPiOverW) {
  const CosineSurface s(kA, kW);
  EXPECT_EQ(s.height(0.0, 0.0), 0.0);                        // highest point, z = 0
  EXPECT_NEAR(s.height(kPi / kW, kPi / kW), -4.0 * kA, 1e-15);  // lowest, z = -4a
}

// Finite differences check the implementation's derivatives against its own height, independently
// of any closed form we might both have got wrong.
TEST(CosineSurface, DerivativesMatchCentralFiniteDifferences) {
  const CosineSurface s(kA, kW);
  auto f = [&](double x, double y) { return s.height(x, y); };
  auto grad = [&](double x, double y) { return s.gradient(x, y); };
  for (const auto& p : kSamplePoints) {
    SCOPED_TRACE("at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
    const Eigen::Vector2d g = s.gradient(p.x, p.y);
    EXPECT_NEAR(g.x(), centralDx(f, p.x, p.y), 1e-9);
    EXPECT_NEAR(g.y(), centralDy(f, p.x, p.y), 1e-9);
    const Eigen::Matrix2d h = s.hessian(p.x, p.y);
    const Eigen::Vector2d dgx = centralDx(grad, p.x, p.y);
    const Eigen::Vector2d dgy = centralDy(grad, p.x, p.y);
    EXPECT_NEAR(h(0, 0), dgx.x(), 1e-8);
    EXPECT_NEAR(h(1, 0), dgx.y(), 1e-8);
    EXPECT_NEAR(h(0, 1), dgy.x(), 1e-8);
    EXPECT_NEAR(h(1, 1), dgy.y(), 1e-8);
  }
}

TEST(CosineSurface, ConstructorRejectsInvalidParameters) {
  EXPECT_THROW(CosineSurface(kNaN, kW), std::invalid_argument);
  EXPECT_THROW(CosineSurface(kInf, kW), std::invalid_argument);
  EXPECT_THROW(CosineSurface(kA, kNaN), std::invalid_argument);
  EXPECT_THROW(CosineSurface(kA, kInf), std::invalid_argument);
  EXPECT_THROW(CosineSurface(kA, 0.0), std::invalid_argument);   // frequency must be > 0
  EXPECT_THROW(CosineSurface(kA, -2.0), std::invalid_argument);
  EXPECT_NO_THROW(CosineSurface(kA, kW));
}

// ------------------------------------------------------------------------------------------
// PlaneSurface: z = z0 + g_x x + g_y y.

struct PlaneCase {
  double gx, gy, z0;
};

class PlaneSurfaceTest : public ::testing::TestWithParam<PlaneCase> {};

TEST_P(PlaneSurfaceTest, IsAnAffineHeightWithConstantGradientAndZeroCurvature) {
  const auto c = GetParam();
  const PlaneSurface s(c.gx, c.gy, c.z0);
  for (const auto& p : kSamplePoints) {
    EXPECT_NEAR(s.height(p.x, p.y), c.z0 + c.gx * p.x + c.gy * p.y, 1e-14);
    EXPECT_EQ(s.gradient(p.x, p.y), Eigen::Vector2d(c.gx, c.gy));
    EXPECT_EQ(s.hessian(p.x, p.y), Eigen::Matrix2d::Zero());
    const Eigen::Vector2d k = principalCurvatures(s, p.x, p.y);
    EXPECT_NEAR(k.x(), 0.0, 1e-15);
    EXPECT_NEAR(k.y(), 0.0, 1e-15);
  }
  EXPECT_EQ(s.maxPrincipalCurvature(), 0.0);
  // A plane never breaks single-point contact, whatever the radius.
  EXPECT_NO_THROW(requireSinglePointContact(s, 1e6));
}

INSTANTIATE_TEST_SUITE_P(FlatAndTilted, PlaneSurfaceTest,
                         ::testing::Values(PlaneCase{0.0, 0.0, 0.0}, PlaneCase{0.0, 0.0, -1.5},
                                           PlaneCase{0.3, 0.0, 0.0}, PlaneCase{-0.2, 0.5, 0.7},
                                           PlaneCase{2.0, -3.0, 0.1}));

TEST(PlaneSurface, ConstructorRejectsNonFiniteParameters) {
  EXPECT_THROW(PlaneSurface(kNaN, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(PlaneSurface(0.0, kInf, 0.0), std::invalid_argument);
  EXPECT_THROW(PlaneSurface(0.0, 0.0, -kInf), std::invalid_argument);
}

// ------------------------------------------------------------------------------------------
// Principal curvatures (shape operator), sign: positive where concave up.

TEST(PrincipalCurvatures, CosineValleyIsConcaveUpWithCurvatureAW2) {
  // At (pi/w, pi/w): grad = 0, Hessian = diag(a w^2, a w^2), so k1 = k2 = a w^2 = 0.8 1/m.
  const CosineSurface s(kA, kW);
  const Eigen::Vector2d k = principalCurvatures(s, kPi / kW, kPi / kW);
  EXPECT_NEAR(k.x(), kA * kW * kW, 1e-12);
  EXPECT_NEAR(k.y(), kA * kW * kW, 1e-12);
}

TEST(PrincipalCurvatures, CosinePeakIsConcaveDownWithCurvatureMinusAW2) {
  const CosineSurface s(kA, kW);
  const Eigen::Vector2d k = principalCurvatures(s, 0.0, 0.0);
  EXPECT_NEAR(k.x(), -kA * kW * kW, 1e-12);
  EXPECT_NEAR(k.y(), -kA * kW * kW, 1e-12);
}

TEST(PrincipalCurvatures, CosineSaddleHasOppositeCurvatures) {
  // At (pi/w, 0): f_xx = +a w^2 (valley across x), f_yy = -a w^2 (ridge across y), grad = 0.
  const CosineSurface s(kA, kW);
  const Eigen::Vector2d k = principalCurvatures(s, kPi / kW, 0.0);
  EXPECT_NEAR(k.x(), -kA * kW * kW, 1e-12);  // (k_min, k_max) order
  EXPECT_NEAR(k.y(), kA * kW * kW, 1e-12);
}

TEST(PrincipalCurvatures, MatchGaussianAndMeanCurvatureOfAGraphAtSlopedPoints) {
  const CosineSurface s(kA, kW);
  for (const auto& p : kSamplePoints) {
    SCOPED_TRACE("at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
    const double fx = -kA * kW * std::sin(kW * p.x), fy = -kA * kW * std::sin(kW * p.y);
    const double fxx = -kA * kW * kW * std::cos(kW * p.x), fyy = -kA * kW * kW * std::cos(kW * p.y);
    const Eigen::Vector2d expected = graphCurvatures(fx, fy, fxx, 0.0, fyy);
    const Eigen::Vector2d k = principalCurvatures(s, p.x, p.y);
    EXPECT_NEAR(k.x(), expected.x(), 1e-12);
    EXPECT_NEAR(k.y(), expected.y(), 1e-12);
    EXPECT_LE(k.x(), k.y());
  }
}

TEST(PrincipalCurvatures, SphericalBowlHasCurvatureOneOverRadiusEverywhere) {
  // A sphere's curvature is 1/r in every direction, also where the graph is steep (slope 2.3 at
  // |(x,y)| = 0.92 r), which exercises the metric I^-1 of the shape operator.
  const double r = 0.5;
  const SphericalBowl bowl(r, +1.0);
  const SphericalBowl dome(r, -1.0);
  for (const auto& p : std::vector<Point>{{0.0, 0.0}, {0.2, -0.1}, {-0.3, 0.3}, {0.46, 0.0}, {0.1, 0.45}}) {
    SCOPED_TRACE("at (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")");
    const Eigen::Vector2d kb = principalCurvatures(bowl, p.x, p.y);
    EXPECT_NEAR(kb.x(), 1.0 / r, 1e-9);
    EXPECT_NEAR(kb.y(), 1.0 / r, 1e-9);
    const Eigen::Vector2d kd = principalCurvatures(dome, p.x, p.y);
    EXPECT_NEAR(kd.x(), -1.0 / r, 1e-9);
    EXPECT_NEAR(kd.y(), -1.0 / r, 1e-9);
  }
}

TEST(PrincipalCurvatures, CylinderHasCurvatureOneOverRadiusAcrossAndZeroAlong) {
  const double r = 0.4;
  const CylindricalTrough trough(r);
  for (double x : {0.0, 0.1, -0.25, 0.35}) {
    const Eigen::Vector2d k = principalCurvatures(trough, x, 0.7);
    EXPECT_NEAR(k.x(), 0.0, 1e-12);
    EXPECT_NEAR(k.y(), 1.0 / r, 1e-9);
  }
}

TEST(CosineSurface, MaxPrincipalCurvatureIsTheValleyCurvatureAW2) {
  // The largest concave-up curvature of eq 59 is attained at the valleys, a w^2 = 0.8 1/m (a
  // dense sampling of the closed-form k_max over one period never exceeds it). The bound must not
  // be below it (unsafe) and should not be looser (it would reject radii that roll fine).
  const CosineSurface s(kA, kW);
  double sampled_max = -kInf;
  for (int i = 0; i <= 200; ++i) {
    for (int j = 0; j <= 200; ++j) {
      const double x = kPi / kW * i / 100.0, y = kPi / kW * j / 100.0;
      const double fx = -kA * kW * std::sin(kW * x), fy = -kA * kW * std::sin(kW * y);
      const double fxx = -kA * kW * kW * std::cos(kW * x), fyy = -kA * kW * kW * std::cos(kW * y);
      sampled_max = std::max(sampled_max, graphCurvatures(fx, fy, fxx, 0.0, fyy).y());
    }
  }
  EXPECT_NEAR(sampled_max, kA * kW * kW, 1e-12);
  EXPECT_GE(s.maxPrincipalCurvature(), kA * kW * kW - 1e-12);
  EXPECT_LE(s.maxPrincipalCurvature(), kA * kW * kW * (1.0 + 1e-9));
}

// ------------------------------------------------------------------------------------------
// Single-point contact (paper assumption 3): R * k_max < 1.

TEST(SinglePointContact, AcceptsThePapersRadiusOnEq59) {
  const CosineSurface s(kA, kW);
  EXPECT_NO_THROW(requireSinglePointContact(s, 0.2));  // R a w^2 = 0.16
  EXPECT_NO_THROW(requireSinglePointContact(s, 1.2));  // 0.96, still < 1
}

TEST(SinglePointContact, RejectsARadiusLargerThanTheValleysRadiusOfCurvature) {
  const CosineSurface s(kA, kW);
  for (double radius : {1.25, 1.3, 5.0}) {  // R a w^2 = 1.0, 1.04, 4.0
    EXPECT_INVALID_ARGUMENT(requireSinglePointContact(s, radius), "radius", "curvature")
        << "radius " << radius;
  }
}

TEST(SinglePointContact, UsesTheSurfacesOwnCurvatureBound) {
  const SphericalBowl bowl(0.5);  // 1/r = 2
  EXPECT_NO_THROW(requireSinglePointContact(bowl, 0.49));
  EXPECT_THROW(requireSinglePointContact(bowl, 0.51), std::invalid_argument);
}

TEST(SinglePointContact, RejectsANonFiniteRadius) {
  const CosineSurface s(kA, kW);
  EXPECT_THROW(requireSinglePointContact(s, kNaN), std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
