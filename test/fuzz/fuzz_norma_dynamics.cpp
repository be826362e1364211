// Norma's model at a state and inputs (norma::NormaDynamics): the robot's parameters (R, L, L0,
// delta0, the four masses, g), variant (0 text, 1 appendix), q = [theta, alpha, phi, delta],
// q dot, the torque T and the force F, the heading psi.
#include <stdexcept>

#include "fuzz_input.hpp"
#include "spherical_robots/norma/norma_dynamics.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots::norma;
  spherical_robots::fuzz::FuzzNumbers in(data, size);
  NormaParameters p;
  for (double* value : {&p.R, &p.L, &p.L0, &p.delta0, &p.m_shell, &p.m_shaft, &p.m_pendulum,
                        &p.m_slider, &p.g}) {
    *value = in.next();
  }
  const LagrangianVariant variant =
      in.nextCount(1) == 0 ? LagrangianVariant::kText : LagrangianVariant::kAppendix;
  Vector4 q, qd;
  for (int i = 0; i < 4; ++i) q[i] = in.next();
  for (int i = 0; i < 4; ++i) qd[i] = in.next();
  const double torque = in.next(), force = in.next(), psi = in.next();
  try {
    const NormaDynamics dynamics(p, variant);
    dynamics.acceleration(q, qd, NormaDynamics::generalizedForces(torque, force));
    dynamics.totalEnergy(q, qd);
    dynamics.planarRates(q, qd, psi);
    dynamics.staticTilt(q[3]);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
