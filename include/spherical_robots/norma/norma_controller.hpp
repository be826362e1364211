#pragma once
// Norma's two-layer path-tracking controller (Moazami et al. 2019, section 4): a kinematic layer
// (eqs 48-51) turns the tracking error into a rolling-rate and a slider set-point, and a PID
// cascade (Fig. 5, Table 1) turns those into the pendulum torque T and the slider force F. Also
// a tracking controller of this project's design (docs/conventions.md, "Norma", "Controller").
// No ROS.
//
// Loop signs (derived from the model, docs/conventions.md): T > 0 raises β̈ = α̈ − θ̈ (at q = 0,
// ∂β̈/∂T = (M⁻¹)22 − (M⁻¹)12 = 43 rad/(s² N m)); a pendulum held at β > 0 accelerates the roll
// (θ̈ = 3.1 g L m_P sin β at q = 0); F > 0 raises δ̈. So with positive gains every loop acts on
// set-point minus measurement.

#include <Eigen/Core>
#include <string>

#include "spherical_robots/core/enum_names.hpp"
#include "spherical_robots/norma/norma_dynamics.hpp"

namespace spherical_robots::norma {

/// A point of the desired path and its time derivatives [m, m/s, m/s²], world frame.
struct PathPoint {
  double x = 0.0, y = 0.0;
  double x_dot = 0.0, y_dot = 0.0;
  double x_ddot = 0.0, y_ddot = 0.0;
};

/// k1 [m], k2 [rad/s], k3 [m] of eqs 50, 51 (section 5's values).
struct KinematicGains {
  double k1 = 0.1;
  double k2 = -0.1;
  double k3 = 5.0;
};

/// Eqs 48-51 at one instant.
struct KinematicCommand {
  double theta_dot_d = 0.0;  ///< θ̇_d [rad/s] (eq 51)
  double delta_d = 0.0;      ///< δ_d [m] (eq 50)
  double zeta = 0.0;         ///< ζ [rad] (eq 49), from e to the heading, in (−π, π]
  double error = 0.0;        ///< ‖e‖ [m] (eq 48)
};

/// Eqs 48-51. e = r_Sp − r_d (eq 48) points from the target to the robot; ζ is the angle from e
/// to the heading (cos ζ < 0 when the robot heads toward a target ahead of it, i.e. is behind,
/// so k2 < 0 speeds it up; sin ζ > 0 when the target lies to the left, and δ > 0 turns left).
/// @throw std::invalid_argument on a non-finite input or R <= 0.
KinematicCommand kinematicLayer(const KinematicGains& gains, double R, double x, double y,
                                double psi, const PathPoint& reference);

/// A PID's gains. Derivative terms act on the measurement.
struct PidGains {
  double kp = 0.0;
  double ki = 0.0;
  double kd = 0.0;
};

enum class ControllerKind {
  kPaper,     ///< eqs 48-51 and Table 1, as published
  kTracking,  ///< this project's: feed-forward yaw rate and tilt, see NormaController
};

/// "paper" | "tracking". @throw std::invalid_argument naming the choices on another name.
inline constexpr EnumNames<ControllerKind, 2> kControllerNames = {
    {{ControllerKind::kPaper, "paper"}, {ControllerKind::kTracking, "tracking"}}};
inline ControllerKind controllerKindFromString(const std::string& name) {
  return enumFromName(kControllerNames, name, "Norma controller");
}
inline std::string toString(ControllerKind kind) { return enumName(kControllerNames, kind); }

/// Gains of both controllers.
struct ControllerGains {
  KinematicGains kinematic;
  PidGains rate{1.0, 0.0, 0.0};        ///< PID1: θ̇_d − θ̇ [rad/s] → β_d [rad]; kd must be 0
  PidGains pendulum{10.0, 7.0, 3.0};   ///< PID2: β_d − β [rad] → T [N m]
  PidGains slider{15.0, 3.0, 10.0};    ///< PID3: δ_d − δ [m] → F [N], plus g m_Sl sin φ
  // Tracking controller (ControllerKind::kTracking).
  double along_gain = 0.2;     ///< k_x [1/s]: speed correction per metre of along-track error
  double cross_gain = 20.0;    ///< k_y [1/m²]: yaw rate per (m/s of path speed · m across)
  double heading_gain = 4.0;   ///< k_ψ [1/m]: yaw rate per m/s of path velocity across the heading
  double tilt_gain = 0.05;     ///< k_φ [m/rad]: slider set-point per radian of tilt error
  double tilt_damping = 0.12;  ///< k_φ̇ [m s/rad]: slider set-point per rad/s of tilt rate
  double max_slider = 0.09;    ///< |δ_d| limit [m] of the tracking controller
  /// The tracking controller's slider loop, in place of PID3: stiff enough (double pole near
  /// −20 s⁻¹) for the slider to damp the tilt, whose own mode (≈1.7 rad/s) is undamped.
  PidGains tracking_slider{200.0, 0.0, 20.0};
};

/// @throw std::invalid_argument naming the first gain that is not finite, PID1's kd != 0
///        (its derivative would need θ̈), or a negative tracking gain or max_slider <= 0.
void validate(const ControllerGains& gains);

/// Number of controller states appended to the plant state: ∫(θ̇_d − θ̇), ∫(β_d − β), ∫(δ_d − δ).
constexpr int kControllerStates = 3;

/// The controller's output at one instant.
struct ControlOutput {
  double torque = 0.0;                  ///< T [N m]
  double force = 0.0;                   ///< F [N]
  double theta_dot_d = 0.0;             ///< θ̇_d [rad/s]
  double delta_d = 0.0;                 ///< δ_d [m]
  double beta_d = 0.0;                  ///< pendulum angle set-point [rad]
  double error = 0.0;                   ///< ‖e‖ [m]
  Eigen::Vector3d integrand = Eigen::Vector3d::Zero();  ///< d/dt of the three integrals
};

/// Both layers over one robot.
///
/// Tracking controller (ControllerKind::kTracking): with the path's velocity v_r (speed s_r) and
/// yaw rate ω_r, and the error r_d − r split into e_∥ along and e_⊥ across the heading, it
/// commands (a unicycle tracking law)
///   θ̇_d = (v_r · h + k_x e_∥) / (R cos φ)                       (eq 12 along the heading h)
///   ψ̇_d = ω_r + k_y s_r e_⊥ + k_ψ (v_r · h⊥)                    (v_r · h⊥ = s_r sin(ψ_r − ψ))
/// the tilt that gives that yaw rate through eq 6, sin φ_d = −ψ̇_d / θ̇_d (θ̇_d regularised near 0,
/// φ_d saturated smoothly with tanh), and the slider that holds that tilt at rest (G3 = 0), with
/// tilt feedback and damping:
///   δ_d = −(m_P L cos β / m_Sl) tan φ_d + k_φ (φ − φ_d) + k_φ̇ φ̇,  smoothly saturated at max_slider,
/// tracked by tracking_slider (stiffer than PID3) with the same gravity feed-forward. The
/// pendulum cascade (PID1, PID2) is the paper's.
class NormaController {
 public:
  /// @throw std::invalid_argument as validate() for the parameters and gains.
  NormaController(const NormaParameters& parameters, ControllerKind kind,
                  const ControllerGains& gains = ControllerGains());

  ControllerKind kind() const { return kind_; }
  const ControllerGains& gains() const { return gains_; }
  /// New gains from the next compute() on (dynamic_reconfigure).
  /// @throw std::invalid_argument as validate(), with the gains unchanged.
  void setGains(const ControllerGains& gains);

  /// T, F and the integrands at plant state (q, q̇, X, Y, ψ) with the controller's integrals
  /// and the desired path point.
  /// @throw std::invalid_argument on a non-finite input.
  ControlOutput compute(const Vector4& q, const Vector4& qd, double x, double y, double psi,
                        const Eigen::Vector3d& integrals, const PathPoint& reference) const;

 private:
  KinematicCommand trackingLayer(const Vector4& q, const Vector4& qd, double x, double y,
                                 double psi, const PathPoint& reference) const;

  NormaParameters parameters_;
  ControllerKind kind_;
  ControllerGains gains_;
};

}  // namespace spherical_robots::norma
