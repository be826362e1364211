#include "spherical_robots/norma/norma_plant.hpp"

#include <boost/numeric/odeint/integrate/integrate_n_steps.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <cmath>
#include <stdexcept>

#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::norma {

Efforts drivingEfforts(const Efforts& measured, bool fresh) {
  return fresh ? measured : Efforts{};
}

PlantVector toPlantVector(const NormaState& state) {
  PlantVector x{};
  for (int i = 0; i < 4; ++i) {
    x[i] = state.q(i);
    x[4 + i] = state.qd(i);
  }
  x[8] = state.x;
  x[9] = state.y;
  x[10] = state.psi;
  return x;
}

NormaState fromPlantVector(const PlantVector& x) {
  NormaState state;
  state.q = Vector4(x[0], x[1], x[2], x[3]);
  state.qd = Vector4(x[4], x[5], x[6], x[7]);
  state.x = x[8];
  state.y = x[9];
  state.psi = x[10];
  return state;
}

PlantVector plantRates(const NormaDynamics& dynamics, const PlantVector& x, const Vector4& u) {
  const NormaState state = fromPlantVector(x);
  const Vector4 qdd = dynamics.acceleration(state.q, state.qd, u);  // eq 46
  const PlanarRates planar = dynamics.planarRates(state.q, state.qd, state.psi);  // eqs 6, 12
  PlantVector rates{};
  for (int i = 0; i < 4; ++i) {
    rates[i] = state.qd(i);
    rates[4 + i] = qdd(i);
  }
  rates[8] = planar.x_dot;
  rates[9] = planar.y_dot;
  rates[10] = planar.psi_dot;
  return rates;
}

// GCC 12 reports odeint's std::array scratch states (m_x_tmp, m_F) as maybe-uninitialized; they
// are written by each stage before they are read.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
NormaState advanceWithHeldInputs(const NormaDynamics& dynamics, const NormaState& state,
                                 double torque, double force, double duration, double step) {
  requireFinite(duration, "duration [s]");
  requirePositive(step, "integration step [s]");
  if (duration < 0.0) throw std::invalid_argument("duration [s] must be >= 0");
  const Vector4 u = NormaDynamics::generalizedForces(torque, force);
  PlantVector x = toPlantVector(state);
  const int steps = static_cast<int>(std::ceil(duration / step - 1e-9));
  if (steps == 0) return state;
  boost::numeric::odeint::integrate_n_steps(
      boost::numeric::odeint::runge_kutta4<PlantVector>(),
      [&](const PlantVector& s, PlantVector& dsdt, double) { dsdt = plantRates(dynamics, s, u); },
      x, 0.0, duration / steps, steps);
  for (const double value : x)
    if (!std::isfinite(value))
      throw std::invalid_argument("Norma's state turned non-finite while integrating");
  return fromPlantVector(x);
}

#pragma GCC diagnostic pop

}  // namespace spherical_robots::norma
