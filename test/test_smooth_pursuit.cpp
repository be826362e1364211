// The smooth tracking law (docs/conventions.md, "The smooth law"): the documented table evaluated
// by hand, what each type does with the desired velocity u (checked through the kinematics, not
// the law's own arithmetic), smoothness at e_t -> 0 where the paper's law jumps, the RS tilt
// bound, the reference's mean velocity, and bad gains.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "expect_invalid_argument.hpp"
#include "terrain_test_support.hpp"
#include "spherical_robots/terrain/pure_pursuit.hpp"
#include "spherical_robots/terrain/reference_path.hpp"
#include "spherical_robots/terrain/smooth_pursuit.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"

namespace {

using namespace spherical_robots::terrain;  // NOLINT: test file

constexpr double kPi = 3.14159265358979323846;
constexpr double kR = 0.2;
constexpr double kTiltLimit = kPi / 3;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using spherical_robots::test_support::kAllRobotTypes;
using spherical_robots::test_support::testName;

// Distinct, non-default gains so that a law reading the wrong gain shows.
SmoothPursuitGains testGains() {
  SmoothPursuitGains g;
  g.window = 0.7;
  g.lead = 0.2;
  g.approach_speed = 0.35;
  g.along_gain = 3.3;
  g.cross_gain = 1.7;
  g.heading_gain = 2.6;
  g.tilt_gain = 6.5;
  g.max_tilt_rate = 1.3;
  g.max_tilt = 0.75;
  g.min_speed = 0.02;
  return g;
}

ContactGeometry geometryOn(const Eigen::Vector2d& gradient, double psi) {
  return spherical_robots::test_support::geometryOn(gradient, psi, kR);
}

TrackingError errorTo(const ContactGeometry& geo, const Eigen::Vector3d& offset) {
  return trackingError(geo, geo.contact_point + offset);
}

// ------------------------------------------------------------------------------------------
// The documented table, written out here.

struct Expected {
  Eigen::Vector3d u;
  DriveRates rates;
};

// conventions.md, "The smooth law": u = w + c, t = w / sqrt(|w|^2 + v_e^2),
// k = K_c e + (K_a - K_c)(e.t) t, c = v_c k / (v_c + |k|); s = u_l / sqrt(u_h^2 + u_l^2 + v_e^2);
//   3R: theta = u_h/R, phi = -u_l/R, psi = k_h s;  2R: theta, phi;  RT: theta, psi;
//   RS: alpha = (|u| + u_h) / (2 R cos phi), phi_dot = r_t tanh(k_t (phi* - phi) / r_t),
//       phi* = asin(S tanh(sigma / S)), sigma = -k_h s alpha / (alpha^2 + (v_e/R)^2), S = sin max.
Expected documentedLaw(RobotType type, const SmoothPursuitGains& k, const ContactGeometry& geo,
                       double tilt, const Eigen::Vector3d& e, const Eigen::Vector3d& w) {
  const double ve = k.min_speed;
  const Eigen::Vector3d t = w / std::sqrt(w.squaredNorm() + ve * ve);
  const Eigen::Vector3d lin = k.cross_gain * e + (k.along_gain - k.cross_gain) * e.dot(t) * t;
  const Eigen::Vector3d u = w + k.approach_speed * lin / (k.approach_speed + lin.norm());
  const double uh = u.dot(geo.heading_frame.col(0)), ul = u.dot(geo.heading_frame.col(1));
  const double s = ul / std::sqrt(uh * uh + ul * ul + ve * ve);
  Expected out{u, {}};
  switch (type) {
    case RobotType::ThreeAxisRolling:
      out.rates = {uh / kR, -ul / kR, k.heading_gain * s};
      break;
    case RobotType::TwoAxisRolling:
      out.rates = {uh / kR, -ul / kR, 0.0};
      break;
    case RobotType::RollingAndTurning:
      out.rates = {uh / kR, 0.0, k.heading_gain * s};
      break;
    case RobotType::RollingAndSteering: {
      const double alpha = (std::sqrt(uh * uh + ul * ul) + uh) / (2 * kR * std::cos(tilt));
      const double sigma = -k.heading_gain * s * alpha / (alpha * alpha + ve * ve / (kR * kR));
      const double bound = std::sin(k.max_tilt);
      const double target = std::asin(bound * std::tanh(sigma / bound));
      out.rates = {alpha,
                   k.max_tilt_rate * std::tanh(k.tilt_gain * (target - tilt) / k.max_tilt_rate), 0.0};
      break;
    }
  }
  return out;
}

class SmoothLaw : public ::testing::TestWithParam<RobotType> {};

TEST_P(SmoothLaw, MatchesTheDocumentedTable) {
  const RobotType type = GetParam();
  const SmoothPursuitController ctrl(type, testGains(), kR, kTiltLimit);
  const ContactGeometry geo = geometryOn({0.3, -0.2}, 0.9);
  const std::vector<Eigen::Vector3d> offsets = {
      {0, 0, 0}, {0.01, -0.02, 0.003}, {1.5, 0.7, -0.2}, {-0.3, 0.05, 0.0}, {0.0, -4.0, 1.0}};
  const std::vector<Eigen::Vector3d> velocities = {
      {0.1, 0.0, 0.03}, {-0.05, 0.08, 0.0}, {0.0, 0.0, 0.0}, {0.3, -0.3, 0.1}};
  for (const Eigen::Vector3d& offset : offsets) {
    for (const Eigen::Vector3d& w : velocities) {
      for (double tilt : {0.0, 0.4, -0.9}) {
        const TrackingError error = errorTo(geo, offset);
        const Expected want = documentedLaw(type, testGains(), geo, tilt, error.error, w);
        const DriveRates got = ctrl.command(geo, tilt, error, w);
        SCOPED_TRACE(::testing::Message() << "offset " << offset.transpose() << " w "
                                          << w.transpose() << " tilt " << tilt);
        EXPECT_LE((ctrl.desiredVelocity(error, w) - want.u).norm(), 1e-14);
        EXPECT_NEAR(got.roll_rate, want.rates.roll_rate, 1e-12);
        EXPECT_NEAR(got.lateral_rate, want.rates.lateral_rate, 1e-12);
        EXPECT_NEAR(got.turn_rate, want.rates.turn_rate, 1e-12);
      }
    }
  }
}

// The correction is K_a e along the path and K_c e across it near p_d, and never faster than
// v_c however far p_d is.
TEST_P(SmoothLaw, CorrectionIsLinearNearThePathAndBoundedFarFromIt) {
  const SmoothPursuitGains k = testGains();
  const SmoothPursuitController ctrl(GetParam(), k, kR, kTiltLimit);
  const ContactGeometry geo = geometryOn({0, 0}, 0.0);
  const Eigen::Vector3d w(0.1, 0.0, 0.0);  // along x
  const double tiny = 1e-7;
  const Eigen::Vector3d along = ctrl.desiredVelocity(errorTo(geo, {tiny, 0, 0}), w) - w;
  const Eigen::Vector3d across = ctrl.desiredVelocity(errorTo(geo, {0, tiny, 0}), w) - w;
  // t = w / sqrt(|w|^2 + v_e^2) is not quite unit: the along gain is K_c + (K_a - K_c) |t|^2.
  const double t2 = 0.01 / (0.01 + k.min_speed * k.min_speed);
  EXPECT_NEAR(along.x() / tiny, k.cross_gain + (k.along_gain - k.cross_gain) * t2, 1e-4);
  EXPECT_NEAR(across.y() / tiny, k.cross_gain, 1e-4);
  EXPECT_NEAR(along.y(), 0.0, 1e-18);
  EXPECT_NEAR(across.x(), 0.0, 1e-18);
  for (double far : {1.0, 10.0, 1e6}) {
    const Eigen::Vector3d c = ctrl.desiredVelocity(errorTo(geo, {far, -far, 0.2 * far}), w) - w;
    EXPECT_LT(c.norm(), k.approach_speed) << far;
  }
  EXPECT_GT((ctrl.desiredVelocity(errorTo(geo, {1e6, 0, 0}), w) - w).norm(),
            0.999 * k.approach_speed);
}

// The point of the law: at convergence the commands are continuous in the error. An error of
// 1e-9 m in any direction moves no rate by more than its slope allows, where the paper's eq 55/57
// turn rate k_psi zeta jumps by 2 pi k_psi between a target a hair behind-left and behind-right.
TEST_P(SmoothLaw, CommandsAreContinuousAtZeroErrorWhereThePapersLawJumps) {
  const RobotType type = GetParam();
  const SmoothPursuitController ctrl(type, testGains(), kR, kTiltLimit);
  const ContactGeometry geo = geometryOn({0.2, 0.1}, -0.4);
  const Eigen::Vector3d w = 0.1 * geo.heading_frame.col(0) + 0.01 * geo.heading_frame.col(1);
  const double tilt = type == RobotType::RollingAndSteering ? -0.1 : 0.0;
  const DriveRates at_zero = ctrl.command(geo, tilt, errorTo(geo, Eigen::Vector3d::Zero()), w);
  for (double bearing = -kPi; bearing <= kPi; bearing += kPi / 16) {
    const Eigen::Vector3d offset = 1e-9 * (std::cos(bearing) * geo.heading_frame.col(0) +
                                           std::sin(bearing) * geo.heading_frame.col(1));
    const DriveRates near = ctrl.command(geo, tilt, errorTo(geo, offset), w);
    // Slopes are at most a few hundred (rad/s)/m with these gains: 1e-9 m moves a rate < 1e-6.
    EXPECT_NEAR(near.roll_rate, at_zero.roll_rate, 1e-6) << "bearing " << bearing;
    EXPECT_NEAR(near.lateral_rate, at_zero.lateral_rate, 1e-6) << "bearing " << bearing;
    EXPECT_NEAR(near.turn_rate, at_zero.turn_rate, 1e-6) << "bearing " << bearing;
  }
  if (type == RobotType::ThreeAxisRolling || type == RobotType::RollingAndTurning) {
    const PurePursuitController paper(type, PursuitGains{}, kR);
    const Eigen::Vector3d back = -geo.heading_frame.col(0), left = geo.heading_frame.col(1);
    const double behind_left = paper.command(errorTo(geo, 1e-9 * (back + 1e-6 * left)), w).turn_rate;
    const double behind_right =
        paper.command(errorTo(geo, 1e-9 * (back - 1e-6 * left)), w).turn_rate;
    EXPECT_NEAR(behind_left - behind_right, 2 * kPi * PursuitGains{}.k_psi, 1e-4);
  }
}

// What the rates do, through the kinematics (paper model, flat ground): 3R and 2R move the
// contact point with u exactly; RT moves along h at u's component there and turns towards u;
// RS rolls forward and tilts so that eq 44 turns it towards u.
TEST_P(SmoothLaw, EachTypeRealisesTheDesiredVelocityAsItsKinematicsAllow) {
  const RobotType type = GetParam();
  const PlaneSurface plane(0.0, 0.0, 0.0);
  const TerrainKinematics kinematics(plane, type, kR, ContactModel::Paper, kTiltLimit);
  const SmoothPursuitController ctrl(type, testGains(), kR, kTiltLimit);
  const TerrainState state{1.0, 2.0, 0.3, type == RobotType::RollingAndSteering ? 0.05 : 0.0};
  const ContactGeometry geo = kinematics.geometry(state);
  const Eigen::Vector3d h = geo.heading_frame.col(0), l = geo.heading_frame.col(1);
  for (const Eigen::Vector3d& offset :
       {Eigen::Vector3d(0.02, 0.05, 0), Eigen::Vector3d(0.3, -0.4, 0), Eigen::Vector3d(-0.1, 0, 0)}) {
    const Eigen::Vector3d w(0.07, 0.05, 0.0);
    const TrackingError error = trackingError(geo, geo.contact_point + offset);
    const Eigen::Vector3d u = ctrl.desiredVelocity(error, w);
    const DriveRates rates = ctrl.command(geo, state.phi, error, w);
    const TerrainStateRate motion = kinematics.stateRate(state, rates);
    const Eigen::Vector2d moved(motion.x_dot, motion.y_dot);
    SCOPED_TRACE(::testing::Message() << "offset " << offset.transpose());
    const double left_of_heading = u.dot(l);
    switch (type) {
      case RobotType::ThreeAxisRolling:
      case RobotType::TwoAxisRolling:
        EXPECT_LE((moved - u.head<2>()).norm(), 1e-15);
        break;
      case RobotType::RollingAndTurning:
        EXPECT_LE((moved - u.dot(h) * h.head<2>()).norm(), 1e-15);
        EXPECT_GT(motion.psi_dot * left_of_heading, 0.0);  // turns towards u
        break;
      case RobotType::RollingAndSteering:
        EXPECT_GE(rates.roll_rate, 0.0);  // never backwards: it could not turn
        // The tilt rate drives phi to the side that makes psi_dot = -alpha_dot sin(phi) turn
        // towards u.
        EXPECT_GT(-rates.lateral_rate * left_of_heading, 0.0);
        break;
    }
    if (type == RobotType::ThreeAxisRolling) {
      EXPECT_GT(motion.psi_dot * left_of_heading, 0.0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllTypes, SmoothLaw, ::testing::ValuesIn(kAllRobotTypes),
                         [](const auto& info) { return testName(info.param); });

// ------------------------------------------------------------------------------------------
// RS specifics: the tilt set-point stays inside max_tilt, and a robot with u abeam keeps rolling.

TEST(SmoothLawRs, NeverDrivesTheTiltPastMaxTilt) {
  const SmoothPursuitGains k = testGains();
  const SmoothPursuitController ctrl(RobotType::RollingAndSteering, k, kR, kTiltLimit);
  const ContactGeometry geo = geometryOn({0, 0}, 0.0);
  // However hard u pulls to either side, at +max_tilt the tilt rate is <= 0 and at -max_tilt
  // >= 0: phi* lies within [-max_tilt, max_tilt].
  for (double bearing = -kPi; bearing <= kPi; bearing += kPi / 12) {
    for (double distance : {0.001, 0.1, 5.0}) {
      const Eigen::Vector3d offset(distance * std::cos(bearing), distance * std::sin(bearing), 0);
      const TrackingError error = errorTo(geo, offset);
      const Eigen::Vector3d w(0.1, 0.0, 0.0);
      EXPECT_LE(ctrl.command(geo, k.max_tilt, error, w).lateral_rate, 0.0) << bearing;
      EXPECT_GE(ctrl.command(geo, -k.max_tilt, error, w).lateral_rate, 0.0) << bearing;
    }
  }
}

TEST(SmoothLawRs, TiltRateStaysWithinItsBound) {
  const SmoothPursuitGains k = testGains();
  const SmoothPursuitController ctrl(RobotType::RollingAndSteering, k, kR, kTiltLimit);
  const ContactGeometry geo = geometryOn({0, 0}, 0.0);
  for (double tilt : {-1.0, -0.5, 0.0, 0.5, 1.0}) {
    for (double side : {-3.0, 3.0}) {
      const DriveRates rates =
          ctrl.command(geo, tilt, errorTo(geo, {0.0, side, 0.0}), Eigen::Vector3d(0.1, 0, 0));
      EXPECT_LT(std::abs(rates.lateral_rate), k.max_tilt_rate) << tilt << " " << side;
    }
  }
}

TEST(SmoothLawRs, RollsAtHalfTheDesiredSpeedWithTheDesiredVelocityAbeam) {
  const SmoothPursuitController ctrl(RobotType::RollingAndSteering, testGains(), kR, kTiltLimit);
  const ContactGeometry geo = geometryOn({0, 0}, 0.0);
  const Eigen::Vector3d abeam(0.0, 0.1, 0.0);  // u to the left, no error: u = w
  const double tilt = 0.3;
  const DriveRates rates = ctrl.command(geo, tilt, errorTo(geo, Eigen::Vector3d::Zero()), abeam);
  // Forward speed R alpha_dot cos(phi) (eq 48) = |u| / 2.
  EXPECT_NEAR(kR * rates.roll_rate * std::cos(tilt), 0.05, 1e-15);
}

TEST(SmoothLawRs, RejectsAMaxTiltAtOrBeyondTheTiltLimitNamingBoth) {
  SmoothPursuitGains k = testGains();
  k.max_tilt = 1.2;
  EXPECT_INVALID_ARGUMENT(SmoothPursuitController(RobotType::RollingAndSteering, k, kR, 1.0),
                          "max_tilt", "1.2", "limit 1");
  // Other types do not tilt and ignore it.
  EXPECT_NO_THROW(SmoothPursuitController(RobotType::RollingAndTurning, k, kR, 1.0));
}

// ------------------------------------------------------------------------------------------
// Bad gains and input.

struct BadGain {
  const char* name;
  double SmoothPursuitGains::*member;
  double value;
  const char* shown;  // the value as the message prints it
  const char* limit;  // the range the message states
};

class SmoothLawBadGain : public ::testing::TestWithParam<BadGain> {};

TEST_P(SmoothLawBadGain, IsRejectedNamingTheGainItsValueAndItsRange) {
  const BadGain c = GetParam();
  SmoothPursuitGains k = testGains();
  k.*c.member = c.value;
  EXPECT_INVALID_ARGUMENT(validate(k), c.name, std::string("got ") + c.shown, c.limit);
  EXPECT_INVALID_ARGUMENT(SmoothPursuitController(RobotType::ThreeAxisRolling, k, kR, kTiltLimit),
                          c.name, std::string("got ") + c.shown);
}

INSTANTIATE_TEST_SUITE_P(
    Gains, SmoothLawBadGain,
    ::testing::Values(
        BadGain{"window", &SmoothPursuitGains::window, -0.5, "-0.5", ">= 0"},
        BadGain{"lead", &SmoothPursuitGains::lead, kNaN, "nan", ">= 0"},
        BadGain{"approach_speed", &SmoothPursuitGains::approach_speed, 0.0, "0", "> 0"},
        BadGain{"along_gain", &SmoothPursuitGains::along_gain, -1.0, "-1", "> 0"},
        BadGain{"cross_gain", &SmoothPursuitGains::cross_gain, 0.0, "0", "> 0"},
        BadGain{"heading_gain", &SmoothPursuitGains::heading_gain, -2.0, "-2", ">= 0"},
        BadGain{"tilt_gain", &SmoothPursuitGains::tilt_gain, 0.0, "0", "> 0"},
        BadGain{"max_tilt_rate", &SmoothPursuitGains::max_tilt_rate, -1.0, "-1", "> 0"},
        BadGain{"max_tilt", &SmoothPursuitGains::max_tilt, -0.1, "-0.1", "> 0"},
        BadGain{"min_speed", &SmoothPursuitGains::min_speed, kNaN, "nan", "> 0"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(SmoothLaw, RejectsABadRadiusAndNonFiniteInput) {
  EXPECT_INVALID_ARGUMENT(
      SmoothPursuitController(RobotType::ThreeAxisRolling, testGains(), 0.0, kTiltLimit), "radius");
  const SmoothPursuitController ctrl(RobotType::RollingAndSteering, testGains(), kR, kTiltLimit);
  const ContactGeometry geo = geometryOn({0, 0}, 0.0);
  const TrackingError error = errorTo(geo, {0.1, 0.0, 0.0});
  EXPECT_INVALID_ARGUMENT(ctrl.command(geo, kNaN, error, Eigen::Vector3d(0.1, 0, 0)), "tilt");
  EXPECT_INVALID_ARGUMENT(ctrl.command(geo, 0.0, error, Eigen::Vector3d(kNaN, 0, 0)),
                          "desired velocity");
}

// ------------------------------------------------------------------------------------------
// The feed-forward's reference velocity: the path's mean velocity over the law's window.

TEST(VelocityWindow, CircleClosedFormIsTheChordAndTheDiamondAveragesItsTwoEdges) {
  const CirclePath circle(2.0, 0.05);
  for (double t : {0.0, 13.0, 77.7}) {
    for (double window : {0.5, 1.0, 20.0}) {
      const Eigen::Vector2d chord =
          (circle.position(t + window / 2) - circle.position(t - window / 2)) / window;
      EXPECT_LE((circle.meanVelocity(t, window) - chord).norm(), 1e-15) << t << " " << window;
    }
  }
  // A window of 1 s centred 0.25 s before a vertex: 0.75 s on the first edge, 0.25 s on the next.
  const DiamondPath diamond(2.0, 0.1);
  const double vertex = std::sqrt(2.0) * 2.0 / 0.1;
  const Eigen::Vector2d first = diamond.velocity(vertex - 1.0), second = diamond.velocity(vertex + 1.0);
  EXPECT_LE((diamond.meanVelocity(vertex - 0.25, 1.0) - (0.75 * first + 0.25 * second)).norm(), 1e-12);
  EXPECT_LE((diamond.meanVelocity(vertex - 5.0, 1.0) - first).norm(), 1e-12);
}

TEST(VelocityWindow, LiftingTakesTheWindowsVelocityOntoTheTangentPlaneAtTheTarget) {
  const CosineSurface surface(0.2, 2.0);
  const CirclePath circle(2.0, 0.05);
  const double t = 31.0;
  const DesiredPoint now = liftOntoSurface(circle, surface, t);
  const DesiredPoint windowed = liftOntoSurface(circle, surface, t, VelocityWindow{0.4, 1.0});
  EXPECT_EQ(windowed.position, now.position);  // p_d(t): only the velocity moves
  const Eigen::Vector2d mean = circle.meanVelocity(t + 0.4, 1.0);
  EXPECT_LE((windowed.velocity.head<2>() - mean).norm(), 1e-15);
  EXPECT_NEAR(windowed.velocity.z(), surface.gradient(now.position.x(), now.position.y()).dot(mean),
              1e-15);
  // No window: p_d'(t) itself, bit for bit.
  EXPECT_EQ(liftOntoSurface(circle, surface, t, VelocityWindow{}).velocity, now.velocity);
  EXPECT_INVALID_ARGUMENT(liftOntoSurface(circle, surface, t, VelocityWindow{-1.0, 1.0}), "lead");
  EXPECT_INVALID_ARGUMENT(liftOntoSurface(circle, surface, t, VelocityWindow{0.0, kNaN}), "length");
}

TEST(PursuitLaw, NamesRoundTripAndAnUnknownNameIsRejectedNamingTheChoices) {
  for (PursuitLaw law : {PursuitLaw::Paper, PursuitLaw::Smooth}) {
    EXPECT_EQ(pursuitLawFromString(toString(law)), law);
  }
  EXPECT_INVALID_ARGUMENT(pursuitLawFromString("fast"), "fast", "paper", "smooth");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
