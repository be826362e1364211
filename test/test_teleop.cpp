// Teleoperation mapping: checked by what the kinematics then do with the rates (the requested
// velocity and yaw rate are what the robot realises), not by re-deriving the mapping.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "spherical_robots/terrain/teleop.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"
#include "spherical_robots/terrain/terrain_simulation.hpp"

namespace {

using namespace spherical_robots::terrain;

constexpr double kR = 0.2;
constexpr double kTiltLimit = M_PI / 3.0;
constexpr double kTiltGain = 2.0;
const PlaneSurface kFlat(0.0, 0.0, 0.0);

// On flat ground at heading psi, the contact point's velocity in the heading frame.
Eigen::Vector2d bodyVelocity(const TerrainKinematics& kin, const TerrainState& s, const DriveRates& r) {
  const TerrainStateRate rate = kin.stateRate(s, r);
  const double c = std::cos(s.psi), sn = std::sin(s.psi);
  return {c * rate.x_dot + sn * rate.y_dot, -sn * rate.x_dot + c * rate.y_dot};
}

class TeleopOnFlatGround : public ::testing::TestWithParam<RobotType> {};

TEST_P(TeleopOnFlatGround, RealisesWhatTheTypeCanAndListsTheRest) {
  const RobotType type = GetParam();
  const TerrainKinematics kin(kFlat, type, kR, ContactModel::Paper, kTiltLimit);
  const TeleopMapping mapping(type, kR, kTiltLimit, kTiltGain);
  const VelocityRequest request{0.2, 0.1, 0.5};
  const TerrainState s{0.4, -0.3, 0.7, 0.0};
  const TeleopCommand command = mapping.command(request, s.phi);
  const Eigen::Vector2d v = bodyVelocity(kin, s, command.rates);
  const std::array<bool, 3> actuated = actuatedRates(type);
  const bool rs = type == RobotType::RollingAndSteering;

  EXPECT_NEAR(v.x(), request.forward, 1e-15);
  const bool follows_leftward = actuated[1] && !rs;
  // RS is left out: its tilt servo rolls it sideways by -R phi_dot (eq 48), whatever is asked.
  if (!rs) {
    EXPECT_NEAR(v.y(), follows_leftward ? request.leftward : 0.0, 1e-15);
  }
  if (actuated[2]) {
    EXPECT_NEAR(kin.stateRate(s, command.rates).psi_dot, request.yaw_rate, 1e-15);
  }

  std::vector<std::string> expected_ignored;
  if (!follows_leftward) expected_ignored.emplace_back("leftward");
  if (type == RobotType::TwoAxisRolling) expected_ignored.emplace_back("yaw_rate");
  EXPECT_EQ(command.ignored, expected_ignored);
}

INSTANTIATE_TEST_SUITE_P(AllTypes, TeleopOnFlatGround,
                         ::testing::Values(RobotType::ThreeAxisRolling, RobotType::TwoAxisRolling,
                                           RobotType::RollingAndTurning,
                                           RobotType::RollingAndSteering),
                         [](const auto& info) { return "type_" + toString(info.param).substr(0, 2); });

TEST(TeleopRollingAndSteering, AtTheServoedTiltItTurnsAtTheRequestedYawRate) {
  // Eq 44: psi_dot = -alpha_dot sin(phi); with phi held where the servo settles (zero tilt rate),
  // the kinematics must turn at the request.
  const TerrainKinematics kin(kFlat, RobotType::RollingAndSteering, kR, ContactModel::Paper, kTiltLimit);
  const TeleopMapping mapping(RobotType::RollingAndSteering, kR, kTiltLimit, kTiltGain);
  for (double yaw : {0.3, -0.3, 0.8, -0.05}) {  // |yaw| / alpha_dot below sin(pi/3) = 0.866
    const VelocityRequest request{0.2, 0.0, yaw};
    const double alpha_dot = request.forward / kR;
    const double settled_tilt = -std::asin(yaw / alpha_dot);
    const TeleopCommand at_rest = mapping.command(request, settled_tilt);
    EXPECT_NEAR(at_rest.rates.lateral_rate, 0.0, 1e-12) << "yaw " << yaw;
    EXPECT_NEAR(kin.stateRate(TerrainState{0, 0, 0, settled_tilt}, at_rest.rates).psi_dot, yaw, 1e-12);
  }
}

TEST(TeleopRollingAndSteering, ClosedLoopTurnsAtTheRequestAndLevelsWhenReleased) {
  const TerrainKinematics kin(kFlat, RobotType::RollingAndSteering, kR, ContactModel::Paper, kTiltLimit);
  const TeleopMapping mapping(RobotType::RollingAndSteering, kR, kTiltLimit, kTiltGain);
  const double dt = 0.005;
  TerrainState s{};
  const auto run = [&](const VelocityRequest& request, double seconds) {
    const double psi0 = s.psi;
    for (int i = 0; i < static_cast<int>(seconds / dt); ++i) {
      s = stepWithHeldRates(kin, s, mapping.command(request, s.phi).rates, dt);
    }
    return (s.psi - psi0) / seconds;
  };
  run({0.2, 0.0, 0.4}, 5.0);                               // settle: tilt time constant 0.5 s
  EXPECT_NEAR(run({0.2, 0.0, 0.4}, 5.0), 0.4, 1e-3);      // then turns at the request
  run({0.2, 0.0, 0.0}, 5.0);                               // stick released
  EXPECT_NEAR(s.phi, 0.0, 1e-3);                           // levelled...
  EXPECT_NEAR(run({0.2, 0.0, 0.0}, 5.0), 0.0, 1e-3);      // ...and no longer turning
}

TEST(TeleopRollingAndSteering, ClampsTheTiltAtItsLimitAndCannotTurnStandingStill) {
  const TeleopMapping mapping(RobotType::RollingAndSteering, kR, kTiltLimit, kTiltGain);
  // 5 rad/s at alpha_dot = 1 rad/s would need sin(phi) = -5: the tilt servo aims at -pi/3.
  EXPECT_NEAR(mapping.command({0.2, 0.0, 5.0}, 0.0).rates.lateral_rate, kTiltGain * -kTiltLimit, 1e-12);
  EXPECT_NEAR(mapping.command({0.2, 0.0, -5.0}, 0.0).rates.lateral_rate, kTiltGain * kTiltLimit, 1e-12);
  // Not rolling: no tilt can turn it (eq 44), so the servo levels it.
  EXPECT_NEAR(mapping.command({0.0, 0.0, 1.0}, 0.2).rates.lateral_rate, -kTiltGain * 0.2, 1e-12);
}

TEST(Teleop, RejectsNonFiniteInputAndBadConstruction) {
  const TeleopMapping mapping(RobotType::ThreeAxisRolling, kR, kTiltLimit, kTiltGain);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(mapping.command({nan, 0, 0}, 0.0), std::invalid_argument);
  EXPECT_THROW(mapping.command({0, 0, INFINITY}, 0.0), std::invalid_argument);
  EXPECT_THROW(mapping.command({0, 0, 0}, nan), std::invalid_argument);
  EXPECT_THROW(TeleopMapping(RobotType::RollingAndSteering, 0.0, kTiltLimit, kTiltGain), std::invalid_argument);
  EXPECT_THROW(TeleopMapping(RobotType::RollingAndSteering, kR, M_PI / 2, kTiltGain), std::invalid_argument);
  EXPECT_THROW(TeleopMapping(RobotType::RollingAndSteering, kR, kTiltLimit, -1.0), std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
