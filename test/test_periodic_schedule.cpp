// PeriodicSchedule: a publication at its rate on a loop whose steps come on time (lock-step,
// batch), late (a wall timer), after a gap and after time went back; counts against the closed
// form duration x rate.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "spherical_robots/core/periodic_schedule.hpp"

namespace spherical_robots {
namespace {

constexpr Nanoseconds kMs = 1000000;

/// The steps at which a schedule of `period` is due, over steps at `times`.
std::vector<Nanoseconds> dueAt(double period, const std::vector<Nanoseconds>& times) {
  PeriodicSchedule schedule(period);
  std::vector<Nanoseconds> due;
  for (const Nanoseconds t : times) {
    if (schedule.take(t)) due.push_back(t);
  }
  return due;
}

/// Steps every 5 ms from 5 ms on, each late by `late(k)` ns.
template <typename Late>
std::vector<Nanoseconds> steps(int count, Late late) {
  std::vector<Nanoseconds> times;
  for (int k = 1; k <= count; ++k) times.push_back(k * 5 * kMs + late(k));
  return times;
}

TEST(PeriodicSchedule, OnStepsThatDivideThePeriodItIsDueEveryFourthStepFromTheFirst) {
  const std::vector<Nanoseconds> due = dueAt(0.02, steps(40, [](int) { return 0; }));
  ASSERT_EQ(due.size(), 10u);
  for (std::size_t i = 0; i < due.size(); ++i) EXPECT_EQ(due[i], (5 + 20 * static_cast<Nanoseconds>(i)) * kMs);
}

TEST(PeriodicSchedule, StepsThatComeLateKeepTheRate) {
  // A 200 Hz wall timer, each firing late by up to 1 ms (a fixed pseudo-random sequence): 10 s
  // of it hold 500 periods of 20 ms, whatever the lateness.
  std::uint32_t state = 12345;
  const auto late = [&](int) {
    state = state * 1664525u + 1013904223u;  // Numerical Recipes' LCG
    return static_cast<Nanoseconds>(state % static_cast<std::uint32_t>(kMs));
  };
  const std::vector<Nanoseconds> due = dueAt(0.02, steps(2000, late));
  EXPECT_GE(due.size(), 499u);
  EXPECT_LE(due.size(), 500u);
  // A publication comes on the step at or after its time, so at most one step (5 ms, plus the
  // difference of two latenesses, < 1 ms) early or late against the previous one.
  for (std::size_t i = 1; i < due.size(); ++i) {
    EXPECT_GE(due[i] - due[i - 1], 14 * kMs) << i;
    EXPECT_LE(due[i] - due[i - 1], 26 * kMs) << i;
  }
}

TEST(PeriodicSchedule, APeriodThatIsNoWholeNumberOfStepsKeepsItsRate) {
  // 30 Hz on 5 ms steps: due at the first step at or after each k/30 s; 3 s hold 90.
  const std::vector<Nanoseconds> due = dueAt(1.0 / 30.0, steps(600, [](int) { return 0; }));
  EXPECT_EQ(due.size(), 90u);
  for (std::size_t i = 1; i < due.size(); ++i) {
    EXPECT_GE(due[i] - due[i - 1], 30 * kMs) << i;
    EXPECT_LE(due[i] - due[i - 1], 35 * kMs) << i;
  }
}

TEST(PeriodicSchedule, AfterAGapItStartsAgainFromTheStep) {
  PeriodicSchedule schedule(0.02);
  EXPECT_TRUE(schedule.take(5 * kMs));
  EXPECT_TRUE(schedule.take(1000 * kMs));   // 1 s later: due, and the schedule is this step's
  EXPECT_FALSE(schedule.take(1015 * kMs));  // not one catch-up after another
  EXPECT_TRUE(schedule.take(1020 * kMs));
}

TEST(PeriodicSchedule, WhenTimeGoesBackItIsDueAtOnce) {
  PeriodicSchedule schedule(0.02);
  EXPECT_TRUE(schedule.take(100 * kMs));
  EXPECT_TRUE(schedule.take(40 * kMs));
  EXPECT_FALSE(schedule.take(45 * kMs));
  EXPECT_TRUE(schedule.take(60 * kMs));
}

}  // namespace
}  // namespace spherical_robots

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
