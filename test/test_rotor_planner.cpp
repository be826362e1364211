// n-step planning of the two-rotor sphere (Svinin et al., eqs 31-34) against the paper's
// published solutions for k = 0 and k = 2.5, independent one-dimensional root scans of the
// symmetric figure eights, the geometry of n steps (P_0 … P_n on a circle, eqs 32-33), and
// verification of every plan by integrating the kinematics (docs/errata.md S3).

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/dynamic_realizability.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "spherical_robots/rotor/geometric_phase.hpp"
#include "spherical_robots/rotor/motion_planner.hpp"
#include "spherical_robots/rotor/plan_execution.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using namespace spherical_robots::rotor;

bool roundsTo(double value, double printed, double half_unit) {
  return std::abs(value - printed) <= half_unit;
}

/// Checks a plan by integrating it here, independently of the planner's verification.
void expectReaches(const PlanRequest& request, const RotorPlan& plan, double tolerance) {
  const PlaneState reached = integrateSteps(request.k, FigureEight(plan.a, plan.b, plan.gamma),
                                            request.steps);
  EXPECT_NEAR(reached.u_a, request.u_a, tolerance);
  EXPECT_NEAR(reached.v_a, request.v_a, tolerance);
  EXPECT_NEAR(reached.psi, plan.psi, tolerance);
  EXPECT_LE(plan.final_error, 1e-8);
  EXPECT_NEAR(plan.length, request.steps * 2 * M_PI * (plan.a + plan.b), 1e-12);
  EXPECT_LE(std::max(plan.a, plan.b), request.max_radius);
}

void expectSortedByLength(const PlanResult& result) {
  for (std::size_t i = 1; i < result.solutions.size(); ++i) {
    EXPECT_LE(result.solutions[i - 1].length, result.solutions[i].length);
  }
}

const RotorPlan* findSymmetric(const PlanResult& result, double a, double tolerance) {
  for (const RotorPlan& plan : result.solutions) {
    if (std::abs(plan.a - a) < tolerance && std::abs(plan.b - a) < tolerance) return &plan;
  }
  return nullptr;
}

TEST(RotorPlanner, PureRollingUnitShiftAlongV) {
  const PlanRequest request{0.0, 1, 0.0, 1.0, 0.0, 0.7, 0};
  const PlanResult result = planRotorMotion(request);
  ASSERT_FALSE(result.solutions.empty()) << result.reason;
  const RotorPlan* plan = findSymmetric(result, std::sin(0.533681), 1e-6);
  ASSERT_NE(plan, nullptr);
  EXPECT_TRUE(roundsTo(arcRadius(plan->a), 0.533681, 5e-7)) << arcRadius(plan->a);
  EXPECT_TRUE(roundsTo(plan->gamma, -1.13393, 5e-6)) << plan->gamma;
  for (const RotorPlan& p : result.solutions) expectReaches(request, p, 1e-8);
  expectSortedByLength(result);
}

TEST(RotorPlanner, FindsThePublishedRadiiForInertiaRatio2p5) {
  const PlanRequest request{2.5, 1, 0.0, 1.0, 0.0, 0.7, 0};
  const PlanResult result = planRotorMotion(request);
  ASSERT_FALSE(result.solutions.empty()) << result.reason;
  const double published[] = {0.300429, 0.491471, 0.538682, 0.609147};
  for (double a : published) {
    const RotorPlan* plan = findSymmetric(result, a, 1e-6);
    ASSERT_NE(plan, nullptr) << "a = " << a;
    EXPECT_TRUE(roundsTo(plan->a, a, 5e-7)) << plan->a;
  }
  EXPECT_TRUE(roundsTo(findSymmetric(result, published[0], 1e-6)->gamma, 0.931883, 5e-7));
  EXPECT_TRUE(roundsTo(findSymmetric(result, published[1], 1e-6)->gamma, -0.69726, 5e-6));
  // "The first solution produces the contact path of minimal length".
  EXPECT_TRUE(roundsTo(result.solutions.front().a, 0.300429, 5e-7));
  EXPECT_TRUE(roundsTo(result.solutions.front().b, 0.300429, 5e-7));
  for (const RotorPlan& p : result.solutions) expectReaches(request, p, 1e-8);
  expectSortedByLength(result);
}

TEST(RotorPlanner, FindsEverySymmetricSolutionOfAOneDimensionalScan) {
  // For ψ = 0 every a = b gives η = 0; the symmetric roots of h(a, a) = h_des found by a fine
  // scan of the integrated step must all be among the plans.
  for (double k : {0.7, 4.0}) {
    const double h_des = 0.6;
    const PlanRequest request{k, 1, h_des, 0.0, 0.0, 0.68, 0};
    const PlanResult result = planRotorMotion(request);
    double a0 = 0.01, h0 = stepPhase(k, a0, a0).h - h_des;
    int expected = 0;
    for (int i = 1; i <= 2000; ++i) {
      const double a1 = 0.01 + (0.68 - 0.01) * i / 2000, h1 = stepPhase(k, a1, a1).h - h_des;
      if ((h0 < 0) != (h1 < 0)) {
        ++expected;
        EXPECT_NE(findSymmetric(result, 0.5 * (a0 + a1), 0.68 / 2000), nullptr)
            << "k = " << k << ", a near " << a0;
      }
      a0 = a1;
      h0 = h1;
    }
    EXPECT_GT(expected, 0);
    for (const RotorPlan& p : result.solutions) expectReaches(request, p, 1e-8);
  }
}

TEST(RotorPlanner, NStepsLieOnACircle) {
  // Eq 33 corrected: h = |sin(η/2) / sin(nη/2)| h_des (the printed form divides sin(η/2) by
  // itself). Each plan's one-step h and η satisfy it, and its intermediate points P_j lie on
  // one circle.
  const PlanRequest request{1.5, 3, 0.4, -0.3, 0.6, 0.7, 0};
  const PlanResult result = planRotorMotion(request);
  ASSERT_FALSE(result.solutions.empty()) << result.reason;
  for (const RotorPlan& plan : result.solutions) {
    expectReaches(request, plan, 1e-8);
    const StepPhase phase = stepPhase(request.k, plan.a, plan.b);
    const double eta = request.psi / request.steps;
    // The planner stops at Newton steps below 1e-10 R.
    EXPECT_NEAR(phase.eta, eta, 1e-9);
    EXPECT_NEAR(phase.h, std::abs(std::sin(eta / 2) / std::sin(3 * eta / 2)) * 0.5, 1e-9);
    const FigureEight curve(plan.a, plan.b, plan.gamma);
    std::vector<Eigen::Vector2d> points{Eigen::Vector2d::Zero()};
    PlaneState state;
    for (int j = 0; j < 3; ++j) {
      state = integrateFigureEight(request.k, curve, 0.0, 2 * M_PI, state);
      points.emplace_back(state.u_a, state.v_a);
    }
    // Circumcentre of P0, P1, P2; P3 must be as far from it.
    const Eigen::Vector2d b = points[1], c = points[2];
    const double d = 2 * (b.x() * c.y() - b.y() * c.x());
    const Eigen::Vector2d centre((c.y() * b.squaredNorm() - b.y() * c.squaredNorm()) / d,
                                 (b.x() * c.squaredNorm() - c.x() * b.squaredNorm()) / d);
    EXPECT_NEAR((points[3] - centre).norm(), centre.norm(), 1e-9);
  }
}

TEST(RotorPlanner, HeadingIsNotReducedModuloTwoPi) {
  // ψ = 7 in one step needs η = 7: with radii <= 0.5 no figure eight turns that far.
  const PlanResult one = planRotorMotion({2.0, 1, 0.3, 0.2, 7.0, 0.5, 0});
  EXPECT_TRUE(one.solutions.empty());
  EXPECT_NE(one.reason.find("eta = psi/n = 7"), std::string::npos) << one.reason;
  // Searching ψ + 2πm finds plans for 7 − 2π, and they reach that heading.
  const PlanRequest request{2.0, 1, 0.3, 0.2, 7.0, 0.5, 1};
  const PlanResult turns = planRotorMotion(request);
  ASSERT_FALSE(turns.solutions.empty()) << turns.reason;
  for (const RotorPlan& plan : turns.solutions) {
    EXPECT_NEAR(plan.psi, 7.0 - 2 * M_PI, 1e-12);
    expectReaches(request, plan, 1e-8);
  }
  // Near the equator the heading turns fast: with radii up to 0.7, η = 7 itself is reachable,
  // and every plan then reaches the accumulated 7 rad.
  const PlanRequest far{2.0, 1, 0.3, 0.2, 7.0, 0.7, 0};
  const PlanResult wide = planRotorMotion(far);
  ASSERT_FALSE(wide.solutions.empty()) << wide.reason;
  for (const RotorPlan& plan : wide.solutions) {
    EXPECT_EQ(plan.psi, 7.0);
    expectReaches(far, plan, 1e-8);
  }
}

TEST(RotorPlanner, UnreachableShiftGivesAReason) {
  const PlanResult result = planRotorMotion({0.0, 1, 5.0, 0.0, 0.0, 0.3, 0});
  EXPECT_TRUE(result.solutions.empty());
  EXPECT_NE(result.reason.find("no figure eight"), std::string::npos) << result.reason;
  // Four steps turning by π/2 each close a square: only the start is reachable.
  const PlanResult square = planRotorMotion({1.0, 4, 1.0, 0.0, 2 * M_PI, 0.7, 0});
  EXPECT_TRUE(square.solutions.empty());
  EXPECT_NE(square.reason.find("polygon"), std::string::npos) << square.reason;
}

TEST(RotorPlanner, ZeroTargetAndPureTurns) {
  // Back to the start with no turn: the symmetric figure eights whose shift vanishes (h(a, a) = 0,
  // found here by an independent scan), never the null manoeuvre a = b -> 0.
  const double k = 2.5;
  const PlanRequest request{k, 1, 0.0, 0.0, 0.0, 0.6, 0};
  const PlanResult result = planRotorMotion(request);
  ASSERT_FALSE(result.solutions.empty()) << result.reason;
  for (const RotorPlan& plan : result.solutions) {
    EXPECT_GE(std::min(plan.a, plan.b), 0.01);
    expectReaches(request, plan, 1e-8);
  }
  const auto signedShift = [k](double a) {
    const StepResult step = rotorStep(k, FigureEight(a, a));
    const double axis = -0.5 * step.half.psi;
    return step.full.u_a * std::cos(axis) + step.full.v_a * std::sin(axis);
  };
  double a0 = 0.05, h0 = signedShift(a0);
  for (int i = 1; i <= 1100; ++i) {
    const double a1 = 0.05 + 0.55 * i / 1100, h1 = signedShift(a1);
    if ((h0 < 0) != (h1 < 0)) {
      EXPECT_NE(findSymmetric(result, 0.5 * (a0 + a1), 0.55 / 1100), nullptr) << "a near " << a0;
    }
    a0 = a1;
    h0 = h1;
  }
  // A pure turn: three equations for two radii, no plan in general, and the reason says so.
  const PlanResult turn = planRotorMotion({k, 2, 0.0, 0.0, 0.5, 0.7, 0});
  EXPECT_TRUE(turn.solutions.empty());
  EXPECT_NE(turn.reason.find("pure turn"), std::string::npos) << turn.reason;
}

TEST(RotorPlanner, ExecutingAPlanThroughTheRotorsReachesTheTarget) {
  // Open loop at θ̇ = 1 rad/s: rotor set-points from the plan (eq 11 on the planned ω), and a
  // plant that knows only the rotor speeds: ω from eq 11 solved for ω, contact coordinates from
  // Montana's eqs 6-10 (not the curve form the planner integrates). The target is the truth.
  const double k = 2.5, scale = 12.0;
  const PlanRequest request{k, 2, 0.5, 0.3, 0.4, 0.7, 0};
  const PlanResult result = planRotorMotion(request);
  ASSERT_FALSE(result.solutions.empty()) << result.reason;
  const RotorPlan& plan = result.solutions.front();
  const FigureEight curve(plan.a, plan.b, plan.gamma);
  // executePlan (core, plan_execution.hpp) integrates the plant alone, Dormand-Prince 5(4).
  const ContactCoordinates x =
      executePlan(k, scale, curve, CurveTiming(request.steps, 1.0, 0.0), 0.0);
  EXPECT_NEAR(x.u_a, request.u_a, 1e-8);
  EXPECT_NEAR(x.v_a, request.v_a, 1e-8);
  EXPECT_NEAR(x.u_o, 0.0, 1e-8);  // back at the south pole
  EXPECT_NEAR(x.v_o, 0.0, 1e-8);
  EXPECT_NEAR(x.psi, request.psi, 1e-8);
  // Rotor speeds and ω round-trip at a sample state.
  const ContactCoordinates at{0.1, 0.2, 0.3, -0.2, 0.7};
  const Eigen::Vector3d omega = curveAngularVelocity(k, curve.at(1.0), 0.7, 1.3);
  const Eigen::Vector2d angles = contactAngles(curve.at(1.0).point);
  const ContactCoordinates on_curve{0.1, 0.2, angles.x(), angles.y(), 0.7};
  EXPECT_LE((rotorAngularVelocity(k, scale, on_curve, rotorSpeeds(k, scale, on_curve, omega)) -
             omega).norm(), 1e-12);
  EXPECT_THROW(rotorAngularVelocity(0.0, scale, at, {1.0, 1.0}), std::invalid_argument);
}

TEST(RotorPlanner, RejectsBadRequests) {
  EXPECT_THROW(planRotorMotion({-0.1, 1, 0, 1, 0, 0.7, 0}), std::invalid_argument);
  EXPECT_THROW(planRotorMotion({1.0, 0, 0, 1, 0, 0.7, 0}), std::invalid_argument);
  EXPECT_THROW(planRotorMotion({1.0, 1, std::nan(""), 1, 0, 0.7, 0}), std::invalid_argument);
  EXPECT_THROW(planRotorMotion({1.0, 1, 0, 1, 0, 0.75, 0}), std::invalid_argument);
  EXPECT_THROW(planRotorMotion({1.0, 1, 0, 1, 0, 0.7, -1}), std::invalid_argument);
  EXPECT_INVALID_ARGUMENT(planRotorMotion({1.0, 1, 0, 1, 0, 0.72, 0}), "max radius", "0.72");
}

TEST(RotorPlanner, RequestsAreBoundedSoThatNoneBlocksThePlanner) {
  // 20,000 heading turns blocked the planner for 9.4 s: refused at once, naming the bound.
  EXPECT_INVALID_ARGUMENT(planRotorMotion({2.5, 1, 0, 1, 0, 0.7, 20000}), "heading turns", "10");
  EXPECT_INVALID_ARGUMENT(planRotorMotion({2.5, 21, 0, 1, 0, 0.7, 0}), "steps", "20");
  EXPECT_INVALID_ARGUMENT(planRotorMotion({1e300, 1, 0, 1, 0, 0.7, 0}), "inertia ratio k");
  EXPECT_INVALID_ARGUMENT(planRotorMotion({2.5, 1, 1e300, 1, 0, 0.7, 0}), "u_a", "1000");
  EXPECT_INVALID_ARGUMENT(planRotorMotion({2.5, 1, 0, 1, -2e3, 0.7, 0}), "psi");
  // The bounds themselves are requests: a plan or a reason, not an exception.
  EXPECT_NO_THROW(planRotorMotion({2.5, 1, 0, 1, 0, 0.7, kMaxHeadingTurns}));
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
