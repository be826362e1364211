#include "spherical_robots/norma/norma_dynamics.hpp"

#include <Eigen/Cholesky>
#include <array>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/core/sin_cos.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::norma {

namespace {

#include "norma_dynamics_terms.inc"

void requireFiniteVector(const Vector4& v, bool rates) {
  static const char* const names[2][4] = {{"theta", "alpha", "phi", "delta"},
                                          {"thetad", "alphad", "phid", "deltad"}};
  for (int i = 0; i < 4; ++i) requireFinite(v(i), names[rates ? 1 : 0][i]);
}

// The generated code fills upper triangles only.
void mirrorUpper(Matrix4& m) {
  for (int i = 1; i < 4; ++i) {
    for (int j = 0; j < i; ++j) m(i, j) = m(j, i);
  }
}

}  // namespace

void validate(const NormaParameters& p) {
  requireAllPositive({{p.R, "R [m]"},
                      {p.L, "L [m]"},
                      {p.L0, "L0 [m]"},
                      {p.delta0, "delta0 [m]"},
                      {p.m_shell, "m_shell [kg]"},
                      {p.m_shaft, "m_shaft [kg]"},
                      {p.m_pendulum, "m_pendulum [kg]"},
                      {p.m_slider, "m_slider [kg]"},
                      {p.g, "g [m/s^2]"}});
}

NormaDynamics::NormaDynamics(const NormaParameters& parameters, LagrangianVariant variant)
    : parameters_(parameters), variant_(variant) {
  validate(parameters_);
}

void NormaDynamics::evaluate(const Vector4& q, Matrix4& m, Matrix4 dm[4], Vector4& gv) const {
  const NormaParameters& p = parameters_;
  const double beta = q(1) - q(0);
  const auto [sb, cb] = sinCos(beta);
  const auto [sf, cf] = sinCos(q(2));
  std::array<Matrix4, 3> d_beta_phi_delta;
  evaluateTextTerms(p, sb, cb, sf, cf, p.delta0 + q(3), m, d_beta_phi_delta, gv);
  if (variant_ == LagrangianVariant::kAppendix) {
    // A.3 lacks the last term of eq 37, ½ I_Sp^z (θ̇ S_φ)² with I_Sp^z = I_Shl + I_Shf^x C_φ².
    const double i_shell = 2.0 / 3.0 * p.m_shell * p.R * p.R;
    const double i_shaft = 1.0 / 3.0 * p.m_shaft * p.R * p.R;
    m(0, 0) -= (i_shell + i_shaft * cf * cf) * sf * sf;
    d_beta_phi_delta[1](0, 0) -= 2.0 * sf * cf * (i_shell + i_shaft * (cf * cf - sf * sf));
  }
  mirrorUpper(m);
  for (auto& d : d_beta_phi_delta) mirrorUpper(d);
  // M depends on θ and α only through β = α − θ.
  dm[0] = -d_beta_phi_delta[0];
  dm[1] = d_beta_phi_delta[0];
  dm[2] = d_beta_phi_delta[1];
  dm[3] = d_beta_phi_delta[2];
}

DynamicsTerms NormaDynamics::terms(const Vector4& q, const Vector4& qd) const {
  requireFiniteVector(q, false);
  requireFiniteVector(qd, true);
  DynamicsTerms out;
  Matrix4 dm[4];
  evaluate(q, out.M, dm, out.G);
  // A.23, A.24 as C = ½ (Ṁ + W − Wᵀ) with column j of W = (∂M/∂q_j) q̇: then Ṁ − 2C = Wᵀ − W.
  Matrix4 w;
  for (int k = 0; k < 4; ++k) w.col(k) = dm[k] * qd;
  Matrix4 m_dot = Matrix4::Zero();
  for (int k = 0; k < 4; ++k) m_dot += dm[k] * qd(k);
  out.C = 0.5 * (m_dot + w - w.transpose());
  return out;
}

Matrix4 NormaDynamics::massMatrix(const Vector4& q) const {
  requireFiniteVector(q, false);
  Matrix4 m;
  Matrix4 dm[4];
  Vector4 gv;
  evaluate(q, m, dm, gv);
  return m;
}

Vector4 NormaDynamics::generalizedForces(double torque, double force) {
  requireFinite(torque, "pendulum torque T [N m]");
  requireFinite(force, "slider force F [N]");
  // The motor turns the pendulum relative to the shell by −α about the shaft (eqs 8, 23, in the
  // shaft frame the shell spins at θ̇ and the pendulum at θ̇ − α̇): δW = T δα, nothing on θ.
  return Vector4(0.0, torque, 0.0, force);
}

Vector4 NormaDynamics::acceleration(const Vector4& q, const Vector4& qd, const Vector4& u) const {
  requireFiniteVector(q, false);
  requireFiniteVector(qd, true);
  for (int i = 0; i < 4; ++i) requireFinite(u(i), "generalized force U");
  Matrix4 m;
  Matrix4 dm[4];
  Vector4 gv;
  evaluate(q, m, dm, gv);
  // C q̇ without forming C: with W as in terms(), W q̇ = Ṁ q̇ and Wᵀ q̇ = [q̇ᵀ ∂M/∂q_j q̇]_j,
  // so C q̇ = Ṁ q̇ − ½ ∂(q̇ᵀ M q̇)/∂q.
  Vector4 c_qd;
  Vector4 m_dot_qd = Vector4::Zero();
  for (int j = 0; j < 4; ++j) {
    const Vector4 dm_qd = dm[j] * qd;
    m_dot_qd += dm_qd * qd(j);
    c_qd(j) = -0.5 * qd.dot(dm_qd);
  }
  c_qd += m_dot_qd;
  return m.llt().solve(u - c_qd - gv);
}

double NormaDynamics::kineticEnergy(const Vector4& q, const Vector4& qd) const {
  requireFiniteVector(qd, true);
  return 0.5 * qd.dot(massMatrix(q) * qd);
}

double NormaDynamics::potentialEnergy(const Vector4& q) const {
  requireFiniteVector(q, false);
  const NormaParameters& p = parameters_;
  const double beta = q(1) - q(0);
  // Eq 20 shifted by m_P g L so that E^p(0) = 0.
  return p.m_slider * p.g * (q(3) + p.delta0) * std::sin(q(2)) -
         p.m_pendulum * p.g * (p.L * std::cos(beta) * std::cos(q(2)) + p.L0 * std::sin(q(2))) +
         p.m_pendulum * p.g * p.L;
}

double NormaDynamics::totalEnergy(const Vector4& q, const Vector4& qd) const {
  return kineticEnergy(q, qd) + potentialEnergy(q);
}

PlanarRates NormaDynamics::planarRates(const Vector4& q, const Vector4& qd, double psi) const {
  requireFiniteVector(q, false);
  requireFiniteVector(qd, true);
  requireFinite(psi, "psi");
  const double r = parameters_.R;
  const auto [sf, cf] = sinCos(q(2));
  const auto [sp, cp] = sinCos(psi);
  PlanarRates out;
  out.x_dot = r * qd(0) * cf * cp + r * qd(2) * sp;  // eq 12
  out.y_dot = r * qd(0) * cf * sp - r * qd(2) * cp;  // eq 12
  out.psi_dot = -qd(0) * sf;                         // eq 6
  return out;
}

double NormaDynamics::staticTilt(double delta) const {
  requireFinite(delta, "delta");
  const NormaParameters& p = parameters_;
  return std::atan2(-(p.m_slider * (p.delta0 + delta) - p.m_pendulum * p.L0), p.m_pendulum * p.L);
}

}  // namespace spherical_robots::norma
