// Kinematics of the four robot types on z = f(x, y) (paper eqs 28-52) in the convention of
// docs/conventions.md, for both contact models. Truth: closed forms on planes, the rolling
// constraint V = Omega x R n checked by finite differences of the centre C = P0 + R n(P0)
// (eq 51), the curvature factor 1 / (1 - R k) derived below, and exact circles for constant rates.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/terrain/robot_type.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"
#include "spherical_robots/terrain/terrain_simulation.hpp"

namespace {

using namespace spherical_robots::terrain;  // NOLINT: test file

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kR = 0.2;           // paper section 6
constexpr double kTilt = kPi / 3.0;  // RS tilt limit used in the paper's simulations

const std::vector<RobotType> kAllTypes = {RobotType::ThreeAxisRolling, RobotType::TwoAxisRolling,
                                          RobotType::RollingAndTurning,
                                          RobotType::RollingAndSteering};

// ------------------------------------------------------------------------------------------
// Independent truth, written from docs/conventions.md and the paper, not from the implementation.

// Eq 10.
Eigen::Vector3d normalOf(const Eigen::Vector2d& g) {
  return Eigen::Vector3d(-g.x(), -g.y(), 1.0) / std::sqrt(1.0 + g.squaredNorm());
}

// R_L = R_T Rz(psi), R_T the rotation by gamma = angle(z, n) about z x n (eqs 11-19), via Eigen.
Eigen::Matrix3d headingFrameOf(const Eigen::Vector2d& g, double psi) {
  const Eigen::Vector3d n = normalOf(g);
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitZ().cross(n);
  Eigen::Matrix3d rt = Eigen::Matrix3d::Identity();
  if (axis.norm() > 0) {
    rt = Eigen::AngleAxisd(std::atan2(axis.norm(), n.z()), axis.normalized()).toRotationMatrix();
  }
  return rt * Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

// What the type realises from commanded rates (conventions.md table), at tilt phi inside the limit.
DriveRates expectedRealised(RobotType type, const DriveRates& c, double phi) {
  switch (type) {
    case RobotType::ThreeAxisRolling:
      return c;
    case RobotType::TwoAxisRolling:
      return {c.roll_rate, c.lateral_rate, 0.0};  // eq 36: psi_dot = 0
    case RobotType::RollingAndTurning:
      return {c.roll_rate, 0.0, c.turn_rate};  // eq 38: phi_dot = 0
    case RobotType::RollingAndSteering:
      return {c.roll_rate, c.lateral_rate, -c.roll_rate * std::sin(phi)};  // eq 44
  }
  return {};
}

// ^L V = (u, v, 0): eq 33 (3R, 2R), eq 38 (RT), eq 48 (RS), from realised rates.
Eigen::Vector3d localVelocity(RobotType type, const DriveRates& r, double phi) {
  const double forward = type == RobotType::RollingAndSteering ? r.roll_rate * std::cos(phi) : r.roll_rate;
  return {kR * forward, -kR * r.lateral_rate, 0.0};
}

// Shell angular velocity (conventions.md, errata T6 for RS): theta_dot l + phi_dot h + psi_dot n;
// RS: alpha_dot (cos phi l + sin phi n) + phi_dot h + psi_dot n.
Eigen::Vector3d expectedOmega(RobotType type, const DriveRates& r, double phi, const Eigen::Matrix3d& rl) {
  const Eigen::Vector3d h = rl.col(0), l = rl.col(1), n = rl.col(2);
  if (type == RobotType::RollingAndSteering) {
    return r.roll_rate * (std::cos(phi) * l + std::sin(phi) * n) + r.lateral_rate * h + r.turn_rate * n;
  }
  return r.roll_rate * l + r.lateral_rate * h + r.turn_rate * n;
}

// The sphere's centre as a function of the contact point's plane coordinates (eq 51).
Eigen::Vector3d centreAt(const Surface& s, double x, double y) {
  return Eigen::Vector3d(x, y, s.height(x, y)) + kR * normalOf(s.gradient(x, y));
}

// d/dt C(x0(t), y0(t)) = J_C (x_dot, y_dot), J_C by central differences.
Eigen::Vector3d centreVelocity(const Surface& s, const TerrainState& st, const TerrainStateRate& rate) {
  const double d = 1e-5;
  const Eigen::Vector3d cx = (centreAt(s, st.x + d, st.y) - centreAt(s, st.x - d, st.y)) / (2 * d);
  const Eigen::Vector3d cy = (centreAt(s, st.x, st.y + d) - centreAt(s, st.x, st.y - d)) / (2 * d);
  return cx * rate.x_dot + cy * rate.y_dot;
}

// n . omega of the heading frame R_L(P0, psi) along the state's motion, by central differences.
double headingTurnRate(const Surface& s, const TerrainState& st, const TerrainStateRate& rate) {
  const double d = 1e-6;
  const auto frameAt = [&](double e) {
    const double x = st.x + e * rate.x_dot, y = st.y + e * rate.y_dot;
    return headingFrameOf(s.gradient(x, y), st.psi + e * rate.psi_dot);
  };
  const Eigen::Matrix3d r = frameAt(0.0);
  const Eigen::Matrix3d spin = (frameAt(d) - frameAt(-d)) / (2 * d) * r.transpose();  // [omega]x
  const Eigen::Vector3d omega(spin(2, 1), spin(0, 2), spin(1, 0));
  return omega.dot(r.col(2));
}

// The contact point's 3D velocity, (x_dot, y_dot, f_x x_dot + f_y y_dot).
Eigen::Vector3d contactVelocity(const Surface& s, const TerrainState& st, const TerrainStateRate& rate) {
  const Eigen::Vector2d g = s.gradient(st.x, st.y);
  return {rate.x_dot, rate.y_dot, g.x() * rate.x_dot + g.y() * rate.y_dot};
}

std::string name(RobotType t) { return toString(t); }
std::string name(ContactModel m) { return toString(m); }

const DriveRates kCommand{1.3, -0.7, 0.4};  // every rate non-zero, so ignored ones show

// Non-flat points of eq 59 (and one flat one), with headings and RS tilts inside the limit.
const std::vector<TerrainState> kStates = {
    {0.3, -0.7, 0.0, 0.0}, {1.1, 0.4, 0.9, 0.5},  {-2.3, 2.9, -2.0, -0.8},
    {0.6, 0.2, 3.0, 0.2},  {0.0, 0.0, 0.4, -0.3}, {0.785, 1.3, -0.6, 1.0}};

// ------------------------------------------------------------------------------------------
// Per type and contact model, on the cosine surface of eq 59.

struct TypeModel {
  RobotType type;
  ContactModel model;
};

void PrintTo(const TypeModel& c, std::ostream* os) {
  *os << toString(c.type) << ", " << toString(c.model) << " contact model";
}

std::vector<TypeModel> allTypeModels() {
  std::vector<TypeModel> v;
  for (auto m : {ContactModel::Paper, ContactModel::Rolling}) {
    for (auto t : kAllTypes) v.push_back({t, m});
  }
  return v;
}

std::string typeModelName(const ::testing::TestParamInfo<TypeModel>& info) {
  std::string t = name(info.param.type);
  return (t[0] == '3' ? "ThreeR" : t[0] == '2' ? "TwoR" : t) + "_" + name(info.param.model);
}

class KinematicsOnCosine : public ::testing::TestWithParam<TypeModel> {
 protected:
  CosineSurface surface_{0.2, 2.0};
  TerrainKinematics kin_{surface_, GetParam().type, kR, GetParam().model, kTilt};
  RobotType type() const { return GetParam().type; }
  double tiltOf(const TerrainState& s) const {
    return type() == RobotType::RollingAndSteering ? s.phi : 0.0;
  }
  TerrainState stateFor(TerrainState s) const {
    if (type() != RobotType::RollingAndSteering) s.phi = 0.0;
    return s;
  }
};

TEST_P(KinematicsOnCosine, RealisesOnlyTheActuatedRatesAndRsTurnsByEq44) {
  for (auto s : kStates) {
    s = stateFor(s);
    const DriveRates got = kin_.realisedRates(s, kCommand);
    const DriveRates want = expectedRealised(type(), kCommand, tiltOf(s));
    EXPECT_NEAR(got.roll_rate, want.roll_rate, 1e-15);
    EXPECT_NEAR(got.lateral_rate, want.lateral_rate, 1e-15);
    EXPECT_NEAR(got.turn_rate, want.turn_rate, 1e-15);
    const TerrainStateRate rate = kin_.stateRate(s, kCommand);
    if (GetParam().model == ContactModel::Paper) {
      EXPECT_NEAR(rate.psi_dot, want.turn_rate, 1e-15);  // eqs 35-39, 44: psi integrates psi_dot
    } else {
      // Rolling: the heading frame itself turns about n at the realised rate, whatever the
      // tangent frame under it does as P0 moves (a shell that does not spin keeps its heading).
      EXPECT_NEAR(headingTurnRate(surface_, s, rate), want.turn_rate, 1e-7);
    }
    // Only RS has a tilt state; it integrates phi_dot (conventions.md table).
    EXPECT_NEAR(rate.phi_dot, type() == RobotType::RollingAndSteering ? want.lateral_rate : 0.0, 1e-15);
  }
}

TEST_P(KinematicsOnCosine, GeometryPutsTheContactOnTheSurfaceAndTheCentreAtPPlusRn) {
  for (auto s : kStates) {
    s = stateFor(s);
    const ContactGeometry g = kin_.geometry(s);
    const Eigen::Vector2d grad = surface_.gradient(s.x, s.y);
    EXPECT_LE((g.contact_point - Eigen::Vector3d(s.x, s.y, surface_.height(s.x, s.y))).norm(), 1e-15);
    EXPECT_LE((g.centre - (g.contact_point + kR * normalOf(grad))).norm(), 1e-15);  // eq 51
    EXPECT_LE((g.gradient - grad).norm(), 1e-15);
    EXPECT_LE((g.heading_frame - headingFrameOf(grad, s.psi)).cwiseAbs().maxCoeff(), 1e-14);
  }
}

TEST(ActuatedRates, ListAndDriveRatesRoundTripInTheActuatorNamesOrder) {
  const DriveRates rates{1.5, -2.5, 3.5};
  const std::vector<std::pair<RobotType, std::vector<std::string>>> names = {
      {RobotType::ThreeAxisRolling, {"theta", "phi", "psi"}},
      {RobotType::TwoAxisRolling, {"theta", "phi"}},
      {RobotType::RollingAndTurning, {"theta", "psi"}},
      {RobotType::RollingAndSteering, {"alpha", "phi"}}};
  for (const auto& [type, expected] : names) {
    EXPECT_EQ(actuatorNames(type), expected) << toString(type);
    const std::vector<double> values = actuatedValues(type, rates);
    ASSERT_EQ(values.size(), expected.size()) << toString(type);
    const DriveRates back = ratesFromActuated(type, values);
    const DriveRates kept = keepActuated(type, rates);
    EXPECT_EQ(back.roll_rate, kept.roll_rate);
    EXPECT_EQ(back.lateral_rate, kept.lateral_rate);
    EXPECT_EQ(back.turn_rate, kept.turn_rate);
    EXPECT_THROW(ratesFromActuated(type, std::vector<double>(expected.size() + 1, 0.0)),
                 std::invalid_argument);
    EXPECT_THROW(ratesFromActuated(type, {}), std::invalid_argument);
  }
}

TEST_P(KinematicsOnCosine, ShellAngularVelocityIsTheRealisedBodyRates) {
  for (auto s : kStates) {
    s = stateFor(s);
    const Eigen::Matrix3d rl = headingFrameOf(surface_.gradient(s.x, s.y), s.psi);
    const DriveRates realised = expectedRealised(type(), kCommand, tiltOf(s));
    const Eigen::Vector3d omega = kin_.shellAngularVelocity(s, kCommand);
    EXPECT_LE((omega - expectedOmega(type(), realised, tiltOf(s), rl)).norm(), 1e-14);
    if (type() == RobotType::RollingAndSteering) {
      // A rolling cone turns about its contact line: Omega lies in the tangent plane (errata T6).
      EXPECT_NEAR(omega.dot(rl.col(2)), 0.0, 1e-14);
    }
  }
}

TEST_P(KinematicsOnCosine, DriveRatesSetTheVelocityTheModelSays) {
  // Paper (eq 28): the contact point moves at R_L ^L V, a tangent vector of magnitude |^L V|.
  // Rolling: the centre moves at R_L ^L V = Omega x R n, and the contact point follows.
  for (auto s : kStates) {
    s = stateFor(s);
    SCOPED_TRACE("state (" + std::to_string(s.x) + ", " + std::to_string(s.y) + ", " +
                 std::to_string(s.psi) + ", " + std::to_string(s.phi) + ")");
    const Eigen::Matrix3d rl = headingFrameOf(surface_.gradient(s.x, s.y), s.psi);
    const DriveRates realised = expectedRealised(type(), kCommand, tiltOf(s));
    const Eigen::Vector3d v_world = rl * localVelocity(type(), realised, tiltOf(s));
    const TerrainStateRate rate = kin_.stateRate(s, kCommand);
    if (GetParam().model == ContactModel::Paper) {
      const Eigen::Vector3d v = contactVelocity(surface_, s, rate);
      EXPECT_LE((v - v_world).norm(), 1e-14);
      EXPECT_NEAR(v.norm(), localVelocity(type(), realised, tiltOf(s)).norm(), 1e-14);
      EXPECT_NEAR(v.dot(rl.col(2)), 0.0, 1e-14);  // tangent to the surface
    } else {
      const Eigen::Vector3d vc = centreVelocity(surface_, s, rate);
      EXPECT_LE((vc - v_world).norm(), 1e-8);
      const Eigen::Vector3d omega = kin_.shellAngularVelocity(s, kCommand);
      EXPECT_LE((omega.cross(kR * rl.col(2)) - vc).norm(), 1e-8);  // no slip at the contact
    }
    // The centre's velocity, both models: finite differences of C = P0 + R n along the motion.
    EXPECT_LE((kin_.centreVelocity(s, kCommand) - centreVelocity(surface_, s, rate)).norm(), 1e-8);
    // The overload taking precomputed geometry agrees.
    const TerrainStateRate again = kin_.stateRate(s, kin_.geometry(s), kCommand);
    EXPECT_EQ(again.x_dot, rate.x_dot);
    EXPECT_EQ(again.y_dot, rate.y_dot);
    EXPECT_EQ(again.psi_dot, rate.psi_dot);
    EXPECT_EQ(again.phi_dot, rate.phi_dot);
  }
}

TEST_P(KinematicsOnCosine, RejectsNonFiniteRatesAndStates) {
  const TerrainState ok{0.3, -0.7, 0.1, 0.2};
  for (double bad : {kNaN, kInf, -kInf}) {
    EXPECT_THROW(kin_.stateRate(ok, DriveRates{bad, 0, 0}), std::invalid_argument);
    EXPECT_THROW(kin_.stateRate(ok, DriveRates{0, bad, 0}), std::invalid_argument);
    EXPECT_THROW(kin_.stateRate(ok, DriveRates{0, 0, bad}), std::invalid_argument);
    for (int i = 0; i < 4; ++i) {
      TerrainState s = ok;
      (i == 0 ? s.x : i == 1 ? s.y : i == 2 ? s.psi : s.phi) = bad;
      EXPECT_THROW(kin_.stateRate(s, kCommand), std::invalid_argument) << "state field " << i;
    }
  }
}

// The checks test the sum of the values first (core/validation.hpp, allFinite): values whose sum
// overflows are finite all the same, and infinities of both signs, whose sum is NaN, are not.
TEST_P(KinematicsOnCosine, FiniteRatesWhoseSumOverflowsAreFinite) {
  const TerrainState ok{0.3, -0.7, 0.1, 0.2};
  EXPECT_NO_THROW(kin_.realisedRates(ok, DriveRates{1e308, 1e308, 1e308}));
  EXPECT_NO_THROW(kin_.realisedRates(ok, DriveRates{-1e308, -1e308, 0}));
  EXPECT_THROW(kin_.realisedRates(ok, DriveRates{kInf, -kInf, 0}), std::invalid_argument);
  EXPECT_THROW(kin_.realisedRates(ok, DriveRates{1e308, 1e308, kNaN}), std::invalid_argument);
}

TEST_P(KinematicsOnCosine, KeepsTheContactPointExactlyOnTheSurfaceOverALongRun) {
  // z0 is never integrated (conventions.md), so it cannot drift: 100 s of RK4 with held rates.
  // RS holds a small tilt: it then runs circles of radius R cot(0.2) ~ 1 m (at its pi/3 limit
  // they would shrink to 0.12 m).
  TerrainState s = stateFor({0.3, -0.7, 0.2, 0.2});
  const DriveRates rates{1.5, type() == RobotType::RollingAndSteering ? 0.0 : 0.4, 0.25};
  double worst = 0.0, farthest = 0.0;
  for (int i = 0; i < 20000; ++i) {
    s = kin_.constrain(stepWithHeldRates(kin_, s, rates, 0.005));
    const ContactGeometry g = kin_.geometry(s);
    worst = std::max(worst, std::abs(g.contact_point.z() - surface_.height(s.x, s.y)));
    farthest = std::max(farthest, std::hypot(s.x - 0.3, s.y + 0.7));
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(farthest, 1.0) << "the robot should have travelled over the bumps";
}

TEST_P(KinematicsOnCosine, StepWithHeldRatesIsFourthOrderAccurate) {
  // Global error of RK4 scales as dt^4: halving dt divides it by ~16. Reference: our own RK4
  // over stateRate with 2000 steps.
  const TerrainState s0 = stateFor({0.3, -0.7, 0.2, 0.3});
  const DriveRates rates{2.0, -1.0, 0.8};
  auto reference = [&](double t_end, int n) {
    TerrainState s = s0;
    const double h = t_end / n;
    auto add = [](TerrainState a, const TerrainStateRate& k, double f) {
      a.x += f * k.x_dot, a.y += f * k.y_dot, a.psi += f * k.psi_dot, a.phi += f * k.phi_dot;
      return a;
    };
    for (int i = 0; i < n; ++i) {
      const auto k1 = kin_.stateRate(s, rates);
      const auto k2 = kin_.stateRate(add(s, k1, h / 2), rates);
      const auto k3 = kin_.stateRate(add(s, k2, h / 2), rates);
      const auto k4 = kin_.stateRate(add(s, k3, h), rates);
      s.x += h / 6 * (k1.x_dot + 2 * k2.x_dot + 2 * k3.x_dot + k4.x_dot);
      s.y += h / 6 * (k1.y_dot + 2 * k2.y_dot + 2 * k3.y_dot + k4.y_dot);
      s.psi += h / 6 * (k1.psi_dot + 2 * k2.psi_dot + 2 * k3.psi_dot + k4.psi_dot);
      s.phi += h / 6 * (k1.phi_dot + 2 * k2.phi_dot + 2 * k3.phi_dot + k4.phi_dot);
    }
    return s;
  };
  const double t_end = 0.4;  // short enough that the RS tilt stays inside its limit
  const TerrainState truth = reference(t_end, 2000);
  auto errorWith = [&](int n) {
    TerrainState s = s0;
    for (int i = 0; i < n; ++i) s = stepWithHeldRates(kin_, s, rates, t_end / n);
    return std::hypot(std::hypot(s.x - truth.x, s.y - truth.y), std::hypot(s.psi - truth.psi, s.phi - truth.phi));
  };
  const double e1 = errorWith(4), e2 = errorWith(8);
  EXPECT_LT(e1, 1e-4);
  EXPECT_GT(e1 / e2, 10.0) << e1 << " " << e2;
  EXPECT_LT(e1 / e2, 24.0) << e1 << " " << e2;
}

INSTANTIATE_TEST_SUITE_P(AllTypesBothModels, KinematicsOnCosine, ::testing::ValuesIn(allTypeModels()),
                         typeModelName);

// ------------------------------------------------------------------------------------------
// Planes: closed forms, and the two contact models coincide.

struct PlaneTypeModel {
  double gx, gy;
  RobotType type;
  ContactModel model;
};

class KinematicsOnPlane : public ::testing::TestWithParam<PlaneTypeModel> {};

TEST_P(KinematicsOnPlane, ContactVelocityIsRThetaDotHMinusRPhiDotL) {
  const auto p = GetParam();
  const PlaneSurface plane(p.gx, p.gy, 0.3);
  const TerrainKinematics kin(plane, p.type, kR, p.model, kTilt);
  const TerrainKinematics other(plane, p.type, kR,
                                p.model == ContactModel::Paper ? ContactModel::Rolling : ContactModel::Paper,
                                kTilt);
  for (double psi : {0.0, 0.7, -2.2, kPi}) {
    TerrainState s{1.0, -2.0, psi, p.type == RobotType::RollingAndSteering ? 0.4 : 0.0};
    const Eigen::Matrix3d rl = headingFrameOf({p.gx, p.gy}, psi);
    const DriveRates r = expectedRealised(p.type, kCommand, s.phi);
    const Eigen::Vector3d want = rl * localVelocity(p.type, r, s.phi);  // R theta_dot h - R phi_dot l
    const TerrainStateRate rate = kin.stateRate(s, kCommand);
    EXPECT_LE((contactVelocity(plane, s, rate) - want).norm(), 1e-14);
    if (p.gx == 0.0 && p.gy == 0.0) {
      // Flat ground, in plain numbers: h = (cos psi, sin psi, 0), l = (-sin psi, cos psi, 0).
      const double fwd = localVelocity(p.type, r, s.phi).x(), lat = r.lateral_rate;
      EXPECT_NEAR(rate.x_dot, fwd * std::cos(psi) + kR * lat * std::sin(psi), 1e-14);
      EXPECT_NEAR(rate.y_dot, fwd * std::sin(psi) - kR * lat * std::cos(psi), 1e-14);
    }
    // On a plane n is constant, so the centre and the contact point move together: the models agree.
    const TerrainStateRate rate2 = other.stateRate(s, kCommand);
    EXPECT_NEAR(rate.x_dot, rate2.x_dot, 1e-14);
    EXPECT_NEAR(rate.y_dot, rate2.y_dot, 1e-14);
    EXPECT_EQ(rate.psi_dot, rate2.psi_dot);
    EXPECT_EQ(rate.phi_dot, rate2.phi_dot);
  }
}

std::vector<PlaneTypeModel> planeCases() {
  std::vector<PlaneTypeModel> v;
  for (auto g : {Eigen::Vector2d(0, 0), Eigen::Vector2d(0.3, -0.5)}) {
    for (auto t : kAllTypes) {
      for (auto m : {ContactModel::Paper, ContactModel::Rolling}) v.push_back({g.x(), g.y(), t, m});
    }
  }
  return v;
}

INSTANTIATE_TEST_SUITE_P(FlatAndTilted, KinematicsOnPlane, ::testing::ValuesIn(planeCases()),
                         [](const auto& info) {
                           const auto& p = info.param;
                           std::string t = name(p.type);
                           return std::string(p.gx == 0 ? "Flat_" : "Tilted_") +
                                  (t[0] == '3' ? "ThreeR" : t[0] == '2' ? "TwoR" : t) + "_" + name(p.model);
                         });

// ------------------------------------------------------------------------------------------
// Rolling model on curved ground: the curvature factor.
//
// At a point where grad f = 0 and the Hessian is diag(f_xx, f_yy), n = (-f_x, -f_y, 1) s_n has
// dn/dx = (-f_xx, 0, 0) and dn/dy = (0, -f_yy, 0) (s_n is stationary), so the centre C = P0 + R n
// has dC/dx = (1 - R f_xx) e_x and dC/dy = (1 - R f_yy) e_y. With V = Omega x R n prescribed, the
// contact point moves at V_x / (1 - R k_x), V_y / (1 - R k_y), k the signed (concave-up positive)
// curvature: faster than the paper model in a valley, slower on a peak.

struct CurvatureCase {
  const char* label;
  double x, y;
  double kx, ky;  // a w^2 = 0.8 with sign
};

class RollingCurvatureFactor : public ::testing::TestWithParam<CurvatureCase> {};

TEST_P(RollingCurvatureFactor, ContactPointSpeedIsScaledByOneOverOneMinusRk) {
  const auto c = GetParam();
  const CosineSurface surface(0.2, 2.0);
  const TerrainKinematics paper(surface, RobotType::ThreeAxisRolling, kR, ContactModel::Paper, kTilt);
  const TerrainKinematics rolling(surface, RobotType::ThreeAxisRolling, kR, ContactModel::Rolling, kTilt);
  for (double psi : {0.0, 0.5, kPi / 2, 2.0}) {
    const TerrainState s{c.x, c.y, psi, 0.0};
    const DriveRates rates{1.0, 0.0, 0.0};  // straight ahead along h = (cos psi, sin psi, 0)
    const TerrainStateRate rp = paper.stateRate(s, rates);
    const TerrainStateRate rr = rolling.stateRate(s, rates);
    EXPECT_NEAR(rp.x_dot, kR * std::cos(psi), 1e-15);
    EXPECT_NEAR(rp.y_dot, kR * std::sin(psi), 1e-15);
    EXPECT_NEAR(rr.x_dot, kR * std::cos(psi) / (1 - kR * c.kx), 1e-14);
    EXPECT_NEAR(rr.y_dot, kR * std::sin(psi) / (1 - kR * c.ky), 1e-14);
  }
}

INSTANTIATE_TEST_SUITE_P(
    CosineCriticalPoints, RollingCurvatureFactor,
    ::testing::Values(CurvatureCase{"Peak", 0.0, 0.0, -0.8, -0.8},
                      CurvatureCase{"Valley", kPi / 2, kPi / 2, 0.8, 0.8},
                      CurvatureCase{"Saddle", kPi / 2, 0.0, 0.8, -0.8}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(RollingModel, DiffersFromThePaperModelOnCurvedGround) {
  const CosineSurface surface(0.2, 2.0);
  const TerrainKinematics paper(surface, RobotType::TwoAxisRolling, kR, ContactModel::Paper, kTilt);
  const TerrainKinematics rolling(surface, RobotType::TwoAxisRolling, kR, ContactModel::Rolling, kTilt);
  const TerrainState s{0.3, -0.7, 0.4, 0.0};
  const TerrainStateRate a = paper.stateRate(s, kCommand), b = rolling.stateRate(s, kCommand);
  EXPECT_GT(std::hypot(a.x_dot - b.x_dot, a.y_dot - b.y_dot), 1e-3);
}

// docs/errata.md T7: the tangent frame of eq 23 turns about n by itself as P0 goes round the circle
// (r = 2 m) on eq 59, by the Gaussian curvature it encloses (Gauss-Bonnet): -∬K dA = 0.85 rad.
TEST(RollingModel, TangentFrameTurnsByTheEnclosedCurvaturePerLapOfTheCircle) {
  const CosineSurface surface(0.2, 2.0);
  constexpr double kCircle = 2.0;  // [m] eq 60, corrected (errata T1)
  // ∬K dA over the disk: K = det(Hessian) / (1 + |grad f|^2)^2, dA = (1 + |grad f|^2)^(1/2) dx dy;
  // midpoint rule in polar coordinates.
  constexpr int kRadial = 400, kAngular = 800;
  double enclosed = 0.0;
  for (int i = 0; i < kRadial; ++i) {
    const double rho = (i + 0.5) * kCircle / kRadial;
    for (int j = 0; j < kAngular; ++j) {
      const double angle = (j + 0.5) * 2.0 * kPi / kAngular;
      const SurfacePoint p = surface.evaluate(rho * std::cos(angle), rho * std::sin(angle));
      const double metric = 1.0 + p.gradient.squaredNorm();
      enclosed += p.hessian.determinant() / std::pow(metric, 1.5) * rho;
    }
  }
  enclosed *= (kCircle / kRadial) * (2.0 * kPi / kAngular);
  EXPECT_NEAR(-enclosed, 0.85, 0.005);
  // The same angle as the frame's own turn: carry a tangent vector round the circle (counter-
  // clockwise, as the path runs) by parallel transport, projecting it on each new tangent plane,
  // and add up how its angle in the frame changes; the frame turns the other way.
  constexpr int kSteps = 20000;
  const auto frameAt = [&](double angle) {
    return headingFrameOf(surface.evaluate(kCircle * std::cos(angle), kCircle * std::sin(angle))
                              .gradient,
                          0.0);
  };
  Eigen::Vector3d carried = frameAt(0.0).col(0);
  double frame_turn = 0.0, previous = 0.0;
  for (int k = 1; k <= kSteps; ++k) {
    const Eigen::Matrix3d frame = frameAt(2.0 * kPi * k / kSteps);
    carried = (carried - carried.dot(frame.col(2)) * frame.col(2)).normalized();
    const double in_frame = std::atan2(carried.dot(frame.col(1)), carried.dot(frame.col(0)));
    frame_turn -= std::remainder(in_frame - previous, 2.0 * kPi);
    previous = in_frame;
  }
  EXPECT_NEAR(frame_turn, -enclosed, 1e-3);
}

// ------------------------------------------------------------------------------------------
// RS specifics: eq 44, the cone's circle, the tilt limit.

TEST(RollingAndSteering, TurnsClockwiseForPositiveTiltAtRateMinusAlphaDotSinPhi) {
  const PlaneSurface flat(0, 0, 0);
  const TerrainKinematics kin(flat, RobotType::RollingAndSteering, kR, ContactModel::Paper, kTilt);
  const TerrainState s{0, 0, 0.3, 0.5};
  const TerrainStateRate rate = kin.stateRate(s, DriveRates{2.0, 0.0, 0.0});
  EXPECT_NEAR(rate.psi_dot, -2.0 * std::sin(0.5), 1e-15);  // eq 44
  EXPECT_NEAR(std::hypot(rate.x_dot, rate.y_dot), kR * 2.0 * std::cos(0.5), 1e-15);  // eq 48
}

TEST(RollingAndSteering, RollsOnTheConesCircleOfRadiusRCotPhiAboutItsApex) {
  // conventions.md: with phi fixed the shell rolls like a cone with apex V = P0 - R cot(phi) l, so
  // the contact point runs a circle of radius R cot(phi) about V, once per 2 pi / (alpha_dot sin phi).
  const PlaneSurface flat(0, 0, 0);
  for (auto model : {ContactModel::Paper, ContactModel::Rolling}) {
    const TerrainKinematics kin(flat, RobotType::RollingAndSteering, kR, model, kTilt);
    const double phi = 0.6, alpha_dot = 3.0;
    TerrainState s{0.5, -0.2, 0.8, phi};
    const Eigen::Vector3d l0 = headingFrameOf({0, 0}, s.psi).col(1);
    const Eigen::Vector2d apex = Eigen::Vector2d(s.x, s.y) - kR / std::tan(phi) * l0.head<2>();
    const double period = 2 * kPi / (alpha_dot * std::sin(phi));
    const int n = 4000;
    double worst = 0.0;
    for (int i = 0; i < n; ++i) {
      s = stepWithHeldRates(kin, s, DriveRates{alpha_dot, 0.0, 0.0}, period / n);
      worst = std::max(worst, std::abs((Eigen::Vector2d(s.x, s.y) - apex).norm() - kR / std::tan(phi)));
    }
    EXPECT_LT(worst, 1e-12);
    EXPECT_NEAR(s.x, 0.5, 1e-10);  // back at the start after one period
    EXPECT_NEAR(s.y, -0.2, 1e-10);
    EXPECT_NEAR(s.psi, 0.8 - 2 * kPi, 1e-10);  // one full clockwise turn
    EXPECT_EQ(s.phi, phi);
  }
}

TEST(RollingAndSteering, TiltStopsAtTheLimitWhenPushedOutwardOnly) {
  const PlaneSurface flat(0, 0, 0);
  const TerrainKinematics kin(flat, RobotType::RollingAndSteering, kR, ContactModel::Paper, kTilt);
  for (double sign : {+1.0, -1.0}) {
    for (double phi : {kTilt, kTilt + 0.05}) {
      const TerrainState s{0, 0, 0, sign * phi};
      const DriveRates outward{1.0, sign * 0.7, 0.0}, inward{1.0, -sign * 0.7, 0.0};
      EXPECT_EQ(kin.realisedRates(s, outward).lateral_rate, 0.0);
      EXPECT_EQ(kin.stateRate(s, outward).phi_dot, 0.0);
      // A tilt that does not move produces no sideways roll either: ^L V = (R a cos phi, 0).
      const TerrainStateRate r = kin.stateRate(s, outward);
      const double c = std::cos(s.phi);
      EXPECT_NEAR(r.x_dot, kR * c, 1e-15);
      EXPECT_NEAR(r.y_dot, 0.0, 1e-15);
      EXPECT_EQ(kin.realisedRates(s, inward).lateral_rate, -sign * 0.7);
      EXPECT_EQ(kin.stateRate(s, inward).phi_dot, -sign * 0.7);
    }
  }
  // Inside the limit the tilt rate passes in both directions.
  EXPECT_EQ(kin.realisedRates({0, 0, 0, 0.5}, DriveRates{1, 0.7, 0}).lateral_rate, 0.7);
}

TEST(RollingAndSteering, ConstrainClampsTheTiltIntoTheLimit) {
  const PlaneSurface flat(0, 0, 0);
  const TerrainKinematics kin(flat, RobotType::RollingAndSteering, kR, ContactModel::Paper, kTilt);
  struct Case {
    double in, out;
  };
  for (const Case c : {Case{1.2, kTilt}, Case{-1.3, -kTilt}, Case{0.5, 0.5}, Case{-kTilt, -kTilt}}) {
    const TerrainState s = kin.constrain({1.5, -2.5, 0.7, c.in});
    EXPECT_EQ(s.phi, c.out) << "phi " << c.in;
    EXPECT_EQ(s.x, 1.5);
    EXPECT_EQ(s.y, -2.5);
    EXPECT_EQ(s.psi, 0.7);
  }
}

TEST(RollingAndSteering, HeldTiltCommandIntegratesToTheLimitAndStays) {
  const PlaneSurface flat(0, 0, 0);
  const TerrainKinematics kin(flat, RobotType::RollingAndSteering, kR, ContactModel::Paper, kTilt);
  TerrainState s{};
  for (int i = 0; i < 400; ++i) s = kin.constrain(stepWithHeldRates(kin, s, DriveRates{1.0, 0.5, 0}, 0.01));
  EXPECT_NEAR(s.phi, kTilt, 1e-12);  // 4 s at 0.5 rad/s would reach 2 rad unclamped
}

// ------------------------------------------------------------------------------------------
// Constant rates integrate to the closed forms.

TEST(TerrainKinematics, ThreeRWithConstantTurnRunsACircleOfRadiusRThetaDotOverPsiDot) {
  const PlaneSurface flat(0, 0, 0);
  const TerrainKinematics kin(flat, RobotType::ThreeAxisRolling, kR, ContactModel::Paper, kTilt);
  const double theta_dot = 2.0, psi_dot = 0.5, psi0 = 0.3, rho = kR * theta_dot / psi_dot;
  TerrainState s{0, 0, psi0, 0};
  const double dt = 0.005;
  for (int i = 1; i <= 2000; ++i) {
    s = stepWithHeldRates(kin, s, DriveRates{theta_dot, 0, psi_dot}, dt);
    const double t = i * dt, psi = psi0 + psi_dot * t;
    ASSERT_NEAR(s.x, rho * (std::sin(psi) - std::sin(psi0)), 1e-11) << "t " << t;
    ASSERT_NEAR(s.y, rho * (std::cos(psi0) - std::cos(psi)), 1e-11) << "t " << t;
    ASSERT_NEAR(s.psi, psi, 1e-12);
  }
}

struct StraightCase {
  double gx, gy;
  ContactModel model;
};

class StraightRollOnPlane : public ::testing::TestWithParam<StraightCase> {};

TEST_P(StraightRollOnPlane, CentreTravelsRThetaDotTAndShellTurnsThetaDotTAboutL) {
  // Rolling without slip: the centre travels the arc length R * angle, along h, while the shell
  // turns by theta_dot T about l (q <- exp(Omega dt / 2) q).
  const auto c = GetParam();
  const PlaneSurface plane(c.gx, c.gy, -0.4);
  const TerrainKinematics kin(plane, RobotType::ThreeAxisRolling, kR, c.model, kTilt);
  const double theta_dot = 1.2, t_end = 2.0, dt = 0.01;
  TerrainState s{0.2, 0.1, 0.6, 0};
  const ContactGeometry g0 = kin.geometry(s);
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  const DriveRates rates{theta_dot, 0, 0};
  for (int i = 0; i < static_cast<int>(t_end / dt + 0.5); ++i) {
    q = advanceOrientation(q, kin.shellAngularVelocity(s, rates), dt);
    s = stepWithHeldRates(kin, s, rates, dt);
  }
  const ContactGeometry g1 = kin.geometry(s);
  const Eigen::Vector3d h = g0.heading_frame.col(0), l = g0.heading_frame.col(1);
  EXPECT_LE((g1.centre - g0.centre - kR * theta_dot * t_end * h).norm(), 1e-12);
  const Eigen::AngleAxisd turned(q);
  EXPECT_NEAR(turned.angle(), theta_dot * t_end, 1e-12);
  EXPECT_LE((turned.axis() - l).norm(), 1e-12);
  EXPECT_EQ(g1.heading_frame.col(0), h);  // heading unchanged
}

INSTANTIATE_TEST_SUITE_P(FlatAndTilted, StraightRollOnPlane,
                         ::testing::Values(StraightCase{0, 0, ContactModel::Paper},
                                           StraightCase{0, 0, ContactModel::Rolling},
                                           StraightCase{0.4, -0.3, ContactModel::Paper},
                                           StraightCase{0.4, -0.3, ContactModel::Rolling}));

// ------------------------------------------------------------------------------------------
// advanceOrientation: exact for constant omega (world frame).

TEST(AdvanceOrientation, OneStepIsTheWorldFrameRotationByOmegaDt) {
  const Eigen::Quaterniond q0(Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, -2, 0.5).normalized()));
  const Eigen::Vector3d omega(0.3, -1.1, 2.0);
  const double dt = 0.37;
  const Eigen::Quaterniond want = Eigen::AngleAxisd(omega.norm() * dt, omega.normalized()) * q0;
  const Eigen::Quaterniond got = advanceOrientation(q0, omega, dt);
  EXPECT_NEAR(std::abs(got.dot(want)), 1.0, 1e-15);  // same rotation (q and -q agree)
  EXPECT_TRUE(got.toRotationMatrix().isApprox(want.toRotationMatrix(), 1e-14));
}

TEST(AdvanceOrientation, ManyStepsStayUnitAndComposeToTheClosedForm) {
  const Eigen::Quaterniond q0(Eigen::AngleAxisd(-0.4, Eigen::Vector3d(0.2, 0.9, -0.3).normalized()));
  const Eigen::Vector3d omega(0.7, 0.2, -0.5);
  const double dt = 0.001;
  const int n = 100000;  // 100 s
  Eigen::Quaterniond q = q0;
  double worst_norm = 0.0;
  for (int i = 0; i < n; ++i) {
    q = advanceOrientation(q, omega, dt);
    worst_norm = std::max(worst_norm, std::abs(q.norm() - 1.0));
  }
  EXPECT_LT(worst_norm, 1e-12);
  const Eigen::Matrix3d want =
      Eigen::AngleAxisd(omega.norm() * n * dt, omega.normalized()).toRotationMatrix() * q0.toRotationMatrix();
  EXPECT_LE((q.toRotationMatrix() - want).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(AdvanceOrientation, ZeroOmegaLeavesTheOrientationAlone) {
  const Eigen::Quaterniond q0(Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitY()));
  const Eigen::Quaterniond q = advanceOrientation(q0, Eigen::Vector3d::Zero(), 0.5);
  EXPECT_NEAR(std::abs(q.dot(q0)), 1.0, 1e-15);
}

// ------------------------------------------------------------------------------------------
// Construction.

TEST(TerrainKinematics, ConstructorRejectsBadRadiusTiltLimitOrMultiPointContact) {
  const CosineSurface surface(0.2, 2.0);
  for (RobotType t : kAllTypes) {
    for (double r : {0.0, -0.2, kNaN, kInf}) {
      EXPECT_THROW((void)TerrainKinematics(surface, t, r, ContactModel::Paper, kTilt), std::invalid_argument)
          << name(t) << " radius " << r;
    }
    // R a w^2 = 1.3 * 0.8 >= 1: the sphere would touch the valleys at two points (assumption 3).
    EXPECT_THROW((void)TerrainKinematics(surface, t, 1.3, ContactModel::Rolling, kTilt), std::invalid_argument);
    EXPECT_NO_THROW((void)TerrainKinematics(surface, t, kR, ContactModel::Rolling, kTilt));
  }
  for (double limit : {0.0, -0.1, kPi / 2, 2.0, kNaN}) {
    EXPECT_THROW((void)TerrainKinematics(surface, RobotType::RollingAndSteering, kR, ContactModel::Paper, limit),
                 std::invalid_argument)
        << "tilt limit " << limit;
  }
}

TEST(ContactModel, ParsesItsTwoNamesAndRejectsOthers) {
  EXPECT_EQ(contactModelFromString("paper"), ContactModel::Paper);
  EXPECT_EQ(contactModelFromString("rolling"), ContactModel::Rolling);
  EXPECT_EQ(contactModelFromString(toString(ContactModel::Rolling)), ContactModel::Rolling);
  EXPECT_THROW(contactModelFromString("slipping"), std::invalid_argument);
  EXPECT_THROW(contactModelFromString(""), std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
