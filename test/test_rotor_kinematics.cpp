// Contact kinematics of the two-rotor sphere (Svinin et al., eqs 1-30) against independent
// truth: the orientation built from Eigen's elementary rotations, the angular velocity as the
// finite-difference derivative Ṙ Rᵀ, rolling without slip (the material contact point is at
// rest), conservation of angular momentum (eq 11) and the chain rule along a curve.

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "spherical_robots/rotor/contact_curve.hpp"
#include "spherical_robots/rotor/contact_kinematics.hpp"
#include "spherical_robots/rotor/dynamic_realizability.hpp"
#include "spherical_robots/rotor/figure_eight.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using namespace spherical_robots::rotor;

Eigen::Matrix3d elementary(double u_o, double v_o, double psi) {
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  return (AngleAxisd(psi, Vector3d::UnitZ()).matrix().transpose() *
          AngleAxisd(v_o, Vector3d::UnitX()).matrix().transpose() *
          AngleAxisd(u_o, Vector3d::UnitY()).matrix().transpose());
}

Eigen::Vector3d vee(const Eigen::Matrix3d& w) {
  return {0.5 * (w(2, 1) - w(1, 2)), 0.5 * (w(0, 2) - w(2, 0)), 0.5 * (w(1, 0) - w(0, 1))};
}

struct Sample {
  ContactCoordinates at;
  double du, dv, dpsi;
};

std::vector<Sample> samples() {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-1.2, 1.2), rate(-2.0, 2.0);
  std::vector<Sample> out;
  for (int i = 0; i < 25; ++i) {
    out.push_back({{angle(random), angle(random), angle(random), angle(random), 3 * angle(random)},
                   rate(random), rate(random), rate(random)});
  }
  return out;
}

TEST(RotorKinematics, OrientationIsTheProductOfElementaryRotations) {
  for (const Sample& s : samples()) {
    const Eigen::Matrix3d r = orientation(s.at.u_o, s.at.v_o, s.at.psi);
    EXPECT_LE((r - elementary(s.at.u_o, s.at.v_o, s.at.psi)).norm(), 1e-14);
    // Eq 1-2: the contact point of the sphere is below its centre.
    EXPECT_LE((r * contactPoint(s.at.u_o, s.at.v_o) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-14);
  }
  // S1: the printed n1_z = cos u_o cos v_o is wrong; R e1 has sin u_o cos v_o.
  const Eigen::Matrix3d r = orientation(0.4, 0.3, 0.2);
  EXPECT_NEAR(r(2, 0), std::sin(0.4) * std::cos(0.3), 1e-15);
  EXPECT_GT(std::abs(r(2, 0) - std::cos(0.4) * std::cos(0.3)), 0.4);
}

TEST(RotorKinematics, AngularVelocityIsTheDerivativeOfTheOrientation) {
  const double h = 1e-6;
  for (const Sample& s : samples()) {
    const auto at = [&](double t) {
      return orientation(s.at.u_o + s.du * t, s.at.v_o + s.dv * t, s.at.psi + s.dpsi * t);
    };
    const Eigen::Matrix3d derivative = (at(h) - at(-h)) / (2 * h);
    const Eigen::Vector3d expected = vee(derivative * at(0).transpose());
    EXPECT_LE((angularVelocity(s.at, s.du, s.dv, s.dpsi) - expected).norm(), 1e-8);
  }
}

TEST(RotorKinematics, ContactRatesInvertTheAngularVelocityAndRoll) {
  for (const Sample& s : samples()) {
    const Eigen::Vector3d omega = angularVelocity(s.at, s.du, s.dv, s.dpsi);
    const ContactRates rates = contactRates(s.at, omega);  // eqs 6-10
    EXPECT_NEAR(rates.u_o, s.du, 1e-12);
    EXPECT_NEAR(rates.v_o, s.dv, 1e-12);
    EXPECT_NEAR(rates.psi, s.dpsi, 1e-12);
    // No slip: centre velocity + ω × (contact − centre) = 0 with contact − centre = (0, 0, −1).
    const Eigen::Vector3d centre(rates.u_a, rates.v_a, 0.0);
    EXPECT_LE((centre + omega.cross(Eigen::Vector3d(0, 0, -1))).norm(), 1e-14);
    // Eqs 15-16 written with u̇_o, v̇_o.
    const double cp = std::cos(s.at.psi), sp = std::sin(s.at.psi), cv = std::cos(s.at.v_o);
    EXPECT_NEAR(rates.u_a, -cp * cv * s.du + sp * s.dv, 1e-12);
    EXPECT_NEAR(rates.v_a, sp * cv * s.du + cp * s.dv, 1e-12);
  }
}

TEST(RotorKinematics, RealizableHeadingRateSatisfiesEq13AndRotorsConserveMomentum) {
  const double scale = 7.5;  // J_zz / J_r
  for (double k : {0.0, 1.3, 2.5, 5.0}) {
    for (Sample s : samples()) {
      s.at.u_o *= 0.5;  // below the equator: cos u_o cos v_o > 0
      s.at.v_o *= 0.5;
      const double dpsi = realizableHeadingRate(k, s.at, s.du, s.dv);  // eq 20
      const Eigen::Vector3d omega = angularVelocity(s.at, s.du, s.dv, dpsi);
      EXPECT_NEAR(realizabilityResidual(k, s.at, omega), 0.0, 1e-12);
      // A different heading rate is not realizable (unless n3z = 0, excluded here).
      const Eigen::Vector3d other = angularVelocity(s.at, s.du, s.dv, dpsi + 0.1);
      EXPECT_GT(std::abs(realizabilityResidual(k, s.at, other)), 1e-3);
      // Eq 11: J_c ω + J_r (n1 φ̇1 + n2 φ̇2) = 0, in units of J_zz.
      const RotorSpeeds phi = rotorSpeeds(k, scale, s.at, omega);
      const Eigen::Matrix3d r = orientation(s.at.u_o, s.at.v_o, s.at.psi);
      const Eigen::Vector3d momentum = Eigen::Vector3d(k, k, 1.0).asDiagonal() * omega +
                                       (r.col(0) * phi.phi1 + r.col(1) * phi.phi2) / scale;
      EXPECT_LE(momentum.norm(), 1e-12);
      EXPECT_THROW(rotorSpeeds(k, scale, s.at, other), std::invalid_argument);
    }
  }
}

TEST(RotorKinematics, InertiaRatioOfEq14) {
  // Shell 2 kg, R 0.1 m, rotors J_r = 1e-4, J_p = 5e-5, total 3 kg.
  const RotorSphereInertia inertia{3.0, 2.0, 0.1, 1e-4, 5e-5};
  const double j_zz = 2.0 / 3.0 * 2.0 * 0.01 + 2 * 5e-5 + 1e-4;
  EXPECT_NEAR(inertiaRatio(inertia), (j_zz + 3.0 * 0.01) / j_zz, 1e-14);
  EXPECT_GT(inertiaRatio(inertia), 1.0);
  EXPECT_NEAR(rotorInertiaScale(inertia), j_zz / 1e-4, 1e-9);
  EXPECT_THROW(inertiaRatio({3.0, 4.0, 0.1, 1e-4, 5e-5}), std::invalid_argument);
  EXPECT_THROW(inertiaRatio({3.0, 2.0, 0.0, 1e-4, 5e-5}), std::invalid_argument);
}

TEST(RotorKinematics, CurveFormIsTheChainRule) {
  // Eqs 24-30 along a turned figure eight against finite differences of eqs 24-25 and eqs 15-16,
  // 20.
  const FigureEight curve(0.55, 0.4, -0.8);
  const double h = 1e-6;
  for (double theta = 0.1; theta < 2 * M_PI; theta += 0.37) {
    if (std::abs(theta - M_PI) < 2 * h) continue;
    const CurvePoint c = curve.at(theta);
    const Eigen::Vector2d angles = contactAngles(c.point);
    const Eigen::Vector2d fd =
        (contactAngles(curve.at(theta + h).point) - contactAngles(curve.at(theta - h).point)) /
        (2 * h);
    const Eigen::Vector2d rates = contactAngleRates(c);
    EXPECT_LE((rates - fd).norm(), 1e-8) << theta;
    for (double k : {0.0, 2.5}) {
      const double psi = 0.9;
      const PlaneState curve_rates = realizableCurveRates(k, c, psi);
      const ContactCoordinates at{0.0, 0.0, angles.x(), angles.y(), psi};
      const double cp = std::cos(psi), sp = std::sin(psi), cv = std::cos(angles.y());
      EXPECT_NEAR(curve_rates.u_a, -cp * cv * fd.x() + sp * fd.y(), 1e-8);
      EXPECT_NEAR(curve_rates.v_a, sp * cv * fd.x() + cp * fd.y(), 1e-8);
      EXPECT_NEAR(curve_rates.psi, realizableHeadingRate(k, at, fd.x(), fd.y()), 1e-8);
    }
  }
}

TEST(RotorKinematics, CircleOfEq35) {
  for (double a : {0.1, 0.5, 0.7}) {
    const Eigen::Vector3d centre(0.0, a * std::sqrt(1 - a * a), -(1 - a * a));
    for (double phi = 0.0; phi < 2 * M_PI; phi += 0.5) {
      const CurvePoint c = sphericalCircle(a, phi, false);
      EXPECT_NEAR(c.point.norm(), 1.0, 1e-15);
      EXPECT_NEAR((c.point - centre).norm(), a, 1e-15);
      const Eigen::Vector3d fd = (sphericalCircle(a, phi + 1e-6, false).point -
                                  sphericalCircle(a, phi - 1e-6, false).point) / 2e-6;
      EXPECT_LE((c.tangent - fd).norm(), 1e-8);
      const CurvePoint m = sphericalCircle(a, phi, true);
      EXPECT_NEAR(m.point.y(), -c.point.y(), 1e-16);
    }
    EXPECT_LE((sphericalCircle(a, 0.0, false).point - Eigen::Vector3d(0, 0, -1)).norm(), 1e-15);
  }
  EXPECT_NEAR(euclideanRadius(arcRadius(0.4)), 0.4, 1e-15);
}

TEST(RotorKinematics, RejectsBadInputNamingIt) {
  EXPECT_INVALID_ARGUMENT(contactPoint(std::nan(""), 0.0), "u_o");
  EXPECT_INVALID_ARGUMENT(angularVelocity({0, 0, 0, 2.0, 0}, 1, 1, 1), "v_o");
  EXPECT_INVALID_ARGUMENT(realizableHeadingRate(-1.0, {}, 1, 1), "k");
  EXPECT_INVALID_ARGUMENT(realizableHeadingRate(1.0, {0, 0, 1.7, 0, 0}, 1, 1), "equator");
  EXPECT_INVALID_ARGUMENT(contactAngles(Eigen::Vector3d(0, 0, 1)), "equator");
  EXPECT_INVALID_ARGUMENT(sphericalCircle(0.8, 0.0, false), "0.8");
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
