// The rotor manoeuvre executive (manoeuvre_executive.hpp), with no ROS master: its open-loop
// commands against the plan's set-points of eq 11 (planSetPointAt) at the sample times, the rules
// of the correction loop against measured rests given by hand, the rotor speed limit against its
// bound, and whole runs of the rotor stack's loop (sampled_rotor_loop.hpp) against the planner's
// target, as the plant itself integrates it.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <stdexcept>
#include <string>
#include <vector>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/config/actuator_models.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "spherical_robots/rotor/manoeuvre_executive.hpp"
#include "spherical_robots/rotor/sampled_rotor_loop.hpp"

namespace {

using namespace spherical_robots;
using namespace spherical_robots::rotor;

constexpr double kK = 2.5;
constexpr Nanoseconds kPeriod = 10'000'000;  // the command period, 10 ms
constexpr Nanoseconds kSecond = 1'000'000'000;

/// launch/rotor_stack.launch's plan: k = 2.5, n = 2, target (0.05 m, 0.03 m, 0.4 rad) = (0.5 R,
/// 0.3 R, 0.4 rad), radii up to 0.7 R.
PlanRequest stackRequest() { return {kK, 2, 0.5, 0.3, 0.4, 0.7, 0}; }

/// launch/rotor_stack.launch's rotor_planner.
ManoeuvreExecutive::Parameters stackParameters() {
  ManoeuvreExecutive::Parameters p;
  p.max_rotor_speed = 25.0;
  return p;
}

RestMeasurement restAt(double u_a, double v_a, double psi, double u_o = 0.0, double v_o = 0.0) {
  return {{u_a, v_a, psi}, Eigen::Vector2d(u_o, v_o), true};
}

/// Steps the executive every command period from `from` until an execution finishes (or for
/// `limit` steps): the sphere measured at `start` at the first step, at `rest` after it.
std::vector<ManoeuvreExecutive::Output> runWith(ManoeuvreExecutive& executive,
                                                const RestMeasurement& start,
                                                const RestMeasurement& rest, Nanoseconds from,
                                                int limit = 100000) {
  std::vector<ManoeuvreExecutive::Output> outputs;
  for (int i = 0; i < limit; ++i) {
    outputs.push_back(executive.step(from + i * kPeriod, i == 0 ? start : rest));
    if (outputs.back().ended) break;
  }
  return outputs;
}

/// The manoeuvres started, in order: each first step of a tracing state after another state.
std::vector<ManoeuvreState> manoeuvresOf(const std::vector<ManoeuvreExecutive::Output>& outputs) {
  std::vector<ManoeuvreState> started;
  ManoeuvreState previous = ManoeuvreState::kIdle;
  for (const ManoeuvreExecutive::Output& out : outputs) {
    if (out.state != previous && out.state != ManoeuvreState::kSettling &&
        out.state != ManoeuvreState::kIdle) {
      started.push_back(out.state);
    }
    previous = out.state;
  }
  return started;
}

/// The angle [rad] between the attitude of contact coordinates and R_zᵀ(ψ) (eq 2 at the pole).
double attitudeError(const ContactCoordinates& x, double psi) {
  const Eigen::Matrix3d reached = orientation(x.u_o, x.v_o, x.psi);
  return Eigen::AngleAxisd(reached.transpose() * orientation(0.0, 0.0, psi)).angle();
}

double planeError(const ContactCoordinates& x, const PlanRequest& target, double radius) {
  return radius * std::hypot(x.u_a - target.u_a, x.v_a - target.v_a);
}

/// The stack's loop from the zero state for `seconds` after its first step.
ContactCoordinates runStack(const RotorStackSampling& sampling,
                            const ManoeuvreExecutive::Parameters& parameters, double seconds,
                            std::vector<ManoeuvreState>* manoeuvres = nullptr) {
  const PlanRequest request = stackRequest();
  SampledRotorLoop loop(sampling, parameters, request, planRotorMotion(request));
  const Nanoseconds step = durationNanoseconds(sampling.plant_step);
  ManoeuvreState previous = ManoeuvreState::kIdle;
  for (Nanoseconds t = 0; t <= durationNanoseconds(seconds); t += step) {
    loop.step();
    const ManoeuvreState state = loop.sample().executive;
    if (manoeuvres && state != previous && state != ManoeuvreState::kSettling &&
        state != ManoeuvreState::kIdle) {
      manoeuvres->push_back(state);
    }
    previous = state;
  }
  return loop.sample().state;
}

RotorStackSampling realisticSampling() {
  RotorStackSampling sampling;
  const config::ActuatorModels models = config::loadActuatorModels(
      config::YamlParameterSource(std::string(SPHERICAL_ROBOTS_SOURCE_DIR) +
                                  "/config/actuators_realistic.yaml"),
      {"rotor_1", "rotor_2"});
  sampling.actuator_models = models.models;
  sampling.noise_seed = models.noise_seed;
  return sampling;
}

TEST(ManoeuvreExecutive, OpenLoopCommandsArePlanSetPointsThenZero) {
  const PlanRequest request = stackRequest();
  const PlanResult plans = planRotorMotion(request);
  ASSERT_FALSE(plans.solutions.empty()) << plans.reason;
  ManoeuvreExecutive executive(stackParameters());
  const Nanoseconds start = 7 * kSecond + 1'000'000;
  EXPECT_FALSE(executive.step(start - kPeriod, std::nullopt).set_point);  // nothing to do yet
  EXPECT_NE(executive.execute(0).find("0 solution(s)"), std::string::npos);
  executive.offerPlans(request, plans);
  ASSERT_EQ(executive.execute(0), "");
  EXPECT_NE(executive.execute(0).find("still executing"), std::string::npos);

  const std::vector<ManoeuvreExecutive::Output> outputs = runWith(executive, restAt(0, 0, 0), restAt(0, 0, 0), start);
  const RotorPlan& best = plans.solutions.front();
  const FigureEight curve(best.a, best.b, best.gamma);
  // The default plan peaks at 12.6 rad/s at 1 rad/s, under the 25 rad/s limit: θ̇ stays 1 rad/s,
  // so the manoeuvre lasts 2πn / θ̇ + the ramp time (CurveTiming).
  const CurveTiming timing(2, 1.0, 1.0);
  const double duration = 4.0 * M_PI + 1.0;
  const int last_sample = static_cast<int>(std::floor((duration + 0.01) / 0.01));
  for (int i = 0; i <= last_sample; ++i) {
    ASSERT_TRUE(outputs[i].set_point) << "sample " << i;
    EXPECT_EQ(outputs[i].state, ManoeuvreState::kExecuting);
    const RotorSpeeds expected = planSetPointAt(kK, 12.0, curve, timing, i * 0.01);
    EXPECT_NEAR(outputs[i].set_point->phi1, expected.phi1, 1e-9) << "t = " << i * 0.01;
    EXPECT_NEAR(outputs[i].set_point->phi2, expected.phi2, 1e-9) << "t = " << i * 0.01;
  }
  EXPECT_EQ(outputs[last_sample].set_point->phi1, 0.0);  // at rest one sample past the end
  EXPECT_EQ(outputs[last_sample].set_point->phi2, 0.0);
  // Then nothing while it settles (1 s), and the end after it.
  ASSERT_EQ(outputs.size(), static_cast<std::size_t>(std::ceil((duration + 1.0) / 0.01)) + 1);
  for (std::size_t i = last_sample + 1; i + 1 < outputs.size(); ++i) {
    EXPECT_FALSE(outputs[i].set_point);
    EXPECT_EQ(outputs[i].state, ManoeuvreState::kSettling);
  }
  ASSERT_TRUE(outputs.back().ended);
  const ManoeuvreVerdict& verdict = *outputs.back().ended;
  EXPECT_EQ(verdict.end, ManoeuvreEnd::kExecuted);
  EXPECT_EQ(verdict.index, 0u);
  EXPECT_EQ(verdict.corrections, 0);
  EXPECT_NEAR(verdict.elapsed, 0.01 * static_cast<double>(outputs.size() - 1), 1e-12);
  EXPECT_EQ(outputs.back().state, ManoeuvreState::kIdle);
  // The measured sphere never moved: it ended where it started, |target| off the goal.
  EXPECT_NEAR(verdict.miss.distance, 0.1 * std::hypot(0.5, 0.3), 1e-15);
  EXPECT_NEAR(verdict.miss.heading, 0.4, 1e-15);
  ASSERT_TRUE(executive.lastMiss());
  EXPECT_EQ(executive.lastMiss()->distance, verdict.miss.distance);
  EXPECT_FALSE(executive.step(start + 10000 * kPeriod, restAt(0, 0, 0)).set_point);
}

TEST(ManoeuvreExecutive, TheGoalIsThePlanTakenFromTheMeasuredRest) {
  // From (u0, v0, ψ0) the plan for (u, v, ψ) ends at (u0, v0) + R_zᵀ(ψ0)(u, v), ψ0 + ψ: measured
  // there at the end, the execution ends on its goal.
  const PlanRequest request = stackRequest();
  ManoeuvreExecutive executive(stackParameters());
  executive.offerPlans(request, planRotorMotion(request));
  ASSERT_EQ(executive.execute(0), "");
  const double psi0 = 1.2;
  const double u = 2.0 + std::cos(psi0) * 0.5 + std::sin(psi0) * 0.3;
  const double v = -1.0 - std::sin(psi0) * 0.5 + std::cos(psi0) * 0.3;
  runWith(executive, restAt(2.0, -1.0, psi0), restAt(u, v, psi0 + 0.4), kSecond);
  ASSERT_TRUE(executive.lastMiss());
  EXPECT_NEAR(executive.lastMiss()->distance, 0.0, 1e-15);
  EXPECT_NEAR(executive.lastMiss()->heading, 0.0, 1e-15);
}

TEST(ManoeuvreExecutive, ProgressIsTheScheduleAndTheMissAsMeasured) {
  const PlanRequest request = stackRequest();
  ManoeuvreExecutive executive(stackParameters());
  executive.offerPlans(request, planRotorMotion(request));
  ASSERT_EQ(executive.execute(0), "");
  // From the zero state the goal is the target (0.5 R, 0.3 R, 0.4 rad); measured at (0.2 R,
  // 0.1 R, 0.1 rad) the sphere is 0.1 √(0.3² + 0.2²) m and 0.3 rad from it.
  const std::vector<ManoeuvreExecutive::Output> outputs =
      runWith(executive, restAt(0, 0, 0), restAt(0.2, 0.1, 0.1), 3 * kSecond);
  const double duration = 4.0 * M_PI + 1.0;  // CurveTiming(2, 1 rad/s, 1 s ramps)
  EXPECT_FALSE(outputs.back().progress);     // the end
  for (std::size_t i = 0; i + 1 < outputs.size(); ++i) {
    ASSERT_TRUE(outputs[i].progress) << "sample " << i;
    const ManoeuvreProgress& progress = *outputs[i].progress;
    const double t = 0.01 * static_cast<double>(i);
    EXPECT_EQ(progress.state, outputs[i].state);
    EXPECT_NEAR(progress.fraction, std::min(t / duration, 1.0), 1e-12) << "t = " << t;
    EXPECT_NEAR(progress.elapsed, t, 1e-12);
    EXPECT_EQ(progress.corrections, 0);
    const double distance = i == 0 ? 0.1 * std::hypot(0.5, 0.3) : 0.1 * std::hypot(0.3, 0.2);
    EXPECT_NEAR(progress.miss.distance, distance, 1e-15);
    EXPECT_NEAR(progress.miss.heading, i == 0 ? 0.4 : 0.3, 1e-15);
  }
}

TEST(ManoeuvreExecutive, ACancelBringsTheRotorsToRestWhereTheSphereStands) {
  const PlanRequest request = stackRequest();
  ManoeuvreExecutive executive(stackParameters());
  EXPECT_THROW(executive.cancel(0, std::nullopt), std::logic_error);
  executive.offerPlans(request, planRotorMotion(request));
  ASSERT_EQ(executive.execute(0), "");
  const Nanoseconds start = 2 * kSecond;
  for (int i = 0; i < 300; ++i) {
    const ManoeuvreExecutive::Output out = executive.step(start + i * kPeriod, restAt(0, 0, 0));
    ASSERT_TRUE(out.set_point);
  }
  // 3 s into the cruise the rotors turn: the plan's set-point there is far from zero.
  const Nanoseconds now = start + 300 * kPeriod;
  const ManoeuvreVerdict canceled = executive.cancel(now, restAt(0.2, 0.1, 0.1));
  EXPECT_EQ(canceled.end, ManoeuvreEnd::kCanceled);
  EXPECT_EQ(canceled.index, 0u);
  EXPECT_NEAR(canceled.elapsed, 3.0, 1e-12);
  EXPECT_NEAR(canceled.miss.distance, 0.1 * std::hypot(0.3, 0.2), 1e-15);
  EXPECT_NEAR(canceled.miss.heading, 0.3, 1e-15);
  EXPECT_NE(canceled.message.find("canceled"), std::string::npos) << canceled.message;
  EXPECT_TRUE(executive.busy());  // the rotors are still to be stopped
  // One zero set-point at the next step, then nothing: the execution is over.
  const ManoeuvreExecutive::Output stop = executive.step(now, restAt(0.2, 0.1, 0.1));
  ASSERT_TRUE(stop.set_point);
  EXPECT_EQ(stop.set_point->phi1, 0.0);
  EXPECT_EQ(stop.set_point->phi2, 0.0);
  EXPECT_EQ(stop.state, ManoeuvreState::kIdle);
  EXPECT_FALSE(stop.ended);
  EXPECT_FALSE(stop.progress);
  EXPECT_FALSE(executive.busy());
  for (int i = 1; i < 200; ++i) {
    const ManoeuvreExecutive::Output out = executive.step(now + i * kPeriod, restAt(0.2, 0.1, 0.1));
    EXPECT_FALSE(out.set_point);
    EXPECT_FALSE(out.ended);
  }
  // A request canceled before its first step: nothing traced, nothing left to do but the stop.
  ASSERT_EQ(executive.execute(0), "");
  const ManoeuvreVerdict unstarted = executive.cancel(now + 200 * kPeriod, restAt(0.2, 0.1, 0.1));
  EXPECT_EQ(unstarted.end, ManoeuvreEnd::kCanceled);
  EXPECT_EQ(unstarted.elapsed, 0.0);
  // Its goal is the plan taken from the rest it would have started from.
  const RestPose goal = planEnd({0.2, 0.1, 0.1}, {0.5, 0.3, 0.4});
  EXPECT_NEAR(unstarted.miss.distance, 0.1 * std::hypot(goal.u_a - 0.2, goal.v_a - 0.1), 1e-15);
  EXPECT_NE(unstarted.message.find("before it started"), std::string::npos) << unstarted.message;
  // A new execution may be asked at once; it starts from rest at the next step.
  ASSERT_EQ(executive.execute(0), "");
  const ManoeuvreExecutive::Output restart = executive.step(now + 201 * kPeriod, restAt(0.2, 0.1, 0.1));
  EXPECT_EQ(restart.state, ManoeuvreState::kExecuting);
  ASSERT_TRUE(restart.set_point);
  EXPECT_EQ(restart.set_point->phi1, 0.0);  // the sin² ramp starts at rest
  EXPECT_EQ(restart.set_point->phi2, 0.0);
}

TEST(ManoeuvreExecutive, NeverTwoArcsInARow) {
  // The contact stays off the pole and the sphere off the goal whatever is done: after the plan
  // an arc, then a figure eight although the contact is still off the pole, then an arc again.
  ManoeuvreExecutive::Parameters p = stackParameters();
  p.corrections = 3;
  ManoeuvreExecutive executive(p);
  const PlanRequest request = stackRequest();
  executive.offerPlans(request, planRotorMotion(request));
  ASSERT_EQ(executive.execute(0), "");
  const std::vector<ManoeuvreExecutive::Output> outputs =
      runWith(executive, restAt(0, 0, 0), restAt(0.45, 0.28, 0.39, 0.01, -0.02), kSecond);
  EXPECT_EQ(manoeuvresOf(outputs),
            (std::vector<ManoeuvreState>{ManoeuvreState::kExecuting,
                                         ManoeuvreState::kReturningToPole,
                                         ManoeuvreState::kCorrecting,
                                         ManoeuvreState::kReturningToPole}));
  EXPECT_EQ(executive.correctionsMade(), 3u);
  ASSERT_TRUE(outputs.back().ended);
  EXPECT_EQ(outputs.back().ended->index, 0u);
  EXPECT_EQ(outputs.back().ended->corrections, 3);
  // Every manoeuvre starts from rest and ends in a zero set-point before it settles.
  for (std::size_t i = 1; i < outputs.size(); ++i) {
    if (outputs[i].state == ManoeuvreState::kSettling &&
        outputs[i - 1].state != ManoeuvreState::kSettling) {
      ASSERT_TRUE(outputs[i - 1].set_point);
      EXPECT_EQ(outputs[i - 1].set_point->phi1, 0.0);
      EXPECT_EQ(outputs[i - 1].set_point->phi2, 0.0);
    }
  }
}

TEST(ManoeuvreExecutive, CorrectionsStopWithinTheTolerancesOrWithoutAFreshRest) {
  ManoeuvreExecutive::Parameters p = stackParameters();
  p.corrections = 3;
  const PlanRequest request = stackRequest();
  const PlanResult plans = planRotorMotion(request);
  // On the pole within 1e-4 rad, 1e-5 m and 1e-3 rad off the goal: no correction.
  ManoeuvreExecutive within(p);
  within.offerPlans(request, plans);
  ASSERT_EQ(within.execute(0), "");
  const std::vector<ManoeuvreExecutive::Output> quiet =
      runWith(within, restAt(0, 0, 0), restAt(0.5 + 5e-5, 0.3, 0.4 + 5e-4, 5e-5, 0.0), kSecond);
  EXPECT_EQ(manoeuvresOf(quiet), std::vector<ManoeuvreState>{ManoeuvreState::kExecuting});
  EXPECT_EQ(within.correctionsMade(), 0u);
  // Off the goal, but the rest is stale: refused, and the execution ends.
  ManoeuvreExecutive stale(p);
  stale.offerPlans(request, plans);
  ASSERT_EQ(stale.execute(0), "");
  RestMeasurement old = restAt(0.4, 0.3, 0.4);
  old.fresh = false;
  const std::vector<ManoeuvreExecutive::Output> outputs = runWith(stale, restAt(0, 0, 0), old, kSecond);
  EXPECT_EQ(manoeuvresOf(outputs), std::vector<ManoeuvreState>{ManoeuvreState::kExecuting});
  const ManoeuvreExecutive::Report& last = outputs.back().reports.front();
  EXPECT_EQ(last.kind, ManoeuvreExecutive::Report::Kind::kRefusal);
  EXPECT_NE(last.text.find("stale"), std::string::npos) << last.text;
}

TEST(ManoeuvreExecutive, RotorSpeedsStayWithinTheirLimit) {
  ManoeuvreExecutive::Parameters p = stackParameters();
  p.max_rotor_speed = 5.0;
  ManoeuvreExecutive executive(p);
  const PlanRequest request = stackRequest();
  const PlanResult plans = planRotorMotion(request);
  executive.offerPlans(request, plans);
  ASSERT_EQ(executive.execute(0), "");
  const std::vector<ManoeuvreExecutive::Output> outputs = runWith(executive, restAt(0, 0, 0), restAt(0, 0, 0), 0);
  double peak = 0.0;
  std::size_t commands = 0;
  for (const ManoeuvreExecutive::Output& out : outputs) {
    if (!out.set_point) continue;
    ++commands;
    peak = std::max({peak, std::abs(out.set_point->phi1), std::abs(out.set_point->phi2)});
  }
  // The plan's peak at θ̇ = 1 rad/s is sampled at 4001 θ (peakRotorSpeed): between the samples
  // the set-points may exceed the limit by a little (3.7e-6 rad/s here).
  EXPECT_LE(peak, 5.0 * (1.0 + 1e-5)) << std::setprecision(17) << peak;
  EXPECT_GE(peak, 0.98 * 5.0);  // lowered to fit, not further
  // Speeds scale with θ̇ (eq 11 is linear in ω, ω in θ̇), so the curve rate is 5 / peak(θ̇ = 1)
  // and the manoeuvre lasts 4π / that + the 1 s ramp, sampled every 10 ms, one zero after.
  const RotorPlan& best = plans.solutions.front();
  const double rate = 5.0 / peakRotorSpeed(kK, 12.0, FigureEight(best.a, best.b, best.gamma));
  EXPECT_EQ(commands, static_cast<std::size_t>(std::floor((4 * M_PI / rate + 1.0) / 0.01)) + 2);
  EXPECT_EQ(outputs.front().reports.front().kind, ManoeuvreExecutive::Report::Kind::kWarning);
  EXPECT_NE(outputs.front().reports.front().text.find("curve rate lowered"), std::string::npos);
  // Slower, the plant still reaches the target: tracing is reparameterisation invariant (eqs 28-30).
  const ContactCoordinates end = runStack(RotorStackSampling{}, p, 4 * M_PI / rate + 4.0);
  EXPECT_LE(planeError(end, request, 0.1), 2e-6);
  EXPECT_LE(attitudeError(end, 0.4), 2e-5);
}

TEST(ManoeuvreExecutive, AJumpOfTheClockDoesNotMoveTheSchedule) {
  const PlanRequest request = stackRequest();
  const PlanResult plans = planRotorMotion(request);
  ManoeuvreExecutive steady(stackParameters()), jumped(stackParameters());
  for (ManoeuvreExecutive* e : {&steady, &jumped}) {
    e->offerPlans(request, plans);
    ASSERT_EQ(e->execute(0), "");
  }
  // No time is taken as elapsed across the jump: the step after it repeats the one before.
  const Nanoseconds jump = 1000 * kSecond;
  std::vector<double> steady_phi1;
  for (int i = 0; i < 800; ++i) {
    const ManoeuvreExecutive::Output a = steady.step(i * kPeriod, restAt(0, 0, 0));
    const ManoeuvreExecutive::Output b =
        jumped.step(i * kPeriod + (i >= 400 ? jump : 0), restAt(0, 0, 0));
    ASSERT_TRUE(a.set_point && b.set_point);
    steady_phi1.push_back(a.set_point->phi1);
    EXPECT_EQ(b.set_point->phi1, steady_phi1[i >= 400 ? i - 1 : i]) << "sample " << i;
    EXPECT_NEAR(b.clock_jump, i == 400 ? 1000.01 : 0.0, 1e-9);
  }
}

TEST(ManoeuvreExecutive, BadParametersAreNamed) {
  ManoeuvreExecutive::Parameters p;
  p.settle = -1.0;
  EXPECT_INVALID_ARGUMENT(ManoeuvreExecutive{p}, "settle time [s]", "-1");
  p = {};
  p.corrections = -2;
  EXPECT_INVALID_ARGUMENT(ManoeuvreExecutive{p}, "corrections", ">= 0", "-2");
  p = {};
  p.curve_rate = std::nan("");
  EXPECT_INVALID_ARGUMENT(ManoeuvreExecutive{p}, "curve rate [rad/s]", "nan");
}

TEST(SampledRotorLoop, TheStacksOpenLoopRunEndsAtTheTarget) {
  // Ideal rotors within 30 rad/s and 300 rad/s^2, the plant at 1 ms, set-points every 10 ms.
  const ContactCoordinates end = runStack(RotorStackSampling{}, stackParameters(), 20.0);
  EXPECT_LE(planeError(end, stackRequest(), 0.1), 2e-6);
  EXPECT_LE(attitudeError(end, 0.4), 2e-5);
}

TEST(SampledRotorLoop, CorrectionsBringTheRealisticRotorsWithinTheStackBounds) {
  // test/rotor_stack_corrected.test: config/actuators_realistic.yaml (50 ms lag, 10 ms dead time,
  // encoder, seeded velocity noise), no feed-forward, three corrections with tolerances at the
  // noise floor (5e-5 m, 5e-4 rad); its bounds 2.5e-4 m and 1e-3 rad fail every open-loop run.
  const RotorStackSampling sampling = realisticSampling();
  const ContactCoordinates open = runStack(sampling, stackParameters(), 20.0);
  EXPECT_GT(planeError(open, stackRequest(), 0.1), 2.5e-4);
  ManoeuvreExecutive::Parameters p = stackParameters();
  p.corrections = 3;
  p.correction_tolerance = 5e-5;
  p.correction_tilt_tolerance = 5e-4;
  std::vector<ManoeuvreState> manoeuvres;
  const ContactCoordinates end = runStack(sampling, p, 50.0, &manoeuvres);
  const double miss = planeError(end, stackRequest(), 0.1);
  const double attitude = attitudeError(end, 0.4);
  std::cout << "corrected run: open loop " << planeError(open, stackRequest(), 0.1) << " m, "
            << attitudeError(open, 0.4) << " rad; corrected " << miss << " m, " << attitude
            << " rad after " << manoeuvres.size() - 1 << " correction(s)\n";
  EXPECT_LE(miss, 2.5e-4);
  EXPECT_LE(attitude, 1e-3);
  ASSERT_GE(manoeuvres.size(), 2u);
  for (std::size_t i = 1; i < manoeuvres.size(); ++i) {
    EXPECT_FALSE(manoeuvres[i] == ManoeuvreState::kReturningToPole &&
                 manoeuvres[i - 1] == ManoeuvreState::kReturningToPole)
        << "two arcs in a row at manoeuvre " << i;
  }
}

TEST(SampledRotorLoop, TheLagFeedForwardBringsLaggedRotorsCloser) {
  // A first-order rotor lag of 50 ms is not a reparameterisation; its inverse fed forward
  // (u = φ̇ + τ φ̈) removes most of what it costs.
  RotorStackSampling sampling;
  hardware::ActuatorModel lag;
  lag.time_constant = 0.05;
  sampling.actuator_models = {lag, lag};
  const ContactCoordinates plain = runStack(sampling, stackParameters(), 20.0);
  ManoeuvreExecutive::Parameters p = stackParameters();
  p.actuator_time_constant = 0.05;
  const ContactCoordinates fed = runStack(sampling, p, 20.0);
  EXPECT_LT(planeError(fed, stackRequest(), 0.1), 0.2 * planeError(plain, stackRequest(), 0.1));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
