// core/stamp against roscpp's own ros::Time and ros::Duration (rostime), the independent truth
// for what a node computes with.
#include <gtest/gtest.h>
#include <ros/duration.h>
#include <ros/time.h>

#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>

#include "spherical_robots/core/stamp.hpp"

namespace spherical_robots {
namespace {

TEST(StampSeconds, EqualsRosTimeAndDurationToSecBitForBit) {
  std::mt19937_64 random(7);
  std::uniform_int_distribution<std::int64_t> any(0, std::int64_t{4000000000} * 1000000000);
  for (int i = 0; i < 100000; ++i) {
    const std::int64_t ns = i < 1000 ? std::int64_t{i} * 10000000 : any(random);
    ros::Time stamp;
    stamp.fromNSec(static_cast<std::uint64_t>(ns));
    EXPECT_EQ(stampSeconds(ns), stamp.toSec()) << ns << " ns";
    if (ns < std::int64_t{2000000000} * 1000000000) {
      const ros::Duration forward(ros::Duration().fromNSec(ns));
      const ros::Duration back(ros::Duration().fromNSec(-ns));
      EXPECT_EQ(stampSeconds(ns), forward.toSec()) << ns << " ns";
      EXPECT_EQ(stampSeconds(-ns), back.toSec()) << -ns << " ns";
    }
  }
  // Not ns * 1e-9: the two differ, which is why the batch run needs this function.
  int differing = 0;
  for (std::int64_t k = 1; k <= 20000; ++k)
    differing += stampSeconds(k * 10000000) != static_cast<double>(k * 10000000) * 1e-9;
  EXPECT_GT(differing, 0);
}

TEST(DurationNanoseconds, EqualsRosDurationFromSec) {
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> any(-1e6, 1e6);
  const double fixed[] = {0.0, 0.001, 0.005, 0.01, 0.02, 1.0 / 50, 1.0 / 1000, 1.0 / 3, 0.5,
                          -0.01, 1e-10, 199.99999999999997};
  for (double seconds : fixed)
    EXPECT_EQ(durationNanoseconds(seconds), ros::Duration(seconds).toNSec()) << seconds << " s";
  for (int i = 0; i < 100000; ++i) {
    const double seconds = any(random);
    EXPECT_EQ(durationNanoseconds(seconds), ros::Duration(seconds).toNSec()) << seconds << " s";
  }
}

TEST(DurationNanoseconds, RejectsWhatRosDurationCannotHold) {
  EXPECT_THROW(durationNanoseconds(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  EXPECT_THROW(durationNanoseconds(std::numeric_limits<double>::infinity()), std::invalid_argument);
  EXPECT_THROW(durationNanoseconds(3e9), std::invalid_argument);
}

TEST(PeriodDue, FallsDueOnTheStepMeantEvenForPeriodsOfNoWholeNanoseconds) {
  EXPECT_TRUE(periodDue(0, 10000000, 0.02));  // never done
  EXPECT_FALSE(periodDue(10000000, 20000000, 0.02));
  EXPECT_TRUE(periodDue(10000000, 30000000, 0.02));
  EXPECT_TRUE(periodDue(30000000, 20000000, 0.02));  // time went back
  // 1/3 s is 333333333.33 ns: three 1 ns clock steps short of it still count as the period.
  EXPECT_TRUE(periodDue(1, 1 + 333333333, 1.0 / 3));
  EXPECT_FALSE(periodDue(1, 1 + 333333332, 1.0 / 3));
}

TEST(WithinTimeout, IsFreshFromItsTimeThroughTheTimeoutAndNotBefore) {
  EXPECT_TRUE(withinTimeout(10000000, 10000000, 0.5));
  EXPECT_TRUE(withinTimeout(10000000, 510000000, 0.5));
  EXPECT_FALSE(withinTimeout(10000000, 510000001, 0.5));
  EXPECT_FALSE(withinTimeout(10000000, 9999999, 0.5));  // accepted in the future
}

}  // namespace
}  // namespace spherical_robots

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
