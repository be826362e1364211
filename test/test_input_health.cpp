// InputHealth (escalation of a node's status under rejected input) and ClockJumpDetector, with
// time as a number: the rules the nodes report on /diagnostics and follow on a jumping clock.
#include <gtest/gtest.h>

#include <limits>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/core/clock_jump.hpp"
#include "spherical_robots/core/input_health.hpp"

namespace sr = spherical_robots;
using sr::ClockStep;
using sr::HealthLevel;

TEST(InputHealth, OkUntilTheFirstRejection) {
  sr::InputHealth health;
  for (double t = 0.0; t < 5.0; t += 0.01) health.accepted(t);
  EXPECT_EQ(health.level(5.0), HealthLevel::kOk);
  EXPECT_EQ(health.rejectionRate(5.0), 0.0);
}

TEST(InputHealth, WarnWhileRejectionsContinueErrorPastTheRate) {
  sr::InputHealth health({1.0, 20.0, 2.0});
  health.rejected(0.0, "NaN velocity");
  EXPECT_EQ(health.level(0.0), HealthLevel::kWarn);
  EXPECT_EQ(health.lastReason(), "NaN velocity");
  // 500 per second: a burst.
  for (int i = 1; i <= 500; ++i) health.rejected(i * 0.002, "burst");
  EXPECT_EQ(health.level(1.0), HealthLevel::kError);
  EXPECT_NEAR(health.rejectionRate(1.0), 500.0, 1.0);
  // 20 per second is the ERROR threshold itself: not above it.
  sr::InputHealth slow({1.0, 20.0, 2.0});
  for (int i = 0; i < 20; ++i) slow.rejected(i * 0.05, "slow");
  EXPECT_EQ(slow.level(0.99), HealthLevel::kWarn);
  slow.rejected(0.995, "one more");
  EXPECT_EQ(slow.level(0.999), HealthLevel::kError);
}

TEST(InputHealth, BackToOkOnlyAfterGoodInputHasFlowedForTheRecoveryTime) {
  sr::InputHealth health({1.0, 20.0, 2.0});
  for (int i = 0; i < 100; ++i) health.rejected(i * 0.01, "burst");
  // The burst ends at 0.99 s; the rate decays out of the window: ERROR, then WARN.
  EXPECT_EQ(health.level(1.0), HealthLevel::kError);
  EXPECT_EQ(health.level(2.5), HealthLevel::kWarn);
  // Silence is not good input: still WARN long after.
  EXPECT_EQ(health.level(10.0), HealthLevel::kWarn);
  health.accepted(10.0);
  EXPECT_EQ(health.level(10.0), HealthLevel::kOk);  // 9 s since the last rejection, good since
  // A new rejection restarts the recovery.
  health.rejected(11.0, "again");
  health.accepted(11.5);
  EXPECT_EQ(health.level(12.9), HealthLevel::kWarn);
  health.accepted(12.9);
  EXPECT_EQ(health.level(13.0), HealthLevel::kOk);
}

TEST(InputHealth, AClockThatWentBackForgetsTheHistory) {
  sr::InputHealth health;
  for (int i = 0; i < 100; ++i) health.rejected(100.0 + i * 0.01, "burst");
  EXPECT_EQ(health.level(101.0), HealthLevel::kError);
  EXPECT_EQ(health.level(1.0), HealthLevel::kOk);
}

TEST(InputHealth, BadPolicyIsRejectedNamingTheField) {
  EXPECT_INVALID_ARGUMENT(sr::InputHealth({0.0, 20.0, 2.0}), "window");
  EXPECT_INVALID_ARGUMENT(sr::InputHealth({1.0, -1.0, 2.0}), "error_rate");
  EXPECT_INVALID_ARGUMENT(
      sr::InputHealth({1.0, 20.0, std::numeric_limits<double>::infinity()}), "recovery");
}

TEST(ClockJumpDetector, StepsAdvanceJumpsAreNamed) {
  sr::ClockJumpDetector clock(5.0);
  EXPECT_EQ(clock.observe(10.0), ClockStep::kStart);
  EXPECT_EQ(clock.observe(10.01), ClockStep::kAdvance);
  EXPECT_EQ(clock.observe(10.01), ClockStep::kHold);
  EXPECT_EQ(clock.observe(15.01), ClockStep::kAdvance);  // exactly max_step: still elapsed time
  EXPECT_EQ(clock.jumps(), 0u);
  // A stray /clock 1000 s ahead, then the real clock again.
  EXPECT_EQ(clock.observe(1015.0), ClockStep::kJumpForward);
  EXPECT_EQ(clock.observe(15.02), ClockStep::kJumpBack);
  EXPECT_EQ(clock.observe(15.03), ClockStep::kAdvance);
  // Any step back is a jump: a replayed bag looping, a restarted clock.
  EXPECT_EQ(clock.observe(15.0299), ClockStep::kJumpBack);
  EXPECT_EQ(clock.jumps(), 3u);
  EXPECT_EQ(clock.observe(std::numeric_limits<double>::quiet_NaN()), ClockStep::kHold);
  EXPECT_EQ(clock.latest(), 15.0299);
  EXPECT_EQ(clock.jumpOver(15.04), 0.0);
  EXPECT_NEAR(clock.jumpOver(1015.04), 1000.0, 1e-9);
  EXPECT_NEAR(clock.jumpOver(15.05), -999.99, 1e-9);
  EXPECT_INVALID_ARGUMENT(sr::ClockJumpDetector(0.0), "max_clock_step");
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
