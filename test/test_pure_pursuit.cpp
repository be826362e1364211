// Pure-pursuit tracking (paper eqs 53-58) in the convention of docs/conventions.md: the signed
// deviation angle zeta, the four control laws written out here from the documented (corrected)
// table, and the closed-loop sign check that the convention is self-consistent.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/terrain/pure_pursuit.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"
#include "spherical_robots/terrain/terrain_simulation.hpp"
#include "expect_invalid_argument.hpp"
#include "terrain_test_support.hpp"

namespace {

using namespace spherical_robots::terrain;  // NOLINT: test file

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kR = 0.2;

const std::vector<RobotType>& kAllTypes = spherical_robots::test_support::kAllRobotTypes;
using spherical_robots::test_support::testName;

ContactGeometry geometryOn(const Eigen::Vector2d& g, double psi) {
  return spherical_robots::test_support::geometryOn(g, psi, kR);
}

// ------------------------------------------------------------------------------------------
// trackingError: e_t = p_d - P0 (eq 53), zeta = atan2(e.l, e.h) (conventions.md, errata T2).

struct FrameCase {
  const char* label;
  Eigen::Vector2d gradient;
  double psi;
};

void PrintTo(const FrameCase& c, std::ostream* os) {
  *os << c.label << " (gradient " << c.gradient.transpose() << ", psi " << c.psi << ")";
}

class TrackingErrorInFrame : public ::testing::TestWithParam<FrameCase> {};

TEST_P(TrackingErrorInFrame, ZetaIsTheSignedBearingFromHInTheTangentPlane) {
  const auto c = GetParam();
  const ContactGeometry geo = geometryOn(c.gradient, c.psi);
  const Eigen::Vector3d h = geo.heading_frame.col(0), l = geo.heading_frame.col(1);
  // Left of h is +l: bearings in (-pi, pi), left positive.
  for (double beta : {0.0, 0.3, 1.2, 2.9, -0.5, -1.6, -3.0}) {
    for (double d : {0.05, 1.0, 7.0}) {
      const Eigen::Vector3d offset = d * (std::cos(beta) * h + std::sin(beta) * l);
      const TrackingError e = trackingError(geo, geo.contact_point + offset);
      EXPECT_NEAR(e.zeta, beta, 1e-12) << "beta " << beta << " d " << d;
      EXPECT_NEAR(e.norm, d, 1e-12);
      EXPECT_LE((e.error - offset).norm(), 1e-12);
    }
  }
}

TEST_P(TrackingErrorInFrame, LeftIsPositiveRightIsNegativeAheadIsZeroBehindIsPi) {
  const auto c = GetParam();
  const ContactGeometry geo = geometryOn(c.gradient, c.psi);
  const Eigen::Vector3d p = geo.contact_point, h = geo.heading_frame.col(0), l = geo.heading_frame.col(1);
  EXPECT_GT(trackingError(geo, p + 0.5 * h + 0.2 * l).zeta, 0.0);
  EXPECT_LT(trackingError(geo, p + 0.5 * h - 0.2 * l).zeta, 0.0);
  EXPECT_NEAR(trackingError(geo, p + 2.0 * h).zeta, 0.0, 1e-12);
  EXPECT_NEAR(std::abs(trackingError(geo, p - 2.0 * h).zeta), kPi, 1e-12);
  EXPECT_NEAR(trackingError(geo, p + 0.3 * l).zeta, kPi / 2, 1e-12);
  EXPECT_NEAR(trackingError(geo, p - 0.3 * l).zeta, -kPi / 2, 1e-12);
}

TEST_P(TrackingErrorInFrame, ComponentAlongTheNormalDoesNotChangeZetaButCountsInTheNorm) {
  const auto c = GetParam();
  const ContactGeometry geo = geometryOn(c.gradient, c.psi);
  const Eigen::Vector3d p = geo.contact_point, h = geo.heading_frame.col(0),
                        l = geo.heading_frame.col(1), n = geo.heading_frame.col(2);
  // Straight above the contact point: no bearing at all, zeta = 0 (atan2(0, 0)).
  const TrackingError up = trackingError(geo, p + 0.4 * n);
  EXPECT_NEAR(up.zeta, 0.0, 1e-12);
  EXPECT_NEAR(up.norm, 0.4, 1e-12);
  // A bearing of 0.7 rad with a large out-of-plane part keeps its bearing.
  const Eigen::Vector3d in_plane = std::cos(0.7) * h + std::sin(0.7) * l;
  const TrackingError e = trackingError(geo, p + in_plane + 3.0 * n);
  EXPECT_NEAR(e.zeta, 0.7, 1e-12);
  EXPECT_NEAR(e.norm, std::sqrt(1.0 + 9.0), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(FlatTiltedSteep, TrackingErrorInFrame,
                         ::testing::Values(FrameCase{"FlatHeading0", {0, 0}, 0.0},
                                           FrameCase{"FlatHeading2p5", {0, 0}, 2.5},
                                           FrameCase{"TiltedHeading0p7", {0.3, -0.5}, 0.7},
                                           FrameCase{"SteepHeadingMinus2", {1.5, 0.8}, -2.0}),
                         [](const auto& info) { return std::string(info.param.label); });

TEST(TrackingError, OnFlatGroundFacingXZetaIsTheCompassBearing) {
  // Plain numbers: facing +x at the origin, a target at (1, 1) is 45 degrees to the left.
  const ContactGeometry geo = geometryOn({0, 0}, 0.0);
  const Eigen::Vector3d p = geo.contact_point;
  EXPECT_NEAR(trackingError(geo, p + Eigen::Vector3d(1, 1, 0)).zeta, kPi / 4, 1e-15);
  EXPECT_NEAR(trackingError(geo, p + Eigen::Vector3d(1, -1, 0)).zeta, -kPi / 4, 1e-15);
  EXPECT_NEAR(trackingError(geo, p + Eigen::Vector3d(-1, 1, 0)).zeta, 3 * kPi / 4, 1e-15);
  EXPECT_NEAR(trackingError(geo, p + Eigen::Vector3d(3, 4, 0)).norm, 5.0, 1e-15);
}

// ------------------------------------------------------------------------------------------
// command(): the laws of docs/conventions.md, evaluated here by hand.

// Distinct, non-default gains so that a law reading the wrong gain shows.
PursuitGains testGains() {
  PursuitGains g;
  g.k_e = 0.4;
  g.k_theta = 1.7;
  g.k_phi1 = 2.3;
  g.k_phi2 = 0.35;
  g.k_psi = 0.9;
  g.k_theta1 = 2.9;
  g.k_theta2 = 0.25;
  g.k_alpha = 0.6;
  g.k_phi = 1.8;
  return g;
}

TrackingError errorOf(double norm, double zeta) {
  TrackingError e;
  e.norm = norm;
  e.zeta = zeta;
  e.error = norm * Eigen::Vector3d(std::cos(zeta), std::sin(zeta), 0.0);
  return e;
}

// conventions.md, "Tracking (eqs 53-58)":
//   3R: theta = k_theta g cos z + |v|/R; phi = -(k_phi1 g + k_phi2) sin z; psi = k_psi z
//   2R: theta = (k_theta1 g + k_theta2) cos z; phi = -(k_phi1 g + k_phi2) sin z; psi = 0
//   RT: theta = k_theta g cos z + |v|/R; psi = k_psi z
//   RS: alpha = k_alpha g cos z + |v|/R; phi = -k_phi z (sign corrected)
// with g = |e| / (k_e + |e|).
DriveRates documentedLaw(RobotType type, const PursuitGains& k, double norm, double zeta, double speed) {
  const double g = norm / (k.k_e + norm);
  const double ff = speed / kR;
  switch (type) {
    case RobotType::ThreeAxisRolling:
      return {k.k_theta * g * std::cos(zeta) + ff, -(k.k_phi1 * g + k.k_phi2) * std::sin(zeta),
              k.k_psi * zeta};
    case RobotType::TwoAxisRolling:
      return {(k.k_theta1 * g + k.k_theta2) * std::cos(zeta),
              -(k.k_phi1 * g + k.k_phi2) * std::sin(zeta), 0.0};
    case RobotType::RollingAndTurning:
      return {k.k_theta * g * std::cos(zeta) + ff, 0.0, k.k_psi * zeta};
    case RobotType::RollingAndSteering:
      return {k.k_alpha * g * std::cos(zeta) + ff, -k.k_phi * zeta, 0.0};
  }
  return {};
}

class CommandLaw : public ::testing::TestWithParam<RobotType> {};

TEST_P(CommandLaw, MatchesTheDocumentedLawForSeveralErrors) {
  const RobotType type = GetParam();
  const PurePursuitController ctrl(type, testGains(), kR);
  const Eigen::Vector3d v(0.08, -0.06, 0.05);  // |v| = sqrt(0.0125)
  struct In {
    double norm, zeta;
  };
  for (const In in : {In{0.0, 0.0}, In{0.1, 0.4}, In{2.0, -1.1}, In{0.7, 2.8}, In{0.3, -kPi / 2},
                      In{5.0, kPi}}) {
    const DriveRates got = ctrl.command(errorOf(in.norm, in.zeta), v);
    const DriveRates want = documentedLaw(type, testGains(), in.norm, in.zeta, std::sqrt(0.0125));
    EXPECT_NEAR(got.roll_rate, want.roll_rate, 1e-13) << "|e| " << in.norm << " zeta " << in.zeta;
    EXPECT_NEAR(got.lateral_rate, want.lateral_rate, 1e-13) << "|e| " << in.norm << " zeta " << in.zeta;
    EXPECT_NEAR(got.turn_rate, want.turn_rate, 1e-13) << "|e| " << in.norm << " zeta " << in.zeta;
  }
}

TEST_P(CommandLaw, UnactuatedRatesAreZero) {
  // 2R cannot turn (eq 56), RT cannot roll sideways (eq 57), RS steers by tilting and its turn
  // rate follows from eq 44, so it is not commanded.
  const RobotType type = GetParam();
  const PurePursuitController ctrl(type, testGains(), kR);
  const DriveRates got = ctrl.command(errorOf(0.8, 1.0), Eigen::Vector3d(0.1, 0.0, 0.0));
  EXPECT_NE(got.roll_rate, 0.0);
  if (type == RobotType::RollingAndTurning) {
    EXPECT_EQ(got.lateral_rate, 0.0);
  } else {
    EXPECT_NE(got.lateral_rate, 0.0);
  }
  if (type == RobotType::TwoAxisRolling || type == RobotType::RollingAndSteering) {
    EXPECT_EQ(got.turn_rate, 0.0);
  } else {
    EXPECT_NE(got.turn_rate, 0.0);
  }
}

TEST_P(CommandLaw, FeedForwardUsesTheFull3DSpeedOfTheDesiredPoint) {
  // |p_d'| / R with p_d' = (x_d', y_d', f_x x_d' + f_y y_d'): a climbing target is faster than
  // its XY shadow. 2R has no feed-forward term (eq 56).
  const RobotType type = GetParam();
  const PurePursuitController ctrl(type, testGains(), kR);
  const TrackingError e = errorOf(0.5, 0.3);
  const double flat = ctrl.command(e, Eigen::Vector3d(0.1, 0.0, 0.0)).roll_rate;
  const double climbing = ctrl.command(e, Eigen::Vector3d(0.1, 0.0, 0.05)).roll_rate;
  const double want = type == RobotType::TwoAxisRolling ? 0.0 : (std::hypot(0.1, 0.05) - 0.1) / kR;
  EXPECT_NEAR(climbing - flat, want, 1e-14);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, CommandLaw, ::testing::ValuesIn(kAllTypes),
                         [](const auto& info) { return testName(info.param); });

// ------------------------------------------------------------------------------------------
// Closed-loop sign check: a target on the left (right) must pull every type to the left
// (right). With the printed eq 25 handedness or the printed RS law this fails (errata T3).

struct SideCase {
  RobotType type;
  double side;  // +1: target on the left, -1: on the right
};

void PrintTo(const SideCase& c, std::ostream* os) {
  *os << toString(c.type) << ", target on the " << (c.side > 0 ? "left" : "right");
}

class ClosedLoopSign : public ::testing::TestWithParam<SideCase> {};

TEST_P(ClosedLoopSign, RobotMovesAndTurnsTowardsATargetOnItsSide) {
  const auto c = GetParam();
  const PlaneSurface flat(0, 0, 0);
  const TerrainKinematics kin(flat, c.type, kR, ContactModel::Paper, kPi / 3);
  const PurePursuitController ctrl(c.type, PursuitGains{}, kR);
  const Eigen::Vector3d target(1.0, c.side * 1.0, 0.0);  // 45 degrees off the heading +x
  TerrainState s{};
  const TrackingError e0 = trackingError(kin.geometry(s), target);
  ASSERT_NEAR(e0.zeta, c.side * kPi / 4, 1e-12);

  // The first small step: holonomic types already move sideways, RT already turns.
  const DriveRates first = kin.realisedRates(s, ctrl.command(e0, Eigen::Vector3d::Zero()));
  const TerrainStateRate r0 = kin.stateRate(s, first);
  if (c.type == RobotType::ThreeAxisRolling || c.type == RobotType::TwoAxisRolling) {
    EXPECT_GT(c.side * r0.y_dot, 0.0);
  }
  if (c.type == RobotType::ThreeAxisRolling || c.type == RobotType::RollingAndTurning) {
    EXPECT_GT(c.side * r0.psi_dot, 0.0);
  }
  if (c.type == RobotType::RollingAndSteering) {
    EXPECT_LT(c.side * r0.phi_dot, 0.0);  // tilts to the side that makes psi_dot = -a sin(phi) turn towards it
  }

  // One second of closed loop (RS needs the tilt to build up before it turns).
  for (int i = 0; i < 100; ++i) {
    const TrackingError e = trackingError(kin.geometry(s), target);
    s = kin.constrain(stepWithHeldRates(kin, s, ctrl.command(e, Eigen::Vector3d::Zero()), 0.01));
  }
  const TrackingError e1 = trackingError(kin.geometry(s), target);
  EXPECT_GT(c.side * s.y, 0.0) << "moved away from the target's side";
  EXPECT_LT(e1.norm, e0.norm);
  if (c.type != RobotType::TwoAxisRolling) {
    EXPECT_GT(c.side * s.psi, 0.0) << "turned away from the target";
    EXPECT_LT(std::abs(e1.zeta), std::abs(e0.zeta));
  }
}

std::vector<SideCase> sideCases() {
  std::vector<SideCase> v;
  for (auto t : kAllTypes) {
    v.push_back({t, +1.0});
    v.push_back({t, -1.0});
  }
  return v;
}

INSTANTIATE_TEST_SUITE_P(AllTypesBothSides, ClosedLoopSign, ::testing::ValuesIn(sideCases()),
                         [](const auto& info) {
                           return testName(info.param.type) + (info.param.side > 0 ? "_Left" : "_Right");
                         });

// ------------------------------------------------------------------------------------------
// Gain validation.

// `key` as a whole word of the message, so that "k_phi" is not satisfied by "k_phi1".
std::string word(const std::string& key) { return " " + key + " "; }

struct GainField {
  const char* name;
  double PursuitGains::*member;
};

const std::vector<GainField> kGainFields = {
    {"k_e", &PursuitGains::k_e},           {"k_theta", &PursuitGains::k_theta},
    {"k_phi1", &PursuitGains::k_phi1},     {"k_phi2", &PursuitGains::k_phi2},
    {"k_psi", &PursuitGains::k_psi},       {"k_theta1", &PursuitGains::k_theta1},
    {"k_theta2", &PursuitGains::k_theta2}, {"k_alpha", &PursuitGains::k_alpha},
    {"k_phi", &PursuitGains::k_phi}};

TEST(PursuitGains, DefaultsAreValid) { EXPECT_NO_THROW(validate(PursuitGains{})); }

TEST(PursuitGains, ValidateRejectsNegativeOrNonFiniteGainsNamingTheGain) {
  for (const auto& f : kGainFields) {
    for (double bad : {-0.1, kNaN, kInf}) {
      PursuitGains g;
      g.*(f.member) = bad;
      EXPECT_INVALID_ARGUMENT(validate(g), word(f.name)) << f.name << " = " << bad;
    }
  }
}

TEST(PursuitGains, ZeroIsAValidGainExceptForKe) {
  // k_e normalises |e| / (k_e + |e|): at k_e = 0 that is 0/0 at the target.
  for (const auto& f : kGainFields) {
    PursuitGains g;
    g.*(f.member) = 0.0;
    if (std::string(f.name) == "k_e") {
      EXPECT_INVALID_ARGUMENT(validate(g), word("k_e")) << "k_e = 0";
    } else {
      EXPECT_NO_THROW(validate(g)) << f.name;
    }
  }
}

TEST(PurePursuitController, ConstructorRejectsBadRadiusAndGains) {
  for (double r : {0.0, -0.2, kNaN}) {
    EXPECT_THROW((void)PurePursuitController(RobotType::ThreeAxisRolling, PursuitGains{}, r),
                 std::invalid_argument);
  }
  PursuitGains bad;
  bad.k_psi = -1.0;
  EXPECT_THROW((void)PurePursuitController(RobotType::RollingAndTurning, bad, kR), std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
