// One step of the two-rotor sphere's figure eight (Svinin et al., section IV) against the paper's
// published numbers, the closed form of eq 36 (pure rolling), and invariants: the rolling
// contact's plane path is as long as the curve on the sphere, the motion it plans satisfies the
// realizability condition (eq 13) everywhere, γ turns the plane path rigidly, and composing two
// leaves equals integrating the figure eight (docs/errata.md S1-S6).

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/rotor/contact_curve.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/dynamic_realizability.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "spherical_robots/rotor/geometric_phase.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using namespace spherical_robots::rotor;

/// |value − printed| <= half a unit of the printed value's last digit.
bool roundsTo(double value, double printed, double half_unit) {
  return std::abs(value - printed) <= half_unit;
}

/// Root of f on [lo, hi] (f changes sign there) to 1e-14.
double rootOf(const std::function<double(double)>& f, double lo, double hi) {
  boost::math::tools::eps_tolerance<double> tolerance(48);
  boost::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(f, lo, hi, tolerance, iterations);
  return 0.5 * (bracket.first + bracket.second);
}

/// Every sign change of f on a grid over [lo, hi], refined.
std::vector<double> rootsOf(const std::function<double(double)>& f, double lo, double hi,
                            int cells) {
  std::vector<double> roots;
  double x0 = lo, f0 = f(lo);
  for (int i = 1; i <= cells; ++i) {
    const double x1 = lo + (hi - lo) * i / cells, f1 = f(x1);
    if ((f0 < 0) != (f1 < 0)) roots.push_back(rootOf(f, x0, x1));
    x0 = x1;
    f0 = f1;
  }
  return roots;
}

/// The symmetric figure eight (a = b) shifts along the line at −η_leaf/2 (the second leaf is the
/// first one reflected across it); h with the sign of the shift's component along that line.
double signedShift(double k, double a) {
  const StepResult step = rotorStep(k, FigureEight(a, a));
  const double axis = -0.5 * step.half.psi;
  return step.full.u_a * std::cos(axis) + step.full.v_a * std::sin(axis);
}

/// γ that points one step's shift along +v_a: the plane path turns by +γ with the curve.
double gammaAlongV(double k, double a, double b) {
  const StepResult step = rotorStep(k, FigureEight(a, b));
  return std::remainder(M_PI / 2 - std::atan2(step.full.v_a, step.full.u_a), 2 * M_PI);
}

/// Section IV's circle: geodesic radius α R with h = 1 for k = 0 (the paper's a ≈ 0.533681R).
double publishedAlpha() {
  return rootOf([](double alpha) { return signedShift(0.0, std::sin(alpha)) + 1.0; }, 0.5, 0.56);
}

/// Plane points (u_a, v_a) of one step at 2 * half_samples + 1 equally spaced θ; the first
/// half_samples + 1 are the half step.
std::vector<Eigen::Vector2d> planePoints(double k, const FigureEight& curve, int half_samples) {
  std::vector<Eigen::Vector2d> points;
  for (const ContactCoordinates& c : samplePath(k, curve, 1, 2 * half_samples)) {
    points.emplace_back(c.u_a, c.v_a);
  }
  return points;
}

/// Proper crossings between non-adjacent segments of a polyline.
int selfIntersections(const std::vector<Eigen::Vector2d>& p) {
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
  };
  int count = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) {
    for (std::size_t j = i + 2; j + 1 < p.size(); ++j) {
      const Eigen::Vector2d r = p[i + 1] - p[i], s = p[j + 1] - p[j], q = p[j] - p[i];
      const double d = cross(r, s);
      if (d == 0.0) continue;
      const double t = cross(q, s) / d, u = cross(q, r) / d;
      if (t > 0.0 && t <= 1.0 && u > 0.0 && u <= 1.0) ++count;
    }
  }
  return count;
}

TEST(RotorPhase, PureRollingShiftIsEq36) {
  // Eq 36 (k = 0) is written for the Euclidean radius a: h = 4 a / √(1 − a²) sin(π √(1 − a²)).
  for (double a : {0.1, 0.3, 0.5, 0.533681, 0.65}) {
    const double c = std::sqrt(1.0 - a * a);
    EXPECT_NEAR(std::abs(signedShift(0.0, a)), std::abs(4 * a / c * std::sin(M_PI * c)), 1e-10)
        << "a = " << a;
    EXPECT_NEAR(stepPhase(0.0, a, a).eta, 0.0, 1e-11) << "a = " << a;
  }
}

TEST(RotorPhase, PublishedRadiusIsGeodesic) {
  // S4: "a ≈ 0.533681R" with h/R = 1 is the geodesic radius; as a Euclidean radius h = 1.1764.
  const double alpha = publishedAlpha();
  EXPECT_TRUE(roundsTo(alpha, 0.533681, 5e-7)) << alpha;
  EXPECT_NEAR(stepPhase(0.0, 0.533681, 0.533681).h, 1.17636, 1e-5);
  EXPECT_NEAR(stepPhase(0.0, std::sin(alpha), std::sin(alpha)).h, 1.0, 1e-10);
}

TEST(RotorPhase, PublishedShiftsAndOrientations) {
  const double a = std::sin(publishedAlpha());
  const double g0 = gammaAlongV(0.0, a, a);
  EXPECT_TRUE(roundsTo(g0, -1.13393, 5e-6)) << g0;
  const double h25 = stepPhase(2.5, a, a).h, h5 = stepPhase(5.0, a, a).h;
  EXPECT_TRUE(roundsTo(h25, 0.410842, 5e-7)) << h25;
  EXPECT_TRUE(roundsTo(h5, 0.515783, 5e-7)) << h5;
  const double g25 = gammaAlongV(2.5, a, a), g5 = gammaAlongV(5.0, a, a);
  EXPECT_TRUE(roundsTo(g25, -0.965672, 5e-7)) << g25;
  EXPECT_TRUE(roundsTo(g5, -0.797416, 5e-7)) << g5;
  // γ really does point the whole step along +v_a (integrated with the turned curve).
  const StepResult turned = rotorStep(2.5, FigureEight(a, a, g25));
  EXPECT_NEAR(turned.full.u_a, 0.0, 1e-11);
  EXPECT_NEAR(turned.full.v_a, h25, 1e-11);
}

TEST(RotorPhase, ZerosOfShiftOverInertiaRatio) {
  const double a = std::sin(publishedAlpha());
  const std::vector<double> zeros =
      rootsOf([a](double k) { return signedShift(k, a); }, 0.0, 12.0, 120);
  ASSERT_GE(zeros.size(), 5u);
  const double published[] = {0.233154, 2.64357, 5.20728, 7.80506};
  const double half_unit[] = {5e-7, 5e-6, 5e-6, 5e-6};
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(roundsTo(zeros[i], published[i], half_unit[i])) << "k" << i + 1 << " " << zeros[i];
  }
  // S5: the fifth zero is 10.4171, not the published 10.9801; h there is 1.106, and h stays
  // above 0.17 over [10.5, 11.5].
  EXPECT_NEAR(zeros[4], 10.4171, 5e-5);
  EXPECT_NEAR(signedShift(10.9801, a), 1.1062, 1e-3);
  for (double k = 10.5; k <= 11.5; k += 0.02) EXPECT_GT(signedShift(k, a), 0.17) << k;
}

TEST(RotorPhase, RadiiForUnitShiftAtInertiaRatio2p5) {
  // S6: a1…a4 are Euclidean radii (unlike section IV's first a, S4); the list goes on above a4.
  std::vector<double> radii;
  for (double target : {1.0, -1.0}) {
    const std::vector<double> r = rootsOf(
        [target](double a) { return signedShift(2.5, a) - target; }, 0.05, 0.7, 260);
    radii.insert(radii.end(), r.begin(), r.end());
  }
  std::sort(radii.begin(), radii.end());
  ASSERT_GE(radii.size(), 5u);
  const double published[] = {0.300429, 0.491471, 0.538682, 0.609147};
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(roundsTo(radii[i], published[i], 5e-7)) << "a" << i + 1 << " " << radii[i];
  }
  EXPECT_NEAR(radii[4], 0.62192, 1e-5);  // the fifth solution the paper does not list
  const double g1 = gammaAlongV(2.5, radii[0], radii[0]);
  const double g2 = gammaAlongV(2.5, radii[1], radii[1]);
  EXPECT_TRUE(roundsTo(g1, 0.931883, 5e-7)) << g1;
  EXPECT_TRUE(roundsTo(g2, -0.69726, 5e-6)) << g2;
  // The first solution's path is shorter than pure rolling's (k = 0, same h): 2 a1 < 2 a(k = 0).
  EXPECT_LT(radii[0], std::sin(publishedAlpha()));
}

TEST(RotorPhase, HolonomyNearTheEquatorLimitChangesFast) {
  // Errata S7: eq 30 divides by z(θ), so near a = R/√2 the heading rate grows like 1/z; for k = 5
  // one leaf's holonomy changes by "~5 rad" per 0.0005 R of radius at a = 0.6995 R.
  const double change = leafPhase(5.0, 0.69975).holonomy - leafPhase(5.0, 0.69925).holonomy;
  EXPECT_TRUE(roundsTo(std::abs(change), 5.0, 0.5)) << change;
}

TEST(RotorPhase, SelfIntersectionsOfTheHalfStep) {
  // "The number of self-intersections of the half-step path is exactly i for k in [k_i, k_i+1]",
  // checked inside each interval (k_0 = 0, k_5 = 10.4171 as we find it, S5).
  const double a = std::sin(publishedAlpha());
  const double bounds[] = {0.0, 0.233154, 2.64357, 5.20728, 7.80506, 10.4171};
  for (int i = 0; i < 5; ++i) {
    for (double t : {0.1, 0.5, 0.9}) {
      const double k = bounds[i] + t * (bounds[i + 1] - bounds[i]);
      std::vector<Eigen::Vector2d> half = planePoints(k, FigureEight(a, a), 1500);
      half.resize(1501);
      const int crossings = selfIntersections(half);
      EXPECT_EQ(crossings, i) << "k = " << k;
    }
  }
}

TEST(RotorPhase, ComposedLeavesEqualTheIntegratedFigureEight) {
  for (double k : {0.0, 1.7, 4.0}) {
    for (const auto& [a, b] : {std::pair{0.3, 0.55}, std::pair{0.62, 0.2}}) {
      const StepResult step = rotorStep(k, FigureEight(a, b));
      const StepPhase phase = stepPhase(k, a, b);
      EXPECT_NEAR(step.full.u_a, phase.shift.x(), 1e-10);
      EXPECT_NEAR(step.full.v_a, phase.shift.y(), 1e-10);
      EXPECT_NEAR(step.full.psi, phase.eta, 1e-10);
      EXPECT_NEAR(step.half.psi, leafPhase(k, a).holonomy, 1e-10);
    }
  }
}

TEST(RotorPhase, LeafFromItsHalfEqualsTheWholeCircle) {
  // leafPhase integrates half a circle; the first half of a figure eight with a = r is the whole
  // first circle, integrated.
  for (double k : {0.0, 2.5, 5.0}) {
    for (double r : {0.05, 0.3, 0.6, 0.69}) {
      const LeafPhase leaf = leafPhase(k, r);
      const PlaneState half = rotorStep(k, FigureEight(r, 0.3)).half;
      // Near the equator both integrations are only good to ~1e-9 (S7).
      const double tolerance = r > 0.65 ? 1e-8 : 1e-10;
      EXPECT_NEAR(leaf.shift.x(), half.u_a, tolerance) << k << " " << r;
      EXPECT_NEAR(leaf.shift.y(), half.v_a, tolerance) << k << " " << r;
      EXPECT_NEAR(leaf.holonomy, half.psi, tolerance) << k << " " << r;
    }
  }
}

TEST(RotorPhase, GammaTurnsThePlanePathRigidly) {
  const double k = 3.1, a = 0.45, b = 0.31;
  const StepResult plain = rotorStep(k, FigureEight(a, b));
  for (double gamma : {-2.0, 0.4, 3.0}) {
    const StepResult turned = rotorStep(k, FigureEight(a, b, gamma));
    const Eigen::Vector2d expected =
        Eigen::Rotation2Dd(gamma) * Eigen::Vector2d(plain.full.u_a, plain.full.v_a);
    EXPECT_NEAR(turned.full.u_a, expected.x(), 1e-10);
    EXPECT_NEAR(turned.full.v_a, expected.y(), 1e-10);
    EXPECT_NEAR(turned.full.psi, plain.full.psi, 1e-10);
  }
}

TEST(RotorPhase, PlanePathIsAsLongAsTheContactCurve) {
  // Rolling without slip: the contact point moves equal distances on the sphere and the plane.
  for (double k : {0.0, 2.5, 5.0}) {
    const FigureEight curve(0.5, 0.35, 0.7);
    const std::vector<Eigen::Vector2d> trace = planePoints(k, curve, 2000);
    double length = 0.0;
    for (std::size_t i = 1; i < trace.size(); ++i) length += (trace[i] - trace[i - 1]).norm();
    EXPECT_NEAR(length, curve.length(), 1e-4 * curve.length()) << "k = " << k;
  }
}

TEST(RotorPhase, SampledPathFollowsTheStepsAndTheCurve) {
  const double k = 1.8;
  const FigureEight curve(0.42, 0.27, -0.6);
  const std::vector<ContactCoordinates> path = samplePath(k, curve, 3, 40);
  ASSERT_EQ(path.size(), 121u);
  const PlaneState end = integrateSteps(k, curve, 3);
  EXPECT_NEAR(path.back().u_a, end.u_a, 1e-10);  // split at the samples, same tolerance
  EXPECT_NEAR(path.back().v_a, end.v_a, 1e-10);
  EXPECT_NEAR(path.back().psi, end.psi, 1e-10);
  for (int i = 0; i <= 40; ++i) {
    const Eigen::Vector3d c = contactPoint(path[40 + i].u_o, path[40 + i].v_o);
    EXPECT_LE((c - curve.at(2 * M_PI * i / 40).point).norm(), 1e-12) << i;
  }
  EXPECT_THROW(samplePath(k, curve, 0, 10), std::invalid_argument);
}

TEST(RotorPhase, PlannedMotionIsRealizableAndRolls) {
  // Along the curve with θ̇ = 1: ω from eqs 17-19 with ψ' of the integrated path satisfies eq 13,
  // the rotors can produce it (eq 11), and the plane rates are those of rolling (eqs 6-7).
  const double k = 2.5;
  const FigureEight curve(0.49, 0.3, 0.2);
  PlaneState state;
  double theta = 0.0;
  for (int i = 1; i <= 40; ++i) {
    const double next = 2 * M_PI * (i - 0.5) / 40;
    state = integrateFigureEight(k, curve, theta, next, state);
    theta = next;
    const CurvePoint c = curve.at(theta);
    const Eigen::Vector2d angles = contactAngles(c.point);
    const Eigen::Vector2d angle_rates = contactAngleRates(c);
    const PlaneState rates = realizableCurveRates(k, c, state.psi);
    const ContactCoordinates coordinates{state.u_a, state.v_a, angles.x(), angles.y(), state.psi};
    const Eigen::Vector3d omega =
        angularVelocity(coordinates, angle_rates.x(), angle_rates.y(), rates.psi);
    EXPECT_NEAR(realizabilityResidual(k, coordinates, omega), 0.0, 1e-12) << theta;
    EXPECT_NO_THROW(rotorSpeeds(k, 10.0, coordinates, omega));
    EXPECT_NEAR(rates.u_a, omega.y(), 1e-12) << theta;
    EXPECT_NEAR(rates.v_a, -omega.x(), 1e-12) << theta;
    // The curve's point is the contact point of eq 1 at (u_o, v_o).
    EXPECT_LE((contactPoint(angles.x(), angles.y()) - c.point).norm(), 1e-14);
  }
}

TEST(RotorPhase, CurveAngularVelocityIsTheDerivativeOfTheIntegratedOrientation) {
  // Along an integrated figure eight, ω = vee(Ṙ Rᵀ) of R(u_o(θ), v_o(θ), ψ(θ)) by central
  // differences (θ̇ = 1); the rotors can produce it (eq 11) and the contact rolls (eqs 6-7).
  const double k = 3.0, h = 1e-5;
  const FigureEight curve(0.5, 0.35, 0.9);
  const auto orientationAt = [&](double theta) {
    const PlaneState s = integrateFigureEight(k, curve, 0.0, theta, PlaneState{});
    const Eigen::Vector2d angles = contactAngles(curve.at(theta).point);
    return orientation(angles.x(), angles.y(), s.psi);
  };
  for (double theta : {0.4, 1.3, 2.9, 3.6, 5.1}) {
    const Eigen::Matrix3d r = orientationAt(theta);
    const Eigen::Matrix3d w = (orientationAt(theta + h) - orientationAt(theta - h)) / (2 * h) *
                              r.transpose();
    const Eigen::Vector3d expected(w(2, 1), w(0, 2), w(1, 0));
    const PlaneState s = integrateFigureEight(k, curve, 0.0, theta, PlaneState{});
    const Eigen::Vector3d omega = curveAngularVelocity(k, curve.at(theta), s.psi, 1.0);
    EXPECT_LE((omega - expected).norm(), 1e-6) << theta;
    const Eigen::Vector2d angles = contactAngles(curve.at(theta).point);
    const ContactCoordinates at{s.u_a, s.v_a, angles.x(), angles.y(), s.psi};
    EXPECT_NEAR(realizabilityResidual(k, at, omega), 0.0, 1e-12);
    const PlaneState rates = realizableCurveRates(k, curve.at(theta), s.psi);
    EXPECT_NEAR(rates.u_a, omega.y(), 1e-12);
    EXPECT_NEAR(rates.v_a, -omega.x(), 1e-12);
    // Twice the rate, twice ω.
    EXPECT_LE((curveAngularVelocity(k, curve.at(theta), s.psi, 2.0) - 2 * omega).norm(), 1e-12);
  }
}

TEST(RotorPhase, RejectsBadInput) {
  EXPECT_THROW(FigureEight(0.0, 0.3), std::invalid_argument);
  EXPECT_THROW(FigureEight(0.3, 0.71), std::invalid_argument);
  EXPECT_THROW(FigureEight(0.3, 0.3, std::nan("")), std::invalid_argument);
  EXPECT_THROW(rotorStep(-1.0, FigureEight(0.3, 0.3)), std::invalid_argument);
  EXPECT_THROW(integrateSteps(1.0, FigureEight(0.3, 0.3), 0), std::invalid_argument);
  EXPECT_THROW(integrateFigureEight(1.0, FigureEight(0.3, 0.3), 1.0, 7.0, {}),
               std::invalid_argument);
  EXPECT_INVALID_ARGUMENT(FigureEight(0.3, 0.75), "second circle radius b", "0.75", "0.7071");
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
