// The tangent frame F_T (paper eqs 10-24, appendix A) and the heading frame F_L (eqs 25-27), in
// the right-handed convention of docs/conventions.md. Truth: the paper's own formulas evaluated
// independently here (Rodrigues eq 19, eq 23, the quaternion route of appendix A with its matrix
// corrected), Eigen's axis-angle/quaternion, and the defining geometric properties.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "spherical_robots/terrain/tangent_frame.hpp"

namespace {

using spherical_robots::terrain::headingFrame;
using spherical_robots::terrain::surfaceNormal;
using spherical_robots::terrain::tangentFrame;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string str(const Eigen::Vector2d& g) {
  return "gradient (" + std::to_string(g.x()) + ", " + std::to_string(g.y()) + ")";
}

// Eq 10: n = s_n (-f_x, -f_y, 1).
Eigen::Vector3d normalEq10(const Eigen::Vector2d& g) {
  return Eigen::Vector3d(-g.x(), -g.y(), 1.0) / std::sqrt(1.0 + g.squaredNorm());
}

// Eq 19: R = I + sin(gamma) E + (1 - cos(gamma)) E^2, with e = z x n / |z x n| (eqs 11-13) and
// gamma = atan2(|z x n|, z . n) (eq 14). Defined only away from flat points.
Eigen::Matrix3d rodriguesEq19(const Eigen::Vector2d& g) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d n = normalEq10(g);
  const Eigen::Vector3d zxn = z.cross(n);
  const Eigen::Vector3d e = zxn.normalized();
  const double gamma = std::atan2(zxn.norm(), z.dot(n));
  Eigen::Matrix3d ex;
  ex << 0, -e.z(), e.y(), e.z(), 0, -e.x(), -e.y(), e.x(), 0;
  return Eigen::Matrix3d::Identity() + std::sin(gamma) * ex + (1.0 - std::cos(gamma)) * ex * ex;
}

// Eq 23 as printed (world <- tangent), with s = |grad|^-1 (eq 13) and s_n (eq 7).
Eigen::Matrix3d printedEq23(const Eigen::Vector2d& g) {
  const double fx = g.x(), fy = g.y();
  const double s2 = 1.0 / (fx * fx + fy * fy);
  const double sn = 1.0 / std::sqrt(1.0 + fx * fx + fy * fy);
  Eigen::Matrix3d r;
  r << 1 - s2 * fx * fx * (1 - sn), -s2 * fx * fy * (1 - sn), -sn * fx,  //
      -s2 * fx * fy * (1 - sn), 1 - s2 * fy * fy * (1 - sn), -sn * fy,   //
      sn * fx, sn * fy, sn;
  return r;
}

// Appendix A, corrected: the standard unit-quaternion rotation matrix with q_k = 0 (the e_z = 0
// axis of eq 13). The printed A.6 has sign/index typos in (0,2), (2,0), (2,1): the correct entries
// are 2 q_j q_r, -2 q_j q_r, +2 q_i q_r. Quaternion from A.1 and the text below A.6:
// q_r = cos(gamma/2), q_i = s f_y sin(gamma/2), q_j = -s f_x sin(gamma/2).
struct AppendixQuaternion {
  double qr, qi, qj;  // q_k = 0
};
AppendixQuaternion appendixQuaternion(const Eigen::Vector2d& g) {
  const double s = 1.0 / g.norm();
  const double gamma = std::atan2(g.norm(), 1.0);  // eq 16: atan2(s^-1, 1)
  return {std::cos(gamma / 2), s * g.y() * std::sin(gamma / 2), -s * g.x() * std::sin(gamma / 2)};
}

Eigen::Matrix3d correctedA6(const Eigen::Vector2d& g) {
  const auto [qr, qi, qj] = appendixQuaternion(g);
  Eigen::Matrix3d r;
  r << 1 - 2 * qj * qj, 2 * qi * qj, 2 * qj * qr,  //
      2 * qi * qj, 1 - 2 * qi * qi, -2 * qi * qr,  //
      -2 * qj * qr, 2 * qi * qr, 1 - 2 * (qi * qi + qj * qj);
  return r;
}

// The printed heading frame, eq 27 (the rotation part of eq 26).
Eigen::Matrix3d printedEq27(const Eigen::Vector2d& g, double psi) {
  const double fx = g.x(), fy = g.y();
  const double s2 = 1.0 / (fx * fx + fy * fy);
  const double sn = 1.0 / std::sqrt(1.0 + fx * fx + fy * fy);
  const double c = std::cos(psi), sp = std::sin(psi);
  const double a = 1 - s2 * fx * fx * (1 - sn), b = s2 * fx * fy * (1 - sn),
               d = 1 - s2 * fy * fy * (1 - sn);
  Eigen::Matrix3d r;
  r << a * c + b * sp, a * sp - b * c, -sn * fx,       //
      -b * c - d * sp, -b * sp + d * c, -sn * fy,      //
      sn * fx * c - sn * fy * sp, sn * fx * sp + sn * fy * c, sn;
  return r;
}

void expectRotation(const Eigen::Matrix3d& r, double tol = 1e-12) {
  EXPECT_TRUE((r.transpose() * r).isApprox(Eigen::Matrix3d::Identity(), tol))
      << "R^T R =\n" << r.transpose() * r;
  EXPECT_NEAR(r.determinant(), 1.0, tol);
}

void expectMatrixNear(const Eigen::Matrix3d& actual, const Eigen::Matrix3d& expected, double tol) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tol) << "actual\n"
                                                            << actual << "\nexpected\n"
                                                            << expected;
}

// Sloped gradients: gentle, along one axis only, steep (about 75 degrees), mixed signs.
const std::vector<Eigen::Vector2d> kSlopedGradients = {
    {0.1, 0.0},  {0.0, -0.3}, {0.4, 0.4},   {-0.25, 0.6}, {1.0, -1.0},
    {3.0, -2.0}, {-0.8, 0.0}, {0.05, -0.02}, {-2.5, -0.7}};

class TangentFrameOnSlope : public ::testing::TestWithParam<Eigen::Vector2d> {};

TEST_P(TangentFrameOnSlope, IsAProperRotation) {
  expectRotation(tangentFrame(GetParam()));
}

TEST_P(TangentFrameOnSlope, ThirdColumnIsTheUnitNormalOfEq10) {
  const Eigen::Vector2d g = GetParam();
  const Eigen::Matrix3d r = tangentFrame(g);
  EXPECT_LE((r.col(2) - normalEq10(g)).norm(), 1e-14);
  EXPECT_LE((surfaceNormal(g) - normalEq10(g)).norm(), 1e-14);
  // n points up and is orthogonal to both surface tangents (1, 0, f_x) and (0, 1, f_y).
  EXPECT_GT(r(2, 2), 0.0);
  EXPECT_NEAR(r.col(2).dot(Eigen::Vector3d(1, 0, g.x())), 0.0, 1e-14);
  EXPECT_NEAR(r.col(2).dot(Eigen::Vector3d(0, 1, g.y())), 0.0, 1e-14);
}

TEST_P(TangentFrameOnSlope, EqualsRodriguesEq19) {
  expectMatrixNear(tangentFrame(GetParam()), rodriguesEq19(GetParam()), 1e-14);
}

TEST_P(TangentFrameOnSlope, EqualsPrintedEq23) {
  expectMatrixNear(tangentFrame(GetParam()), printedEq23(GetParam()), 1e-14);
}

TEST_P(TangentFrameOnSlope, EqualsEigenAxisAngleAndTheCorrectedAppendixA6) {
  const Eigen::Vector2d g = GetParam();
  const Eigen::Vector3d e = Eigen::Vector3d(g.y(), -g.x(), 0.0).normalized();  // eq 13
  const double gamma = std::atan2(g.norm(), 1.0);                              // eq 16
  const Eigen::Quaterniond q(Eigen::AngleAxisd(gamma, e));
  EXPECT_NEAR(q.z(), 0.0, 1e-15);  // q_k = 0 as appendix A states
  expectMatrixNear(tangentFrame(g), q.toRotationMatrix(), 1e-14);
  expectMatrixNear(tangentFrame(g), correctedA6(g), 1e-14);
}

// docs/errata.md T5, at its point f_x = 0.3, f_y = -0.2: the printed A.5 (q_k = 0) and A.6 are
// not rotations, and neither is eq 23; the corrected A.6 is, to 1e-16.
TEST(AppendixA, PrintedA5AndA6AreNotRotationsAtTheErrataPoint) {
  const Eigen::Vector2d g(0.3, -0.2);
  const auto [qr, qi, qj] = appendixQuaternion(g);
  const double qk = 0.0;
  Eigen::Matrix3d a5, a6;
  a5 << 1 - 2 * (qj * qj + qk * qk), 2 * (qi * qj - qk * qr), 2 * (qi * qk - qj * qr),  //
      2 * (qi * qj - qk * qr), 1 - 2 * (qi * qi + qk * qk), 2 * (qj * qk - qi * qr),    //
      2 * (qi * qk - qj * qr), 2 * (qj * qk - qi * qr), 1 - 2 * (qi * qi + qj * qj);
  a6 << 1 - 2 * qj * qj, 2 * qi * qj, -2 * qi * qr,  //
      2 * qi * qj, 1 - 2 * qi * qi, -2 * qi * qr,    //
      -2 * qi * qr, -2 * qi * qr, 1 - 2 * (qi * qi + qj * qj);
  const auto orthogonality_error = [](const Eigen::Matrix3d& r) {
    return (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  };
  const Eigen::Matrix3d eq23 = printedEq23(g);
  // The printed digits.
  EXPECT_NEAR(orthogonality_error(a5), 0.54, 0.005);
  EXPECT_NEAR((a5 - eq23).cwiseAbs().maxCoeff(), 0.56, 0.005);
  EXPECT_NEAR(orthogonality_error(a6), 0.37, 0.005);
  EXPECT_NEAR((a6 - eq23).cwiseAbs().maxCoeff(), 0.47, 0.005);
  expectMatrixNear(correctedA6(g), eq23, 1e-16);
}

// Minimal rotation (the eq 11 choice e = z x n): the rotation axis lies in the horizontal plane,
// so the frame has no twist about z. Equivalently, the rotation angle equals the angle between z
// and n, which no other rotation taking z to n achieves.
TEST_P(TangentFrameOnSlope, IsTheMinimalRotationTakingZToN) {
  const Eigen::Vector2d g = GetParam();
  const Eigen::Matrix3d r = tangentFrame(g);
  const Eigen::AngleAxisd aa(r);
  EXPECT_NEAR(aa.axis().z(), 0.0, 1e-12);
  EXPECT_NEAR(aa.angle(), std::acos(normalEq10(g).z()), 1e-12);
  EXPECT_LE((r * Eigen::Vector3d::UnitZ() - normalEq10(g)).norm(), 1e-14);
}

INSTANTIATE_TEST_SUITE_P(Gradients, TangentFrameOnSlope, ::testing::ValuesIn(kSlopedGradients),
                         [](const auto& info) { return "g" + std::to_string(info.index); });

TEST(TangentFrame, IsExactlyTheIdentityAtAFlatPoint) {
  // Eq 23 is 0/0 here (s = 1/0); the package's form must give I exactly.
  EXPECT_EQ(tangentFrame(Eigen::Vector2d::Zero()), Eigen::Matrix3d::Identity());
  EXPECT_EQ(surfaceNormal(Eigen::Vector2d::Zero()), Eigen::Vector3d::UnitZ());
}

TEST(TangentFrame, IsFiniteAndFirstOrderCorrectForTinyGradients) {
  // For |grad| << 1, R = I + [k]x + O(|grad|^2) with k = z x n ~ (f_y, -f_x, 0).
  for (double m : {1e-300, 1e-200, 1e-12, 1e-8}) {
    for (const Eigen::Vector2d& dir : {Eigen::Vector2d(1, 0), Eigen::Vector2d(-0.6, 0.8)}) {
      const Eigen::Vector2d g = m * dir;
      SCOPED_TRACE(str(g));
      const Eigen::Matrix3d r = tangentFrame(g);
      ASSERT_TRUE(r.allFinite()) << r;
      expectRotation(r, 1e-14);
      Eigen::Matrix3d first_order;
      first_order << 1, 0, -g.x(), 0, 1, -g.y(), g.x(), g.y(), 1;
      expectMatrixNear(r, first_order, 2.0 * m * m + 4e-16);
      // the normal column is exact, not just near z
      EXPECT_LE((r.col(2) - normalEq10(g)).norm(), 1e-16);
    }
  }
}

TEST(TangentFrame, RejectsANonFiniteGradient) {
  for (const Eigen::Vector2d& g : {Eigen::Vector2d(kNaN, 0.0), Eigen::Vector2d(0.0, kNaN),
                                   Eigen::Vector2d(kInf, 0.1), Eigen::Vector2d(0.2, -kInf)}) {
    SCOPED_TRACE(str(g));
    EXPECT_THROW(tangentFrame(g), std::invalid_argument);
    EXPECT_THROW(headingFrame(g, 0.3), std::invalid_argument);
  }
}

// ------------------------------------------------------------------------------------------
// Heading frame R_L = R_T Rz(psi), columns (h, l, n), psi right-handed about n.

struct HeadingCase {
  Eigen::Vector2d gradient;
  double psi;
};

class HeadingFrameTest : public ::testing::TestWithParam<HeadingCase> {};

TEST_P(HeadingFrameTest, IsARightHandedFrameWithLEqualNCrossH) {
  const auto c = GetParam();
  const Eigen::Matrix3d rl = headingFrame(c.gradient, c.psi);
  expectRotation(rl);
  const Eigen::Vector3d h = rl.col(0), l = rl.col(1), n = rl.col(2);
  EXPECT_LE((l - n.cross(h)).norm(), 1e-14);
  EXPECT_LE((n - normalEq10(c.gradient)).norm(), 1e-14);
}

TEST_P(HeadingFrameTest, RotatesTheTangentAxesByPsiAboutN) {
  // h = cos(psi) i_T + sin(psi) j_T, l = -sin(psi) i_T + cos(psi) j_T, with (i_T, j_T) from the
  // independent closed form of eq 19 (or I on flat ground).
  const auto c = GetParam();
  const Eigen::Matrix3d rt =
      c.gradient.norm() > 0 ? rodriguesEq19(c.gradient) : Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d rl = headingFrame(c.gradient, c.psi);
  const Eigen::Vector3d h = std::cos(c.psi) * rt.col(0) + std::sin(c.psi) * rt.col(1);
  const Eigen::Vector3d l = -std::sin(c.psi) * rt.col(0) + std::cos(c.psi) * rt.col(1);
  EXPECT_LE((rl.col(0) - h).norm(), 1e-14);
  EXPECT_LE((rl.col(1) - l).norm(), 1e-14);
}

TEST_P(HeadingFrameTest, HeadingTurnsCounterClockwiseAboutNAsPsiGrows) {
  // Right-handed about n: dh/dpsi = n x h and dl/dpsi = n x l = -h (central differences).
  const auto c = GetParam();
  const double d = 1e-6;
  const Eigen::Matrix3d rl = headingFrame(c.gradient, c.psi);
  const Eigen::Matrix3d drl =
      (headingFrame(c.gradient, c.psi + d) - headingFrame(c.gradient, c.psi - d)) / (2 * d);
  const Eigen::Vector3d h = rl.col(0), l = rl.col(1), n = rl.col(2);
  EXPECT_LE((drl.col(0) - n.cross(h)).norm(), 1e-8);
  EXPECT_LE((drl.col(1) - n.cross(l)).norm(), 1e-8);
  EXPECT_LE(drl.col(2).norm(), 1e-8);  // turning about n leaves n alone
}

TEST_P(HeadingFrameTest, IsThePrintedEq27WithTheHeadingSignReversed) {
  // conventions.md: the printed eq 25 is Rz(-psi), so eq 27 at -psi is our frame at psi.
  const auto c = GetParam();
  if (c.gradient.norm() == 0.0) GTEST_SKIP() << "eq 27 is 0/0 at a flat point";
  expectMatrixNear(headingFrame(c.gradient, c.psi), printedEq27(c.gradient, -c.psi), 1e-14);
}

INSTANTIATE_TEST_SUITE_P(
    GradientsAndHeadings, HeadingFrameTest,
    ::testing::Values(HeadingCase{{0.0, 0.0}, 0.0}, HeadingCase{{0.0, 0.0}, 0.7},
                      HeadingCase{{0.0, 0.0}, -2.5}, HeadingCase{{0.3, -0.2}, 0.0},
                      HeadingCase{{0.3, -0.2}, 1.2}, HeadingCase{{-1.5, 0.8}, -0.4},
                      HeadingCase{{2.0, 2.0}, 3.0}, HeadingCase{{0.0, 0.5}, 4.0 * std::atan(1.0)}),
    [](const auto& info) { return "c" + std::to_string(info.index); });

TEST(HeadingFrame, OnFlatGroundHIsTheCompassDirectionOfPsi) {
  for (double psi : {0.0, 0.5, 1.5707963267948966, 2.0, -1.0, 3.0}) {
    const Eigen::Matrix3d rl = headingFrame(Eigen::Vector2d::Zero(), psi);
    EXPECT_LE((rl.col(0) - Eigen::Vector3d(std::cos(psi), std::sin(psi), 0)).norm(), 1e-15);
    EXPECT_LE((rl.col(1) - Eigen::Vector3d(-std::sin(psi), std::cos(psi), 0)).norm(), 1e-15);
    EXPECT_EQ(rl.col(2), Eigen::Vector3d::UnitZ());
  }
}

TEST(HeadingFrame, RejectsANonFiniteHeading) {
  // DESIGN.md: every public core function rejects non-finite input.
  EXPECT_THROW(headingFrame(Eigen::Vector2d(0.1, 0.2), kNaN), std::invalid_argument);
  EXPECT_THROW(headingFrame(Eigen::Vector2d(0.1, 0.2), kInf), std::invalid_argument);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
