// The serial SRC-joint manipulator (Zong, Liang, Lam 2022, section III) against independent
// truth: forward kinematics against the closed form of straight rolls (built here with
// Eigen::AngleAxis), the stacked aligned chain, and the Jacobian J_{B_n} (eq 38) against finite
// differences of the end-effector pose, rolling each joint by ±ε along each tangent-plane axis,
// for n = 2…6 with equal and unequal radii.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/freebot/src_manipulator.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using spherical_robots::freebot::LinkPose;
using spherical_robots::freebot::SrcJoint;
using spherical_robots::freebot::SrcJointState;
using spherical_robots::freebot::SrcManipulator;

Eigen::Quaterniond angleAxis(const Eigen::Vector3d& v) {
  if (v.norm() == 0.0) {
    return Eigen::Quaterniond::Identity();
  }
  return Eigen::Quaterniond(Eigen::AngleAxisd(v.norm(), v.normalized()));
}

Eigen::Vector3d logOf(const Eigen::Quaterniond& q) {
  const Eigen::AngleAxisd aa(q);
  return aa.angle() * aa.axis();
}

std::vector<double> radiiFor(std::size_t joints, bool equal, std::mt19937& rng) {
  std::uniform_real_distribution<double> radius(0.02, 0.06);
  std::vector<double> radii(joints + 1, 0.034);
  if (!equal) {
    for (double& r : radii) {
      r = radius(rng);
    }
  }
  return radii;
}

/// A general joint state: a straight roll, then a second roll in another direction (with
/// unequal radii not a straight roll of anything).
SrcJointState randomState(const SrcJoint& joint, std::mt19937& rng) {
  std::uniform_real_distribution<double> uniform(-1.5, 1.5);
  const SrcJointState first = joint.straightRoll({uniform(rng), uniform(rng)});
  return joint.roll(first, {uniform(rng), uniform(rng)}, 1.0);
}

TEST(SrcManipulatorTest, AlignedChainIsAStackOfSpheres) {
  const SrcManipulator chain({0.05, 0.03, 0.04, 0.02});
  const std::vector<LinkPose> poses =
      chain.forwardKinematics(std::vector<SrcJointState>(3, SrcJointState{}));
  const double heights[] = {0.08, 0.15, 0.21};
  for (int i = 0; i < 3; ++i) {
    EXPECT_LE((poses[i].position - Eigen::Vector3d(0, 0, heights[i])).norm(), 1e-15);
    EXPECT_LE(poses[i].orientation.angularDistance(Eigen::Quaterniond::Identity()), 1e-15);
  }
  EXPECT_NEAR(chain.reach(), 0.21, 1e-15);
}

TEST(SrcManipulatorTest, ForwardKinematicsOfStraightRollsInClosedForm) {
  // Straight roll u of joint i: B_i turns by exp(u) relative to B_{i-1}, and its centre sits at
  // (l_{i-1} + l_i) exp(l_i/(l_{i-1} + l_i) u) z in B_{i-1}'s frame.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(-2.0, 2.0);
  for (bool equal : {true, false}) {
    const std::vector<double> radii = radiiFor(4, equal, rng);
    const SrcManipulator chain(radii);
    std::vector<Eigen::Vector2d> u(4);
    for (auto& v : u) {
      v = {uniform(rng), uniform(rng)};
    }
    const std::vector<LinkPose> poses = chain.forwardKinematics(chain.straightRolls(u));
    Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) {
      const double sum = radii[i] + radii[i + 1];
      const Eigen::Vector3d rotation(u[i].x(), u[i].y(), 0.0);
      position += orientation *
                  (sum * (angleAxis(radii[i + 1] / sum * rotation) * Eigen::Vector3d::UnitZ()));
      orientation = orientation * angleAxis(rotation);
      EXPECT_LE((poses[i].position - position).norm(), 1e-15) << "link " << i + 1;
      EXPECT_LE(poses[i].orientation.angularDistance(orientation), 1e-13) << "link " << i + 1;
      EXPECT_LE(poses[i].joint.angularDistance(angleAxis(rotation)), 1e-13);
    }
    // Neighbouring spheres touch: centres l_{i-1} + l_i apart.
    Eigen::Vector3d previous = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR((poses[i].position - previous).norm(), radii[i] + radii[i + 1], 1e-15);
      previous = poses[i].position;
    }
  }
}

class JacobianTest : public ::testing::TestWithParam<std::tuple<int, bool>> {};

TEST_P(JacobianTest, MatchesFiniteDifferencesOfRolling) {
  const auto [joints, equal] = GetParam();
  std::mt19937 rng(100 + joints + (equal ? 0 : 50));
  for (int trial = 0; trial < 5; ++trial) {
    const std::vector<double> radii = radiiFor(joints, equal, rng);
    const SrcManipulator chain(radii);
    std::vector<SrcJointState> states;
    for (int i = 0; i < joints; ++i) {
      states.push_back(randomState(chain.joint(i), rng));
    }
    const Eigen::MatrixXd jacobian = chain.jacobian(states);
    ASSERT_EQ(jacobian.rows(), 6);
    ASSERT_EQ(jacobian.cols(), 2 * joints);
    const double eps = 1e-6;
    for (int i = 0; i < joints; ++i) {
      const double base = radii[i];
      const double link = radii[i + 1];
      for (int axis = 0; axis < 2; ++axis) {
        // Roll joint i by s about P_i's axis: B_i turns by s l_{i-1}/(l_i + l_{i-1}) and B_{i-1}
        // by −s l_i/(l_i + l_{i-1}) relative to P_i (rolling without slipping).
        const auto rolled = [&](double s) {
          std::vector<SrcJointState> out = states;
          const Eigen::Vector3d e = s * Eigen::Vector3d::Unit(axis);
          out[i].link = angleAxis(base / (base + link) * e) * states[i].link;
          out[i].base = angleAxis(-link / (base + link) * e) * states[i].base;
          return chain.forwardKinematics(out).back();
        };
        const LinkPose plus = rolled(eps);
        const LinkPose minus = rolled(-eps);
        const Eigen::Vector3d v = (plus.position - minus.position) / (2 * eps);
        const Eigen::Vector3d w =
            logOf(plus.orientation * minus.orientation.conjugate()) / (2 * eps);
        const int column = 2 * i + axis;
        EXPECT_LE((jacobian.col(column).head<3>() - v).norm(), 1e-8)
            << "joint " << i + 1 << " axis " << axis << ": " << jacobian.col(column).transpose()
            << " vs " << v.transpose();
        EXPECT_LE((jacobian.col(column).tail<3>() - w).norm(), 1e-8)
            << "joint " << i + 1 << " axis " << axis;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ChainsOf2To6, JacobianTest,
                         ::testing::Combine(::testing::Range(2, 7), ::testing::Bool()));

TEST(SrcManipulatorTest, PrimedJacobianOfEq35LacksTheLeverArmBeyondEachJoint) {
  // Errata F5: eq 38 stacks the primed J'_{B_n v} of eq 35, [^I R_{B_0} Φ_{1v} ... ^I R_{B_{n-1}}
  // Φ_{nv}], each joint's column moving only its own link. For three Table II links (0.034 m)
  // rolled by (0.5, 0.3), (−0.4, 0.6), (0.2, −0.7) rad it is off from J_{B_n v} by 0.124, 0.136,
  // 0.068, 0.068, 0, 0 m/s per rad/s (column norms).
  const SrcManipulator chain({0.034, 0.034, 0.034, 0.034});
  const std::vector<SrcJointState> states =
      chain.straightRolls({{0.5, 0.3}, {-0.4, 0.6}, {0.2, -0.7}});
  const std::vector<LinkPose> poses = chain.forwardKinematics(states);
  Eigen::MatrixXd primed(3, 6);
  for (int i = 0; i < 3; ++i) {
    const Eigen::Matrix3d base_to_inertial =
        i == 0 ? Eigen::Matrix3d::Identity() : poses[i - 1].orientation.toRotationMatrix();
    primed.middleCols<2>(2 * i) =
        base_to_inertial * chain.joint(i).freeModes(states[i]).bottomRows<3>();  // eq 35
  }
  const Eigen::MatrixXd off = chain.jacobian(states).topRows<3>() - primed;
  const double printed[] = {0.124, 0.136, 0.068, 0.068, 0.0, 0.0};
  for (int column = 0; column < 6; ++column) {
    EXPECT_NEAR(off.col(column).norm(), printed[column], 5e-4) << "column " << column + 1;
  }
}

TEST(SrcManipulatorTest, JacobianComesWithTheEndEffectorPose) {
  std::mt19937 rng(5);
  const SrcManipulator chain({0.03, 0.05, 0.02});
  const std::vector<SrcJointState> states = {randomState(chain.joint(0), rng),
                                             randomState(chain.joint(1), rng)};
  LinkPose end;
  chain.jacobian(states, end);
  const LinkPose fk = chain.forwardKinematics(states).back();
  EXPECT_LE((end.position - fk.position).norm(), 1e-16);
  EXPECT_LE(end.orientation.angularDistance(fk.orientation), 1e-15);
  EXPECT_LE((chain.endEffector(states).position - fk.position).norm(), 1e-16);
}

TEST(SrcManipulatorTest, RejectsBadInput) {
  EXPECT_THROW(SrcManipulator({0.03}), std::invalid_argument);
  EXPECT_THROW(SrcManipulator({0.03, 0.0}), std::invalid_argument);
  const SrcManipulator chain({0.03, 0.03, 0.03});
  EXPECT_INVALID_ARGUMENT(chain.forwardKinematics(std::vector<SrcJointState>(3)), "joint count");
  std::vector<SrcJointState> states(2);
  states[1].link = Eigen::Quaterniond(0.9, 0.0, 0.0, 0.0);
  EXPECT_INVALID_ARGUMENT(chain.forwardKinematics(states), "joint 2 q_{i,1}");
  EXPECT_THROW(chain.straightRolls({Eigen::Vector2d::Zero()}), std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
