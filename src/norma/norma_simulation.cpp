#include "spherical_robots/norma/norma_simulation.hpp"

#include <cmath>
#include <limits>

#include "spherical_robots/core/sin_cos.hpp"
#include "spherical_robots/core/validation.hpp"

namespace spherical_robots::norma {
namespace {

// Plant state layout: q (4), q̇ (4), X, Y, ψ; the closed loop appends the controller integrals.
constexpr std::size_t kPlantStates = 11;

Vector4 segment(const OdeState& x, std::size_t first) {
  return Vector4(x[first], x[first + 1], x[first + 2], x[first + 3]);
}

void writePlantRates(const NormaDynamics& dynamics, const OdeState& x, const Vector4& u,
                     OdeState& dxdt) {
  const Vector4 q = segment(x, 0), qd = segment(x, 4);
  const Vector4 qdd = dynamics.acceleration(q, qd, u);
  const PlanarRates planar = dynamics.planarRates(q, qd, x[10]);
  for (std::size_t i = 0; i < 4; ++i) {
    dxdt[i] = qd(i);
    dxdt[4 + i] = qdd(i);
  }
  dxdt[8] = planar.x_dot;
  dxdt[9] = planar.y_dot;
  dxdt[10] = planar.psi_dot;
}

NormaSample plantSample(const NormaDynamics& dynamics, const OdeState& x, double t) {
  NormaSample s;
  s.t = t;
  s.q = segment(x, 0);
  s.qd = segment(x, 4);
  s.x = x[8];
  s.y = x[9];
  s.psi = x[10];
  s.energy = dynamics.totalEnergy(s.q, s.qd);
  return s;
}

}  // namespace

PathPoint lissajousPath(double t) {
  requireFinite(t, "t [s]");
  const auto [s1, c1] = sinCos(0.01 * t);
  const double s2 = 2.0 * s1 * c1, c2 = c1 * c1 - s1 * s1;  // of 0.02 t
  PathPoint p;
  p.x = 2.0 * s1;
  p.y = 1.5 * s2;
  p.x_dot = 0.02 * c1;
  p.y_dot = 0.03 * c2;
  p.x_ddot = -0.0002 * s1;
  p.y_ddot = -0.0006 * s2;
  return p;
}

double pathStartHeading() {
  const PathPoint start = lissajousPath(0.0);
  return std::atan2(start.y_dot, start.x_dot);
}

std::vector<NormaSample> runOpenLoop(const NormaParameters& parameters,
                                     const OpenLoopConfig& config) {
  const NormaDynamics dynamics(parameters, config.variant);
  requireFinite(config.slider_stiffness, "slider stiffness [N/m]");
  const double k = config.slider_stiffness;
  OdeState x(kPlantStates, 0.0);
  for (std::size_t i = 0; i < 4; ++i) {
    requireFinite(config.q0(i), "q0");
    requireFinite(config.qd0(i), "qd0");
    x[i] = config.q0(i);
    x[4 + i] = config.qd0(i);
  }
  std::vector<NormaSample> samples;
  const OdeRhs rhs = [&](const OdeState& state, OdeState& dxdt, double) {
    writePlantRates(dynamics, state, Vector4(0.0, 0.0, 0.0, -k * state[3]), dxdt);
  };
  integrateLogged(rhs, x, config.duration, config.log_rate, config.ode,
                  [&](const OdeState& state, double t) {
                    NormaSample s = plantSample(dynamics, state, t);
                    s.energy += 0.5 * k * s.q(3) * s.q(3);
                    samples.push_back(s);
                  });
  return samples;
}

std::vector<NormaSample> runClosedLoop(const NormaParameters& parameters,
                                       const ClosedLoopConfig& config) {
  const NormaDynamics dynamics(parameters, config.variant);
  const NormaController controller(parameters, config.controller, config.gains);
  OdeState x(kPlantStates + kControllerStates, 0.0);
  x[10] = pathStartHeading();
  // The Jacobian's columns evaluate the right-hand side many times at one t.
  double path_time = std::numeric_limits<double>::quiet_NaN();
  PathPoint path_point;
  auto control = [&](const OdeState& state, double t) {
    if (t != path_time) {
      path_point = lissajousPath(t);
      path_time = t;
    }
    const Eigen::Vector3d integrals(state[11], state[12], state[13]);
    return controller.compute(segment(state, 0), segment(state, 4), state[8], state[9],
                              state[10], integrals, path_point);
  };
  const OdeRhs rhs = [&](const OdeState& state, OdeState& dxdt, double t) {
    const ControlOutput u = control(state, t);
    writePlantRates(dynamics, state, NormaDynamics::generalizedForces(u.torque, u.force), dxdt);
    for (std::size_t i = 0; i < 3; ++i) dxdt[kPlantStates + i] = u.integrand(i);
  };
  std::vector<NormaSample> samples;
  integrateLogged(rhs, x, config.duration, config.log_rate, config.ode,
                  [&](const OdeState& state, double t) {
                    NormaSample s = plantSample(dynamics, state, t);
                    const PathPoint r = lissajousPath(t);
                    const ControlOutput u = control(state, t);
                    s.x_d = r.x;
                    s.y_d = r.y;
                    s.error = std::hypot(s.x - r.x, s.y - r.y);
                    s.torque = u.torque;
                    s.force = u.force;
                    samples.push_back(s);
                  });
  return samples;
}

}  // namespace spherical_robots::norma
