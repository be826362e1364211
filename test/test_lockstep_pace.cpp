// LockstepPace: the cap of N times real time and the pause, resume and single-step services of
// a lock-step clock, with time as numbers (core/lockstep_pace.hpp); ClockPublication: how often
// it sends /clock (core/clock_publication.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "spherical_robots/core/clock_publication.hpp"
#include "spherical_robots/core/lockstep_pace.hpp"

using spherical_robots::ClockPublication;
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
  pace.started(7 * kMs, 50.0002);  // on the schedule: the first step stays the anchor
  EXPECT_NEAR(*pace.delayBefore(1005 * kMs, 50.04), 0.06, 1e-12);
  EXPECT_EQ(*pace.delayBefore(1005 * kMs, 50.2), 0.0);
  pace.started(1005 * kMs, 50.1);
  EXPECT_NEAR(pace.realTimeFactor(1005 * kMs, 50.1), 10.0, 1e-9);
}

// A timer firing late (50 ms behind the schedule at 10x) is made up: the steps after it start at
// once until the loop is back on the schedule of the first step.
TEST(LockstepPace, MakesUpALagUpToMaxLag) {
  LockstepPace pace(0.01, 10.0);
  pace.started(0, 0.0);
  pace.started(10 * kMs, 0.051);  // due at 0.001: 0.05 s late, within kMaxLag
  EXPECT_EQ(*pace.delayBefore(20 * kMs, 0.051), 0.0);
  EXPECT_NEAR(*pace.delayBefore(600 * kMs, 0.051), 0.009, 1e-12);  // due at 0.06
}

// 2 s of wall time waiting for a participant that fell silent (dropped after its timeout): the cap
// counts afresh from the step after the wait instead of making up 20 s of simulated time at full
// speed (the terrain stack at 10x did: its respawned controller rejoined 19 s later).
TEST(LockstepPace, DoesNotRaceAfterAStall) {
  LockstepPace pace(0.01, 10.0);
  pace.started(0, 0.0);
  pace.started(10 * kMs, 2.0);
  EXPECT_NEAR(*pace.delayBefore(20 * kMs, 2.0), 0.001, 1e-12);
  EXPECT_NEAR(*pace.delayBefore(1010 * kMs, 2.05), 0.05, 1e-12);  // 1 s on: 0.1 s after 2.0
  EXPECT_NEAR(pace.realTimeFactor(1010 * kMs, 2.1), 1.01 / 2.1, 1e-12)
      << "the run's figure still counts from its first step";
}

// A pause is not made up after the resume either: 30 s paused at 10x would be 300 s at full speed.
TEST(LockstepPace, DoesNotRaceAfterAResume) {
  LockstepPace pace(0.01, 10.0);
  pace.started(0, 0.0);
  pace.started(10 * kMs, 0.001);
  pace.pause();
  EXPECT_FALSE(pace.delayBefore(20 * kMs, 15.0));
  pace.resume();
  EXPECT_EQ(*pace.delayBefore(20 * kMs, 30.0), 0.0);  // the first step after the resume: at once
  pace.started(20 * kMs, 30.0);
  EXPECT_NEAR(*pace.delayBefore(30 * kMs, 30.0), 0.001, 1e-12);
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

// At 1 kHz of wall time, steps 0.3 ms of wall time apart (terrain at 33 x real time) are sent one in
// four: the 1st, then the first at least 1 ms after it; a step not sent is sent once time waits,
// and no step twice.
TEST(ClockPublication, AtMostRateMessagesPerWallSecondAndTheLastStepOnceTimeWaits) {
  ClockPublication clock(1000.0);
  int sent = 0;
  std::int64_t last_sent = -1;
  for (int k = 0; k < 100; ++k) {
    const std::int64_t step = k * 10 * kMs;
    const double wall = 1.0 + k * 0.0003;
    if (clock.due(step, wall, false)) {
      if (last_sent >= 0) {
        EXPECT_EQ(step - last_sent, 40 * kMs) << "at step " << k;
      }
      clock.published(step, wall);
      last_sent = step;
      ++sent;
    }
  }
  EXPECT_EQ(sent, 25);
  const std::int64_t last = 99 * 10 * kMs;
  ASSERT_NE(last_sent, last) << "the last step was sent anyway: the next check proves nothing";
  EXPECT_TRUE(clock.due(last, 1.0 + 99 * 0.0003, true)) << "time waits after an unsent step";
  clock.published(last, 1.0 + 99 * 0.0003);
  EXPECT_FALSE(clock.due(last, 5.0, true)) << "the same step twice";
  EXPECT_FALSE(clock.due(last, 5.0, false));
}

TEST(ClockPublication, RateZeroSendsEveryStepAndANegativeOrNonFiniteRateIsRejected) {
  ClockPublication every(0.0);
  for (int k = 0; k < 10; ++k) {
    ASSERT_TRUE(every.due(k * kMs, 1.0, false)) << "step " << k << " at the same wall time";
    every.published(k * kMs, 1.0);
  }
  EXPECT_THROW(ClockPublication(-1.0), std::invalid_argument);
  EXPECT_THROW(ClockPublication(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  EXPECT_THROW(ClockPublication(std::numeric_limits<double>::infinity()), std::invalid_argument);
}
