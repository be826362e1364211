// Correcting a manoeuvre of the two-rotor sphere (manoeuvre_correction.hpp): where a plan ends when
// traced from a rest pose other than the zero state, against the plant (eqs 6-11) driven by the
// plan's rotor set-points from that pose; the correction target as planEnd's inverse; and the rest
// pose read back from attitudes built by eq 2.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "spherical_robots/rotor/manoeuvre_correction.hpp"
#include "spherical_robots/rotor/motion_planner.hpp"
#include "spherical_robots/rotor/plan_execution.hpp"

namespace {

using namespace spherical_robots::rotor;

constexpr double kScale = 12.0;  // J_zz / J_r

// The plant rolled by the plan's set-points held every `hold` [s] from a rest pose.
ContactCoordinates traceFrom(const RestPose& start, double k, const FigureEight& curve,
                             const CurveTiming& timing, double hold) {
  ContactCoordinates x{start.u_a, start.v_a, 0.0, 0.0, start.psi};
  const int holds = static_cast<int>(std::ceil(timing.duration() / hold));
  for (int i = 0; i < holds; ++i) {
    x = advancePlant(k, kScale, x, planSetPointAt(k, kScale, curve, timing, i * hold), hold, hold);
  }
  return x;
}

TEST(ManoeuvreCorrection, PlanEndMatchesThePlantFromAnyRestPose) {
  const double k = 2.5;
  PlanRequest request;
  request.k = k;
  request.steps = 2;
  request.u_a = 0.5;
  request.v_a = 0.3;
  request.psi = 0.4;
  const PlanResult result = planRotorMotion(request);
  ASSERT_FALSE(result.solutions.empty()) << result.reason;
  const RotorPlan& plan = result.solutions.front();
  const FigureEight curve(plan.a, plan.b, plan.gamma);
  const CurveTiming timing(request.steps, 1.0, 1.0);
  for (const RestPose start : {RestPose{0.0, 0.0, 0.0}, RestPose{0.3, -0.2, 0.7},
                               RestPose{-1.5, 2.0, -2.9}, RestPose{0.1, 0.1, M_PI}}) {
    const ContactCoordinates reached = traceFrom(start, k, curve, timing, 1e-3);
    const RestPose predicted = planEnd(start, {request.u_a, request.v_a, request.psi});
    // 1 ms holds cost 1.7e-7 R from the zero state (test_rotor_execution); the same here.
    EXPECT_NEAR(reached.u_a, predicted.u_a, 1e-6) << "from psi " << start.psi;
    EXPECT_NEAR(reached.v_a, predicted.v_a, 1e-6) << "from psi " << start.psi;
    EXPECT_NEAR(reached.psi, predicted.psi, 1e-6) << "from psi " << start.psi;
    EXPECT_NEAR(reached.u_o, 0.0, 1e-6);
    EXPECT_NEAR(reached.v_o, 0.0, 1e-6);
  }
}

TEST(ManoeuvreCorrection, CorrectionTargetInvertsPlanEnd) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> place(-3.0, 3.0);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI);
  for (int i = 0; i < 1000; ++i) {
    const RestPose from{place(random), place(random), angle(random)};
    const RestPose to{place(random), place(random), angle(random) + 2.0 * M_PI * (i % 3 - 1)};
    const PlanTarget target = correctionTarget(from, to);
    EXPECT_GT(target.psi, -M_PI);
    EXPECT_LE(target.psi, M_PI);
    const RestPose end = planEnd(from, target);
    EXPECT_NEAR(end.u_a, to.u_a, 1e-12);
    EXPECT_NEAR(end.v_a, to.v_a, 1e-12);
    EXPECT_NEAR(std::remainder(end.psi - to.psi, 2.0 * M_PI), 0.0, 1e-12);
    // The displacement keeps its length: the plane only turns it.
    EXPECT_NEAR(std::hypot(target.u_a, target.v_a), std::hypot(to.u_a - from.u_a, to.v_a - from.v_a),
                1e-12);
  }
  // Already there: nothing to do.
  const PlanTarget none = correctionTarget({0.2, 0.1, 1.0}, {0.2, 0.1, 1.0 + 2.0 * M_PI});
  EXPECT_NEAR(none.u_a, 0.0, 1e-15);
  EXPECT_NEAR(none.v_a, 0.0, 1e-15);
  EXPECT_NEAR(none.psi, 0.0, 1e-12);
}

TEST(ManoeuvreCorrection, MeasuredRestPoseReadsEq2Attitudes) {
  for (const double psi : {0.0, 0.4, -1.2, 3.0, -3.1, M_PI}) {
    const Eigen::Quaterniond attitude(orientation(0.0, 0.0, psi));
    const RestPose pose = measuredRestPose(0.05, -0.02, 0.1, attitude);
    EXPECT_NEAR(pose.u_a, 0.5, 1e-15);
    EXPECT_NEAR(pose.v_a, -0.2, 1e-15);
    EXPECT_NEAR(std::remainder(pose.psi - psi, 2.0 * M_PI), 0.0, 1e-12) << psi;
    EXPECT_GT(pose.psi, -M_PI);
    EXPECT_LE(pose.psi, M_PI);
    // The sign of the quaternion does not matter.
    const Eigen::Quaterniond negated(-attitude.w(), -attitude.x(), -attitude.y(), -attitude.z());
    EXPECT_NEAR(std::remainder(measuredRestPose(0.0, 0.0, 0.1, negated).psi - psi, 2.0 * M_PI), 0.0,
                1e-12);
  }
  // A contact 1e-3 rad off the south pole: ψ within second order of the tilt.
  const Eigen::Quaterniond tilted(orientation(1e-3, -2e-3, 0.4));
  EXPECT_NEAR(measuredRestPose(0.0, 0.0, 0.1, tilted).psi, 0.4, 5e-6);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(measuredRestPose(nan, 0.0, 0.1, Eigen::Quaterniond::Identity()),
               std::invalid_argument);
  EXPECT_THROW(measuredRestPose(0.0, 0.0, 0.0, Eigen::Quaterniond::Identity()),
               std::invalid_argument);
  EXPECT_THROW(measuredRestPose(0.0, 0.0, 0.1, Eigen::Quaterniond(nan, 0.0, 0.0, 0.0)),
               std::invalid_argument);
  EXPECT_INVALID_ARGUMENT(measuredRestPose(0.0, 0.0, 0.1, Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0)),
                          "upside down");
  // An unset odom orientation is no attitude.
  EXPECT_INVALID_ARGUMENT(measuredRestPose(0.0, 0.0, 0.1, Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0)),
                          "norm 1 within 1e-3", "norm 0");
  EXPECT_INVALID_ARGUMENT(measuredContactAngles(Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0)),
                          "norm 1 within 1e-3");
  EXPECT_THROW(planEnd({nan, 0.0, 0.0}, {}), std::invalid_argument);
  EXPECT_THROW(correctionTarget({}, {0.0, 0.0, nan}), std::invalid_argument);
}

TEST(ManoeuvreCorrection, ContactAnglesReadEq2Attitudes) {
  for (const auto& [u_o, v_o, psi] : {std::tuple{0.0, 0.0, 0.3}, std::tuple{2e-3, -1.5e-3, -2.0},
                                      std::tuple{0.4, 0.3, 1.0}, std::tuple{-1.0, 0.5, 3.0}}) {
    const Eigen::Vector2d angles = measuredContactAngles(Eigen::Quaterniond(orientation(u_o, v_o, psi)));
    EXPECT_NEAR(angles.x(), u_o, 1e-12);
    EXPECT_NEAR(angles.y(), v_o, 1e-12);
  }
  EXPECT_INVALID_ARGUMENT(measuredContactAngles(Eigen::Quaterniond(0.0, 1.0, 0.0, 0.0)),
                          "above the sphere's equator");
}

// The arc traced through the plant: the contact ends at the south pole; the arc is a geodesic of
// the angle between its ends, its tangent the derivative of its points.
TEST(ManoeuvreCorrection, PoleReturnArcBringsTheContactBackToThePole) {
  const double k = 2.5;
  const CurveTiming timing(1, 1.0, 1.0);
  for (const auto& [u_o, v_o] : {std::pair{2e-3, -1.5e-3}, std::pair{0.2, -0.1},
                                 std::pair{-0.05, 0.3}}) {
    const PoleReturnArc arc(u_o, v_o);
    const Eigen::Vector3d start = contactPoint(u_o, v_o);
    EXPECT_NEAR(arc.angle(), std::acos(-start.z()), 1e-9);
    EXPECT_LE((arc.at(0.0).point - start).norm(), 1e-15);
    EXPECT_LE((arc.at(2.0 * M_PI).point - Eigen::Vector3d(0.0, 0.0, -1.0)).norm(), 1e-15);
    for (const double theta : {0.5, 2.0, 4.0}) {
      const Eigen::Vector3d difference = (arc.at(theta + 1e-6).point - arc.at(theta - 1e-6).point) / 2e-6;
      EXPECT_LE((difference - arc.at(theta).tangent).norm(), 1e-8);
      EXPECT_NEAR(arc.at(theta).point.norm(), 1.0, 1e-15);
    }
    ContactCoordinates x{0.3, -0.2, u_o, v_o, 0.7};
    const double hold = 1e-3;
    for (int i = 0; i * hold < timing.duration(); ++i) {
      x = advancePlant(k, kScale, x, arcSetPointAt(k, kScale, arc, timing, i * hold), hold, hold);
    }
    EXPECT_NEAR(x.u_o, 0.0, 1e-6 * (arc.angle() + 1e-3)) << "from " << u_o << ", " << v_o;
    EXPECT_NEAR(x.v_o, 0.0, 1e-6 * (arc.angle() + 1e-3)) << "from " << u_o << ", " << v_o;
  }
  EXPECT_EQ(PoleReturnArc(0.0, 0.0).angle(), 0.0);
  const RotorSpeeds still = arcSetPointAt(k, kScale, PoleReturnArc(0.0, 0.0), timing, 2.0);
  EXPECT_EQ(still.phi1, 0.0);
  EXPECT_EQ(still.phi2, 0.0);
  EXPECT_THROW(PoleReturnArc(M_PI, 0.0), std::invalid_argument);
  EXPECT_THROW(arcSetPointAt(k, kScale, PoleReturnArc(0.1, 0.0), CurveTiming(2, 1.0, 1.0), 1.0),
               std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
