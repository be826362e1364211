// core/publication_rate.hpp against counts made by hand: a rate is events over the time of the
// last reports, in the caller's time, and a clock that stands still, goes back or a node with
// nothing to publish are not called faults.
#include <gtest/gtest.h>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/core/publication_rate.hpp"

namespace spherical_robots {
namespace {

constexpr Nanoseconds kSecond = 1000000000;

/// Ticks `rate` [Hz] for `seconds` and reports at the end; returns the report.
PublicationRate::Report publishFor(PublicationRate& rate, Nanoseconds& now, int per_second,
                                   int seconds, bool expected = true) {
  for (int i = 0; i < per_second * seconds; ++i) rate.tick();
  now += seconds * kSecond;
  return rate.report(now, expected);
}

TEST(PublicationRate, CountsEventsOverTheLastReports) {
  PublicationRate rate(50.0, 0.1, 3);
  Nanoseconds now = 0;
  EXPECT_EQ(rate.report(now, true).message, "measuring");
  // Report intervals of 10 s each (a lock-step run at 10 x real time, reporting every wall
  // second): 500 events per report.
  for (int k = 1; k <= 5; ++k) {
    const PublicationRate::Report report = publishFor(rate, now, 50, 10);
    const int reports_in_window = k < 3 ? k : 3;
    EXPECT_EQ(report.events, 500u * reports_in_window);
    EXPECT_DOUBLE_EQ(report.window, 10.0 * reports_in_window);
    ASSERT_TRUE(report.frequency);
    EXPECT_DOUBLE_EQ(*report.frequency, 50.0);
    EXPECT_EQ(report.level, HealthLevel::kOk) << report.message;
    EXPECT_EQ(report.total, 500u * k);
  }
}

TEST(PublicationRate, WarnsOutsideTheToleranceAndErrsWithoutEvents) {
  PublicationRate rate(100.0, 0.1, 1);
  Nanoseconds now = 0;
  rate.report(now, true);
  EXPECT_EQ(publishFor(rate, now, 91, 1).level, HealthLevel::kOk);   // 91 >= 90
  EXPECT_EQ(publishFor(rate, now, 89, 1).level, HealthLevel::kWarn);  // 89 < 90
  EXPECT_EQ(publishFor(rate, now, 111, 1).level, HealthLevel::kWarn);  // 111 > 110
  const PublicationRate::Report silent = publishFor(rate, now, 0, 1);
  EXPECT_EQ(silent.level, HealthLevel::kError);
  EXPECT_EQ(silent.events, 0u);
}

TEST(PublicationRate, AClockStandingStillIsNoFaultAndCountsNoTime) {
  PublicationRate rate(50.0, 0.1, 5);
  Nanoseconds now = 0;
  rate.report(now, true);
  publishFor(rate, now, 50, 2);
  // Paused for three reports: no events, no time.
  for (int k = 0; k < 3; ++k) {
    const PublicationRate::Report paused = rate.report(now, true);
    EXPECT_EQ(paused.level, HealthLevel::kOk);
    EXPECT_FALSE(paused.frequency);
  }
  // Measured from the pause on: 2 s at 50 Hz.
  const PublicationRate::Report resumed = publishFor(rate, now, 50, 2);
  EXPECT_EQ(resumed.events, 100u);
  EXPECT_DOUBLE_EQ(resumed.window, 2.0);
  EXPECT_EQ(resumed.level, HealthLevel::kOk);
}

TEST(PublicationRate, AClockGoingBackStartsAfresh) {
  PublicationRate rate(50.0, 0.1, 5);
  Nanoseconds now = 100 * kSecond;
  rate.report(now, true);
  publishFor(rate, now, 50, 2);
  now = 0;  // a replayed clock
  const PublicationRate::Report back = rate.report(now, true);
  EXPECT_EQ(back.level, HealthLevel::kOk);
  EXPECT_FALSE(back.frequency);
  const PublicationRate::Report after = publishFor(rate, now, 50, 1);
  EXPECT_EQ(after.events, 50u);
  EXPECT_DOUBLE_EQ(*after.frequency, 50.0);
}

TEST(PublicationRate, IdleSpellsAreNotCountedAsSilence) {
  PublicationRate rate(100.0, 0.1, 5);
  Nanoseconds now = 0;
  rate.report(now, false);
  const PublicationRate::Report idle = publishFor(rate, now, 0, 10, false);
  EXPECT_EQ(idle.level, HealthLevel::kOk);
  EXPECT_EQ(idle.message, "idle: nothing to publish");
  // A manoeuvre starts halfway through the next report interval: 0.5 s at 100 Hz. That interval
  // only starts the window; the rate is measured from its end.
  for (int i = 0; i < 50; ++i) rate.tick();
  now += kSecond;
  EXPECT_EQ(rate.report(now, true).level, HealthLevel::kOk);
  const PublicationRate::Report busy = publishFor(rate, now, 100, 1);
  EXPECT_EQ(busy.events, 100u);
  EXPECT_DOUBLE_EQ(*busy.frequency, 100.0);
}

TEST(PublicationRate, RefusesBadSettings) {
  EXPECT_INVALID_ARGUMENT(PublicationRate(0.0, 0.1), "target rate 0 Hz");
  EXPECT_INVALID_ARGUMENT(PublicationRate(50.0, 1.0), "rate tolerance 1");
  EXPECT_INVALID_ARGUMENT(PublicationRate(50.0, -0.1), "rate tolerance -0.1");
  EXPECT_INVALID_ARGUMENT(PublicationRate(50.0, 0.1, 0), "window of 0 reports");
}

}  // namespace
}  // namespace spherical_robots

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
