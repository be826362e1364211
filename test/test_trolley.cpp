// The FreeBOT driving trolley (Zong, Liang, Lam 2022, section IV, appendix C) against
// independent truth: the wheel geometry of appendix C worked out here, round trips between
// wheel speeds and trolley speeds and between joint velocity and trolley motion, the contact
// point moving along the trolley's heading at the forward speed, the arc plan reaching the
// target contact, and the closed-loop control laws.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/freebot/src_joint.hpp"
#include "spherical_robots/freebot/trolley_control.hpp"
#include "spherical_robots/freebot/trolley_drive.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using spherical_robots::freebot::ArcDrive;
using spherical_robots::freebot::ArcPlan;
using spherical_robots::freebot::dependentControl;
using spherical_robots::freebot::driveToContact;
using spherical_robots::freebot::effectiveRadius;
using spherical_robots::freebot::forwardSpeed;
using spherical_robots::freebot::jointVelocityOf;
using spherical_robots::freebot::planArc;
using spherical_robots::freebot::SrcJoint;
using spherical_robots::freebot::SrcJointState;
using spherical_robots::freebot::TrolleyDrive;
using spherical_robots::freebot::TrolleyGains;
using spherical_robots::freebot::trolleyReference;
using spherical_robots::freebot::TrolleySpeeds;
using spherical_robots::freebot::WheelSpeeds;
using spherical_robots::wrapToPi;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Table II geometry.
const TrolleyDrive kTableII(0.005, 0.046, 0.032, 0.034);

TEST(TrolleyDriveTest, WheelGeometryOfAppendixC) {
  // Wheels 23 mm either side of the middle touch the inner shell (32 mm) at
  // r' = sqrt(0.032² − 0.023²) = 22.249 mm from the shell's turning axis.
  EXPECT_NEAR(kTableII.wheelContactRadius(), std::sqrt(0.032 * 0.032 - 0.023 * 0.023), 1e-17);
  EXPECT_NEAR(kTableII.wheelContactRadius(), 0.0222486, 1e-7);
  // Both wheels at 1 rad/s: rim speed 5 mm/s turns the shell at 0.005 / r' rad/s, whose outer
  // surface moves at 0.034 times that.
  const TrolleySpeeds forward = kTableII.trolleySpeeds({1.0, 1.0});
  EXPECT_NEAR(forward.forward, 0.034 * 0.005 / 0.0222486, 1e-8);
  EXPECT_NEAR(forward.steering, 0.0, 1e-18);
  // Opposite wheels: the rims (23 mm off the middle) yaw the trolley at 0.005 / 0.023 rad/s.
  const TrolleySpeeds spin = kTableII.trolleySpeeds({1.0, -1.0});
  EXPECT_NEAR(spin.forward, 0.0, 1e-18);
  EXPECT_NEAR(spin.steering, 2 * 0.005 / 0.046, 1e-16);
}

TEST(TrolleyDriveTest, WheelAndTrolleySpeedsRoundTrip) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> uniform(-20.0, 20.0);
  for (int trial = 0; trial < 100; ++trial) {
    const WheelSpeeds wheels{uniform(rng), uniform(rng)};
    const WheelSpeeds back = kTableII.wheelSpeeds(kTableII.trolleySpeeds(wheels));
    EXPECT_NEAR(back.right, wheels.right, 1e-13);
    EXPECT_NEAR(back.left, wheels.left, 1e-13);
    const TrolleySpeeds trolley{0.01 * uniform(rng), uniform(rng)};
    const TrolleySpeeds again = kTableII.trolleySpeeds(kTableII.wheelSpeeds(trolley));
    EXPECT_NEAR(again.forward, trolley.forward, 1e-15);
    EXPECT_NEAR(again.steering, trolley.steering, 1e-13);
  }
}

TEST(TrolleyDriveTest, RejectsImpossibleGeometry) {
  EXPECT_INVALID_ARGUMENT(TrolleyDrive(0.005, 0.064, 0.032, 0.034), "wheel interval");
  EXPECT_INVALID_ARGUMENT(TrolleyDrive(0.005, 0.046, 0.035, 0.034), "inner radius");
  EXPECT_INVALID_ARGUMENT(TrolleyDrive(0.0, 0.046, 0.032, 0.034), "wheel radius");
  EXPECT_INVALID_ARGUMENT(TrolleyDrive(0.005, kNaN, 0.032, 0.034), "wheel interval");
  EXPECT_INVALID_ARGUMENT(kTableII.wheelSpeeds({kNaN, 0.0}), "u_f");
}

TEST(TrolleyControlTest, JointVelocityAndTrolleyMotionRoundTripInEveryQuadrant) {
  const SrcJoint joint(0.04, 0.03);
  EXPECT_NEAR(effectiveRadius(joint), 0.04 * 0.03 / 0.07, 1e-18);
  for (int k = 0; k < 16; ++k) {
    const double angle = -M_PI + (k + 0.5) * M_PI / 8;
    const Eigen::Vector2d omega = 0.7 * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    const auto reference = trolleyReference(joint, omega);
    EXPECT_NEAR(reference.forward_speed, 0.7 * 0.04 * 0.03 / 0.07, 1e-15);
    EXPECT_LE((jointVelocityOf(joint, reference.forward_speed, reference.direction) - omega).norm(),
              1e-14);
  }
  const auto zero = trolleyReference(joint, Eigen::Vector2d::Zero());
  EXPECT_EQ(zero.forward_speed, 0.0);
}

TEST(TrolleyControlTest, ContactPointRunsAlongTheHeadingAtTheForwardSpeed) {
  // The trolley stays at the contact point: moving at u_f along φ, the contact point moves at
  // u_f along φ over B_{i-1} (in P_i), and over B_i's shell at u_f as well.
  const SrcJoint joint(0.04, 0.03);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const SrcJointState state = joint.straightRoll({uniform(rng), uniform(rng)});
  const double u_f = 0.02;
  const double dt = 1e-7;
  for (double phi : {0.3, 2.0, -2.5}) {
    const SrcJointState next = joint.roll(state, jointVelocityOf(joint, u_f, phi), dt);
    const Eigen::Vector3d contact0 = 0.04 * joint.position(state).normalized();
    const Eigen::Vector3d contact1 = 0.04 * joint.position(next).normalized();
    const Eigen::Vector3d in_plane = state.base * (contact1 - contact0) / dt;  // into P_i
    EXPECT_LE((in_plane - u_f * Eigen::Vector3d(std::cos(phi), std::sin(phi), 0.0)).norm(), 1e-8);
    const auto on_link = [&](const SrcJointState& s) {
      return Eigen::Vector3d(SrcJoint::jointQuaternion(s).conjugate() *
                             (-0.03 * joint.position(s).normalized()));
    };
    EXPECT_NEAR((on_link(next) - on_link(state)).norm() / dt, u_f, 1e-8);
  }
}

TEST(TrolleyControlTest, ArcPlanOfEq55) {
  // From the aligned start to a straight roll u the contact runs l_{i-1} l_i/(l_i + l_{i-1}) ‖u‖
  // along the heading of (u_y, −u_x) (eq 51: u ∥ (−sin φ, cos φ)).
  const SrcJoint joint(0.04, 0.03);
  const Eigen::Vector2d u(-0.6, 0.9);
  const ArcPlan plan = planArc(joint, SrcJointState{}, joint.straightRoll(u));
  EXPECT_NEAR(plan.distance, 0.04 * 0.03 / 0.07 * u.norm(), 1e-15);
  EXPECT_NEAR(plan.direction, std::atan2(-u.x(), u.y()), 1e-14);
  EXPECT_NEAR(planArc(joint, SrcJointState{}, SrcJointState{}).distance, 0.0, 1e-18);
}

TEST(TrolleyControlTest, SteerThenMoveReachesTheTargetContact) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> uniform(-1.5, 1.5);
  for (const auto& [base, link] : {std::make_pair(0.034, 0.034), std::make_pair(0.04, 0.03)}) {
    const SrcJoint joint(base, link);
    for (int trial = 0; trial < 5; ++trial) {
      const SrcJointState start = joint.straightRoll({uniform(rng), uniform(rng)});
      const SrcJointState target = joint.straightRoll({uniform(rng), uniform(rng)});
      const ArcDrive drive = driveToContact(joint, start, uniform(rng), target, TrolleyGains{},
                                            1e-3, 1e-6, 1e-7, 60.0);
      EXPECT_LT(drive.time, 60.0);
      const Eigen::Vector3d reached = joint.position(drive.state).normalized();
      const Eigen::Vector3d wanted = joint.position(target).normalized();
      EXPECT_LE(base * (reached - wanted).norm(), 1e-6);
      if (base == link) {
        // Equal spheres: the contact point fixes the whole joint state.
        EXPECT_LE(SrcJoint::jointQuaternion(drive.state)
                      .angularDistance(SrcJoint::jointQuaternion(target)),
                  1e-4);
      }
    }
  }
}

TEST(TrolleyControlTest, DependentControlAlignsTheHeading) {
  // Closed loop of eqs 49, 57 with a fixed reference: φ_e → 0 and u_f → u_f^r.
  const TrolleyGains gains;
  const spherical_robots::freebot::TrolleyReference reference{0.01, 1.2};
  double phi = -2.0;
  TrolleySpeeds speeds;
  for (int step = 0; step < 5000; ++step) {
    speeds = dependentControl(reference, 0.0, phi, gains);
    phi += 1e-3 * speeds.steering;
  }
  EXPECT_NEAR(wrapToPi(reference.direction - phi), 0.0, 1e-9);
  EXPECT_NEAR(speeds.forward, reference.forward_speed, 1e-12);
  // Eq 63 with ṡ = u_f: s → s^r.
  double s = 0.0;
  for (int step = 0; step < 10000; ++step) {
    s += 1e-3 * forwardSpeed(0.05, 0.0, s, gains);
  }
  EXPECT_NEAR(s, 0.05, 1e-12);
  EXPECT_NEAR(wrapToPi(3 * M_PI), M_PI, 1e-15);
  EXPECT_NEAR(wrapToPi(-M_PI), M_PI, 1e-15);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
