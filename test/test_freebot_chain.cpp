// A chain of FreeBOT modules driven by its trolleys against independent truth: the contact point
// running a great circle of the base sphere at the forward speed, a spin in place that rolls
// nothing, a steady turn whose contact point closes a small circle with the holonomy of a cone
// (geodesic curvature u_s / u_f), and the closed loop bringing every joint to target contact
// points whose forward kinematics is known, within the wheel limits.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "spherical_robots/freebot/freebot_chain.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using spherical_robots::freebot::ChainState;
using spherical_robots::freebot::DriveLimits;
using spherical_robots::freebot::FreebotChain;
using spherical_robots::freebot::ModuleDrive;
using spherical_robots::freebot::SrcJointState;
using spherical_robots::freebot::TrolleyGains;
using spherical_robots::freebot::TrolleyGeometry;
using spherical_robots::freebot::TrolleySpeeds;
using spherical_robots::freebot::WheelSpeeds;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The contact normal of joint `i` in B_{i-1}'s frame (the unit vector from B_{i-1}'s centre
/// towards B_i's), read from the chain's forward kinematics, not from the joint state directly.
Eigen::Vector3d contactNormal(const FreebotChain& chain, const ChainState& state, std::size_t i) {
  const auto poses = chain.manipulator().forwardKinematics(state.joints);
  const Eigen::Vector3d base_centre = i == 0 ? Eigen::Vector3d::Zero() : poses[i - 1].position;
  const Eigen::Quaterniond base_orientation =
      i == 0 ? Eigen::Quaterniond::Identity() : poses[i - 1].orientation;
  return base_orientation.conjugate() * (poses[i].position - base_centre).normalized();
}

/// Wheel speeds that give these trolley speeds, from eq 65 solved here by hand from Table II's
/// geometry (appendix C): rim speed r_w w = r' u_f / r_out ± u_s l_w / 2.
WheelSpeeds wheelsFor(double forward, double steering, double outer_radius) {
  const double r_w = 0.005, l_w = 0.046, r_in = outer_radius - 0.002;
  const double r_contact = std::sqrt(r_in * r_in - 0.25 * l_w * l_w);
  const double mean = r_contact * forward / outer_radius / r_w;
  const double half = 0.5 * l_w * steering / r_w;
  return {mean + half, mean - half};
}

TEST(FreebotChainTest, StraightRunFollowsAGreatCircle) {
  // Both spheres of joint 2 differ (0.04 on 0.05): the contact point runs along the heading on
  // B_1 at u_f, so after T its normal has turned by u_f T / l_1 towards the heading.
  const FreebotChain chain({0.034, 0.05, 0.04}, TrolleyGeometry{});
  ChainState state = chain.alignedState();
  const double heading = 0.7, forward = 0.01, duration = 3.0;
  state.headings[1] = heading;
  const std::vector<WheelSpeeds> wheels = {{0.0, 0.0}, wheelsFor(forward, 0.0, 0.04)};
  for (int k = 0; k < 300; ++k) state = chain.advance(state, wheels, duration / 300);
  const double angle = forward * duration / 0.05;
  const Eigen::Vector3d expected(std::sin(angle) * std::cos(heading),
                                 std::sin(angle) * std::sin(heading), std::cos(angle));
  EXPECT_LT((contactNormal(chain, state, 1) - expected).norm(), 1e-9);
  EXPECT_NEAR(state.headings[1], heading, 1e-15);
  EXPECT_LT((contactNormal(chain, state, 0) - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
}

TEST(FreebotChainTest, SpinInPlaceRollsNothing) {
  const FreebotChain chain({0.034, 0.034}, TrolleyGeometry{});
  ChainState state = chain.alignedState();
  const double steering = 1.5;
  state = chain.advance(state, {wheelsFor(0.0, steering, 0.034)}, 1.0);
  EXPECT_NEAR(state.headings[0], steering, 1e-12);
  EXPECT_LT(state.joints[0].link.angularDistance(Eigen::Quaterniond::Identity()), 1e-15);
  EXPECT_LT(state.joints[0].base.angularDistance(Eigen::Quaterniond::Identity()), 1e-15);
}

TEST(FreebotChainTest, SteadyTurnClosesASmallCircleWithTheConeHolonomy) {
  // Constant u_f and u_s: geodesic curvature κ = u_s / u_f on B_0 (radius l_0), a circle of
  // angular radius α with cot α / l_0 = κ and length 2π l_0 sin α. After one lap the contact
  // point is back and the heading has turned by κ L = 2π cos α (the holonomy of the cap).
  const double l0 = 0.034;
  const FreebotChain chain({l0, 0.034}, TrolleyGeometry{});
  const double forward = 0.01, alpha = 0.6;
  const double steering = forward / (l0 * std::tan(alpha));
  const double lap = 2.0 * M_PI * l0 * std::sin(alpha) / forward;
  const std::vector<WheelSpeeds> wheels = {wheelsFor(forward, steering, 0.034)};
  // Steps that turn the heading by less than 0.01 rad (one sub-step each): the midpoint heading
  // makes the error second order, 4x smaller at half the step.
  std::vector<double> closing, off_circle;
  for (const int steps : {1000, 2000}) {
    ChainState state = chain.alignedState();
    double max_off = 0.0;
    for (int k = 0; k < steps; ++k) {
      state = chain.advance(state, wheels, lap / steps);
      // Every point of the lap stays on the circle through the start with centre direction at
      // α from the start, to the left of the heading (φ = 0 along x: the centre is towards +y).
      const Eigen::Vector3d centre(0.0, std::sin(alpha), std::cos(alpha));
      max_off = std::max(max_off, std::abs(std::acos(std::clamp(
                                               contactNormal(chain, state, 0).dot(centre), -1.0,
                                               1.0)) - alpha));
    }
    closing.push_back((contactNormal(chain, state, 0) - Eigen::Vector3d::UnitZ()).norm());
    off_circle.push_back(max_off);
    EXPECT_NEAR(state.headings[0],
                std::remainder(2.0 * M_PI * std::cos(alpha), 2.0 * M_PI), 1e-12) << steps;
  }
  EXPECT_LT(closing[1], 1e-6);
  EXPECT_LT(off_circle[1], 1e-6);
  EXPECT_NEAR(closing[0] / closing[1], 4.0, 0.2);
  EXPECT_NEAR(off_circle[0] / off_circle[1], 4.0, 0.2);
}

TEST(FreebotChainTest, ClosedLoopReachesTargetsWithinTheLimits) {
  // Equal radii (Table II): the contact points fix the joint states, so the end-effector pose
  // of the targets' forward kinematics is reached.
  const FreebotChain chain({0.034, 0.034, 0.034, 0.034}, TrolleyGeometry{});
  std::mt19937 random(3);
  std::uniform_real_distribution<double> angle(-2.5, 2.5);
  for (int trial = 0; trial < 6; ++trial) {
    // Even trials: Table II limits (a 2 rad/s turn needs 9.2 rad/s, under the 10 rad/s limit);
    // odd ones: wheels limited to 3 rad/s, which binds while steering.
    DriveLimits limits;
    if (trial % 2 == 1) limits.max_wheel_speed = 3.0;
    std::vector<Eigen::Vector2d> rolls;
    for (int i = 0; i < 3; ++i) rolls.emplace_back(angle(random), angle(random));
    const std::vector<SrcJointState> targets = chain.manipulator().straightRolls(rolls);
    ChainState state = chain.alignedState();
    for (double& heading : state.headings) heading = angle(random);
    bool arrived = false;
    double fastest = 0.0;
    const double dt = 0.01;
    for (int k = 0; k < 6000 && !arrived; ++k) {
      const std::vector<ModuleDrive> drives = chain.drive(state, targets, TrolleyGains{}, limits);
      std::vector<WheelSpeeds> wheels;
      arrived = true;
      for (const ModuleDrive& drive : drives) {
        wheels.push_back(drive.wheels);
        fastest = std::max({fastest, std::abs(drive.wheels.right), std::abs(drive.wheels.left)});
        EXPECT_LE(std::abs(drive.trolley.forward), limits.max_forward_speed + 1e-15);
        EXPECT_LE(std::abs(drive.trolley.steering), limits.max_steering_speed + 1e-12);
        arrived = arrived && drive.arrived;
      }
      state = chain.advance(state, wheels, dt);
    }
    ASSERT_TRUE(arrived) << "trial " << trial;
    EXPECT_LE(fastest, limits.max_wheel_speed + 1e-12);
    if (trial % 2 == 1) {
      EXPECT_GT(fastest, 0.999 * limits.max_wheel_speed);
    }
    const auto reached = chain.manipulator().endEffector(state.joints);
    const auto wanted = chain.manipulator().endEffector(targets);
    // Three contact arcs within 2 µm each on 34 mm spheres, levers below 0.21 m.
    EXPECT_LT((reached.position - wanted.position).norm(), 3 * 0.21 * 2e-6 / 0.017) << trial;
    EXPECT_LT(reached.orientation.angularDistance(wanted.orientation), 3 * 2 * 2e-6 / 0.034);
  }
}

TEST(FreebotChainTest, BadInputNamesTheProblem) {
  EXPECT_THROW(FreebotChain({0.034}, TrolleyGeometry{}), std::invalid_argument);
  EXPECT_THROW(FreebotChain({0.034, 0.002}, TrolleyGeometry{}), std::invalid_argument);
  EXPECT_THROW(FreebotChain({0.034, 0.02}, TrolleyGeometry{}), std::invalid_argument);  // l_w
  const FreebotChain chain({0.034, 0.034}, TrolleyGeometry{});
  ChainState state = chain.alignedState();
  EXPECT_THROW(chain.advance(state, {}, 0.01), std::invalid_argument);
  EXPECT_THROW(chain.advance(state, {{kNaN, 0.0}}, 0.01), std::invalid_argument);
  EXPECT_THROW(chain.advance(state, {{0.0, 0.0}}, -0.01), std::invalid_argument);
  state.headings[0] = kNaN;
  EXPECT_INVALID_ARGUMENT(chain.advance(state, {{0.0, 0.0}}, 0.01), "phi_1");
  DriveLimits limits;
  limits.contact_tolerance = 0.0;
  EXPECT_THROW(chain.drive(chain.alignedState(), {SrcJointState{}}, TrolleyGains{}, limits),
               std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
