// Executing a plan through the rotors (plan_execution.hpp): the curve timing against its own
// definition (θ(t) integrates θ̇(t), ends at 2πn), the set-points against eq 11 at the planned
// heading and place, the plant against rigid-body rolling in closed form, and the sampled
// (zero-order hold) execution against the plan's target as the period shrinks.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/rotor/contact_curve.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/dynamic_realizability.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "spherical_robots/rotor/geometric_phase.hpp"
#include "spherical_robots/rotor/motion_planner.hpp"
#include "spherical_robots/rotor/plan_execution.hpp"

namespace {

using namespace spherical_robots::rotor;

constexpr double kScale = 12.0;  // J_zz / J_r

double endError(const ContactCoordinates& x, double u, double v, double psi) {
  return std::max({std::abs(x.u_a - u), std::abs(x.v_a - v), std::abs(x.psi - psi),
                   std::abs(x.u_o), std::abs(x.v_o)});
}

TEST(RotorExecution, CurveTimingIntegratesItsRate) {
  const CurveTiming timing(3, 1.5, 2.0);
  const double total = 6 * M_PI;
  EXPECT_NEAR(timing.duration(), total / 1.5 + 2.0, 1e-12);
  EXPECT_EQ(timing.theta(-1.0), 0.0);
  EXPECT_NEAR(timing.theta(timing.duration()), total, 1e-12);
  EXPECT_EQ(timing.rate(0.0), 0.0);
  EXPECT_EQ(timing.rate(timing.duration()), 0.0);
  EXPECT_NEAR(timing.rate(5.0), 1.5, 1e-12);
  // θ(t) = ∫ θ̇ by the trapezoid rule, and θ̇ = dθ/dt by central differences, everywhere
  // (across both ramp joints).
  double integral = 0.0;
  const int n = 200000;
  const double dt = timing.duration() / n;
  for (int i = 0; i < n; ++i) {
    const double t = i * dt;
    integral += 0.5 * dt * (timing.rate(t) + timing.rate(t + dt));
    if (i % 1000 == 0 && i > 0) {
      EXPECT_NEAR(integral, timing.theta(t + dt), 1e-8) << "t = " << t + dt;
      EXPECT_NEAR((timing.theta(t + 1e-6) - timing.theta(t - 1e-6)) / 2e-6, timing.rate(t), 1e-6)
          << "t = " << t;
    }
  }
  EXPECT_NEAR(integral, total, 1e-8);
  // Largest θ̈ = π M / (2 ramp) at mid-ramp.
  EXPECT_NEAR((timing.rate(1.0 + 1e-6) - timing.rate(1.0 - 1e-6)) / 2e-6, M_PI * 1.5 / 4.0, 1e-6);
  EXPECT_THROW(CurveTiming(0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(CurveTiming(1, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(CurveTiming(1, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(CurveTiming(1, 1.0, 7.0), std::invalid_argument);  // 1 rad/s x 7 s > 2π
}

TEST(RotorExecution, SetPointsAreEq11AtThePlannedHeadingAndPlace) {
  // The set-point uses ψ = 0 at the origin; eq 11 at the heading and place the plan actually has
  // there (integrated by the planner's own integrator) must give the same speeds. The leaves
  // share θ by their radii, which keeps the contact speed, and so the set-points, continuous.
  const double k = 2.5, rate = 0.8;
  const FigureEight curve(0.4, 0.55, 0.7);
  // The first leaf (radius 0.4) takes 2π 0.4/0.95 of a step's θ, at dθ_leaf/dθ = 0.95/0.8.
  const double split = 2 * M_PI * 0.4 / 0.95;
  for (const double theta : {0.0, 0.3, 1.7, split, 3.5, 5.9, 2 * M_PI, 2 * M_PI + 2.0}) {
    const int step = theta > 2 * M_PI ? 1 : 0;
    const double local = theta - 2 * M_PI * step;
    const bool second = local > split;
    const double leaf = second ? M_PI + (local - split) * 0.95 / 1.1 : local * 0.95 / 0.8;
    const double leaf_rate = rate * (second ? 0.95 / 1.1 : 0.95 / 0.8);
    const PlaneState start = step == 0 ? PlaneState{} : integrateSteps(k, curve, 1);
    const PlaneState at = integrateFigureEight(k, curve, 0.0, leaf, start);
    const CurvePoint c = curve.onLeaf(second, leaf);
    const Eigen::Vector2d angles = contactAngles(c.point);
    const ContactCoordinates planned{at.u_a, at.v_a, angles.x(), angles.y(), at.psi};
    const RotorSpeeds truth =
        rotorSpeeds(k, kScale, planned, curveAngularVelocity(k, c, at.psi, leaf_rate));
    // The contact moves at (a + b) θ̇ on both leaves.
    EXPECT_NEAR(c.tangent.norm() * leaf_rate, 0.95 * rate, 1e-12) << "theta " << theta;
    const RotorSpeeds speeds = planSetPoint(k, kScale, curve, 2, theta, rate);
    EXPECT_NEAR(speeds.phi1, truth.phi1, 1e-9) << "theta " << theta;
    EXPECT_NEAR(speeds.phi2, truth.phi2, 1e-9) << "theta " << theta;
  }
  // Continuous where the leaves meet and where the steps do.
  for (const double joint : {split, 2 * M_PI, 2 * M_PI + split}) {
    const RotorSpeeds before = planSetPoint(k, kScale, curve, 2, joint - 1e-9, rate);
    const RotorSpeeds after = planSetPoint(k, kScale, curve, 2, joint + 1e-9, rate);
    EXPECT_NEAR(before.phi1, after.phi1, 1e-6) << "theta " << joint;
    EXPECT_NEAR(before.phi2, after.phi2, 1e-6) << "theta " << joint;
  }
  EXPECT_THROW(planSetPoint(k, kScale, curve, 2, 4 * M_PI + 0.1, rate), std::invalid_argument);
  EXPECT_THROW(planSetPoint(k, kScale, curve, 0, 1.0, rate), std::invalid_argument);
  // The peak scales the speeds at θ̇ = 1.
  const double peak = peakRotorSpeed(k, kScale, curve);
  for (int i = 0; i <= 100; ++i) {
    const RotorSpeeds s = planSetPoint(k, kScale, curve, 1, 2 * M_PI * i / 100, 1.0);
    EXPECT_LE(std::max(std::abs(s.phi1), std::abs(s.phi2)), peak + 1e-12);
  }
}

TEST(RotorExecution, HeldRotorSpeedsRollTheSphereStraight) {
  // From the zero state one rotor alone gives ω along a horizontal body axis that stays
  // horizontal: the rigid body turns by R_y(w t) (R_x(w t)) and the centre moves by ω × (0, 0, R).
  const double k = 2.0, w = 0.3, t = 2.5;
  // ω = −(1/s) diag(1/k, 1/k, 1) n2 φ̇2 with n2 = y: φ̇2 = −s k w gives ω = (0, w, 0).
  const ContactCoordinates y_roll =
      advancePlant(k, kScale, {}, {0.0, -kScale * k * w}, t, 1e-3);
  EXPECT_NEAR(y_roll.u_a, w * t, 1e-10);
  EXPECT_NEAR(y_roll.v_a, 0.0, 1e-12);
  EXPECT_LE((orientation(y_roll.u_o, y_roll.v_o, y_roll.psi) -
             Eigen::AngleAxisd(w * t, Eigen::Vector3d::UnitY()).toRotationMatrix()).norm(), 1e-10);
  const ContactCoordinates x_roll =
      advancePlant(k, kScale, {}, {-kScale * k * w, 0.0}, t, 1e-3);
  EXPECT_NEAR(x_roll.u_a, 0.0, 1e-12);
  EXPECT_NEAR(x_roll.v_a, -w * t, 1e-10);
  EXPECT_LE((orientation(x_roll.u_o, x_roll.v_o, x_roll.psi) -
             Eigen::AngleAxisd(w * t, Eigen::Vector3d::UnitX()).toRotationMatrix()).norm(), 1e-10);
  EXPECT_THROW(advancePlant(k, kScale, {}, {0.0, 1.0}, -1.0, 1e-3), std::invalid_argument);
  EXPECT_THROW(advancePlant(k, kScale, {}, {0.0, 1.0}, 1.0, 0.0), std::invalid_argument);
}

TEST(RotorExecution, SampledExecutionConvergesToTheTarget) {
  // The ROS loop streams set-points at a fixed rate and holds them: the end error against the
  // target (the truth) falls with the period, and the continuous execution ends on it. The
  // numbers bound the rostest's tolerance (docs/results.md).
  const double k = 2.5;
  const PlanRequest request{k, 2, 0.5, 0.3, 0.4, 0.7, 0};
  const PlanResult result = planRotorMotion(request);
  ASSERT_FALSE(result.solutions.empty()) << result.reason;
  const RotorPlan& plan = result.solutions.front();
  const FigureEight curve(plan.a, plan.b, plan.gamma);
  const CurveTiming timing(request.steps, 1.0, 1.0);
  const ContactCoordinates exact = executePlan(k, kScale, curve, timing, 0.0);
  EXPECT_LE(endError(exact, 0.5, 0.3, 0.4), 1e-8);
  const double coarse = endError(executePlan(k, kScale, curve, timing, 0.01, 0.5), 0.5, 0.3, 0.4);
  const double fine = endError(executePlan(k, kScale, curve, timing, 0.001, 0.5), 0.5, 0.3, 0.4);
  std::printf("end error [R]: period 10 ms %.3g, 1 ms %.3g\n", coarse, fine);
  EXPECT_LE(coarse, 1e-3);
  EXPECT_LE(fine, 0.2 * coarse);  // at least first order
  EXPECT_THROW(executePlan(k, kScale, curve, timing, -0.01), std::invalid_argument);
}

TEST(RotorExecution, LagFeedForwardRestoresTheTarget) {
  // Rotors with a first-order lag (τ = 50 ms, as config/actuators_realistic.yaml), simulated here
  // exactly for a held command (y += (1 − e^{−h/τ}) (u − y)): uncompensated they miss the target
  // (the lag is not a pure delay), with the feed-forward they end on it to the sampling error.
  const double k = 2.5, tau = 0.05, h = 0.001;
  const PlanResult result = planRotorMotion({k, 2, 0.5, 0.3, 0.4, 0.7, 0});
  ASSERT_FALSE(result.solutions.empty()) << result.reason;
  const RotorPlan& plan = result.solutions.front();
  const FigureEight curve(plan.a, plan.b, plan.gamma);
  const CurveTiming timing(2, 1.0, 1.0);
  const SetPointSchedule schedule = [&](double t) {
    return planSetPointAt(k, kScale, curve, timing, t);
  };
  const auto run = [&](double compensated_tau) {
    ContactCoordinates x;
    RotorSpeeds y;
    const double alpha = 1.0 - std::exp(-h / tau);
    for (long i = 0; i * h < timing.duration() + 1.0; ++i) {
      const RotorSpeeds u =
          lagCompensatedSetPoint(schedule, i * h, compensated_tau, h);
      x = advancePlant(k, kScale, x, y, h, h);  // the plant holds the last measured speed
      y.phi1 += alpha * (u.phi1 - y.phi1);
      y.phi2 += alpha * (u.phi2 - y.phi2);
    }
    return endError(x, 0.5, 0.3, 0.4);
  };
  const double plain = run(0.0), compensated = run(tau);
  std::printf("end error [R] with a 50 ms lag: %.3g plain, %.3g compensated\n", plain,
              compensated);
  EXPECT_GE(plain, 1e-3);
  EXPECT_LE(compensated, 0.05 * plain);
  EXPECT_THROW(lagCompensatedSetPoint(schedule, 1.0, -0.1, h), std::invalid_argument);
  EXPECT_THROW(lagCompensatedSetPoint(schedule, 1.0, tau, 0.0), std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
