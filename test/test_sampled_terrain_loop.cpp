// The terrain stack's loop as a batch run (terrain::SampledTerrainLoop) against truths that do not
// come from it: the continuous-time closed loop it samples (its limit as the sampling gets
// faster), the actuators' limits, the order of one lock-step step (a command reaches the plant
// two steps after the state it answers), and the stamps ROS would give. That it equals the
// launched stack value for value is test/batch_equality_terrain.test.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/terrain/sampled_terrain_loop.hpp"
#include "spherical_robots/terrain/terrain_simulation.hpp"
#include "shipped_config.hpp"

namespace {

using namespace spherical_robots::terrain;  // NOLINT: test file
namespace config = spherical_robots::config;

constexpr double kRadius = 0.2;  // urdf/terrain_robot.urdf

struct Scenario {
  explicit Scenario(RobotType type, PursuitLaw law = PursuitLaw::Smooth,
                    const std::string& path_name = "circle")
      : settings(spherical_robots::test_support::shippedTerrainConfig()),
        surface(config::makeSurface(settings.surface)),
        path(config::makePath(path_name, settings)),
        kinematics(*surface, type, kRadius, ContactModel::Paper, settings.tilt_limit),
        law(config::makePursuitController(law, type, settings, kRadius)) {}
  config::TerrainConfig settings;
  std::unique_ptr<Surface> surface;
  std::unique_ptr<ReferencePath> path;
  TerrainKinematics kinematics;
  std::unique_ptr<PursuitController> law;
};

/// Every node at every plant step, actuators that follow at once: only the sampling differs from
/// the continuous loop.
StackSampling everyStep(double step) {
  StackSampling sampling;
  sampling.plant_step = step;
  sampling.publish_rate = sampling.control_rate = sampling.hardware_rate = 1.0 / step;
  sampling.max_velocity = 100.0;
  sampling.max_acceleration = 1e9;
  return sampling;
}

/// |contact point after `seconds` of the sampled loop - the continuous run's|.
double distanceFromContinuous(const Scenario& s, double step, double seconds) {
  SampledTerrainLoop loop(s.kinematics, *s.law, *s.path, everyStep(step));
  const long steps = std::lround(seconds / step);
  for (long k = 0; k <= steps; ++k) loop.step();  // the first step is t = 0
  TerrainSimulation continuous(s.kinematics, *s.law, *s.path, TerrainState{});
  for (int k = 0; k < std::lround(seconds / 1e-3); ++k) continuous.step(1e-3);
  EXPECT_NEAR(loop.sample().t, seconds, 1e-12);
  return (loop.sample().geometry.contact_point - continuous.sample().geometry.contact_point).norm();
}

TEST(SampledTerrainLoop, ApproachesTheContinuousLoopAtFirstOrderAsTheSamplingGetsFaster) {
  for (RobotType type : {RobotType::ThreeAxisRolling, RobotType::RollingAndSteering}) {
    const Scenario s(type);
    // A zero-order hold and one step of delay: the distance halves with the step.
    const double coarse = distanceFromContinuous(s, 0.02, 10.0);
    const double middle = distanceFromContinuous(s, 0.01, 10.0);
    const double fine = distanceFromContinuous(s, 0.005, 10.0);
    std::printf("[ sampled - continuous at 10 s ] %s: step 20 ms %.3g m, 10 ms %.3g m, 5 ms %.3g m\n",
                toString(type).c_str(), coarse, middle, fine);
    EXPECT_NEAR(coarse / middle, 2.0, 0.2) << toString(type) << ": " << coarse << ", " << middle;
    EXPECT_NEAR(middle / fine, 2.0, 0.2) << toString(type) << ": " << middle << ", " << fine;
    EXPECT_LT(fine, 0.01) << toString(type);
  }
}

TEST(SampledTerrainLoop, TheStacksActuatorLimitsHoldEvenForAChatteringLaw) {
  const Scenario s(RobotType::ThreeAxisRolling, PursuitLaw::Paper);
  const StackSampling stack;
  SampledTerrainLoop loop(s.kinematics, *s.law, *s.path, stack);
  loop.step();
  DriveRates last = loop.sample().realised;
  const double max_change = stack.max_acceleration / stack.hardware_rate;  // one hardware period
  for (int k = 0; k < 6000; ++k) {  // 60 s, the paper law chatters from about 12 s on
    loop.step();
    const DriveRates now = loop.sample().realised;  // 3R realises what it measures
    for (const auto& [a, b] : {std::pair{now.roll_rate, last.roll_rate},
                               std::pair{now.lateral_rate, last.lateral_rate},
                               std::pair{now.turn_rate, last.turn_rate}}) {
      ASSERT_LE(std::abs(a), stack.max_velocity) << "step " << k;
      ASSERT_LE(std::abs(a - b), max_change * (1 + 1e-12)) << "step " << k;
    }
    last = now;
  }
}

TEST(SampledTerrainLoop, ACommandMovesThePlantTwoStepsAfterTheStateItAnswers) {
  const Scenario s(RobotType::ThreeAxisRolling);
  SampledTerrainLoop loop(s.kinematics, *s.law, *s.path);
  // Step 1: the plant starts time; the controller answers its state; the actuators take the
  // command and report their velocity at that instant, still 0.
  loop.step();
  EXPECT_EQ(loop.sample().t, 0.0);
  EXPECT_NE(loop.sample().tracked.rates.roll_rate, 0.0);
  // Step 2: the plant moves with what it measured (nothing yet); the actuators ramp up.
  loop.step();
  EXPECT_EQ(loop.sample().state.x, 0.0);
  EXPECT_EQ(loop.sample().state.y, 0.0);
  EXPECT_EQ(loop.sample().realised.roll_rate, 0.0);
  // Step 3: it moves.
  loop.step();
  EXPECT_GT(std::hypot(loop.sample().state.x, loop.sample().state.y), 0.0);
  EXPECT_GT(std::abs(loop.sample().realised.roll_rate), 0.0);
}

TEST(SampledTerrainLoop, StampsAreWholeNanosecondsFromTheFirstStepAtOnePlantStep) {
  const Scenario s(RobotType::RollingAndTurning);
  SampledTerrainLoop loop(s.kinematics, *s.law, *s.path);
  for (int k = 1; k <= 1000; ++k) {
    loop.step();
    ASSERT_EQ(loop.now(), k * 10000000LL);
    // ros::Duration((k - 1) * 10 ms).toSec(): whole seconds plus 1e-9 x the nanoseconds left.
    const long long ns = (k - 1) * 10000000LL;
    ASSERT_EQ(loop.sample().t, static_cast<double>(ns / 1000000000) +
                                   1e-9 * static_cast<double>(ns % 1000000000));
  }
}

TEST(SampledTerrainLoop, RejectsABadSamplingNamingItAndALawOfAnotherType) {
  const Scenario s(RobotType::ThreeAxisRolling);
  StackSampling bad;
  bad.control_rate = 0.0;
  try {
    SampledTerrainLoop loop(s.kinematics, *s.law, *s.path, bad);
    FAIL() << "a controller rate of 0 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("controller rate"), std::string::npos) << e.what();
  }
  bad = StackSampling{};
  bad.plant_step = std::nan("");
  EXPECT_THROW(SampledTerrainLoop(s.kinematics, *s.law, *s.path, bad), std::invalid_argument);
  const Scenario other(RobotType::TwoAxisRolling);
  EXPECT_THROW(SampledTerrainLoop(s.kinematics, *other.law, *s.path), std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
