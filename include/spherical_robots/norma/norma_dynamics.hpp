#pragma once
// Norma, the slider-and-pendulum spherical robot (Moazami, Palanki, Zargarzadeh 2019): the
// Euler-Lagrange dynamics M(q) q̈ + C(q, q̇) q̇ + G(q) = U (eq 46) with q = [θ, α, φ, δ] and the
// planar rolling kinematics of eqs 6 and 12. No ROS.
//
// M, ∂M/∂q and G are generated from the Lagrangian of eq 45 by derivations/derive_norma_dynamics.py;
// C is the Christoffel matrix of M (A.23, A.24), so Ṁ − 2C is skew-symmetric. The appendix's
// M (A.3-A.21) differs from the text's in M11 only: it lacks the shell-and-shaft yaw kinetic
// energy ½ I_Sp^z (θ̇ S_φ)² of eq 37 (docs/errata.md, N3). Both are offered.

#include <Eigen/Core>
#include <string>

#include "spherical_robots/core/enum_names.hpp"

namespace spherical_robots::norma {

/// Section 5's robot. m_Sp = m_shell + m_shaft = 3 kg (text after eq 21).
struct NormaParameters {
  double R = 0.2;            ///< shell radius [m]
  double L = 0.15;           ///< pendulum length [m]
  double L0 = 0.10;          ///< pendulum pivot's distance from the centre along the shaft [m]
  double delta0 = 0.1;       ///< slider's rest distance from the centre along the shaft [m]
  double m_shell = 2.5;      ///< shell mass m_Shl [kg]; I_Shl = 2/3 m_Shl R² (eq 38)
  double m_shaft = 0.5;      ///< shaft mass m_Shf [kg]; I_Shf^x = 1/3 m_Shf R² (eq 39, corrected)
  double m_pendulum = 0.5;   ///< pendulum bob m_P [kg], a point mass on a massless rod
  double m_slider = 0.5;     ///< slider m_Sl [kg], a point mass
  double g = 9.81;           ///< gravity [m/s²]
};

/// @throw std::invalid_argument naming the first parameter that is not finite and > 0.
void validate(const NormaParameters& parameters);

/// Which printed form of the inertia matrix to use (docs/errata.md, N3).
enum class LagrangianVariant {
  kText,      ///< eq 45 (eqs 7-44): the default
  kAppendix,  ///< A.3-A.21: eq 45 without the sphere's yaw term ½ I_Sp^z (θ̇ S_φ)² in M11
};

/// "text" | "appendix". @throw std::invalid_argument naming the choices on another name.
inline constexpr EnumNames<LagrangianVariant, 2> kVariantNames = {
    {{LagrangianVariant::kText, "text"}, {LagrangianVariant::kAppendix, "appendix"}}};
inline LagrangianVariant lagrangianVariantFromString(const std::string& name) {
  return enumFromName(kVariantNames, name, "Lagrangian variant");
}
inline std::string toString(LagrangianVariant variant) { return enumName(kVariantNames, variant); }

using Vector4 = Eigen::Vector4d;
using Matrix4 = Eigen::Matrix4d;

/// The four terms of eq 46 at one state.
struct DynamicsTerms {
  Matrix4 M = Matrix4::Zero();  ///< inertia matrix [kg m², kg m, kg]
  Matrix4 C = Matrix4::Zero();  ///< Christoffel Coriolis/centripetal matrix (A.23, A.24)
  Vector4 G = Vector4::Zero();  ///< gravity vector [N m, N m, N m, N] (A.41)
};

/// Velocity of the sphere's centre in the world and its yaw rate (eqs 6, 12).
struct PlanarRates {
  double x_dot = 0.0;    ///< Ẋ [m/s]
  double y_dot = 0.0;    ///< Ẏ [m/s]
  double psi_dot = 0.0;  ///< ψ̇ [rad/s]
};

/// q = [θ, α, φ, δ]: shell rolling angle about the shaft, pendulum angle relative to the shell
/// (the pendulum hangs at α − θ from its rest direction, eq 15), shaft tilt about the
/// longitudinal axis, slider displacement from δ0 along the shaft [rad, rad, rad, m].
class NormaDynamics {
 public:
  /// @throw std::invalid_argument as validate().
  explicit NormaDynamics(const NormaParameters& parameters,
                         LagrangianVariant variant = LagrangianVariant::kText);

  const NormaParameters& parameters() const { return parameters_; }
  LagrangianVariant variant() const { return variant_; }

  /// M, C and G at (q, q̇).
  /// @throw std::invalid_argument on a non-finite component.
  DynamicsTerms terms(const Vector4& q, const Vector4& qd) const;

  /// M(q). @throw std::invalid_argument on a non-finite component.
  Matrix4 massMatrix(const Vector4& q) const;

  /// U of eq 46 for the pendulum motor torque T [N m] (acting on the pendulum about the shaft,
  /// reacting on the shell) and the slider force F [N] along the shaft, by virtual work:
  /// U = [0, T, 0, F] (the text above eq 47; eq 47's right-hand side [T, 0, 0, F] is wrong,
  /// docs/errata.md N4). @throw std::invalid_argument on a non-finite input.
  static Vector4 generalizedForces(double torque, double force);

  /// q̈ = M⁻¹ (U − C q̇ − G) [rad/s², m/s²].
  /// @throw std::invalid_argument on a non-finite component.
  Vector4 acceleration(const Vector4& q, const Vector4& qd, const Vector4& u) const;

  /// ½ q̇ᵀ M q̇ [J].
  double kineticEnergy(const Vector4& q, const Vector4& qd) const;
  /// E^p of eq 20 [J], zero at q = 0 when m_P L0 = m_Sl δ0 (eq 1).
  double potentialEnergy(const Vector4& q) const;
  /// Kinetic plus potential [J], conserved when U = 0.
  double totalEnergy(const Vector4& q, const Vector4& qd) const;

  /// Eqs 6, 12 at heading ψ [rad].
  /// @throw std::invalid_argument on a non-finite input.
  PlanarRates planarRates(const Vector4& q, const Vector4& qd, double psi) const;

  /// The tilt φ [rad] at which a slider held at δ [m] balances the robot at rest with the
  /// pendulum hanging (α = θ), G3 = 0: tan φ = −(m_Sl (δ0 + δ) − m_P L0) / (m_P L).
  /// @throw std::invalid_argument on a non-finite δ.
  double staticTilt(double delta) const;

 private:
  void evaluate(const Vector4& q, Matrix4& m, Matrix4 dm[4], Vector4& gv) const;

  NormaParameters parameters_;
  LagrangianVariant variant_;
};

}  // namespace spherical_robots::norma
