// A plant's simulated odometry and IMU (core SimulatedSensors). Truth: exactness with the noise
// off (what keeps the stacks equal to their batch runs), the sample mean and deviation of many
// draws against the configured ones, the repeatability a seed promises, and the IMU's specific
// force in closed form (at rest +g up; in uniform circular motion the centripetal acceleration).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/core/simulated_sensors.hpp"

namespace {

using spherical_robots::BodyMotion;
using spherical_robots::ImuReading;
using spherical_robots::SensorNoise;
using spherical_robots::SimulatedSensors;

BodyMotion someMotion() {
  return {Eigen::Vector3d(1.0, -2.0, -0.0),
          Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ())),
          Eigen::Vector3d(0.2, 0.0, -0.01), Eigen::Vector3d(0.0, 0.0, 0.3)};
}

/// Noise on every part, each its own deviation.
SensorNoise everyNoise(std::uint32_t seed) {
  return {0.01, 0.02, 0.03, 0.04, 0.1, seed};
}

TEST(SimulatedSensors, WithoutNoiseTheOdometryIsTheTruthToTheBit) {
  SimulatedSensors sensors({});
  const BodyMotion truth = someMotion();
  for (int i = 0; i < 3; ++i) {
    const BodyMotion odometry = sensors.odometry(truth);
    EXPECT_EQ(odometry.position, truth.position);
    EXPECT_TRUE(std::signbit(odometry.position.z()));  // -0.0 stays -0.0
    EXPECT_EQ(odometry.orientation.coeffs(), truth.orientation.coeffs());
    EXPECT_EQ(odometry.linear, truth.linear);
    EXPECT_EQ(odometry.angular, truth.angular);
  }
}

TEST(SimulatedSensors, NoiseHasTheConfiguredDeviationAndRepeatsWithItsSeed) {
  const SensorNoise noise = everyNoise(42);
  SimulatedSensors sensors(noise), again(noise);
  const BodyMotion truth = someMotion();
  constexpr int kDraws = 20000;
  double sum = 0.0, squares = 0.0, yaw_squares = 0.0, twist_squares = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const BodyMotion odometry = sensors.odometry(truth);
    const BodyMotion repeated = again.odometry(truth);
    ASSERT_EQ(odometry.position, repeated.position) << i;
    ASSERT_EQ(odometry.orientation.coeffs(), repeated.orientation.coeffs()) << i;
    const double dx = odometry.position.x() - truth.position.x();
    sum += dx;
    squares += dx * dx;
    // A turn about z only: the body stays gravity-aligned.
    const Eigen::Quaterniond turn = odometry.orientation * truth.orientation.conjugate();
    EXPECT_NEAR(turn.x(), 0.0, 1e-15);
    EXPECT_NEAR(turn.y(), 0.0, 1e-15);
    const double yaw = 2.0 * std::atan2(turn.z(), turn.w());
    yaw_squares += yaw * yaw;
    const double dv = odometry.linear.y() - truth.linear.y();
    twist_squares += dv * dv;
  }
  // Standard errors: the mean's sigma / sqrt(N); the deviation's about sigma / sqrt(2N).
  const double spread = 4.0 / std::sqrt(2.0 * kDraws);  // four standard errors, relative
  EXPECT_NEAR(sum / kDraws, 0.0, 4.0 * noise.position / std::sqrt(kDraws));
  EXPECT_NEAR(std::sqrt(squares / kDraws), noise.position, spread * noise.position);
  EXPECT_NEAR(std::sqrt(yaw_squares / kDraws), noise.yaw, spread * noise.yaw);
  EXPECT_NEAR(std::sqrt(twist_squares / kDraws), noise.linear_velocity, spread * noise.linear_velocity);
}

TEST(SimulatedSensors, TheImuLeavesTheOdometrysDrawsAsTheyWere) {
  SimulatedSensors with_imu(everyNoise(3)), without(everyNoise(3));
  const BodyMotion truth = someMotion();
  for (int i = 0; i < 100; ++i) {
    with_imu.imu(0.01 * i, truth);
    const BodyMotion a = with_imu.odometry(truth), b = without.odometry(truth);
    ASSERT_EQ(a.position, b.position) << i;
    ASSERT_EQ(a.angular, b.angular) << i;
  }
}

TEST(SimulatedSensors, ImuReadsGravityAtRestAndTheCentripetalAccelerationOnACircle) {
  SimulatedSensors sensors({});
  BodyMotion rest;
  rest.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(1.1, Eigen::Vector3d::UnitZ()));
  for (double t : {0.0, 0.01, 0.02}) {
    const ImuReading reading = sensors.imu(t, rest);
    EXPECT_LT((reading.linear_acceleration - Eigen::Vector3d(0, 0, SimulatedSensors::kGravity)).norm(),
              1e-15);
    EXPECT_EQ(reading.orientation.coeffs(), rest.orientation.coeffs());
  }
  // Heading along a circle of radius r at speed v: body x forward, the centre to the left (+y).
  SimulatedSensors circling({});
  const double r = 2.0, v = 0.1, omega = v / r, dt = 1e-4;
  Eigen::Vector3d last_reading;
  for (int k = 0; k < 3; ++k) {
    const double t = k * dt, heading = omega * t;
    BodyMotion motion;
    motion.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()));
    motion.linear = Eigen::Vector3d(v, 0.0, 0.0);
    motion.angular = Eigen::Vector3d(0.0, 0.0, omega);
    last_reading = circling.imu(t, motion).linear_acceleration;
  }
  // The backward difference over dt lags by dt / 2: its error is v omega^2 dt / 2 in x.
  EXPECT_NEAR(last_reading.x(), 0.0, v * omega * omega * dt);
  EXPECT_NEAR(last_reading.y(), v * omega, 1e-9);
  EXPECT_NEAR(last_reading.z(), SimulatedSensors::kGravity, 1e-12);
}

TEST(SimulatedSensors, RefusesADeviationThatIsNone) {
  SensorNoise bad;
  bad.yaw = -0.1;
  EXPECT_INVALID_ARGUMENT(SimulatedSensors{bad}, "yaw noise");
  bad.yaw = 0.0;
  bad.linear_acceleration = std::numeric_limits<double>::quiet_NaN();
  EXPECT_INVALID_ARGUMENT(SimulatedSensors{bad}, "linear acceleration noise");
}

TEST(BodyMotion, VelocitiesTurnIntoTheBodysAxes) {
  // Body turned a quarter about z: odom +x is body -y.
  const BodyMotion motion = spherical_robots::bodyMotion(
      Eigen::Vector3d(1, 2, 3), Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ())),
      Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 2));
  EXPECT_LT((motion.linear - Eigen::Vector3d(0, -1, 0)).norm(), 1e-15);
  EXPECT_LT((motion.angular - Eigen::Vector3d(0, 0, 2)).norm(), 1e-15);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
