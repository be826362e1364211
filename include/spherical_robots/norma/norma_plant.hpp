#pragma once
// Norma as a plant driven by measured actuator efforts (the norma_plant node): the state of
// eq 46 plus the planar pose of eqs 6 and 12, advanced over a control period with the pendulum
// torque and slider force held, by fixed-step RK4 (Boost.Odeint). No ROS.

#include <array>

#include "spherical_robots/norma/norma_dynamics.hpp"

namespace spherical_robots::norma {

/// q = [θ, α, φ, δ], their rates, and the centre's position and heading on the floor.
struct NormaState {
  Vector4 q = Vector4::Zero();
  Vector4 qd = Vector4::Zero();
  double x = 0.0;    ///< X [m]
  double y = 0.0;    ///< Y [m]
  double psi = 0.0;  ///< ψ [rad]
};

/// The pendulum torque T [N m] and slider force F [N] the actuators report applying.
struct Efforts {
  double torque = 0.0;
  double force = 0.0;
};

/// What drives the plant: the last measured efforts while they are fresh, none once they are
/// stale (no actuator state within the plant's state_timeout: nothing is known to push). The
/// norma_plant node and the sampled batch loop (sampled_norma_loop.hpp) share this rule.
Efforts drivingEfforts(const Efforts& measured, bool fresh);

/// The plant's ODE state: q, q̇, X, Y, ψ.
using PlantVector = std::array<double, 11>;

PlantVector toPlantVector(const NormaState& state);
NormaState fromPlantVector(const PlantVector& x);

/// d/dt of the plant state for generalized forces u (eq 46 solved for q̈, eqs 6 and 12).
/// @throw std::invalid_argument on a non-finite state or input.
PlantVector plantRates(const NormaDynamics& dynamics, const PlantVector& x, const Vector4& u);

/// The state `duration` [s] later with torque T [N m] and force F [N] held (U = [0, T, 0, F]), in
/// RK4 steps no longer than `step` [s]. Non-stiff: the open-loop plant's fastest mode is slow; the
/// stiffness of the closed loop is the controller's, which runs outside at its own rate.
/// @throw std::invalid_argument on a non-finite input, duration < 0, step <= 0, or a state that
///        turns non-finite.
NormaState advanceWithHeldInputs(const NormaDynamics& dynamics, const NormaState& state,
                                 double torque, double force, double duration, double step);

}  // namespace spherical_robots::norma
