// LockstepPace: the cap of N times real time and the pause, resume and single-step services of
// a lock-step clock, with time as numbers (core/lockstep_pace.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "spherical_robots/core/lockstep_pace.hpp"

using spherical_robots::LockstepPace;

namespace {

constexpr std::int64_t kMs = 1000000;  // [ns]

}  // namespace

TEST(LockstepPace, UncappedStepsAtOnce) {
  LockstepPace pace(0.001, 0.0);
  pace.started(0, 100.0);
  EXPECT_EQ(pace.delayBefore(1000 * kMs, 100.0), 0.0);
}

// Capped at 10x: the step 1 s of simulated time after the first is due 0.1 s of wall time after
// it; early it waits the rest, late it starts at once (no catching up beyond the cap).
TEST(LockstepPace, CapHoldsTheStepUntilItsWallTime) {
  LockstepPace pace(0.001, 10.0);
  EXPECT_EQ(pace.delayBefore(5 * kMs, 50.0), 0.0);  // before the first step: nothing to pace by
  pace.started(5 * kMs, 50.0);
  pace.started(7 * kMs, 51.0);  // only the first step anchors the pace
  EXPECT_NEAR(*pace.delayBefore(1005 * kMs, 50.04), 0.06, 1e-12);
  EXPECT_EQ(*pace.delayBefore(1005 * kMs, 50.2), 0.0);
  pace.started(1005 * kMs, 50.1);
  EXPECT_NEAR(pace.realTimeFactor(1005 * kMs, 50.1), 10.0, 1e-9);
}

TEST(LockstepPace, PausedStepsOnlyWhenAskedOnce) {
  LockstepPace pace(0.001, 0.0);
  EXPECT_EQ(pace.stepOnce(), "not paused: call lockstep/pause first");
  pace.pause();
  EXPECT_TRUE(pace.paused());
  EXPECT_FALSE(pace.delayBefore(kMs, 0.0));
  EXPECT_EQ(pace.stepOnce(), "");
  EXPECT_EQ(pace.stepOnce(), "");
  EXPECT_TRUE(pace.delayBefore(kMs, 0.0));
  EXPECT_TRUE(pace.delayBefore(2 * kMs, 0.0));
  EXPECT_FALSE(pace.delayBefore(3 * kMs, 0.0));  // two asked, two taken
  pace.stepOnce();
  pace.pause();  // a new pause forgets the steps asked for before it
  EXPECT_FALSE(pace.delayBefore(3 * kMs, 0.0));
  pace.resume();
  EXPECT_FALSE(pace.paused());
  EXPECT_TRUE(pace.delayBefore(3 * kMs, 0.0));
}

TEST(LockstepPace, RealTimeFactorIsNanBeforeTheFirstStep) {
  LockstepPace pace(0.001, 0.0);
  EXPECT_TRUE(std::isnan(pace.realTimeFactor(kMs, 1.0)));
  pace.started(0, 1.0);
  EXPECT_TRUE(std::isnan(pace.realTimeFactor(0, 1.0)));  // no wall time yet
  EXPECT_NEAR(pace.realTimeFactor(3000 * kMs, 2.0), 3.0, 1e-12);
}

// A run's figure: the wall time after its last step (observers draining, the stack shutting down)
// does not dilute it. 10 s of simulated time in 0.5 s of wall time is 20x, asked at any time later.
TEST(LockstepPace, RealTimeFactorStopsAtTheEnd) {
  LockstepPace pace(0.01, 0.0);
  pace.started(0, 7.0);
  EXPECT_NEAR(pace.realTimeFactor(5000 * kMs, 7.25), 20.0, 1e-9);
  pace.finished(7.5);
  pace.finished(8.0);  // only the first end counts
  EXPECT_NEAR(pace.realTimeFactor(10000 * kMs, 7.5), 20.0, 1e-9);
  EXPECT_NEAR(pace.realTimeFactor(10000 * kMs, 9.0), 20.0, 1e-9);
}

TEST(LockstepPace, RejectsAStepOrCapOutOfItsDomain) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(LockstepPace(0.001, -1.0), std::invalid_argument);
  EXPECT_THROW(LockstepPace(0.001, kInf), std::invalid_argument);
  EXPECT_THROW(LockstepPace(0.001, kNaN), std::invalid_argument);
  EXPECT_THROW(LockstepPace(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(LockstepPace(kNaN, 1.0), std::invalid_argument);
  EXPECT_EQ(LockstepPace(0.001, 10.0).describe(), "0.001 s per step, at most 10x real time");
  EXPECT_EQ(LockstepPace(0.01, 0.0).describe(), "0.01 s per step, as fast as the participants answer");
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
