// Norma's dynamics (Moazami et al. 2019) against independent truth: an energy function written
// here directly from the bodies' positions (eqs 7, 17, 19), velocities and angular velocities
// (eqs 8, 29, 36) and the inertias of eqs 38-44, differentiated numerically; the invariants of a
// Christoffel C; energy conservation of the unforced robot; the static tilt of a held slider;
// the virtual work of the two actuators (docs/errata.md, N1-N6).

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "spherical_robots/config/norma_description.hpp"
#include "spherical_robots/config/robot_description.hpp"
#include "spherical_robots/norma/norma_dynamics.hpp"
#include "spherical_robots/norma/norma_simulation.hpp"
#include "expect_invalid_argument.hpp"

namespace {

using spherical_robots::norma::LagrangianVariant;
using spherical_robots::norma::Matrix4;
using spherical_robots::norma::NormaDynamics;
using spherical_robots::norma::NormaParameters;
using spherical_robots::norma::OdeMethod;
using spherical_robots::norma::OpenLoopConfig;
using spherical_robots::norma::runOpenLoop;
using spherical_robots::norma::Vector4;
using Vec3 = Eigen::Vector3d;

// A number with its time derivative, so that a velocity is the exact derivative of the position
// formula it comes from.
struct Dual {
  double v, d;
};
Dual operator+(Dual a, Dual b) { return {a.v + b.v, a.d + b.d}; }
Dual operator-(Dual a, Dual b) { return {a.v - b.v, a.d - b.d}; }
Dual operator*(Dual a, Dual b) { return {a.v * b.v, a.d * b.v + a.v * b.d}; }
Dual operator*(double s, Dual a) { return {s * a.v, s * a.d}; }
Dual sin(Dual a) { return {std::sin(a.v), std::cos(a.v) * a.d}; }
Dual cos(Dual a) { return {std::cos(a.v), -std::sin(a.v) * a.d}; }

struct DualVec {
  Dual x, y, z;
  Vec3 value() const { return {x.v, y.v, z.v}; }
  Vec3 rate() const { return {x.d, y.d, z.d}; }
};

// The paper's kinetic and potential energy of each body, in {F_l} (eqs 21, 37, 41, 43): the
// centre moves with eq 9; the pendulum bob and the slider sit at eqs 17 and 19 relative to it
// (their velocities, eqs 28 and 34, are the derivatives of those positions in {F_l} plus eq 9);
// the angular velocities are eqs 8, 29, 36 and the inertias eqs 38-44, point-mass terms included
// as the paper writes them.
struct EnergyParts {
  double kinetic = 0.0;
  double potential = 0.0;
  double sphere_yaw = 0.0;  // ½ I_Sp^z (θ̇ S_φ)², the term A.3 lacks
};

EnergyParts paperEnergy(const NormaParameters& p, const Vector4& q, const Vector4& qd) {
  const Dual th{q(0), qd(0)}, al{q(1), qd(1)}, ph{q(2), qd(2)}, de{q(3), qd(3)};
  const Dual b = al - th;
  const Dual d = de + Dual{p.delta0, 0.0};
  const DualVec r_p{p.L * sin(b), -p.L0 * cos(ph) + p.L * cos(b) * sin(ph),
                    Dual{0, 0} - (p.L * cos(b) * cos(ph) + p.L0 * sin(ph))};  // eq 17
  const DualVec r_sl{Dual{0, 0}, d * cos(ph), d * sin(ph)};                   // eq 19
  const double cf = std::cos(q(2)), sf = std::sin(q(2));
  const Vec3 v_centre(p.R * qd(0) * cf, -p.R * qd(2), 0.0);  // eq 9
  const Vec3 omega_sphere(qd(2), qd(0) * cf, -qd(0) * sf);   // eq 8
  const double bd = qd(1) - qd(0);
  const Vec3 omega_pendulum(qd(2), -bd * cf, bd * sf);  // eq 29
  const Vec3 omega_slider = omega_sphere;               // eq 36
  const Vec3 v_p = v_centre + r_p.rate();
  const Vec3 v_sl = v_centre + r_sl.rate();

  const double m_sp = p.m_shell + p.m_shaft;
  const double i_shl = 2.0 / 3.0 * p.m_shell * p.R * p.R;  // eq 38
  const double i_shf = 1.0 / 3.0 * p.m_shaft * p.R * p.R;  // eq 39, rod of length 2R
  const Vec3 i_sp(i_shl + i_shf, i_shl + i_shf * sf * sf, i_shl + i_shf * cf * cf);  // eq 40
  const double cb = std::cos(b.v), dv = d.v;
  const Vec3 i_p(p.m_pendulum * (p.L0 * p.L0 + p.L * p.L * cb * cb),
                 p.m_pendulum * std::pow(p.L * cb * cf + p.L0 * sf, 2),
                 p.m_pendulum * std::pow(p.L0 * cf - p.L * sf, 2));  // eq 42
  const Vec3 i_sl(p.m_slider * dv * dv, p.m_slider * dv * dv * sf * sf,
                  p.m_slider * dv * dv * cf * cf);  // eq 44
  auto rot = [](const Vec3& i, const Vec3& w) { return 0.5 * w.dot(i.cwiseProduct(w)); };

  EnergyParts e;
  e.kinetic = 0.5 * m_sp * v_centre.squaredNorm() + rot(i_sp, omega_sphere) +
              0.5 * p.m_pendulum * v_p.squaredNorm() + rot(i_p, omega_pendulum) +
              0.5 * p.m_slider * v_sl.squaredNorm() + rot(i_sl, omega_slider);
  // Heights above the centre (eqs 17, 19 z components); the centre's own height is constant.
  e.potential = p.g * (p.m_pendulum * r_p.z.v + p.m_slider * r_sl.z.v) + p.m_pendulum * p.g * p.L;
  e.sphere_yaw = 0.5 * i_sp.z() * std::pow(qd(0) * sf, 2);
  return e;
}

double kinetic(const NormaParameters& p, LagrangianVariant variant, const Vector4& q,
               const Vector4& qd) {
  const EnergyParts e = paperEnergy(p, q, qd);
  return variant == LagrangianVariant::kText ? e.kinetic : e.kinetic - e.sphere_yaw;
}

// The kinetic energy is a quadratic form in q̇: polarisation gives M exactly.
Matrix4 massFromEnergy(const NormaParameters& p, LagrangianVariant variant, const Vector4& q) {
  Matrix4 m;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const Vector4 ei = Vector4::Unit(i), ej = Vector4::Unit(j);
      m(i, j) = kinetic(p, variant, q, ei + ej) - kinetic(p, variant, q, ei) -
                kinetic(p, variant, q, ej);
    }
  }
  return m;
}

std::vector<std::pair<Vector4, Vector4>> randomStates(int count) {
  std::mt19937 rng(2019);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), tilt(-1.2, 1.2), slide(-0.1, 0.1),
      rate(-2.0, 2.0);
  std::vector<std::pair<Vector4, Vector4>> states;
  for (int k = 0; k < count; ++k) {
    states.emplace_back(Vector4(angle(rng), angle(rng), tilt(rng), slide(rng)),
                        Vector4(rate(rng), rate(rng), rate(rng), rate(rng)));
  }
  return states;
}

const LagrangianVariant kVariants[] = {LagrangianVariant::kText, LagrangianVariant::kAppendix};

TEST(NormaDynamics, MassMatrixIsSymmetricPositiveDefinite) {
  for (LagrangianVariant variant : kVariants) {
    const NormaDynamics dynamics(NormaParameters(), variant);
    for (const auto& [q, qd] : randomStates(200)) {
      const Matrix4 m = dynamics.massMatrix(q);
      EXPECT_LT((m - m.transpose()).cwiseAbs().maxCoeff(), 1e-15);
      const Eigen::SelfAdjointEigenSolver<Matrix4> eig(m);
      EXPECT_GT(eig.eigenvalues().minCoeff(), 1e-3) << q.transpose();
    }
  }
}

TEST(NormaDynamics, MassMatrixMatchesIndependentEnergy) {
  const NormaParameters p;
  for (LagrangianVariant variant : kVariants) {
    const NormaDynamics dynamics(p, variant);
    for (const auto& [q, qd] : randomStates(100)) {
      EXPECT_LT((dynamics.massMatrix(q) - massFromEnergy(p, variant, q)).cwiseAbs().maxCoeff(),
                1e-13);
      EXPECT_NEAR(dynamics.kineticEnergy(q, qd), kinetic(p, variant, q, qd), 1e-13);
    }
  }
}

TEST(NormaDynamics, VariantsDifferOnlyBySphereYawTermInM11) {
  const NormaParameters p;
  const NormaDynamics text(p, LagrangianVariant::kText), appendix(p, LagrangianVariant::kAppendix);
  const Vector4 q(0.3, -0.2, 0.4, 0.05);
  Matrix4 expected = Matrix4::Zero();
  const double i_z = 2.0 / 3.0 * 2.5 * 0.04 + 1.0 / 3.0 * 0.5 * 0.04 * std::pow(std::cos(0.4), 2);
  expected(0, 0) = i_z * std::pow(std::sin(0.4), 2);
  EXPECT_LT((text.massMatrix(q) - appendix.massMatrix(q) - expected).cwiseAbs().maxCoeff(), 1e-15);
  // docs/errata.md N3: at the tracking run's largest tilt, phi = 0.373 rad, the term is
  // 0.0096 kg m^2.
  const Vector4 tilted(0.3, -0.2, 0.373, 0.05);
  EXPECT_NEAR(text.massMatrix(tilted)(0, 0) - appendix.massMatrix(tilted)(0, 0), 0.0096, 5e-5);
  // Upright (φ = 0) the term vanishes.
  EXPECT_EQ(text.massMatrix(Vector4(0.3, -0.2, 0.0, 0.05)),
            appendix.massMatrix(Vector4(0.3, -0.2, 0.0, 0.05)));
}

TEST(NormaDynamics, GravityIsGradientOfIndependentPotential) {
  const NormaParameters p;
  const NormaDynamics dynamics(p);
  const double h = 1e-6;
  for (const auto& [q, qd] : randomStates(100)) {
    const Vector4 g = dynamics.terms(q, qd).G;
    for (int i = 0; i < 4; ++i) {
      const Vector4 dq = h * Vector4::Unit(i);
      const double fd = (paperEnergy(p, q + dq, qd).potential -
                         paperEnergy(p, q - dq, qd).potential) / (2 * h);
      EXPECT_NEAR(g(i), fd, 1e-8);
    }
    EXPECT_NEAR(dynamics.potentialEnergy(q), paperEnergy(p, q, qd).potential, 1e-14);
  }
}

// Euler-Lagrange with T = ½ q̇ᵀ M q̇: C q̇ = Ṁ q̇ − ∂T/∂q, both by central differences of the
// independent energy.
TEST(NormaDynamics, CoriolisTimesRateMatchesIndependentEnergy) {
  const NormaParameters p;
  const double h = 1e-5;
  for (LagrangianVariant variant : kVariants) {
    const NormaDynamics dynamics(p, variant);
    for (const auto& [q, qd] : randomStates(50)) {
      const Matrix4 m_dot = (massFromEnergy(p, variant, q + h * qd) -
                             massFromEnergy(p, variant, q - h * qd)) / (2 * h);
      Vector4 dt_dq;
      for (int i = 0; i < 4; ++i) {
        const Vector4 dq = h * Vector4::Unit(i);
        dt_dq(i) = (kinetic(p, variant, q + dq, qd) - kinetic(p, variant, q - dq, qd)) / (2 * h);
      }
      const Vector4 expected = m_dot * qd - dt_dq;
      const Vector4 got = dynamics.terms(q, qd).C * qd;
      EXPECT_LT((got - expected).cwiseAbs().maxCoeff(), 1e-8 * (1.0 + expected.norm()));
    }
  }
}

TEST(NormaDynamics, MdotMinusTwoCIsSkewSymmetric) {
  const double h = 1e-6;
  for (LagrangianVariant variant : kVariants) {
    const NormaDynamics dynamics(NormaParameters(), variant);
    for (const auto& [q, qd] : randomStates(50)) {
      const Matrix4 m_dot =
          (dynamics.massMatrix(q + h * qd) - dynamics.massMatrix(q - h * qd)) / (2 * h);
      const Matrix4 n = m_dot - 2.0 * dynamics.terms(q, qd).C;
      EXPECT_LT((n + n.transpose()).cwiseAbs().maxCoeff(), 1e-8);
      // and C is not trivially symmetric-free: N itself is not zero for a generic state.
      EXPECT_GT(n.cwiseAbs().maxCoeff(), 1e-3);
    }
  }
}

// Power of the motor torque T on the pendulum relative to the shell about the shaft: the
// pendulum's angular velocity (eq 29) minus the shell's (eq 8) is −α̇ ĵ_s, so T's power is T α̇;
// the slider force's power is F times the slider's speed along the shaft, δ̇ (eq 31).
TEST(NormaDynamics, GeneralizedForcesAreVirtualWorkOfActuators) {
  const double torque = 1.7, force = -0.6;
  for (const auto& [q, qd] : randomStates(20)) {
    const double cf = std::cos(q(2)), sf = std::sin(q(2));
    const Vec3 omega_sphere(qd(2), qd(0) * cf, -qd(0) * sf);
    const Vec3 omega_pendulum(qd(2), (qd(0) - qd(1)) * cf, -(qd(0) - qd(1)) * sf);
    const Vec3 alpha_axis(0.0, -cf, sf);  // −ĵ_s in {F_l} (eqs 17, 19 frame)
    const double power = torque * (omega_pendulum - omega_sphere).dot(alpha_axis) + force * qd(3);
    EXPECT_NEAR(NormaDynamics::generalizedForces(torque, force).dot(qd), power, 1e-14);
  }
}

// With no input the Lagrangian system conserves E = T + V; the free slider would leave the
// shaft, so a conservative spring ½ k δ² holds it.
struct UnforcedRun {
  double drift;   ///< max |E(t) − E(0)| / |E(0)| over the logged samples
  double motion;  ///< max |φ(t) − φ(0)| [rad]
};

/// 20 s from a moving start, dopri5 at rtol = atol = 1e-12, logged at 10 Hz.
UnforcedRun runUnforced(LagrangianVariant variant) {
  OpenLoopConfig config;
  config.variant = variant;
  config.q0 = Vector4(0.0, 0.8, 0.3, 0.02);
  config.qd0 = Vector4(1.0, -0.5, 0.4, 0.1);
  config.slider_stiffness = 20.0;
  config.duration = 20.0;
  config.log_rate = 10.0;
  config.ode.method = OdeMethod::kDopri5;
  config.ode.rtol = 1e-12;
  config.ode.atol = 1e-12;
  const auto samples = runOpenLoop(NormaParameters(), config);
  EXPECT_EQ(samples.size(), 201u);
  const double e0 = samples.front().energy;
  EXPECT_GT(std::abs(e0), 0.1);
  UnforcedRun run{0.0, 0.0};
  for (const auto& s : samples) {
    run.drift = std::max(run.drift, std::abs(s.energy - e0) / std::abs(e0));
    run.motion = std::max(run.motion, std::abs(s.q(2) - config.q0(2)));
  }
  return run;
}

TEST(NormaDynamics, UnforcedEnergyIsConserved) {
  for (LagrangianVariant variant : kVariants) {
    const UnforcedRun run = runUnforced(variant);
    EXPECT_LT(run.drift, 1e-8);
    EXPECT_GT(run.motion, 0.1);  // the robot really moved
  }
}

// docs/errata.md N6 quotes the text model's drift, 5.9e-11 (to its printed digits).
TEST(NormaDynamics, UnforcedEnergyDriftIsTheErrataFigure) {
  const double drift = runUnforced(LagrangianVariant::kText).drift;
  std::cout << "[ result   ] relative energy drift over 20 s: " << drift << "\n";
  EXPECT_NEAR(drift, 5.9e-11, 0.05e-11);
}

// A slider held at δ tilts the resting robot until the plumb line through the centre passes
// through the centre of mass: m_Sl (δ0 + δ) C_φ = m_P (L0 C_φ − L S_φ) with the pendulum
// hanging, i.e. tan φ = −m_Sl δ / (m_P L) under eq 1.
TEST(NormaDynamics, HeldSliderTiltsToClosedForm) {
  const NormaParameters p;
  const NormaDynamics dynamics(p);
  for (double delta : {-0.1, -0.03, 0.0, 0.05, 0.1}) {
    const double phi = std::atan(-p.m_slider * delta / (p.m_pendulum * p.L));
    EXPECT_NEAR(dynamics.staticTilt(delta), phi, 1e-15);
    const Vector4 q(0.4, 0.4, phi, delta);  // pendulum hanging: α = θ
    const Vector4 g = dynamics.terms(q, Vector4::Zero()).G;
    // Holding force F = G4 = m_Sl g S_φ: the robot stays at rest.
    const Vector4 acc = dynamics.acceleration(
        q, Vector4::Zero(), NormaDynamics::generalizedForces(0.0, g(3)));
    EXPECT_LT(acc.cwiseAbs().maxCoeff(), 1e-14) << delta;
    // Tilted a little further, gravity pulls it back.
    const Vector4 tilted(0.4, 0.4, phi + 0.01, delta);
    EXPECT_LT(dynamics.acceleration(tilted, Vector4::Zero(),
                                    NormaDynamics::generalizedForces(0.0, g(3)))(2),
              0.0);
  }
  // δ = 0.1 m (the end of the outward stroke R − δ0) gives −33.7°.
  EXPECT_NEAR(dynamics.staticTilt(0.1) * 180.0 / M_PI, -33.69, 0.01);
}

TEST(NormaDynamics, PlanarRatesFollowEqs6And12) {
  const NormaDynamics dynamics{NormaParameters()};
  const Vector4 q(1.0, 0.0, 0.3, 0.0), qd(0.5, 0.0, 0.2, 0.0);
  const auto rates = dynamics.planarRates(q, qd, M_PI / 2);
  // Heading +y: rolling moves the centre along +y, tilting along +x (eq 9 in {F_l}: −R φ̇ ĵ).
  EXPECT_NEAR(rates.x_dot, 0.2 * 0.2, 1e-15);
  EXPECT_NEAR(rates.y_dot, 0.2 * 0.5 * std::cos(0.3), 1e-15);
  EXPECT_NEAR(rates.psi_dot, -0.5 * std::sin(0.3), 1e-15);
}

TEST(NormaDynamics, RejectsInvalidInput) {
  NormaParameters bad;
  bad.L = -0.1;
  EXPECT_INVALID_ARGUMENT(NormaDynamics(bad), "L [m]");
  const NormaDynamics dynamics{NormaParameters()};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(dynamics.massMatrix(Vector4(0, nan, 0, 0)), std::invalid_argument);
  EXPECT_THROW(dynamics.terms(Vector4::Zero(), Vector4(0, 0, 0, nan)), std::invalid_argument);
  EXPECT_THROW(NormaDynamics::generalizedForces(nan, 0.0), std::invalid_argument);
}

// The shipped URDF is section 5's robot, and eq 1 (m_P L0 = m_Sl δ0) holds for it.
TEST(NormaDescription, ShippedUrdfIsSection5Robot) {
  namespace config = spherical_robots::config;
  const std::string xml =
      config::readTextFile(std::string(SPHERICAL_ROBOTS_SOURCE_DIR) + "/urdf/norma.urdf");
  const NormaParameters p = config::normaParametersFromUrdf(xml);
  EXPECT_DOUBLE_EQ(p.R, 0.2);
  EXPECT_DOUBLE_EQ(p.L, 0.15);
  EXPECT_DOUBLE_EQ(p.L0, 0.10);
  EXPECT_DOUBLE_EQ(p.delta0, 0.1);
  EXPECT_DOUBLE_EQ(p.m_shell + p.m_shaft, 3.0);
  EXPECT_DOUBLE_EQ(p.m_shaft, 0.5);
  EXPECT_DOUBLE_EQ(p.m_pendulum, 0.5);
  EXPECT_DOUBLE_EQ(p.m_slider, 0.5);
  EXPECT_NEAR(p.m_pendulum * p.L0, p.m_slider * p.delta0, 1e-15);
  // A pendulum axis turned round contradicts the conventions; a missing link is named.
  std::string flipped = xml;
  flipped.replace(flipped.find("<axis xyz=\"0 -1 0\"/>"), 21, "<axis xyz=\"0 1 0\"/>");
  EXPECT_THROW(config::normaParametersFromUrdf(flipped), std::invalid_argument);
  std::string no_slider = xml;
  no_slider.replace(no_slider.find("name=\"slider_joint\""), 19, "name=\"other_joint\"");
  EXPECT_INVALID_ARGUMENT(config::normaParametersFromUrdf(no_slider), "slider_joint");
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
