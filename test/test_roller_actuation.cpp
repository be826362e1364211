// The friction drive as the roller stack's actuation (roller_actuation.hpp, roller_config.hpp)
// against closed forms: the centre velocity V = ω × r z of rolling on a level floor, eq 28's slip
// S1 = −S2 = (v1 sin α1 − v2 sin α2)/2, peripheral speed = roller radius × motor rate, and the
// inverse followed by the forward kinematics giving back the commanded velocity.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/config/roller_config.hpp"
#include "spherical_robots/roller/roller_actuation.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using spherical_robots::config::makeRollerActuation;
using spherical_robots::config::RollerConfig;
using spherical_robots::roller::RollerActuation;
using spherical_robots::roller::rollingRates;
using spherical_robots::terrain::DriveRates;

constexpr double kSphereRadius = 0.2;

RollerActuation paperDrive() { return makeRollerActuation(RollerConfig{}, kSphereRadius); }

/// V = ω × r z, the centre's velocity rolling without slip on the floor at −r z (eq 13).
Eigen::Vector3d centreVelocity(const Eigen::Vector3d& omega) {
  return omega.cross(kSphereRadius * Eigen::Vector3d::UnitZ());
}

TEST(RollingRates, CentreMovesAsThe2RRatesOnALevelFloor) {
  // 2R on a level floor with psi = 0: theta_dot about l = y moves the centre along h = x,
  // phi_dot about h = x moves it along -y (R theta_dot h - R phi_dot l).
  const Eigen::Vector3d omega(0.3, -0.7, 5.0);
  const DriveRates rates = rollingRates(omega);
  const Eigen::Vector3d expected(kSphereRadius * rates.roll_rate, -kSphereRadius * rates.lateral_rate, 0.0);
  EXPECT_LT((centreVelocity(omega) - expected).norm(), 1e-15);
  EXPECT_EQ(rates.turn_rate, 0.0) << "the spin moves nothing on a level floor and is dropped";
}

TEST(RollerActuation, InverseThenForwardGivesTheCommandedCentreVelocity) {
  const RollerActuation actuation = paperDrive();
  std::mt19937 random(3);
  std::uniform_real_distribution<double> rate(-2.0, 2.0);
  for (int trial = 0; trial < 200; ++trial) {
    DriveRates command;
    command.roll_rate = rate(random);
    command.lateral_rate = rate(random);
    const auto motor = actuation.motorRates(command);
    const auto state = actuation.driveState(motor);
    const Eigen::Vector3d wanted(kSphereRadius * command.roll_rate,
                                 -kSphereRadius * command.lateral_rate, 0.0);
    EXPECT_LT((centreVelocity(state.omega) - wanted).norm(), 1e-12 * (1.0 + wanted.norm()))
        << "trial " << trial;
    // The realised ω lies in the drive's plane: it rolls on the rollers up to eq 28's slip.
    EXPECT_NEAR(state.omega.dot(actuation.drive().omegaPlaneNormal()), 0.0, 1e-12);
  }
}

TEST(RollerActuation, AsTheStacksDriveGivesBackThe2RCommandThroughTheMotors) {
  // The roller stack's drive in the batch run (terrain::ActuatorDrive): the controller's 2R rates
  // to motor set-points, the motors' rates back to 2R rates; a turn rate, which 2R never has, is
  // dropped on the way in and not made on the way out.
  const RollerActuation actuation = paperDrive();
  const spherical_robots::terrain::ActuatorDrive& drive = actuation;
  EXPECT_EQ(drive.actuatorNames(), (std::vector<std::string>{"roller_1", "roller_2"}));
  std::mt19937 random(5);
  std::uniform_real_distribution<double> rate(-2.0, 2.0);
  for (int trial = 0; trial < 100; ++trial) {
    const DriveRates command{rate(random), rate(random), rate(random)};
    const DriveRates back = drive.driveRates(drive.setpoints(command));
    EXPECT_NEAR(back.roll_rate, command.roll_rate, 1e-12) << "trial " << trial;
    EXPECT_NEAR(back.lateral_rate, command.lateral_rate, 1e-12) << "trial " << trial;
    EXPECT_EQ(back.turn_rate, 0.0);
  }
  EXPECT_THROW(drive.driveRates({1.0}), std::invalid_argument);
}

TEST(RollerActuation, PeripheralSpeedIsRollerRadiusTimesMotorRate) {
  RollerConfig config;
  config.roller_radius = 0.05;
  const RollerActuation actuation = makeRollerActuation(config, kSphereRadius);
  const auto state = actuation.driveState({4.0, -6.0});
  EXPECT_DOUBLE_EQ(state.speeds.v1, 0.2);
  EXPECT_DOUBLE_EQ(state.speeds.v2, -0.3);
}

TEST(RollerActuation, SlipIsEq28ForAnyMeasuredRates) {
  const RollerActuation actuation = paperDrive();
  const double alpha1 = M_PI / 6.0, alpha2 = -M_PI / 6.0;  // the defaults, 30 and -30 degrees
  for (const auto& motor : {std::array<double, 2>{10.0, 10.0}, std::array<double, 2>{-3.0, 7.5},
                            std::array<double, 2>{0.0, 12.0}}) {
    const auto state = actuation.driveState(motor);
    const double expected =
        0.5 * (state.speeds.v1 * std::sin(alpha1) - state.speeds.v2 * std::sin(alpha2));
    EXPECT_NEAR(state.slip[0], expected, 1e-12);
    EXPECT_NEAR(state.slip[1], -expected, 1e-12);
  }
}

TEST(RollerActuation, AtRestEverythingIsZero) {
  const RollerActuation actuation = paperDrive();
  const auto motor = actuation.motorRates(DriveRates{});
  EXPECT_EQ(motor[0], 0.0);
  EXPECT_EQ(motor[1], 0.0);
  const auto state = actuation.driveState({0.0, 0.0});
  EXPECT_EQ(state.omega.norm(), 0.0);
  EXPECT_EQ(state.slip[0], 0.0);
  EXPECT_EQ(state.motion.speed, 0.0);
}

TEST(RollerActuation, RejectsBadInputNamingIt) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  RollerConfig config;
  config.roller_radius = 0.0;
  EXPECT_INVALID_ARGUMENT(makeRollerActuation(config, kSphereRadius), "roller radius");
  const RollerActuation actuation = paperDrive();
  DriveRates bad;
  bad.roll_rate = nan;
  EXPECT_THROW(actuation.motorRates(bad), std::invalid_argument);
  EXPECT_THROW(actuation.driveState({nan, 0.0}), std::invalid_argument);
  EXPECT_THROW(rollingRates(Eigen::Vector3d(nan, 0.0, 0.0)), std::invalid_argument);
  config.roller_radius = 0.03;
  config.contact2 = config.contact1;  // parallel contact points: no drive plane
  EXPECT_THROW(makeRollerActuation(config, kSphereRadius), std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
