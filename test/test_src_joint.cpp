// The two-DOF SRC joint (Zong, Liang, Lam 2022, section II) against independent truth: a
// world-frame integration of one sphere rolling on another without slipping or spinning, the
// arc lengths the contact point sweeps on both spheres, the velocity of B_i's material point at
// the contact, finite differences of eq 2 and of the free modes, and the mirror property of
// equal spheres. The printed rolling relations (eqs 1, 4, 5, 13, Table I) fail the same checks
// (docs/errata.md, F1-F3).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "spherical_robots/freebot/src_joint.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using spherical_robots::freebot::quaternionRate;
using spherical_robots::freebot::rotationQuaternion;
using spherical_robots::freebot::rotationVector;
using spherical_robots::freebot::SrcJoint;
using spherical_robots::freebot::SrcJointState;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Eigen::Quaterniond angleAxis(const Eigen::Vector3d& v) {
  if (v.norm() == 0.0) {
    return Eigen::Quaterniond::Identity();
  }
  return Eigen::Quaterniond(Eigen::AngleAxisd(v.norm(), v.normalized()));
}

/// A curved joint-velocity path [rad/s] (expressed along the P_i axes), so that states depend
/// on the path when the radii differ.
Eigen::Vector2d curvedVelocity(double t) {
  return {-0.3 + 1.8 * std::sin(1.3 * t), -0.15 + 1.5 * std::cos(0.7 * t)};
}

/// Independent truth: B_{i-1} fixed, its frame the world. B_i's centre c, orientation R and the
/// contact frame P (z along n = c/|c|, no spin about n) integrated by RK4 from
///   ω = R_P (u, 0)  (B_i's angular velocity, tangent: no spin),
///   ċ = l_i ω × n   (B_i's material point at the contact, c − l_i n, is at rest: no slip),
///   Ṙ = ω^× R,  Ṙ_P = (n × ṅ)^× R_P  (P follows the contact point without spinning).
struct WorldRolling {
  double base_radius;
  double link_radius;
  Eigen::Vector3d centre;
  Eigen::Matrix3d body = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d plane = Eigen::Matrix3d::Identity();

  WorldRolling(double base, double link)
      : base_radius(base), link_radius(link), centre(0.0, 0.0, base + link) {}

  struct Rates {
    Eigen::Vector3d centre;
    Eigen::Matrix3d body;
    Eigen::Matrix3d plane;
  };

  static Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
    Eigen::Matrix3d m;
    m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return m;
  }

  Rates rates(const Eigen::Vector3d& c, const Eigen::Matrix3d& r, const Eigen::Matrix3d& p,
              const Eigen::Vector2d& u) const {
    const Eigen::Vector3d n = c.normalized();
    const Eigen::Vector3d omega = p * Eigen::Vector3d(u.x(), u.y(), 0.0);
    const Eigen::Vector3d c_dot = link_radius * omega.cross(n);
    const Eigen::Vector3d n_dot = c_dot / (base_radius + link_radius);
    return {c_dot, skew(omega) * r, skew(n.cross(n_dot)) * p};
  }

  void step(double t, double dt) {
    const Rates k1 = rates(centre, body, plane, curvedVelocity(t));
    const Rates k2 = rates(centre + 0.5 * dt * k1.centre, body + 0.5 * dt * k1.body,
                           plane + 0.5 * dt * k1.plane, curvedVelocity(t + 0.5 * dt));
    const Rates k3 = rates(centre + 0.5 * dt * k2.centre, body + 0.5 * dt * k2.body,
                           plane + 0.5 * dt * k2.plane, curvedVelocity(t + 0.5 * dt));
    const Rates k4 = rates(centre + dt * k3.centre, body + dt * k3.body, plane + dt * k3.plane,
                           curvedVelocity(t + dt));
    centre += dt / 6 * (k1.centre + 2 * k2.centre + 2 * k3.centre + k4.centre);
    body += dt / 6 * (k1.body + 2 * k2.body + 2 * k3.body + k4.body);
    plane += dt / 6 * (k1.plane + 2 * k2.plane + 2 * k3.plane + k4.plane);
  }
};

/// The joint model rolled along curvedVelocity for `duration` in steps of dt (midpoint rule: the
/// model rolls exactly for a velocity held constant over a step).
SrcJointState modelRoll(const SrcJoint& joint, double duration, double dt) {
  SrcJointState state;
  for (double t = 0.0; t < duration - 1e-12; t += dt) {
    state = joint.roll(state, curvedVelocity(t + 0.5 * dt), dt);
  }
  return state;
}

class RadiiTest : public ::testing::TestWithParam<std::pair<double, double>> {};

/// Largest difference between the world-frame integration of B_i (radius link) rolling on B_{i-1}
/// (radius base) and a joint model after `duration`, both stepped with dt: centre [m] /
/// (l_i + l_{i-1}), B_i's and P_i's rotations.
double modelDiscrepancy(const SrcJoint& joint, double base, double link, double dt,
                        double duration) {
  WorldRolling world(base, link);
  for (double t = 0.0; t < duration - 1e-12; t += dt) {
    world.step(t, dt);
  }
  const SrcJointState state = modelRoll(joint, duration, dt);
  const double centre = (joint.position(state) - world.centre).norm() / (base + link);
  const double body = (SrcJoint::jointQuaternion(state).toRotationMatrix() - world.body).norm();
  const double plane = (state.base.conjugate().toRotationMatrix() - world.plane).norm();
  // The path went somewhere: the contact moved by more than a radian on B_{i-1}.
  EXPECT_LT(world.centre.normalized().z(), std::cos(1.0));
  return std::max({centre, body, plane});
}

TEST_P(RadiiTest, WorldFrameRollingMatchesTheJointModel) {
  const auto [base, link] = GetParam();
  // The model holds the velocity over a step (midpoint rule), RK4 does not: they differ by
  // O(dt²), and by nothing else — halving dt divides the discrepancy by 4.
  const SrcJoint joint(base, link);
  const double coarse = modelDiscrepancy(joint, base, link, 1e-3, 6.0);
  const double fine = modelDiscrepancy(joint, base, link, 5e-4, 6.0);
  EXPECT_LT(coarse, 1e-6);
  EXPECT_NEAR(coarse / fine, 4.0, 0.2);
}

/// What a joint model does at the contact over 3 s of the curved path (dt = 1e-4 s), with B_i of
/// radius link on B_{i-1} of radius base.
struct ContactSweep {
  double arc_base = 0.0;             ///< [m] swept by the contact point on B_{i-1}
  double arc_link = 0.0;             ///< [m] swept on B_i
  double worst_contact_speed = 0.0;  ///< [m/s] of B_i's material point at the contact
  double largest_speed = 0.0;        ///< [m/s] of B_i's centre
};

ContactSweep sweepContact(const SrcJoint& joint, double base, double link) {
  const double dt = 1e-4;
  SrcJointState state;
  ContactSweep sweep;
  const auto contact_on_base = [&](const SrcJointState& s) {
    return Eigen::Vector3d(base * joint.position(s).normalized());
  };
  const auto contact_on_link = [&](const SrcJointState& s) {  // in B_i's own frame
    return Eigen::Vector3d(SrcJoint::jointQuaternion(s).conjugate() *
                           (-link * joint.position(s).normalized()));
  };
  for (double t = 0.0; t < 3.0; t += dt) {
    const SrcJointState next = joint.roll(state, curvedVelocity(t + 0.5 * dt), dt);
    sweep.arc_base += (contact_on_base(next) - contact_on_base(state)).norm();
    sweep.arc_link += (contact_on_link(next) - contact_on_link(state)).norm();
    // Velocity of B_i's material point at the contact, from the model's pose (central in time).
    const Eigen::Quaterniond q0 = SrcJoint::jointQuaternion(state);
    const Eigen::Quaterniond q1 = SrcJoint::jointQuaternion(next);
    const Eigen::Vector3d omega = rotationVector(q1 * q0.conjugate()) / dt;
    const Eigen::Vector3d centre_rate = (joint.position(next) - joint.position(state)) / dt;
    const Eigen::Vector3d mid_normal = (joint.position(next) + joint.position(state)).normalized();
    const Eigen::Vector3d contact_rate = centre_rate + omega.cross(-link * mid_normal);
    sweep.worst_contact_speed = std::max(sweep.worst_contact_speed, contact_rate.norm());
    sweep.largest_speed = std::max(sweep.largest_speed, centre_rate.norm());
    state = next;
  }
  return sweep;
}

TEST_P(RadiiTest, ContactSweepsEqualArcsAndIsAtRest) {
  const auto [base, link] = GetParam();
  const ContactSweep sweep = sweepContact(SrcJoint(base, link), base, link);
  EXPECT_GT(sweep.arc_base, 0.5 * base);
  EXPECT_NEAR(sweep.arc_link / sweep.arc_base, 1.0, 1e-6);
  EXPECT_LT(sweep.worst_contact_speed, 1e-6 * sweep.largest_speed);
}

// Paper section V-A: l_i = 0.03 m on l_{i-1} = 0.04 m; plus equal radii and a large ratio.
INSTANTIATE_TEST_SUITE_P(Radii, RadiiTest,
                         ::testing::Values(std::make_pair(0.04, 0.03), std::make_pair(0.034, 0.034),
                                           std::make_pair(0.02, 0.07)));

TEST(SrcJointTest, PrintedRatesOfEqs1And13SlipWithUnequalRadii) {
  // Printed: ^Pω_{B_i} = l_i/(l_i+l_{i-1}) ω, ^Pω_{B_{i-1}} = −l_{i-1}/(l_i+l_{i-1}) ω. The arcs
  // then sweep l_i l_i/(L) vs l_{i-1} l_{i-1}/(L) per unit ‖ω‖: their ratio is (l_i/l_{i-1})².
  const double base = 0.04;
  const double link = 0.03;
  const double sum = base + link;
  const double printed_link_arc = link * link / sum;
  const double printed_base_arc = base * base / sum;
  EXPECT_NEAR(printed_link_arc / printed_base_arc, 0.5625, 1e-12);
  // The model's rates give equal arcs: l_i |^Pω_{B_i}| = l_{i-1} |^Pω_{B_{i-1}}| = l' |ω|.
  const SrcJoint joint(base, link);
  const Eigen::Vector2d omega(0.3, -0.4);
  EXPECT_NEAR(link * joint.linkRateInPlane(omega).norm(), base * link / sum * 0.5, 1e-15);
  EXPECT_NEAR(base * joint.baseRateInPlane(omega).norm(), base * link / sum * 0.5, 1e-15);
  // Relative rate of the bodies is the joint velocity itself (eq 1 and eq 13 together).
  EXPECT_LE((joint.linkRateInPlane(omega) - joint.baseRateInPlane(omega) -
             Eigen::Vector3d(0.3, -0.4, 0.0))
                .norm(),
            1e-15);
}

TEST(SrcJointTest, PrintedRatesSlipAndDriftFromRolling) {
  // Errata F1's figures for the printed rates, l_i = 0.03 m on l_{i-1} = 0.04 m. Eqs 1 and 13 as
  // printed, l_i/(l_i+l_{i-1}) ω and −l_{i-1}/(l_i+l_{i-1}) ω, are the corrected rates of a joint
  // with the two radii exchanged (and eq 7's centre distance l_i + l_{i-1} is the same).
  const double base = 0.04;
  const double link = 0.03;
  const SrcJoint printed(link, base);
  const ContactSweep sweep = sweepContact(printed, base, link);
  EXPECT_NEAR(sweep.arc_link / sweep.arc_base, 0.5625, 5e-5);  // (l_i/l_{i-1})²
  // The contact point moves at (l_{i-1} − l_i) |ω| and the centre at l_{i-1} |ω|; the path's
  // largest |ω| in 3 s is 1.7856 rad/s (at t = 3 s): 0.0179 and 0.071 m/s.
  EXPECT_NEAR(sweep.worst_contact_speed, 0.0179, 5e-5);
  EXPECT_NEAR(sweep.largest_speed, 0.071, 5e-4);
  // And it drifts from the world-frame rolling (RadiiTest's O(dt²) for the corrected rates).
  EXPECT_NEAR(modelDiscrepancy(printed, base, link, 1e-3, 6.0), 0.89, 5e-3);
}

TEST(SrcJointTest, QuaternionRateIsEq2) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Quaterniond q = Eigen::Quaterniond::UnitRandom();
    const Eigen::Vector3d omega(normal(rng), normal(rng), normal(rng));
    const double h = 1e-6;
    // The body turns at ω (reference frame) for ±h: q(±h) = exp(±h ω) q.
    const Eigen::Vector4d difference =
        ((angleAxis(h * omega) * q).coeffs() - (angleAxis(-h * omega) * q).coeffs()) / (2 * h);
    EXPECT_LE((quaternionRate(q, omega).coeffs() - difference).norm(), 1e-8);
  }
  EXPECT_THROW(quaternionRate(Eigen::Quaterniond::Identity(), {kNaN, 0, 0}), std::invalid_argument);
}

TEST(SrcJointTest, RotationVectorsRoundTrip) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::Vector3d v(uniform(rng), uniform(rng), uniform(rng));
    v = 3.0 * uniform(rng) * v.normalized();
    EXPECT_LE(rotationQuaternion(v).angularDistance(angleAxis(v)), 1e-14);
    EXPECT_LE((rotationVector(angleAxis(v)) - v).norm(), 1e-12);
  }
  const Eigen::Vector3d tiny(1e-9, -2e-9, 3e-9);
  EXPECT_LE((rotationVector(rotationQuaternion(tiny)) - tiny).norm(), 1e-22);
}

TEST(SrcJointTest, StraightRollIsExpOfTheRotationVectorForAnyRadii) {
  for (const auto& [base, link] : {std::make_pair(0.04, 0.03), std::make_pair(0.01, 0.05)}) {
    const SrcJoint joint(base, link);
    const Eigen::Vector2d u(0.7, -1.1);
    const SrcJointState state = joint.straightRoll(u);
    EXPECT_LE(SrcJoint::jointQuaternion(state).angularDistance(angleAxis({0.7, -1.1, 0.0})), 1e-14);
    // The contact point tilts by l_i/(l_i + l_{i-1}) of the roll: P turns with B_i's centre.
    const Eigen::Vector3d expected =
        (base + link) * (angleAxis(link / (base + link) * Eigen::Vector3d(0.7, -1.1, 0.0)) *
                         Eigen::Vector3d::UnitZ());
    EXPECT_LE((joint.position(state) - expected).norm(), 1e-15);
  }
}

TEST(SrcJointTest, EqualSpheresRollAsMirrorImages) {
  // Two equal spheres: B_i is B_{i-1} mirrored in the tangent plane, so q_i is the rotation about
  // z × n by twice the contact point's polar angle, whatever the path.
  const SrcJoint joint(0.034, 0.034);
  const SrcJointState state = modelRoll(joint, 5.0, 1e-2);
  const Eigen::Vector3d n = joint.position(state).normalized();
  const double polar = std::atan2(Eigen::Vector3d::UnitZ().cross(n).norm(), n.z());
  const Eigen::Quaterniond mirror =
      angleAxis(2.0 * polar * Eigen::Vector3d::UnitZ().cross(n).normalized());
  EXPECT_LE(SrcJoint::jointQuaternion(state).angularDistance(mirror), 1e-12);
  EXPECT_NEAR(SrcJoint::jointQuaternion(state).z(), 0.0, 1e-12);
  // ... hence the state is the straight roll by its rotation vector.
  const SrcJointState straight = joint.straightRoll(joint.rotationVectorOf(state));
  EXPECT_LE(SrcJoint::jointQuaternion(straight).angularDistance(SrcJoint::jointQuaternion(state)),
            1e-12);
  EXPECT_LE((joint.position(straight) - joint.position(state)).norm(), 1e-15);
}

TEST(SrcJointTest, UnequalSpheresDependOnThePath) {
  // Same contact point, different orientation: the joint state is not a function of (u_x, u_y).
  const SrcJoint joint(0.04, 0.03);
  const SrcJointState curved = modelRoll(joint, 5.0, 1e-2);
  const SrcJointState straight = joint.straightRoll(joint.rotationVectorOf(curved));
  EXPECT_LE((joint.position(straight) - joint.position(curved)).norm(), 1e-15);
  EXPECT_GT(SrcJoint::jointQuaternion(straight).angularDistance(SrcJoint::jointQuaternion(curved)),
            0.05);
}

TEST(SrcJointTest, FreeModesAreTheRollingVelocity) {
  // Φ_i (eq 16) against finite differences of the pose, rolling by ±ε about each P_i axis with
  // the rates of eqs 1 and 13 (rotations built here with Eigen::AngleAxis).
  for (const auto& [base, link] : {std::make_pair(0.04, 0.03), std::make_pair(0.034, 0.034)}) {
    const SrcJoint joint(base, link);
    const SrcJointState state = modelRoll(joint, 4.0, 1e-2);
    const spherical_robots::freebot::FreeModes phi = joint.freeModes(state);
    const double eps = 1e-6;
    const double sum = base + link;
    for (int axis = 0; axis < 2; ++axis) {
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
      const auto rolled = [&, base = base, link = link](double s) {  // copies: as above
        SrcJointState out;
        out.link = angleAxis(s * base / sum * e) * state.link;
        out.base = angleAxis(-s * link / sum * e) * state.base;
        return out;
      };
      const SrcJointState plus = rolled(eps);
      const SrcJointState minus = rolled(-eps);
      const Eigen::Vector3d v = (joint.position(plus) - joint.position(minus)) / (2 * eps);
      const Eigen::Vector3d w = rotationVector(SrcJoint::jointQuaternion(plus) *
                                               SrcJoint::jointQuaternion(minus).conjugate()) /
                                (2 * eps);
      EXPECT_LE((phi.col(axis).head<3>() - w).norm(), 1e-8) << "axis " << axis;
      EXPECT_LE((phi.col(axis).tail<3>() - v).norm(), 1e-9) << "axis " << axis;
    }
  }
}

TEST(SrcJointTest, RollingAboutXMovesTheLinkTowardsMinusY) {
  // At the aligned start a roll about x tilts B_i's centre towards −y at l_i per rad/s
  // (eq 16's sign; Table I's + sign and eq 14's l_{i-1} give +l_{i-1}).
  const SrcJoint joint(0.04, 0.03);
  const auto phi = joint.freeModes(SrcJointState{});
  EXPECT_LE((phi.col(0).tail<3>() - Eigen::Vector3d(0.0, -0.03, 0.0)).norm(), 1e-17);
  EXPECT_LE((phi.col(1).tail<3>() - Eigen::Vector3d(0.03, 0.0, 0.0)).norm(), 1e-17);
  EXPECT_LE((phi.col(0).head<3>() - Eigen::Vector3d::UnitX()).norm(), 1e-17);
}

TEST(SrcJointTest, RejectsBadInput) {
  EXPECT_INVALID_ARGUMENT(SrcJoint(0.0, 0.03), "l_{i-1}");
  EXPECT_INVALID_ARGUMENT(SrcJoint(0.03, -1.0), "l_i");
  EXPECT_INVALID_ARGUMENT(SrcJoint(0.03, kNaN), "l_i");
  const SrcJoint joint(0.03, 0.03);
  EXPECT_INVALID_ARGUMENT(joint.roll(SrcJointState{}, {kNaN, 0.0}, 1.0), "omega_x");
  SrcJointState bad;
  bad.base = Eigen::Quaterniond(1.0, 1e-4, 0.0, 0.0);
  EXPECT_INVALID_ARGUMENT(SrcJoint::requireValid(bad, "joint 2"), "joint 2 q_{i-1,2}");
  bad.base = Eigen::Quaterniond(1.0, 1e-5, 0.0, 0.0).normalized();
  EXPECT_NO_THROW(SrcJoint::requireValid(bad, "joint 2"));
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
