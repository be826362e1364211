// The body frame (REP 105 base_link) of a sphere on terrain and back (terrain::BodyFrame). Truth:
// closed forms on a tilted plane, the defining properties (gravity-aligned, x along h's horizontal
// projection, C = P0 + R n), the round trip state -> pose -> state on eq 59, and central finite
// differences of the pose along the kinematics' own rates for the twist.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/core/angles.hpp"
#include "spherical_robots/terrain/body_frame.hpp"
#include "spherical_robots/terrain/surface.hpp"
#include "spherical_robots/terrain/terrain_kinematics.hpp"
#include "terrain_test_support.hpp"

namespace {

using namespace spherical_robots::terrain;
using spherical_robots::wrapToPi;
using spherical_robots::yawOf;
using spherical_robots::test_support::kAllRobotTypes;

constexpr double kTiltLimit = M_PI / 3.0;

struct Random {
  std::mt19937 engine{7};
  double uniform(double low, double high) { return std::uniform_real_distribution<>(low, high)(engine); }
};

// Eq 59 with config/terrain.yaml's a and w, and a sphere five times the shipped one, whose
// R kappa = 0.8 makes the centre surface far from the contact surface (Newton has work to do).
const CosineSurface kEq59(0.2, 2.0);
constexpr double kLargeRadius = 1.0;

TEST(BodyFrame, PoseIsGravityAlignedAtTheCentreAlongTheHeadingsProjection) {
  Random random;
  for (int i = 0; i < 200; ++i) {
    const TerrainState state{random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-4, 4), 0.0};
    const ContactGeometry geometry = contactGeometry(kEq59, 0.2, state);
    const BodyPose pose = BodyFrame::pose(geometry);
    EXPECT_EQ(pose.centre, geometry.centre);
    const Eigen::Matrix3d axes = pose.orientation.toRotationMatrix();
    EXPECT_LT((axes.col(2) - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
    Eigen::Vector3d projected = geometry.heading_frame.col(0);
    projected.z() = 0.0;
    EXPECT_LT((axes.col(0) - projected.normalized()).norm(), 1e-15);
  }
}

TEST(BodyFrame, RoundTripRecoversTheState) {
  Random random;
  for (double radius : {0.2, kLargeRadius}) {
    const BodyFrame frame(kEq59, radius);
    double worst_position = 0.0, worst_heading = 0.0;
    for (int i = 0; i < 500; ++i) {
      const TerrainState state{random.uniform(-5, 5), random.uniform(-5, 5), random.uniform(-7, 7),
                               random.uniform(-1, 1)};
      const TerrainState back = frame.state(BodyFrame::pose(contactGeometry(kEq59, radius, state)), state.phi);
      worst_position = std::max({worst_position, std::abs(back.x - state.x), std::abs(back.y - state.y)});
      worst_heading = std::max(worst_heading, std::abs(wrapToPi(back.psi - state.psi)));
      EXPECT_EQ(back.phi, state.phi);
    }
    EXPECT_LT(worst_position, 1e-12) << "R = " << radius;
    EXPECT_LT(worst_heading, 1e-12) << "R = " << radius;
  }
}

// z = g x: n = (-sin a, 0, cos a) with tan a = g; the minimal rotation turns about y, so
// i_T = (cos a, 0, sin a), j_T = y and h = (cos psi cos a, sin psi, cos psi sin a).
TEST(BodyFrame, TiltedPlaneClosedForms) {
  const double slope = 0.7, radius = 0.3, alpha = std::atan(slope);
  const PlaneSurface plane(slope, 0.0, 0.25);
  const BodyFrame frame(plane, radius);
  const TerrainKinematics kinematics(plane, RobotType::ThreeAxisRolling, radius, ContactModel::Paper,
                                     kTiltLimit);
  for (double psi : {-2.5, -1.0, 0.0, 0.4, 1.5707963267948966, 3.0}) {
    const TerrainState state{0.8, -1.2, psi, 0.0};
    const ContactGeometry geometry = kinematics.geometry(state);
    const BodyPose pose = BodyFrame::pose(geometry);
    const Eigen::Vector3d centre(0.8 - radius * std::sin(alpha), -1.2,
                                 0.25 + slope * 0.8 + radius * std::cos(alpha));
    EXPECT_LT((pose.centre - centre).norm(), 1e-15);
    const double yaw = std::atan2(std::sin(psi), std::cos(psi) * std::cos(alpha));
    EXPECT_NEAR(wrapToPi(yawOf(pose.orientation) - yaw), 0.0, 1e-15) << "psi " << psi;

    // The paper model moves P0 (and so C, n being constant) at R theta' h; psi turns at psi'.
    const double roll = 1.3, turn = 0.6;
    const BodyTwist twist =
        frame.twist(geometry, kinematics.stateRate(state, geometry, {roll, 0.0, turn}));
    const double horizontal = std::hypot(std::cos(psi) * std::cos(alpha), std::sin(psi));
    EXPECT_NEAR(twist.linear.x(), radius * roll * horizontal, 1e-14);
    EXPECT_NEAR(twist.linear.y(), 0.0, 1e-14);
    EXPECT_NEAR(twist.linear.z(), radius * roll * std::cos(psi) * std::sin(alpha), 1e-14);
    EXPECT_EQ(twist.angular.x(), 0.0);
    EXPECT_EQ(twist.angular.y(), 0.0);
    // d yaw / d psi of the yaw above.
    EXPECT_NEAR(twist.angular.z(), turn * std::cos(alpha) / (horizontal * horizontal), 1e-14);

    // Back: P0 = C - R n exactly, and psi.
    const TerrainState back = frame.state(pose, 0.0);
    EXPECT_NEAR(back.x, 0.8, 1e-14);
    EXPECT_NEAR(back.y, -1.2, 1e-14);
    EXPECT_NEAR(wrapToPi(back.psi - psi), 0.0, 1e-14);
  }
}

// The twist against central differences of the pose along the state's own rate, in both contact
// models (the rolling model's psi' carries the tangent frame's turning; the paper's does not), for
// every type.
TEST(BodyFrame, TwistIsTheDerivativeOfThePose) {
  Random random;
  // [s]: the central difference's error, h^2/6 of the third derivative, stays below 1e-9 m/s,
  // and its rounding, |C| eps / h, below 1e-9 m/s.
  constexpr double kStep = 1e-6;
  for (ContactModel model : {ContactModel::Paper, ContactModel::Rolling}) {
    for (RobotType type : kAllRobotTypes) {
      const TerrainKinematics kinematics(kEq59, type, kLargeRadius, model, kTiltLimit);
      const BodyFrame frame(kEq59, kLargeRadius);
      for (int i = 0; i < 50; ++i) {
        const TerrainState state{random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-4, 4),
                                 random.uniform(-0.8, 0.8)};
        const DriveRates rates{random.uniform(-2, 2), random.uniform(-2, 2), random.uniform(-2, 2)};
        const TerrainStateRate rate = kinematics.stateRate(state, rates);
        auto moved = [&](double dt) {
          return BodyFrame::pose(kinematics.geometry({state.x + rate.x_dot * dt, state.y + rate.y_dot * dt,
                                                      state.psi + rate.psi_dot * dt, state.phi}));
        };
        const BodyPose after = moved(kStep), before = moved(-kStep);
        const BodyPose pose = BodyFrame::pose(kinematics.geometry(state));
        const BodyTwist twist = frame.twist(kinematics.geometry(state), rate);
        const Eigen::Vector3d velocity = (after.centre - before.centre) / (2.0 * kStep);
        EXPECT_LT((pose.orientation * twist.linear - velocity).norm(), 1e-8)
            << toString(model) << " " << toString(type) << " case " << i;
        const double yaw_rate =
            wrapToPi(yawOf(after.orientation) - yawOf(before.orientation)) / (2.0 * kStep);
        EXPECT_NEAR(twist.angular.z(), yaw_rate, 1e-7)
            << toString(model) << " " << toString(type) << " case " << i;
      }
    }
  }
}

TEST(BodyFrame, YawOfATiltedAttitudeIsItsXAxisHeading) {
  Random random;
  for (int i = 0; i < 100; ++i) {
    const double yaw = random.uniform(-3, 3);
    const Eigen::Quaterniond attitude = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                                        Eigen::AngleAxisd(random.uniform(-1.4, 1.4), Eigen::Vector3d::UnitY()) *
                                        Eigen::AngleAxisd(random.uniform(-3, 3), Eigen::Vector3d::UnitX());
    EXPECT_NEAR(wrapToPi(yawOf(attitude) - yaw), 0.0, 1e-13);
    // Scale does not matter.
    EXPECT_NEAR(wrapToPi(yawOf(Eigen::Quaterniond(attitude.coeffs() * 3.0)) - yaw), 0.0, 1e-13);
  }
}

TEST(BodyFrame, RefusesWhatHasNoState) {
  const BodyFrame frame(kEq59, 0.2);
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  EXPECT_INVALID_ARGUMENT(frame.state({Eigen::Vector3d(kNaN, 0, 0), Eigen::Quaterniond::Identity()}, 0.0),
                          "not finite");
  EXPECT_INVALID_ARGUMENT(frame.state({Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity()}, kNaN),
                          "phi");
  // x axis straight up: a quarter turn about y.
  const Eigen::Quaterniond up(Eigen::AngleAxisd(-M_PI / 2.0, Eigen::Vector3d::UnitY()));
  EXPECT_INVALID_ARGUMENT(frame.state({Eigen::Vector3d::Zero(), up}, 0.0), "vertical x axis");
  EXPECT_INVALID_ARGUMENT(BodyFrame(kEq59, 2.0), "single-point contact");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
