// SampledNormaLoop, the Norma stack's loop as lock-step samples it: its first steps equal the
// same core pieces called by hand in the order docs/lockstep.md gives; the actuators' limits
// hold; stale efforts leave a robot at rest at rest; the step count is the stack's (60 s: 60,001
// states, as the stack publishes); with a tiny step it approaches the continuous closed loop;
// bad configurations are rejected, naming the field. And LoopTimeline, the rule it shares with
// every plant node.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/config/norma_description.hpp"
#include "spherical_robots/config/robot_description.hpp"
#include "spherical_robots/core/loop_timeline.hpp"
#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/norma/sampled_norma_loop.hpp"

namespace norma = spherical_robots::norma;
using spherical_robots::ClockStep;
using spherical_robots::LoopTimeline;
using spherical_robots::Nanoseconds;
using spherical_robots::stampSeconds;

namespace {

constexpr Nanoseconds kMillisecond = 1000000;

norma::NormaParameters normaParameters() {
  namespace config = spherical_robots::config;
  return config::normaParametersFromUrdf(
      config::readTextFile(std::string(SPHERICAL_ROBOTS_SOURCE_DIR) + "/urdf/norma.urdf"));
}

// The state as norma_controller reads it: q, q̇ from joint_states, X, Y from odom, and ψ as the
// heading (yawOf) of the orientation norma_plant publishes (a turn by ψ about z).
norma::NormaMeasurement measurementOf(const norma::NormaState& state) {
  const Eigen::Quaterniond published(Eigen::AngleAxisd(state.psi, Eigen::Vector3d::UnitZ()));
  return {state.q, state.qd, state.x, state.y, spherical_robots::yawOf(published)};
}

void expectSameState(const norma::NormaState& a, const norma::NormaState& b, int step) {
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(a.q(i), b.q(i)) << "q" << i << " at step " << step;
    EXPECT_EQ(a.qd(i), b.qd(i)) << "qd" << i << " at step " << step;
  }
  EXPECT_EQ(a.x, b.x) << step;
  EXPECT_EQ(a.y, b.y) << step;
  EXPECT_EQ(a.psi, b.psi) << step;
}

// Steps 1-3 by hand, in the documented order, from the pieces the nodes call: the plant's first
// tick only starts; the controller works on the state stamped t (absolute seconds); the hardware
// takes the command at t and updates to t; the next step advances the plant by the difference of
// the stamps with those efforts held. The torque limit is set below the first command, so the
// applied torque must be exactly the limit.
TEST(SampledNormaLoop, FirstStepsAreTheNodesCoreCallsInTheirOrder) {
  norma::SampledLoopConfig config;
  config.controller = norma::ControllerKind::kPaper;
  config.limits = {1.0, 200.0};
  config.duration = 1.0;
  const norma::NormaParameters parameters = normaParameters();
  norma::SampledNormaLoop loop(parameters, config);

  const norma::NormaDynamics dynamics(parameters, config.variant);
  norma::NormaControlLoop controller(norma::NormaController(parameters, config.controller),
                                     config.limits);
  spherical_robots::hardware::ActuatorLimits torque_limit, force_limit;
  torque_limit.kind = force_limit.kind = spherical_robots::hardware::ActuatorKind::Effort;
  torque_limit.max_effort = 1.0;
  force_limit.max_effort = 200.0;
  spherical_robots::hardware::SimulatedActuators actuators(
      {"pendulum_motor", "slider_motor"}, {torque_limit, force_limit}, 0.1);
  norma::NormaState state;
  state.psi = std::atan2(0.03, 0.02);
  norma::Efforts applied;

  for (int k = 1; k <= 3; ++k) {
    const Nanoseconds now = k * kMillisecond;
    if (k > 1) {
      controller.actuatorsApplied(applied.torque, applied.force);
      state = norma::advanceWithHeldInputs(dynamics, state, applied.torque, applied.force,
                                           stampSeconds(now - (k - 1) * kMillisecond), 0.001);
    }
    const norma::ControlOutput command = controller.step(stampSeconds(now), measurementOf(state));
    ASSERT_EQ(actuators.command({"pendulum_motor", "slider_motor"}, {command.torque, command.force},
                                stampSeconds(now)), "");
    actuators.update(stampSeconds(now));
    const norma::Efforts driving = applied;
    applied = {actuators.efforts()[0], actuators.efforts()[1]};

    const norma::SampledStep& step = loop.step();
    EXPECT_EQ(step.time, now);
    expectSameState(step.state, state, k);
    ASSERT_TRUE(step.command.has_value());
    EXPECT_EQ(step.command->torque, command.torque) << k;
    EXPECT_EQ(step.command->force, command.force) << k;
    EXPECT_EQ(step.applied.torque, applied.torque) << k;
    EXPECT_EQ(step.applied.force, applied.force) << k;
    EXPECT_EQ(step.driving.torque, k == 1 ? 0.0 : driving.torque) << k;
  }
  // The paper's first command, T = 10 sqrt(0.0013) / 0.2 = 1.80 N m (eq 51 and PID1, PID2 at
  // rest), is above the 1 N m limit: the plant was driven by exactly 1 N m.
  EXPECT_GT(loop.latest().command->torque, 1.0);
  EXPECT_EQ(loop.latest().driving.torque, 1.0);
  EXPECT_GT(loop.latest().state.qd(1), 0.0);  // the pendulum swings up under it
}

// With efforts older than state_timeout as soon as they come (a timeout below the step), nothing
// drives the plant: a robot at rest stays exactly at rest, whatever the controller commands.
TEST(SampledNormaLoop, StaleEffortsLeaveTheRobotAtRest) {
  norma::SampledLoopConfig config;
  config.controller = norma::ControllerKind::kTracking;
  config.state_timeout = 0.0005;
  config.duration = 0.1;
  norma::SampledNormaLoop loop(normaParameters(), config);
  int steps = 0;
  while (!loop.complete()) {
    const norma::SampledStep& step = loop.step();
    ++steps;
    EXPECT_EQ(step.driving.torque, 0.0);
    EXPECT_EQ(step.driving.force, 0.0);
    EXPECT_NE(step.applied.torque, 0.0);  // commanded and applied, but never fresh at the plant
    for (int i = 0; i < 4; ++i) EXPECT_EQ(step.state.q(i), 0.0);
    EXPECT_EQ(step.state.x, 0.0);
    EXPECT_EQ(step.state.psi, config.initial_psi);
  }
  EXPECT_EQ(steps, 101);
}

// The stack's plant publishes duration / step + 1 states (5 s: 5,001, measured by
// test/norma_batch_equality.test's script): the first at the first step, the last at duration
// after it. Rows every 10 steps fall at whole 10 ms since the first step.
TEST(SampledNormaLoop, RunsAndLogsTheStacksSteps) {
  norma::SampledLoopConfig config;
  config.duration = 5.0;
  const std::vector<norma::NormaSample> every = norma::runSampledLoop(normaParameters(), config, 1);
  ASSERT_EQ(every.size(), 5001u);
  const std::vector<norma::NormaSample> tenth = norma::runSampledLoop(normaParameters(), config, 10);
  ASSERT_EQ(tenth.size(), 501u);
  for (std::size_t i = 0; i < tenth.size(); ++i) {
    EXPECT_EQ(tenth[i].t, stampSeconds(static_cast<Nanoseconds>(i) * 10 * kMillisecond));
    EXPECT_EQ(tenth[i].x, every[10 * i].x);
  }
  EXPECT_EQ(every.back().t, 5.0);
  config.duration = 0.0;  // the first step only
  EXPECT_EQ(norma::runSampledLoop(normaParameters(), config, 1).size(), 1u);
}

// The sample-and-hold loop approaches the continuous closed loop (runClosedLoop, rosenbrock4 at
// tight tolerances, an independent integration) as its step shrinks: at 2 s the centre is within
// a few micrometres with 0.1 ms steps, and ten times closer than with 1 ms steps.
TEST(SampledNormaLoop, TinyStepApproachesTheContinuousLoop) {
  const norma::NormaParameters parameters = normaParameters();
  norma::ClosedLoopConfig continuous;
  continuous.controller = norma::ControllerKind::kTracking;
  continuous.duration = 2.0;
  continuous.log_rate = 1.0;
  continuous.ode.rtol = continuous.ode.atol = 1e-11;
  const norma::NormaSample truth = norma::runClosedLoop(parameters, continuous).back();
  auto distanceAt = [&](double step) {
    norma::SampledLoopConfig config;
    config.controller = norma::ControllerKind::kTracking;
    config.step = step;
    config.duration = 2.0;
    const norma::NormaSample end = norma::runSampledLoop(parameters, config, 1).back();
    EXPECT_EQ(end.t, 2.0);
    return std::hypot(end.x - truth.x, end.y - truth.y);
  };
  const double coarse = distanceAt(0.001), fine = distanceAt(0.0001);
  EXPECT_GT(std::hypot(truth.x, truth.y), 0.05);  // it moved
  EXPECT_LT(fine, 5e-6);
  EXPECT_LT(fine, 0.2 * coarse);
}

TEST(SampledNormaLoop, RejectsBadConfigurations) {
  const norma::NormaParameters parameters = normaParameters();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto with = [](auto change) {
    norma::SampledLoopConfig config;
    change(config);
    return config;
  };
  using Config = norma::SampledLoopConfig;
  EXPECT_INVALID_ARGUMENT(norma::SampledNormaLoop(parameters, with([](Config& c) { c.step = 0.0; })),
                          "step");
  EXPECT_INVALID_ARGUMENT(norma::SampledNormaLoop(parameters, with([](Config& c) { c.step = 6.0; })),
                          "max_clock_step");
  EXPECT_INVALID_ARGUMENT(
      norma::SampledNormaLoop(parameters, with([](Config& c) {
                                             c.step = 1e-12;
                                             c.duration = 0.0;
                                           })),
      "1 ns");
  EXPECT_INVALID_ARGUMENT(
      norma::SampledNormaLoop(parameters, with([&](Config& c) { c.step = nan; })), "step");
  EXPECT_INVALID_ARGUMENT(
      norma::SampledNormaLoop(parameters, with([](Config& c) { c.state_timeout = 0.0; })),
      "state_timeout");
  EXPECT_INVALID_ARGUMENT(
      norma::SampledNormaLoop(parameters, with([](Config& c) { c.duration = -1.0; })), "duration");
  EXPECT_INVALID_ARGUMENT(
      norma::SampledNormaLoop(parameters, with([&](Config& c) { c.duration = nan; })), "duration");
  EXPECT_INVALID_ARGUMENT(
      norma::SampledNormaLoop(parameters, with([](Config& c) { c.limits.max_torque = -1.0; })),
      "max_torque");
  EXPECT_INVALID_ARGUMENT(
      norma::SampledNormaLoop(parameters, with([](Config& c) { c.command_timeout = 0.0; })),
      "timeout");
  EXPECT_INVALID_ARGUMENT(
      norma::SampledNormaLoop(parameters, with([&](Config& c) { c.initial_psi = nan; })), "psi");
  EXPECT_INVALID_ARGUMENT(
      norma::SampledNormaLoop(parameters, with([](Config& c) { c.duration = 1e300; })), "1e+300");
  EXPECT_INVALID_ARGUMENT(norma::runSampledLoop(parameters, {}, 0), "steps per logged row");

  norma::SampledNormaLoop loop(parameters, with([](Config& c) { c.duration = 0.001; }));
  loop.step();
  loop.step();
  EXPECT_TRUE(loop.complete());
  EXPECT_THROW(loop.step(), std::logic_error);
}

// The plant loop's rules: the first tick starts (a tick at 0, no clock yet, does not); a later
// one advances by the difference of the stamps as ros::Duration::toSec() gives it; the same time
// again holds, a jump (back, or forward beyond max_clock_step) holds too; the scenario is
// complete duration after the first tick.
TEST(LoopTimeline, StartsAdvancesHoldsAndCompletes) {
  LoopTimeline timeline(0.003, 5.0);
  EXPECT_TRUE(timeline.tick(0).starts);
  EXPECT_FALSE(timeline.started());
  const LoopTimeline::Tick first = timeline.tick(kMillisecond);
  EXPECT_TRUE(first.starts);
  EXPECT_FALSE(first.advances());
  EXPECT_EQ(timeline.start(), kMillisecond);
  const LoopTimeline::Tick second = timeline.tick(2 * kMillisecond);
  EXPECT_TRUE(second.advances());
  EXPECT_EQ(second.elapsed, 1e-9 * 1e6);  // ros::Duration(0, 1000000).toSec()
  EXPECT_EQ(timeline.tick(2 * kMillisecond).clock, ClockStep::kHold);
  EXPECT_FALSE(timeline.tick(kMillisecond).advances());  // back
  EXPECT_EQ(timeline.clock().jumps(), 1u);
  const LoopTimeline::Tick far = timeline.tick(6 * spherical_robots::Nanoseconds{1000000000});
  EXPECT_EQ(far.clock, ClockStep::kJumpForward);
  EXPECT_FALSE(far.advances());

  LoopTimeline run(0.003, 5.0);
  run.tick(kMillisecond);
  EXPECT_FALSE(run.complete(3 * kMillisecond));
  EXPECT_TRUE(run.complete(4 * kMillisecond));
  EXPECT_TRUE(run.finished());
  LoopTimeline forever(0.0, 5.0);
  forever.tick(kMillisecond);
  EXPECT_FALSE(forever.complete(1000 * kMillisecond));
  EXPECT_INVALID_ARGUMENT(LoopTimeline(1.0, 0.0), "max_clock_step");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
