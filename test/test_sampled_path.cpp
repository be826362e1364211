// SampledPath (terrain/sampled_path.hpp), the user's own path, against closed forms: the circle of
// eq 60 sampled at N points against CirclePath within the cubic spline's error bounds (Hall and
// Meyer 1976, for a spline whose ends are exact, as a periodic one's are: |f - s| <= 5/384 h^4
// max|f''''| and |f' - s'| <= 1/24 h^3 max|f''''|) and at their orders 4 and 3; polynomials of
// degree <= 3 reproduced exactly; the velocity against a finite difference of the position; the
// ends, the repetition of a closed path, the timing of untimed points and of stamps, and bad
// input refused naming the point and its value. Then PathTracker::follow, the time base of a
// path received while the robot runs, and PathTracker::setLaw, a law changed while it runs.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/terrain/path_tracker.hpp"
#include "spherical_robots/terrain/pure_pursuit.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/sampled_path.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace {

using namespace spherical_robots::terrain;  // NOLINT: test file
using spherical_robots::Nanoseconds;

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 2.0;  // config/terrain.yaml's circle
constexpr double kRate = 0.05;
const double kPeriod = 2.0 * kPi / kRate;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The circle at intervals + 1 equally spaced times over one period, from t0 [s]: the last point
/// is the first, so the path is closed.
std::vector<TimedPoint> circlePoints(const CirclePath& circle, int intervals, double t0 = 0.0) {
  std::vector<TimedPoint> points;
  for (int i = 0; i <= intervals; ++i) {
    const double t = kPeriod * i / intervals;
    points.push_back({t0 + t, circle.position(t)});
  }
  return points;
}

struct Errors {
  double position = 0.0;  // [m]
  double velocity = 0.0;  // [m/s]
};

/// The largest |path - truth| over [from, to], at `samples` + 1 times.
Errors largestErrors(const ReferencePath& path, const ReferencePath& truth, double from, double to,
                     int samples = 20000) {
  Errors errors;
  for (int i = 0; i <= samples; ++i) {
    const double t = from + (to - from) * i / samples;
    const PathPoint got = path.at(t);
    const PathPoint want = truth.at(t);
    errors.position = std::max(errors.position, (got.position - want.position).norm());
    errors.velocity = std::max(errors.velocity, (got.velocity - want.velocity).norm());
  }
  return errors;
}

// Each coordinate of the circle has |x''''| <= r w^4; the vector error is at most sqrt(2) times
// a coordinate's.
double positionBound(double h) { return std::sqrt(2.0) * 5.0 / 384.0 * std::pow(h, 4) * kRadius * std::pow(kRate, 4); }
double velocityBound(double h) { return std::sqrt(2.0) / 24.0 * std::pow(h, 3) * kRadius * std::pow(kRate, 4); }

TEST(SampledPath, ClosedCircleIsWithinTheSplineBoundsAndConvergesAtOrdersFourAndThree) {
  const CirclePath circle(kRadius, kRate);
  Errors previous;
  for (int intervals : {16, 32, 64, 128}) {
    const SampledPath path = SampledPath::timed(circlePoints(circle, intervals));
    ASSERT_TRUE(path.closed());
    EXPECT_NEAR(path.duration(), kPeriod, 1e-12);
    // Over a lap before the start and after the end too: a closed path repeats both ways.
    const Errors errors = largestErrors(path, circle, -kPeriod, 2.0 * kPeriod);
    const double h = kPeriod / intervals;
    EXPECT_LE(errors.position, positionBound(h)) << intervals << " intervals";
    EXPECT_LE(errors.velocity, velocityBound(h)) << intervals << " intervals";
    if (previous.position > 0.0) {
      // Halving h: errors / 16 and / 8 (orders 4 and 3), asserted as orders above 3.5 and 2.5.
      EXPECT_GT(previous.position / errors.position, std::pow(2.0, 3.5)) << intervals;
      EXPECT_GT(previous.velocity / errors.velocity, std::pow(2.0, 2.5)) << intervals;
    }
    previous = errors;
  }
}

TEST(SampledPath, NonUniformTimesStayWithinTheBoundOfTheLongestInterval) {
  const CirclePath circle(kRadius, kRate);
  std::vector<TimedPoint> points;
  const int intervals = 60;
  for (int i = 0; i <= intervals; ++i) {
    // Intervals of 0.6 to 1.4 times the mean, alternating: a planner's uneven spacing.
    const double t = kPeriod * (i + (i % intervals == 0 ? 0.0 : 0.2 * (i % 2 == 0 ? 1 : -1))) / intervals;
    points.push_back({t, circle.position(t)});
  }
  const SampledPath path = SampledPath::timed(points);
  const Errors errors = largestErrors(path, circle, 0.0, kPeriod);
  const double longest = 1.4 * kPeriod / intervals;
  EXPECT_LE(errors.position, positionBound(longest));
  EXPECT_LE(errors.velocity, velocityBound(longest));
}

TEST(SampledPath, OpenArcConvergesAtOrderFourUpToItsNotAKnotEnds) {
  const CirclePath circle(kRadius, kRate);
  Errors previous;
  for (int intervals : {8, 16, 32, 64}) {
    std::vector<TimedPoint> points;  // a quarter of the circle: open
    for (int i = 0; i <= intervals; ++i) {
      const double t = 0.25 * kPeriod * i / intervals;
      points.push_back({t, circle.position(t)});
    }
    const SampledPath path = SampledPath::timed(points);
    ASSERT_FALSE(path.closed());
    const Errors errors = largestErrors(path, circle, 0.0, 0.25 * kPeriod);
    if (previous.position > 0.0) {
      EXPECT_GT(previous.position / errors.position, std::pow(2.0, 3.5)) << intervals;
      EXPECT_GT(previous.velocity / errors.velocity, std::pow(2.0, 2.5)) << intervals;
    }
    previous = errors;
  }
}

TEST(SampledPath, ReproducesCubicsExactlyOnUnevenTimes) {
  // Not-a-knot ends make the spline of a cubic's samples that cubic.
  const auto x = [](double t) { return 1.0 - 2.0 * t + 0.5 * t * t + 0.25 * t * t * t; };
  const auto dx = [](double t) { return -2.0 + t + 0.75 * t * t; };
  const auto y = [](double t) { return -0.5 + 0.1 * t * t - 0.3 * t * t * t; };
  const auto dy = [](double t) { return 0.2 * t - 0.9 * t * t; };
  std::vector<TimedPoint> points;
  for (double t : {0.0, 0.3, 1.1, 1.5, 2.6, 4.0, 4.2}) points.push_back({t, {x(t), y(t)}});
  const SampledPath path = SampledPath::timed(points);
  for (int i = 0; i <= 420; ++i) {
    const double t = 0.01 * i;
    const PathPoint p = path.at(t);
    EXPECT_NEAR(p.position.x(), x(t), 1e-12) << t;
    EXPECT_NEAR(p.position.y(), y(t), 1e-12) << t;
    EXPECT_NEAR(p.velocity.x(), dx(t), 1e-11) << t;
    EXPECT_NEAR(p.velocity.y(), dy(t), 1e-11) << t;
  }
}

TEST(SampledPath, TwoPointsMakeALineAndThreeAParabola) {
  const SampledPath line = SampledPath::timed({{2.0, {1.0, 1.0}}, {6.0, {3.0, -1.0}}});
  EXPECT_NEAR(line.duration(), 4.0, 0.0);
  for (double t : {0.0, 1.0, 2.5, 4.0}) {
    EXPECT_NEAR((line.position(t) - Eigen::Vector2d(1.0 + 0.5 * t, 1.0 - 0.5 * t)).norm(), 0.0, 1e-15);
    EXPECT_NEAR((line.velocity(t) - Eigen::Vector2d(0.5, -0.5)).norm(), 0.0, 1e-15);
  }
  // x = t, y = t^2 - 3 t at t = 0, 1, 3.
  const SampledPath parabola = SampledPath::timed({{0.0, {0.0, 0.0}}, {1.0, {1.0, -2.0}}, {3.0, {3.0, 0.0}}});
  for (double t : {0.0, 0.5, 2.0, 3.0}) {
    EXPECT_NEAR((parabola.position(t) - Eigen::Vector2d(t, t * t - 3.0 * t)).norm(), 0.0, 1e-14) << t;
    EXPECT_NEAR((parabola.velocity(t) - Eigen::Vector2d(1.0, 2.0 * t - 3.0)).norm(), 0.0, 1e-14) << t;
  }
}

TEST(SampledPath, VelocityIsTheDerivativeOfPositionAcrossTheSeamOfALoop) {
  // A hand-made loop at uneven times, closed: its velocity is continuous across the seam.
  const SampledPath loop = SampledPath::timed({{0.0, {0.0, 0.0}},
                                               {2.0, {1.0, 0.2}},
                                               {3.5, {1.5, 1.0}},
                                               {6.0, {0.5, 1.8}},
                                               {7.0, {-0.4, 1.1}},
                                               {9.0, {0.0, 0.0}}});
  ASSERT_TRUE(loop.closed());
  const double step = 1e-5;
  for (double t : {-3.0, -1e-9, 0.0, 1.0, 2.0, 4.2, 7.0, 8.999, 9.0, 9.5, 20.0}) {
    const Eigen::Vector2d difference = (loop.position(t + step) - loop.position(t - step)) / (2.0 * step);
    EXPECT_NEAR((loop.velocity(t) - difference).norm(), 0.0, 1e-7) << t;
  }
  EXPECT_NEAR((loop.velocity(9.0 - 1e-9) - loop.velocity(1e-9)).norm(), 0.0, 1e-7);
  for (double t : {0.3, 4.0, 8.7}) {
    for (int laps : {-2, -1, 1, 3}) {
      EXPECT_NEAR((loop.position(t + laps * 9.0) - loop.position(t)).norm(), 0.0, 1e-12);
    }
  }
}

TEST(SampledPath, OpenPathHoldsItsFirstPointBeforeAndItsLastAfterAtRest) {
  // Times from 5 s: the path's own t = 0 is its first point's.
  const SampledPath path = SampledPath::timed({{5.0, {0.0, 0.0}}, {7.0, {1.0, 0.0}},
                                               {8.0, {1.5, 0.5}}, {10.0, {2.0, 2.0}}});
  ASSERT_FALSE(path.closed());
  EXPECT_EQ(path.duration(), 5.0);
  EXPECT_EQ(path.size(), 4u);
  EXPECT_NEAR((path.position(2.0) - Eigen::Vector2d(1.0, 0.0)).norm(), 0.0, 1e-15);
  for (double t : {-100.0, -1e-6}) {
    EXPECT_EQ(path.position(t), Eigen::Vector2d(0.0, 0.0)) << t;
    EXPECT_EQ(path.velocity(t), Eigen::Vector2d::Zero()) << t;
  }
  for (double t : {5.0 + 1e-6, 1e6}) {
    EXPECT_NEAR((path.position(t) - Eigen::Vector2d(2.0, 2.0)).norm(), 0.0, 1e-15) << t;
    EXPECT_EQ(path.velocity(t), Eigen::Vector2d::Zero()) << t;
  }
  EXPECT_GT(path.velocity(5.0).norm(), 0.0);  // the spline's own at the last point
}

TEST(SampledPath, MeanVelocityOfTheSampledCircleIsTheClosedForm) {
  const CirclePath circle(kRadius, kRate);
  const SampledPath path = SampledPath::timed(circlePoints(circle, 400));
  // The chord over the window of positions each within positionBound(h) of the circle's.
  const double window = 0.5;
  const double bound = 2.0 * positionBound(kPeriod / 400) / window;
  for (double t : {0.0, 0.1, 31.0, 125.0, 200.0}) {
    EXPECT_NEAR((path.meanVelocity(t, window) - circle.meanVelocity(t, window)).norm(), 0.0, bound) << t;
  }
}

TEST(SampledPath, UntimedPointsAreTimedByTheirDistancesAndRepeatsSkipped) {
  // 5 m then 6 m at 0.5 m/s; the repeated point is a planner's repeated goal.
  const SampledPath path = SampledPath::atSpeed(
      {{0.0, 0.0}, {3.0, 4.0}, {3.0, 4.0}, {3.0, 10.0}}, 0.5);
  EXPECT_EQ(path.size(), 3u);
  EXPECT_NEAR(path.duration(), 22.0, 1e-12);
  EXPECT_NEAR((path.position(10.0) - Eigen::Vector2d(3.0, 4.0)).norm(), 0.0, 1e-12);
  // Collinear points at a constant speed: the spline is the line, at that speed.
  const SampledPath line = SampledPath::atSpeed({{0.0, 0.0}, {1.0, 0.0}, {3.0, 0.0}, {3.5, 0.0}}, 0.25);
  for (double t : {1.0, 6.0, 13.0}) {
    EXPECT_NEAR((line.position(t) - Eigen::Vector2d(0.25 * t, 0.0)).norm(), 0.0, 1e-12) << t;
    EXPECT_NEAR((line.velocity(t) - Eigen::Vector2d(0.25, 0.0)).norm(), 0.0, 1e-12) << t;
  }
}

TEST(SampledPath, IncreasingStampsAreTimesFromTheFirstAndEqualOnesUntimed) {
  constexpr Nanoseconds kSecond = 1000000000;
  const SampledPath timed = SampledPath::fromStamped(
      {{100 * kSecond, {0.0, 0.0}}, {101 * kSecond, {1.0, 0.0}}, {103 * kSecond, {1.0, 2.0}}}, 0.1);
  EXPECT_NEAR(timed.duration(), 3.0, 1e-15);
  EXPECT_NEAR((timed.position(1.0) - Eigen::Vector2d(1.0, 0.0)).norm(), 0.0, 1e-15);
  for (Nanoseconds stamp : {Nanoseconds{0}, 7 * kSecond}) {
    const SampledPath untimed = SampledPath::fromStamped(
        {{stamp, {0.0, 0.0}}, {stamp, {1.0, 0.0}}, {stamp, {1.0, 2.0}}}, 0.1);
    EXPECT_NEAR(untimed.duration(), 30.0, 1e-12) << stamp;  // 3 m at 0.1 m/s
  }
}

// fuzz_read_path_file's finding (test/fuzz/corpus/fuzz_read_path_file/huge_coordinate.csv): the
// shipped S-curve with one y typed as 1e41 m gave the points after it the same time in double
// precision (2e42 s + 5.8 s = 2e42 s), so the spline's system was singular and a std::logic_error
// (a bug's exception) ended sphere_sim with an internal error.
TEST(SampledPath, UntimedPointsWhoseTimesDoubleCannotTellApartAreRefusedNamingThePoint) {
  const std::vector<Eigen::Vector2d> points = {{0.0, 0.0}, {0.5, 0.0}, {1.0, 1e41}, {1.5, 0.3},
                                               {2.0, 0.6}, {2.4, 1.0}, {2.6, 1.5}};
  // Point 2 is 1e41 m out and point 3 as far back: 2e42 s; point 4's 5.83 s step is lost.
  EXPECT_INVALID_ARGUMENT(SampledPath::atSpeed(points, 0.1), "path point 4", "2e+42 s + 5.83",
                          "not a finite time after the point before's");
  // A time beyond a double's range: 1e308 m at 0.1 m/s.
  EXPECT_INVALID_ARGUMENT(SampledPath::atSpeed({{0.0, 0.0}, {1e308, 0.0}}, 0.1), "path point 1",
                          "not a finite time");
}

TEST(SampledPath, BadPointsAreRefusedNamingTheirIndexAndValue) {
  using spherical_robots::test_support::throwsInvalidArgumentNaming;
  EXPECT_TRUE(throwsInvalidArgumentNaming([] { SampledPath::timed({{0.0, {1.0, 1.0}}}); },
                                          {"at least 2 points", "got 1"}));
  EXPECT_TRUE(throwsInvalidArgumentNaming([] { SampledPath::timed({}); }, {"at least 2", "got 0"}));
  const std::vector<TimedPoint> nan_x = {{0.0, {0.0, 0.0}}, {1.0, {1.0, 0.0}}, {2.0, {2.0, 0.0}},
                                         {3.0, {kNaN, 0.0}}};
  EXPECT_TRUE(throwsInvalidArgumentNaming([&] { SampledPath::timed(nan_x); },
                                          {"path point 3", "x [m]", "finite", "nan"}));
  try {
    SampledPath::timed(nan_x);
  } catch (const InvalidPathPoint& e) {
    EXPECT_EQ(e.index(), 3u);
  }
  EXPECT_TRUE(throwsInvalidArgumentNaming(
      [] { SampledPath::timed({{0.0, {0.0, 0.0}}, {2.0, {1.0, 0.0}}, {1.5, {2.0, 0.0}}}); },
      {"path point 2", "t [s] must be after point 1's 2", "got 1.5"}));
  EXPECT_TRUE(throwsInvalidArgumentNaming(
      [] { SampledPath::timed({{0.0, {0.0, 0.0}}, {0.0, {1.0, 0.0}}}); }, {"path point 1", "after"}));
  EXPECT_TRUE(throwsInvalidArgumentNaming(
      [] { SampledPath::timed({{0.0, {0.0, 0.0}}, {INFINITY, {1.0, 0.0}}}); },
      {"path point 1", "t [s] must be finite", "inf"}));
  EXPECT_TRUE(throwsInvalidArgumentNaming(
      [] { SampledPath::atSpeed({{0.0, 0.0}, {0.0, kNaN}}, 0.1); }, {"path point 1", "y [m]", "nan"}));
  EXPECT_TRUE(throwsInvalidArgumentNaming(
      [] { SampledPath::atSpeed({{0.0, 0.0}, {1.0, 0.0}}, 0.0); }, {"speed", "got 0"}));
  EXPECT_TRUE(throwsInvalidArgumentNaming(
      [] { SampledPath::atSpeed({{1.0, 2.0}, {1.0, 2.0}, {1.0, 2.0}}, 0.1); },
      {"at least 2 distinct points", "got 1"}));
  constexpr Nanoseconds kSecond = 1000000000;
  EXPECT_TRUE(throwsInvalidArgumentNaming(
      [] {
        SampledPath::fromStamped({{1 * kSecond, {0.0, 0.0}}, {3 * kSecond, {1.0, 0.0}},
                                  {2 * kSecond, {2.0, 0.0}}}, 0.1);
      },
      {"path point 2", "stamp 2 s is not after point 1's 3 s"}));
  // Some stamps equal, not all: neither timed nor untimed.
  EXPECT_TRUE(throwsInvalidArgumentNaming(
      [] {
        SampledPath::fromStamped({{1 * kSecond, {0.0, 0.0}}, {1 * kSecond, {1.0, 0.0}},
                                  {2 * kSecond, {2.0, 0.0}}}, 0.1);
      },
      {"path point 1", "stamps must all increase"}));
  const SampledPath path = SampledPath::timed({{0.0, {0.0, 0.0}}, {1.0, {1.0, 0.0}}});
  EXPECT_TRUE(throwsInvalidArgumentNaming([&] { path.at(kNaN); }, {"time", "finite"}));
}

// ------------------------------------------------------------------------------------------
// PathTracker::follow: when a received path's clock starts.

class ReceivedPathTimeBase : public ::testing::Test {
 protected:
  static constexpr Nanoseconds kSecond = 1000000000;

  ReceivedPathTimeBase()
      : plane_(0.0, 0.0, 0.0),
        kinematics_(plane_, RobotType::ThreeAxisRolling, 0.2, ContactModel::Paper, 1.0),
        law_(RobotType::ThreeAxisRolling, defaultGains(RobotType::ThreeAxisRolling), 0.2),
        circle_(kRadius, kRate),
        line_(SampledPath::timed({{0.0, {0.0, 0.0}}, {10.0, {1.0, 0.0}}})),
        tracker_(law_, circle_, plane_) {}

  DesiredPoint desiredAt(Nanoseconds now) {
    return tracker_.command(now, kinematics_.geometry(TerrainState{}), 0.0).desired;
  }

  PlaneSurface plane_;
  TerrainKinematics kinematics_;
  PurePursuitController law_;  // takes p_d' at t itself: the velocity is the path's
  CirclePath circle_;
  SampledPath line_;
  PathTracker tracker_;
};

TEST_F(ReceivedPathTimeBase, AFutureFirstStampStartsTheClockThenAndHoldsTheStartUntil) {
  tracker_.follow(circle_, 5 * kSecond, 1 * kSecond);
  const DesiredPoint waiting = desiredAt(3 * kSecond);
  EXPECT_NEAR((waiting.position.head<2>() - circle_.position(0.0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(waiting.velocity, Eigen::Vector3d::Zero());
  const DesiredPoint going = desiredAt(6 * kSecond);
  EXPECT_NEAR((going.position.head<2>() - circle_.position(1.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((going.velocity.head<2>() - circle_.velocity(1.0)).norm(), 0.0, 1e-15);
}

TEST_F(ReceivedPathTimeBase, APastFirstStampStartsTheClockAtTheNextCommand) {
  desiredAt(0);  // tracking the circle from t = 0
  desiredAt(9 * kSecond);
  tracker_.follow(line_, 0, 10 * kSecond);  // stamps at 0: a planner's, long past
  const DesiredPoint first = desiredAt(10 * kSecond + kSecond / 50);
  EXPECT_NEAR((first.position.head<2>() - line_.position(0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((first.velocity.head<2>() - line_.velocity(0.0)).norm(), 0.0, 1e-15);
  const DesiredPoint later = desiredAt(14 * kSecond + kSecond / 50);
  EXPECT_NEAR((later.position.head<2>() - line_.position(4.0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(&tracker_.path(), &line_);
}

// PathTracker::setLaw (dynamic_reconfigure's new gains mid-run): the path's clock goes on, and the
// next command is eq 55's with the new gains, from the error the tracker reports.
TEST_F(ReceivedPathTimeBase, ANewLawCommandsFromTheNextStepOnTheSameClock) {
  desiredAt(0);
  desiredAt(5 * kSecond);
  PursuitGains gains = defaultGains(RobotType::ThreeAxisRolling);
  gains.k_theta = 0.7;
  gains.k_phi1 = 1.1;
  gains.k_phi2 = 0.05;
  gains.k_psi = 0.4;
  const PurePursuitController retuned(RobotType::ThreeAxisRolling, gains, 0.2);
  tracker_.setLaw(retuned);
  EXPECT_EQ(&tracker_.law(), &retuned);
  const TrackingCommand command =
      tracker_.command(6 * kSecond, kinematics_.geometry(TerrainState{}), 0.0);
  EXPECT_NEAR((command.desired.position.head<2>() - circle_.position(6.0)).norm(), 0.0, 1e-15);
  const double n = command.error.norm / (gains.k_e + command.error.norm);
  const double zeta = command.error.zeta;
  EXPECT_NEAR(command.rates.roll_rate,
              gains.k_theta * n * std::cos(zeta) + circle_.velocity(6.0).norm() / 0.2, 1e-12);
  EXPECT_NEAR(command.rates.lateral_rate, -(gains.k_phi1 * n + gains.k_phi2) * std::sin(zeta), 1e-12);
  EXPECT_NEAR(command.rates.turn_rate, gains.k_psi * zeta, 1e-12);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
