#pragma once
// Norma runs: the closed loop on the path of eq 52 and the open-loop (zero-input) plant, both
// integrated with Boost.Odeint (ode_integrator.hpp) and sampled at a log rate. No ROS.

#include <Eigen/Core>
#include <vector>

#include "spherical_robots/norma/norma_controller.hpp"
#include "spherical_robots/norma/norma_dynamics.hpp"
#include "spherical_robots/norma/ode_integrator.hpp"

namespace spherical_robots::norma {

/// Eq 52: X_d = 2 sin(0.01 t), Y_d = 1.5 sin(0.02 t) [m], t [s].
PathPoint lissajousPath(double t);

/// ψ(0) along eq 52's initial velocity (0.02, 0.03) m/s [rad]: the paper's scenario starts so
/// (launch/norma_stack.launch's initial_psi is this number).
double pathStartHeading();

/// One logged instant.
struct NormaSample {
  double t = 0.0;                  ///< [s]
  Vector4 q = Vector4::Zero();     ///< θ, α, φ [rad], δ [m]
  Vector4 qd = Vector4::Zero();    ///< their rates
  double x = 0.0, y = 0.0;         ///< centre of the sphere [m]
  double psi = 0.0;                ///< heading [rad]
  double x_d = 0.0, y_d = 0.0;     ///< desired point [m] (0 in open loop)
  double error = 0.0;              ///< ‖r − r_d‖ [m] (0 in open loop)
  double torque = 0.0;             ///< T [N m] (0 in open loop)
  double force = 0.0;              ///< F [N] (0 in open loop)
  double energy = 0.0;             ///< total mechanical energy [J]
};

/// Open loop: U = 0 from (q0, q̇0) at X = Y = ψ = 0. A slider spring of stiffness
/// slider_stiffness [N/m] toward δ = 0 (potential ½ k δ², included in energy) may hold the
/// slider; 0 leaves it free, as the paper's model is.
struct OpenLoopConfig {
  LagrangianVariant variant = LagrangianVariant::kText;
  Vector4 q0 = Vector4::Zero();
  Vector4 qd0 = Vector4::Zero();
  double slider_stiffness = 0.0;
  double duration = 5.0;    ///< [s]
  double log_rate = 100.0;  ///< [Hz]
  OdeOptions ode;
};

/// The paper's scenario (eq 52): all q, q̇ and X, Y zero at t = 0, ψ(0) along the desired
/// initial velocity, controller integrals zero.
struct ClosedLoopConfig {
  LagrangianVariant variant = LagrangianVariant::kText;
  ControllerKind controller = ControllerKind::kPaper;
  ControllerGains gains;
  double duration = 1300.0;  ///< [s]
  double log_rate = 1.0;     ///< [Hz]
  OdeOptions ode;
};

/// @throw std::invalid_argument on invalid parameters, options or initial state, or if the
///        state turns non-finite.
std::vector<NormaSample> runOpenLoop(const NormaParameters& parameters,
                                     const OpenLoopConfig& config);

/// @throw std::invalid_argument as runOpenLoop.
std::vector<NormaSample> runClosedLoop(const NormaParameters& parameters,
                                       const ClosedLoopConfig& config);

}  // namespace spherical_robots::norma
