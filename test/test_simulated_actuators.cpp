// SimulatedActuators against closed forms: constant-acceleration ramps, clamps, trapezoid
// positions, the command-timeout watchdog, rejected commands, e-stop; the actuator models
// (first-order lag, dead time, encoder quantisation, velocity noise).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/hardware/simulated_actuators.hpp"
#include "expect_invalid_argument.hpp"

using spherical_robots::hardware::ActuatorKind;
using spherical_robots::hardware::ActuatorLimits;
using spherical_robots::hardware::ActuatorModel;
using spherical_robots::hardware::SimulatedActuators;

namespace {

constexpr double kTol = 1e-12;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Three actuators with max_velocity 10 rad/s, max_acceleration 20 rad/s^2, timeout 0.5 s; the
// clock starts at t = 0.
SimulatedActuators makeActuators(double max_velocity = 10.0, double max_acceleration = 20.0,
                                 double timeout = 0.5) {
  SimulatedActuators actuators({"theta", "phi", "psi"},
                               std::vector<ActuatorLimits>(3, {max_velocity, max_acceleration}),
                               timeout);
  actuators.update(0.0);
  return actuators;
}

// Steps the clock from `from` to `to` in increments of dt (the last one may be shorter).
void stepTo(SimulatedActuators& actuators, double from, double to, double dt) {
  for (double t = from + dt; t < to; t += dt) actuators.update(t);
  actuators.update(to);
}

// Position of an actuator starting at rest at t = 0 with a step set-point v (|v| <= max_velocity)
// under acceleration limit a: v(t) = a t up to T = |v|/a, then v.
double rampPosition(double v, double a, double t) {
  const double ramp_time = std::abs(v) / a;
  const double sign = v >= 0.0 ? 1.0 : -1.0;
  if (t <= ramp_time) return sign * 0.5 * a * t * t;
  return sign * 0.5 * a * ramp_time * ramp_time + v * (t - ramp_time);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST(SimulatedActuators, StartsAtRest) {
  auto actuators = makeActuators();
  actuators.update(1.0);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(actuators.velocities()[i], 0.0);
    EXPECT_EQ(actuators.positions()[i], 0.0);
  }
  EXPECT_FALSE(actuators.hasCommand());
  EXPECT_FALSE(actuators.timedOut());
}

TEST(SimulatedActuators, StepSetPointRampsAtExactlyMaxAcceleration) {
  auto actuators = makeActuators(10.0, 20.0, 100.0);
  ASSERT_EQ(actuators.command({"theta", "phi"}, {5.0, -3.0}, 0.0), "");
  for (double t : {0.01, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 1.0}) {
    actuators.update(t);
    EXPECT_NEAR(actuators.velocities()[0], std::min(20.0 * t, 5.0), kTol) << "t = " << t;
    EXPECT_NEAR(actuators.velocities()[1], -std::min(20.0 * t, 3.0), kTol) << "t = " << t;
    EXPECT_EQ(actuators.velocities()[2], 0.0);
  }
}

TEST(SimulatedActuators, SetPointClampedAtMaxVelocity) {
  auto actuators = makeActuators(10.0, 20.0, 100.0);
  // 100 times the limit is still a (clamped) set-point; beyond it, see the next test.
  ASSERT_EQ(actuators.command({"theta", "psi"}, {100.0, -1000.0}, 0.0), "");
  EXPECT_EQ(actuators.setpoints()[0], 10.0);
  EXPECT_EQ(actuators.setpoints()[2], -10.0);
  stepTo(actuators, 0.0, 2.0, 0.01);
  EXPECT_EQ(actuators.velocities()[0], 10.0);
  EXPECT_EQ(actuators.velocities()[2], -10.0);
  // Ramp to the clamp in 10/20 = 0.5 s, then 1.5 s at 10 rad/s.
  EXPECT_NEAR(actuators.positions()[0], 0.5 * 20.0 * 0.25 + 10.0 * 1.5, 1e-9);
}

TEST(SimulatedActuators, PositionIsTheTrapezoidIntegralWhateverTheStep) {
  for (double dt : {0.001, 0.0137, 0.1, 0.4, 3.0}) {
    auto actuators = makeActuators(10.0, 20.0, 100.0);
    ASSERT_EQ(actuators.command({"theta", "phi", "psi"}, {7.0, -2.5, 10.0}, 0.0), "");
    double t = 0.0;
    while (t < 3.0) {
      t = std::min(t + dt, 3.0);
      actuators.update(t);
      EXPECT_NEAR(actuators.positions()[0], rampPosition(7.0, 20.0, t), 1e-9) << "dt " << dt;
      EXPECT_NEAR(actuators.positions()[1], rampPosition(-2.5, 20.0, t), 1e-9) << "dt " << dt;
      EXPECT_NEAR(actuators.positions()[2], rampPosition(10.0, 20.0, t), 1e-9) << "dt " << dt;
    }
  }
}

TEST(SimulatedActuators, SetPointChangeRampsFromTheCurrentVelocity) {
  auto actuators = makeActuators(10.0, 20.0, 100.0);
  ASSERT_EQ(actuators.command({"theta"}, {4.0}, 0.0), "");
  actuators.update(1.0);
  ASSERT_EQ(actuators.command({"theta"}, {-4.0}, 1.0), "");
  actuators.update(1.2);
  EXPECT_NEAR(actuators.velocities()[0], 0.0, kTol);
  actuators.update(1.5);
  EXPECT_NEAR(actuators.velocities()[0], -4.0, kTol);
  // 3.6 rad by t = 1 (0.2 s ramp, 0.8 s at 4 rad/s); the reversal 1.0..1.4 s is symmetric
  // about v = 0 (no net travel); then 0.1 s at -4 rad/s.
  EXPECT_NEAR(actuators.positions()[0], 3.6 - 0.4, 1e-12);
}

// diff_drive_controller's classic: a 1 rad/s command, then silence; with a 0.5 s timeout the
// set-point drops to 0 at t = 0.5 and the ramp down takes v/a.
TEST(SimulatedActuators, WatchdogBringsActuatorsToRestAfterTimeout) {
  const double v = 1.0, a = 20.0, timeout = 0.5;
  for (double dt : {0.001, 0.01, 0.07, 2.0}) {
    auto actuators = makeActuators(10.0, a, timeout);
    ASSERT_EQ(actuators.command({"theta"}, {v}, 0.0), "");
    actuators.update(timeout - 1e-9);
    EXPECT_FALSE(actuators.timedOut());
    EXPECT_NEAR(actuators.velocities()[0], v, kTol);
    stepTo(actuators, timeout - 1e-9, 2.0, dt);
    EXPECT_TRUE(actuators.timedOut()) << "dt " << dt;
    EXPECT_EQ(actuators.velocities()[0], 0.0) << "dt " << dt;
    EXPECT_EQ(actuators.setpoints()[0], 0.0);
    // Ramp up loses v^2/(2a), ramp down gains it back: travel is exactly v * timeout, and in any
    // case below the bound v (timeout + v/a).
    EXPECT_NEAR(actuators.positions()[0], v * timeout, 1e-9) << "dt " << dt;
    EXPECT_LT(actuators.positions()[0], v * (timeout + v / a));
  }
}

TEST(SimulatedActuators, ATimeoutAfterACommandToRestStopsNothing) {
  // The last command asked every actuator for rest: the watchdog fires, but changes nothing.
  auto resting = makeActuators(10.0, 20.0, 0.5);
  ASSERT_EQ(resting.command({"theta", "phi", "psi"}, {2.0, -1.0, 0.5}, 0.0), "");
  ASSERT_EQ(resting.command({"theta", "phi", "psi"}, {0.0, 0.0, 0.0}, 1.0), "");
  resting.update(1.4);
  EXPECT_FALSE(resting.timedOut());
  EXPECT_FALSE(resting.timedOutAtRest());
  resting.update(2.0);
  EXPECT_TRUE(resting.timedOut());
  EXPECT_TRUE(resting.timedOutAtRest());
  // One actuator still asked to move (the others unmentioned keep their last set-point): the
  // watchdog stopped it.
  auto moving = makeActuators(10.0, 20.0, 0.5);
  ASSERT_EQ(moving.command({"theta", "phi", "psi"}, {0.0, 0.0, 0.0}, 0.0), "");
  ASSERT_EQ(moving.command({"phi"}, {1.0}, 0.1), "");
  moving.update(2.0);
  EXPECT_TRUE(moving.timedOut());
  EXPECT_FALSE(moving.timedOutAtRest());
  // A command clears both.
  ASSERT_EQ(resting.command({"theta"}, {0.0}, 2.0), "");
  EXPECT_FALSE(resting.timedOut());
  EXPECT_FALSE(resting.timedOutAtRest());
}

TEST(SimulatedActuators, WatchdogRampDownFollowsTheClosedForm) {
  auto actuators = makeActuators(10.0, 20.0, 0.5);
  ASSERT_EQ(actuators.command({"phi"}, {8.0}, 0.0), "");
  // Up to 8 rad/s by 0.4 s, held to 0.5 s, down at 20 rad/s^2 until 0.9 s.
  actuators.update(0.6);
  EXPECT_NEAR(actuators.velocities()[1], 8.0 - 20.0 * 0.1, kTol);
  actuators.update(0.9);
  EXPECT_NEAR(actuators.velocities()[1], 0.0, kTol);
  EXPECT_NEAR(actuators.positions()[1], 0.5 * 8.0 * 0.4 + 8.0 * 0.1 + 0.5 * 8.0 * 0.4, 1e-12);
}

TEST(SimulatedActuators, FreshCommandsKeepTheWatchdogQuiet) {
  auto actuators = makeActuators(10.0, 20.0, 0.5);
  for (double t = 0.0; t < 5.0; t += 0.4) {
    ASSERT_EQ(actuators.command({"theta"}, {2.0}, t), "");
    actuators.update(t + 0.399);
    EXPECT_FALSE(actuators.timedOut()) << "t = " << t;
    EXPECT_NEAR(actuators.velocities()[0], 2.0, kTol);
  }
  // A command after a timeout is accepted and clears it.
  actuators.update(10.0);
  ASSERT_TRUE(actuators.timedOut());
  ASSERT_EQ(actuators.command({"theta"}, {1.0}, 10.0), "");
  EXPECT_FALSE(actuators.timedOut());
  actuators.update(10.2);
  EXPECT_NEAR(actuators.velocities()[0], 1.0, kTol);
}

TEST(SimulatedActuators, BadCommandsAreRejectedWithAReasonAndChangeNothing) {
  struct Case {
    std::vector<std::string> names;
    std::vector<double> velocities;
    double t;
    std::string reason;
  };
  const std::vector<Case> cases = {
      {{"theta"}, {kNaN}, 0.2, "non-finite"},
      {{"theta", "phi"}, {1.0, kInf}, 0.2, "non-finite"},
      {{"theta"}, {-kInf}, 0.2, "non-finite"},
      {{"theta", "bogus"}, {1.0, 2.0}, 0.2, "unknown actuator 'bogus'"},
      {{"theta", "phi"}, {1.0}, 0.2, "2 names but 1 set-points"},
      {{"theta"}, {}, 0.2, "1 names but 0 set-points"},
      {{}, {}, 0.2, "no actuator"},
      {{"phi", "phi"}, {1.0, 1.0}, 0.2, "named twice"},
      {{"theta"}, {1.0}, kNaN, "non-finite command time"},
  };
  for (const auto& c : cases) {
    auto actuators = makeActuators(10.0, 20.0, 0.5);
    ASSERT_EQ(actuators.command({"theta", "phi"}, {3.0, -1.0}, 0.0), "");
    actuators.update(0.1);
    const auto setpoints = actuators.setpoints();
    const auto velocities = actuators.velocities();
    const auto positions = actuators.positions();
    const std::string reason = actuators.command(c.names, c.velocities, c.t);
    EXPECT_TRUE(contains(reason, c.reason)) << "got '" << reason << "', want '" << c.reason << "'";
    EXPECT_EQ(actuators.setpoints(), setpoints) << c.reason;
    EXPECT_EQ(actuators.velocities(), velocities) << c.reason;
    EXPECT_EQ(actuators.positions(), positions) << c.reason;
    // Nor did it refresh the watchdog: the first command's deadline (0.5 s) still holds.
    actuators.update(0.5);
    EXPECT_TRUE(actuators.timedOut()) << c.reason;
  }
}

TEST(SimulatedActuators, TimeGoingBackwardsIsIgnored) {
  auto actuators = makeActuators(10.0, 20.0, 100.0);
  ASSERT_EQ(actuators.command({"theta"}, {2.0}, 0.0), "");
  actuators.update(1.0);
  const double position = actuators.positions()[0];
  actuators.update(0.5);
  actuators.update(kNaN);
  actuators.update(-kInf);
  EXPECT_EQ(actuators.positions()[0], position);
  actuators.update(1.1);
  EXPECT_NEAR(actuators.positions()[0], rampPosition(2.0, 20.0, 1.1), 1e-12);
}

TEST(SimulatedActuators, ImplausibleSetPointsAreRejectedNotClampedAndChangeNothing) {
  auto actuators = makeActuators(10.0, 20.0, 0.5);
  ASSERT_EQ(actuators.command({"theta"}, {2.0}, 0.0), "");
  for (double huge : {1e300, -1e300, 1000.000001}) {
    const std::string reason = actuators.command({"phi", "theta"}, {1.0, huge}, 0.1);
    EXPECT_TRUE(contains(reason, "'theta'") && contains(reason, "100 times its limit 10"))
        << reason;
  }
  // The rejected commands touched nothing: not phi's set-point, not the watchdog (0.5 s after the
  // accepted command at 0, not after the rejected ones at 0.1).
  EXPECT_EQ(actuators.setpoints()[0], 2.0);
  EXPECT_EQ(actuators.setpoints()[1], 0.0);
  actuators.update(0.5);
  EXPECT_TRUE(actuators.timedOut());
}

TEST(SimulatedActuators, RebaseAfterAClockJumpTakesNoTimeAsElapsed) {
  // A stray /clock 1000 s ahead, then back: the actuators neither integrate 1000 s nor freeze
  // until the clock reaches 1000 s again.
  auto actuators = makeActuators(10.0, 20.0, 0.5);
  ASSERT_EQ(actuators.command({"theta"}, {2.0}, 0.0), "");
  actuators.update(0.2);
  const double position = actuators.positions()[0];
  const double velocity = actuators.velocities()[0];
  actuators.rebase(1000.2);
  EXPECT_EQ(actuators.positions()[0], position);
  EXPECT_EQ(actuators.velocities()[0], velocity);
  EXPECT_FALSE(actuators.timedOut());
  EXPECT_NEAR(actuators.commandAge(), 0.2, kTol);
  actuators.rebase(0.21);
  EXPECT_EQ(actuators.now(), 0.21);
  EXPECT_NEAR(actuators.commandAge(), 0.2, kTol);
  // Commands and time go on from the rebased clock: the ramp continues from where it was.
  ASSERT_EQ(actuators.command({"theta"}, {2.0}, 0.31), "");
  EXPECT_NEAR(actuators.positions()[0], rampPosition(2.0, 20.0, 0.3), 1e-12);
  actuators.update(0.81);
  EXPECT_TRUE(actuators.timedOut());  // 0.5 s after the command at 0.31, in rebased time
}

TEST(SimulatedActuators, LateCommandTakesEffectAtTheLatestTimeSeen) {
  auto actuators = makeActuators(10.0, 20.0, 0.5);
  actuators.update(2.0);
  ASSERT_EQ(actuators.command({"theta"}, {1.0}, 1.0), "");
  // Watchdog restarted at 2.0, not 1.0.
  actuators.update(2.49);
  EXPECT_FALSE(actuators.timedOut());
  EXPECT_NEAR(actuators.velocities()[0], 1.0, kTol);
  actuators.update(2.5);
  EXPECT_TRUE(actuators.timedOut());
}

TEST(SimulatedActuators, StopZeroesImmediatelyAndHoldsPosition) {
  auto actuators = makeActuators(10.0, 20.0, 100.0);
  ASSERT_EQ(actuators.command({"theta", "phi", "psi"}, {5.0, -5.0, 1.0}, 0.0), "");
  actuators.update(1.0);
  actuators.stop(1.5);
  const auto positions = actuators.positions();
  EXPECT_NEAR(positions[0], rampPosition(5.0, 20.0, 1.5), 1e-12);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(actuators.velocities()[i], 0.0);
    EXPECT_EQ(actuators.setpoints()[i], 0.0);
  }
  actuators.update(3.0);
  EXPECT_EQ(actuators.positions(), positions);
  // The next command moves them again, from rest.
  ASSERT_EQ(actuators.command({"theta"}, {5.0}, 3.0), "");
  actuators.update(3.1);
  EXPECT_NEAR(actuators.velocities()[0], 2.0, kTol);
}

TEST(SimulatedActuators, EStopRejectsCommandsUntilReleased) {
  auto actuators = makeActuators(10.0, 20.0, 100.0);
  ASSERT_EQ(actuators.command({"theta"}, {5.0}, 0.0), "");
  actuators.update(1.0);
  actuators.setEStop(true, 1.0);
  EXPECT_TRUE(actuators.eStopped());
  EXPECT_EQ(actuators.velocities()[0], 0.0);
  EXPECT_TRUE(contains(actuators.command({"theta"}, {5.0}, 1.1), "e-stop engaged"));
  actuators.update(2.0);
  EXPECT_EQ(actuators.velocities()[0], 0.0);
  EXPECT_EQ(actuators.setpoints()[0], 0.0);

  actuators.setEStop(false, 2.0);
  EXPECT_FALSE(actuators.eStopped());
  actuators.update(2.5);
  EXPECT_EQ(actuators.velocities()[0], 0.0) << "release must not resume the old set-point";
  ASSERT_EQ(actuators.command({"theta"}, {5.0}, 2.5), "");
  actuators.update(2.6);
  EXPECT_NEAR(actuators.velocities()[0], 2.0, kTol);
}

TEST(SimulatedActuators, BadConstructorArgumentsThrowWithContext) {
  const std::vector<std::string> names = {"theta", "phi"};
  const std::vector<ActuatorLimits> good(2, {10.0, 20.0});
  EXPECT_NO_THROW(SimulatedActuators(names, good, 0.5));

  EXPECT_INVALID_ARGUMENT(SimulatedActuators({}, {}, 0.5), "no actuator names");
  EXPECT_INVALID_ARGUMENT(SimulatedActuators(names, {{10.0, 20.0}}, 0.5), "1 limit entries");
  EXPECT_INVALID_ARGUMENT(SimulatedActuators({"theta", "theta"}, good, 0.5),
                          "'theta' appears twice");
  EXPECT_INVALID_ARGUMENT(SimulatedActuators({"theta", ""}, good, 0.5), "#1 is empty");
  for (double bad : {0.0, -1.0, kNaN, kInf}) {
    EXPECT_INVALID_ARGUMENT(SimulatedActuators(names, {{10.0, 20.0}, {bad, 20.0}}, 0.5),
                            "max_velocity of 'phi'")
        << bad;
    EXPECT_INVALID_ARGUMENT(SimulatedActuators(names, {{10.0, bad}, {10.0, 20.0}}, 0.5),
                            "max_acceleration of 'theta'")
        << bad;
    EXPECT_INVALID_ARGUMENT(SimulatedActuators(names, good, bad), "command_timeout") << bad;
  }
  EXPECT_INVALID_ARGUMENT(SimulatedActuators(names, {{-3.0, 20.0}, {10.0, 20.0}}, 0.5), "got -3");
}

// dynamic_reconfigure lowers the rate limit while an actuator runs at 8 rad/s: the set-point is
// clamped to the new 5 rad/s and the velocity ramps down to it at the new 4 rad/s^2 (closed form
// v(t) = 8 - 4 (t - 1) until 5, at t = 1.75 s), never jumps.
TEST(SimulatedActuators, LoweredLimitsClampTheSetPointAndTheVelocityRampsDown) {
  SimulatedActuators actuators = makeActuators(10.0, 20.0, 100.0);
  ASSERT_EQ(actuators.command({"theta"}, {8.0}, 0.0), "");
  actuators.update(1.0);
  ASSERT_NEAR(actuators.velocities()[0], 8.0, kTol);
  actuators.setLimits(std::vector<ActuatorLimits>(3, {5.0, 4.0}), 100.0, 1.0);
  EXPECT_NEAR(actuators.setpoints()[0], 5.0, kTol);
  EXPECT_NEAR(actuators.velocities()[0], 8.0, kTol);  // the velocity does not jump
  for (double t : {1.25, 1.5, 1.7}) {
    actuators.update(t);
    EXPECT_NEAR(actuators.velocities()[0], 8.0 - 4.0 * (t - 1.0), kTol) << t;
  }
  actuators.update(2.5);
  EXPECT_NEAR(actuators.velocities()[0], 5.0, kTol);
  // A later command is clamped to the new limit and counted as saturated.
  ASSERT_EQ(actuators.command({"phi"}, {9.0}, 2.5), "");
  EXPECT_NEAR(actuators.setpoints()[1], 5.0, kTol);
  EXPECT_EQ(actuators.saturations()[1], 1u);
}

// A shorter timeout moves the watchdog deadline to the last command + the new timeout.
TEST(SimulatedActuators, ANewCommandTimeoutMovesTheWatchdogDeadline) {
  SimulatedActuators actuators = makeActuators(10.0, 20.0, 5.0);
  ASSERT_EQ(actuators.command({"theta"}, {2.0}, 0.0), "");
  actuators.update(0.2);
  actuators.setLimits(actuators.limits(), 0.3, 0.2);
  actuators.update(0.29);
  EXPECT_FALSE(actuators.timedOut());
  actuators.update(0.31);
  EXPECT_TRUE(actuators.timedOut());
  EXPECT_DOUBLE_EQ(actuators.commandTimeout(), 0.3);
}

// The same rules as the constructor's, and a refused change changes nothing.
TEST(SimulatedActuators, BadLimitsAreRefusedAndChangeNothing) {
  SimulatedActuators actuators = makeActuators(10.0, 20.0, 0.5);
  ASSERT_EQ(actuators.command({"theta"}, {3.0}, 0.0), "");
  for (double bad : {0.0, -1.0, kNaN, kInf}) {
    EXPECT_INVALID_ARGUMENT(actuators.setLimits({{10.0, 20.0}, {bad, 20.0}, {10.0, 20.0}}, 0.5, 0.1),
                            "max_velocity of 'phi'")
        << bad;
    EXPECT_INVALID_ARGUMENT(actuators.setLimits(actuators.limits(), bad, 0.1), "command_timeout")
        << bad;
  }
  EXPECT_INVALID_ARGUMENT(actuators.setLimits({{10.0, 20.0}}, 0.5, 0.1), "1 limit entries");
  ActuatorLimits effort{10.0, 20.0, 2.0, ActuatorKind::Effort};
  EXPECT_INVALID_ARGUMENT(actuators.setLimits({effort, {10.0, 20.0}, {10.0, 20.0}}, 0.5, 0.1),
                          "'theta' cannot change between velocity and effort");
  EXPECT_EQ(actuators.now(), 0.0);  // refused before the clock moved
  EXPECT_DOUBLE_EQ(actuators.limits()[1].max_velocity, 10.0);
  EXPECT_DOUBLE_EQ(actuators.commandTimeout(), 0.5);
  EXPECT_DOUBLE_EQ(actuators.setpoints()[0], 3.0);
}

// ---- Actuator models ------------------------------------------------------------------------

namespace {

// Three actuators as in makeActuators, the same model for each; the clock starts at t = 0.
SimulatedActuators makeModelled(const ActuatorModel& model, double max_acceleration = 20.0,
                                double timeout = 100.0, std::uint32_t seed = 0) {
  SimulatedActuators actuators({"theta", "phi", "psi"},
                               std::vector<ActuatorLimits>(3, {10.0, max_acceleration}), timeout,
                               std::vector<ActuatorModel>(3, model), seed);
  actuators.update(0.0);
  return actuators;
}

ActuatorModel lag(double tau) {
  ActuatorModel model;
  model.time_constant = tau;
  return model;
}

}  // namespace

// With tau = 0.2 s and a = 100 rad/s^2 a step of 5 rad/s never saturates (5/0.2 = 25 < 100):
// v(t) = v_sp (1 - e^{-t/tau}), x(t) = v_sp (t - tau (1 - e^{-t/tau})), whatever the step.
TEST(SimulatedActuatorModels, LagStepResponseIsTheExponentialWhateverTheStep) {
  const double tau = 0.2, v_sp = 5.0;
  for (double dt : {0.001, 0.0137, 0.1, 0.4, 3.0}) {
    auto actuators = makeModelled(lag(tau), 100.0);
    ASSERT_EQ(actuators.command({"theta", "phi"}, {v_sp, -v_sp}, 0.0), "");
    double t = 0.0;
    while (t < 3.0) {
      t = std::min(t + dt, 3.0);
      actuators.update(t);
      const double v = v_sp * (1.0 - std::exp(-t / tau));
      const double x = v_sp * (t - tau * (1.0 - std::exp(-t / tau)));
      EXPECT_NEAR(actuators.velocities()[0], v, 1e-12) << "t " << t << " dt " << dt;
      EXPECT_NEAR(actuators.velocities()[1], -v, 1e-12) << "t " << t << " dt " << dt;
      EXPECT_NEAR(actuators.positions()[0], x, 1e-12) << "t " << t << " dt " << dt;
      EXPECT_EQ(actuators.velocities()[2], 0.0);
    }
  }
  // The named points of the step response: 63.2 % at tau, 95.0 % at 3 tau.
  auto actuators = makeModelled(lag(tau), 100.0);
  ASSERT_EQ(actuators.command({"theta"}, {v_sp}, 0.0), "");
  actuators.update(tau);
  EXPECT_NEAR(actuators.velocities()[0] / v_sp, 0.6321205588285577, 1e-12);
  actuators.update(3.0 * tau);
  EXPECT_NEAR(actuators.velocities()[0] / v_sp, 0.950212931632136, 1e-12);
}

// dv/dt = clamp((u - v)/tau, ±a): a step of 8 rad/s with tau = 0.2 s, a = 20 rad/s^2 ramps at a
// until u - v = a tau = 4 (t1 = 0.2 s), then v = u - 4 e^{-(t - t1)/tau}.
TEST(SimulatedActuatorModels, LagSaturatesAtMaxAcceleration) {
  const double tau = 0.2, a = 20.0, u = 8.0, t1 = (u - a * tau) / a;
  for (double dt : {0.001, 0.03, 0.5}) {
    auto actuators = makeModelled(lag(tau), a);
    ASSERT_EQ(actuators.command({"psi"}, {u}, 0.0), "");
    double t = 0.0;
    while (t < 2.0) {
      t = std::min(t + dt, 2.0);
      actuators.update(t);
      const double v = t <= t1 ? a * t : u - a * tau * std::exp(-(t - t1) / tau);
      const double x = t <= t1 ? 0.5 * a * t * t
                               : 0.5 * a * t1 * t1 + u * (t - t1) -
                                     a * tau * tau * (1.0 - std::exp(-(t - t1) / tau));
      EXPECT_NEAR(actuators.velocities()[2], v, 1e-12) << "t " << t << " dt " << dt;
      EXPECT_NEAR(actuators.positions()[2], x, 1e-12) << "t " << t << " dt " << dt;
    }
  }
}

TEST(SimulatedActuatorModels, DeadTimeDelaysTheSetPointThenTheRampStarts) {
  ActuatorModel model;
  model.dead_time = 0.3;
  for (double dt : {0.001, 0.07, 0.25}) {
    auto actuators = makeModelled(model, 20.0, 100.0);
    ASSERT_EQ(actuators.command({"theta"}, {5.0}, 0.0), "");
    EXPECT_EQ(actuators.setpoints()[0], 5.0);
    EXPECT_EQ(actuators.activeSetpoints()[0], 0.0);
    double t = 0.0;
    while (t < 2.0) {
      t = std::min(t + dt, 2.0);
      actuators.update(t);
      if (t < 0.3) {
        EXPECT_EQ(actuators.velocities()[0], 0.0) << "t " << t;
        EXPECT_EQ(actuators.positions()[0], 0.0) << "t " << t;
        EXPECT_EQ(actuators.activeSetpoints()[0], 0.0) << "t " << t;
      } else {
        EXPECT_EQ(actuators.activeSetpoints()[0], 5.0) << "t " << t;
      }
      EXPECT_NEAR(actuators.velocities()[0], std::clamp(20.0 * (t - 0.3), 0.0, 5.0), 1e-12)
          << "t " << t << " dt " << dt;
      EXPECT_NEAR(actuators.positions()[0], t < 0.3 ? 0.0 : rampPosition(5.0, 20.0, t - 0.3),
                  1e-12)
          << "t " << t << " dt " << dt;
    }
  }
}

TEST(SimulatedActuatorModels, DeadTimeThenLag) {
  ActuatorModel model = lag(0.1);
  model.dead_time = 0.05;
  auto actuators = makeModelled(model, 100.0);
  // Two commands in flight: 2 rad/s at 0 (active at 0.05), -1 rad/s at 0.02 (active at 0.07).
  ASSERT_EQ(actuators.command({"phi"}, {2.0}, 0.0), "");
  ASSERT_EQ(actuators.command({"phi"}, {-1.0}, 0.02), "");
  actuators.update(0.05);
  EXPECT_EQ(actuators.velocities()[1], 0.0);
  actuators.update(0.2);
  const double v_at_07 = 2.0 * (1.0 - std::exp(-0.02 / 0.1));
  EXPECT_NEAR(actuators.velocities()[1], -1.0 + (v_at_07 + 1.0) * std::exp(-0.13 / 0.1), 1e-12);
}

TEST(SimulatedActuatorModels, WatchdogAndStopAreNotDelayedAndDropPendingSetPoints) {
  ActuatorModel model;
  model.dead_time = 0.3;
  auto actuators = makeModelled(model, 20.0, 0.5);
  ASSERT_EQ(actuators.command({"theta"}, {5.0}, 0.0), "");
  ASSERT_EQ(actuators.command({"theta"}, {2.0}, 0.4), "");  // active at 0.7
  // Up from 0.3 at 20 rad/s^2 (5 by 0.55); 2 becomes active at 0.7, before the deadline 0.9.
  actuators.update(0.7);
  EXPECT_NEAR(actuators.velocities()[0], 5.0, 1e-12);
  EXPECT_EQ(actuators.activeSetpoints()[0], 2.0);
  ASSERT_EQ(actuators.command({"theta"}, {4.0}, 0.8), "");  // pending until 1.1
  actuators.update(1.3);  // deadline 1.3: velocity went 5 -> 2 by 0.85, held; now zero set-point
  EXPECT_TRUE(actuators.timedOut());
  EXPECT_EQ(actuators.activeSetpoints()[0], 0.0);
  EXPECT_NEAR(actuators.velocities()[0], 4.0, 1e-12);  // 2 -> 4 from 1.1 (0.1 s), held to 1.3
  actuators.update(1.5);
  EXPECT_NEAR(actuators.velocities()[0], 0.0, 1e-12);
  // stop() drops a pending set-point too.
  ASSERT_EQ(actuators.command({"theta"}, {3.0}, 2.0), "");
  actuators.stop(2.1);
  actuators.update(3.0);
  EXPECT_EQ(actuators.velocities()[0], 0.0);
  EXPECT_EQ(actuators.activeSetpoints()[0], 0.0);

  // A timeout shorter than the dead time: the watchdog (at 0.2) drops the set-point that would
  // have become active at 0.3, so the actuator never moves.
  auto slow = makeModelled(model, 20.0, 0.2);
  ASSERT_EQ(slow.command({"phi"}, {5.0}, 0.0), "");
  slow.update(0.2);
  EXPECT_TRUE(slow.timedOut());
  slow.update(1.0);
  EXPECT_EQ(slow.velocities()[1], 0.0);
  EXPECT_EQ(slow.positions()[1], 0.0);
}

TEST(SimulatedActuatorModels, QuantisedPositionIsAMultipleOfTheResolutionNearTheTrueOne) {
  ActuatorModel model;
  model.position_resolution = 2.0 * M_PI / 4096.0;  // a 12-bit encoder
  const double res = model.position_resolution;
  auto actuators = makeModelled(model);
  ASSERT_EQ(actuators.command({"theta", "phi", "psi"}, {3.3, -0.7, 0.01}, 0.0), "");
  bool differed = false;
  for (double t = 0.0137; t < 3.0; t += 0.0137) {
    actuators.update(t);
    for (std::size_t i = 0; i < 3; ++i) {
      const double reported = actuators.measuredPositions()[i];
      const double steps = reported / res;
      EXPECT_NEAR(steps, std::round(steps), 1e-9) << "t " << t;
      EXPECT_LE(std::abs(reported - actuators.positions()[i]), 0.5 * res + 1e-12) << "t " << t;
      differed = differed || reported != actuators.positions()[i];
      // Velocity reported as-is: quantisation touches positions only.
      EXPECT_EQ(actuators.measuredVelocities()[i], actuators.velocities()[i]);
    }
  }
  EXPECT_TRUE(differed);
  // The true state is the unquantised one: still the ramp's closed form.
  EXPECT_NEAR(actuators.positions()[0], rampPosition(3.3, 20.0, actuators.now()), 1e-9);
}

// N = 20000 samples of sigma = 0.5 rad/s on a constant true velocity: the sample mean is within
// 4 sigma/sqrt(N) of 0 and the sample standard deviation within 4 sigma/sqrt(2N) of sigma (the
// standard errors of the two estimates, 4 of them: deterministic anyway, the seed is fixed).
TEST(SimulatedActuatorModels, NoiseIsReproducibleGaussianAndLeavesTheTrueStateAlone) {
  ActuatorModel model;
  model.velocity_noise = 0.5;
  const double sigma = model.velocity_noise;
  auto a = makeModelled(model, 20.0, 1e6, 42);
  auto b = makeModelled(model, 20.0, 1e6, 42);
  auto other_seed = makeModelled(model, 20.0, 1e6, 43);
  auto ideal = makeModelled(ActuatorModel{}, 20.0, 1e6);
  for (auto* actuators : {&a, &b, &other_seed, &ideal})
    ASSERT_EQ(actuators->command({"theta", "phi"}, {2.0, -1.0}, 0.0), "");
  const int n = 20000;
  double sum = 0.0, sum_sq = 0.0;
  bool seeds_differ = false;
  for (int k = 1; k <= n; ++k) {
    const double t = 1.0 + 0.01 * k;  // at the set-points since t = 0.1
    for (auto* actuators : {&a, &b, &other_seed, &ideal}) actuators->update(t);
    ASSERT_EQ(a.measuredVelocities(), b.measuredVelocities()) << "sample " << k;
    seeds_differ = seeds_differ || a.measuredVelocities() != other_seed.measuredVelocities();
    ASSERT_EQ(a.velocities(), ideal.velocities());
    ASSERT_EQ(a.positions(), ideal.positions());
    ASSERT_EQ(a.measuredPositions(), a.positions());
    const double e = a.measuredVelocities()[0] - 2.0;
    sum += e;
    sum_sq += e * e;
  }
  EXPECT_TRUE(seeds_differ);
  const double mean = sum / n;
  const double std_dev = std::sqrt((sum_sq - n * mean * mean) / (n - 1));
  EXPECT_NEAR(mean, 0.0, 4.0 * sigma / std::sqrt(n));
  EXPECT_NEAR(std_dev, sigma, 4.0 * sigma / std::sqrt(2.0 * n));
}

// Explicit all-off models reproduce the ideal actuator bit for bit (and its closed forms), and
// the measurement is the true state.
// dynamic_reconfigure's server applies the start-up limits before the first update: that must
// not start the clock or draw noise, or the run would differ from its batch twin.
TEST(SimulatedActuatorModels, LimitsSetBeforeTheClockStartsDrawNoNoise) {
  ActuatorModel noisy;
  noisy.velocity_noise = 0.05;
  const auto make = [&] {
    return SimulatedActuators({"theta"}, {{10.0, 20.0}}, 100.0, {noisy}, 7);
  };
  SimulatedActuators plain = make();
  SimulatedActuators reconfigured = make();
  reconfigured.setLimits(reconfigured.limits(), 100.0, 0.0);  // the clock starts at 0.01 in both
  for (double t : {0.01, 0.02, 0.03}) {
    plain.update(t);
    reconfigured.update(t);
    EXPECT_EQ(plain.measuredVelocities()[0], reconfigured.measuredVelocities()[0]) << t;
  }
}

TEST(SimulatedActuatorModels, AllOffIsTheIdealActuatorExactly) {
  for (double dt : {0.001, 0.0137, 0.1, 0.4}) {
    auto ideal = makeActuators(10.0, 20.0, 0.5);
    auto off = makeModelled(ActuatorModel{}, 20.0, 0.5, 12345);
    for (auto* actuators : {&ideal, &off})
      ASSERT_EQ(actuators->command({"theta", "phi", "psi"}, {7.0, -2.5, 10.0}, 0.0), "");
    double t = 0.0;
    while (t < 2.0) {
      t = std::min(t + dt, 2.0);
      ideal.update(t);
      off.update(t);
      ASSERT_EQ(off.velocities(), ideal.velocities()) << "t " << t;
      ASSERT_EQ(off.positions(), ideal.positions()) << "t " << t;
      ASSERT_EQ(off.measuredVelocities(), off.velocities());
      ASSERT_EQ(off.measuredPositions(), off.positions());
      ASSERT_EQ(off.activeSetpoints(), off.setpoints());
      if (t <= 0.5) {
        EXPECT_NEAR(off.positions()[1], rampPosition(-2.5, 20.0, t), 1e-9);
      }
    }
    // The watchdog's closed form: 7 rad/s by 0.35 s, held to 0.5, down by 0.85.
    EXPECT_TRUE(off.timedOut());
    EXPECT_EQ(off.velocities()[0], 0.0);
    EXPECT_NEAR(off.positions()[0], 7.0 * 0.5, 1e-9);
  }
}

TEST(SimulatedActuatorModels, BadModelValuesAreRejectedNamingActuatorAndField) {
  const std::vector<std::string> names = {"theta", "phi"};
  const std::vector<ActuatorLimits> limits(2, {10.0, 20.0});
  const auto build = [&](std::vector<ActuatorModel> models) {
    SimulatedActuators(names, limits, 0.5, std::move(models));
  };
  EXPECT_NO_THROW(build({}));
  EXPECT_NO_THROW(build({ActuatorModel{}, {0.1, 0.02, 0.001, 0.3}}));
  EXPECT_INVALID_ARGUMENT(build({ActuatorModel{}}), "1 model entries");
  for (double bad : {-1e-9, -2.0, kNaN, kInf, -kInf}) {
    EXPECT_INVALID_ARGUMENT(build({ActuatorModel{}, {bad, 0, 0, 0}}), "time_constant of 'phi'")
        << bad;
    EXPECT_INVALID_ARGUMENT(build({{0, bad, 0, 0}, ActuatorModel{}}), "dead_time of 'theta'")
        << bad;
    EXPECT_INVALID_ARGUMENT(build({ActuatorModel{}, {0, 0, bad, 0}}),
                            "position_resolution of 'phi'")
        << bad;
    EXPECT_INVALID_ARGUMENT(build({{0, 0, 0, bad}, ActuatorModel{}}), "velocity_noise of 'theta'")
        << bad;
  }
  EXPECT_INVALID_ARGUMENT(build({ActuatorModel{}, {-2.0, 0, 0, 0}}), "got -2");
}

TEST(SimulatedActuators, CountsSaturatedSetPointsAndTheCommandAge) {
  auto actuators = makeActuators(10.0, 20.0, 100.0);
  EXPECT_TRUE(std::isnan(actuators.commandAge()));
  ASSERT_EQ(actuators.command({"theta", "phi"}, {12.0, -3.0}, 0.0), "");
  ASSERT_EQ(actuators.command({"theta"}, {-10.5}, 0.1), "");
  ASSERT_EQ(actuators.command({"theta"}, {10.0}, 0.2), "");  // at the limit: not clamped
  EXPECT_EQ(actuators.saturations()[0], 2u);
  EXPECT_EQ(actuators.saturations()[1], 0u);
  actuators.update(0.5);
  EXPECT_NEAR(actuators.commandAge(), 0.3, kTol);
}

namespace {

// Effort actuators (a torque motor "pendulum", a force motor "slider") beside a velocity one.
SimulatedActuators makeEffortActuators(double timeout = 0.5, double time_constant = 0.0,
                                       double dead_time = 0.0) {
  ActuatorLimits rate{10.0, 20.0};
  ActuatorLimits torque{10.0, 20.0, 2.0, ActuatorKind::Effort};
  ActuatorLimits force{10.0, 20.0, 50.0, ActuatorKind::Effort};
  const ActuatorModel model{time_constant, dead_time, 0.0, 0.0};
  SimulatedActuators actuators({"wheel", "pendulum", "slider"}, {rate, torque, force}, timeout,
                               {ActuatorModel{}, model, model});
  actuators.update(0.0);
  return actuators;
}

}  // namespace

TEST(SimulatedEffortActuators, ApplyTheClampedSetPointAtOnceAndNeverMove) {
  auto actuators = makeEffortActuators();
  ASSERT_EQ(actuators.command({"pendulum", "slider", "wheel"}, {1.5, -80.0, 4.0}, 0.0), "");
  EXPECT_EQ(actuators.efforts()[1], 1.5);
  EXPECT_EQ(actuators.efforts()[2], -50.0) << "clamped to max_effort, not max_velocity";
  EXPECT_EQ(actuators.setpoints()[2], -50.0);
  stepTo(actuators, 0.0, 0.3, 0.01);
  EXPECT_EQ(actuators.efforts()[1], 1.5);
  EXPECT_EQ(actuators.efforts()[0], 0.0) << "a velocity actuator applies no effort";
  EXPECT_NEAR(actuators.velocities()[0], 4.0, kTol) << "the velocity actuator ramps as before";
  EXPECT_EQ(actuators.velocities()[1], 0.0) << "the load's motion is the plant's, not known here";
  EXPECT_EQ(actuators.positions()[2], 0.0);
}

TEST(SimulatedEffortActuators, LagIsTheExponentialWhateverTheStep) {
  const double tau = 0.05;
  for (const double dt : {0.001, 0.01, 0.037}) {
    auto actuators = makeEffortActuators(100.0, tau);
    ASSERT_EQ(actuators.command({"pendulum"}, {1.0}, 0.0), "");
    stepTo(actuators, 0.0, 0.1, dt);
    EXPECT_NEAR(actuators.efforts()[1], 1.0 - std::exp(-0.1 / tau), 1e-12) << "dt " << dt;
  }
}

TEST(SimulatedEffortActuators, DeadTimeDelaysTheEffort) {
  auto actuators = makeEffortActuators(100.0, 0.0, 0.02);
  ASSERT_EQ(actuators.command({"slider"}, {10.0}, 0.0), "");
  actuators.update(0.019);
  EXPECT_EQ(actuators.efforts()[2], 0.0);
  actuators.update(0.021);
  EXPECT_EQ(actuators.efforts()[2], 10.0);
}

TEST(SimulatedEffortActuators, WatchdogAndEStopDropTheEffortAtOnceEvenWithALag) {
  auto actuators = makeEffortActuators(0.5, 0.05);
  ASSERT_EQ(actuators.command({"pendulum", "slider"}, {2.0, 30.0}, 0.0), "");
  actuators.update(0.499);
  EXPECT_GT(actuators.efforts()[1], 1.99);
  actuators.update(0.51);  // deadline 0.5 s: zero at the deadline, not through the 50 ms lag
  EXPECT_TRUE(actuators.timedOut());
  EXPECT_EQ(actuators.efforts()[1], 0.0);
  EXPECT_EQ(actuators.efforts()[2], 0.0);

  ASSERT_EQ(actuators.command({"slider"}, {30.0}, 0.6), "");
  actuators.update(0.8);
  EXPECT_GT(actuators.efforts()[2], 29.0);
  actuators.setEStop(true, 0.8);
  EXPECT_EQ(actuators.efforts()[2], 0.0);
  EXPECT_NE(actuators.command({"slider"}, {30.0}, 0.9), "");
  EXPECT_EQ(actuators.efforts()[2], 0.0);
}

TEST(SimulatedEffortActuators, NonFiniteEffortIsRejectedNamingIt) {
  auto actuators = makeEffortActuators();
  ASSERT_EQ(actuators.command({"slider"}, {5.0}, 0.0), "");
  const std::string reason = actuators.command({"slider"}, {kNaN}, 0.1);
  EXPECT_TRUE(contains(reason, "non-finite effort")) << reason;
  EXPECT_EQ(actuators.efforts()[2], 5.0) << "the last good set-point stands";
  EXPECT_INVALID_ARGUMENT(
      SimulatedActuators({"slider"}, {ActuatorLimits{1.0, 1.0, 0.0, ActuatorKind::Effort}}, 0.5),
      "max_effort");
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
