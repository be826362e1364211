// Norma's controller (norma::NormaController::compute) at a plant state and a path point, with
// gains from the input: kind (0 paper, 1 tracking), the gains (k1 k2 k3, rate, pendulum, slider
// and tracking_slider kp ki kd, along, cross, heading, tilt gains, tilt damping, max slider),
// q, q dot, X, Y, psi, the three integrals, the path point (x, y and their two derivatives).
#include <stdexcept>

#include "fuzz_input.hpp"
#include "spherical_robots/norma/norma_controller.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots::norma;
  spherical_robots::fuzz::FuzzNumbers in(data, size);
  const ControllerKind kind = in.nextCount(1) == 0 ? ControllerKind::kPaper : ControllerKind::kTracking;
  ControllerGains g;
  for (double* value :
       {&g.kinematic.k1, &g.kinematic.k2, &g.kinematic.k3, &g.rate.kp, &g.rate.ki, &g.rate.kd,
        &g.pendulum.kp, &g.pendulum.ki, &g.pendulum.kd, &g.slider.kp, &g.slider.ki, &g.slider.kd,
        &g.tracking_slider.kp, &g.tracking_slider.ki, &g.tracking_slider.kd, &g.along_gain,
        &g.cross_gain, &g.heading_gain, &g.tilt_gain, &g.tilt_damping, &g.max_slider}) {
    *value = in.next();
  }
  Vector4 q, qd;
  for (int i = 0; i < 4; ++i) q[i] = in.next();
  for (int i = 0; i < 4; ++i) qd[i] = in.next();
  const double x = in.next(), y = in.next(), psi = in.next();
  const Eigen::Vector3d integrals{in.next(), in.next(), in.next()};  // braces: in order
  PathPoint reference;
  for (double* value : {&reference.x, &reference.y, &reference.x_dot, &reference.y_dot,
                        &reference.x_ddot, &reference.y_ddot}) {
    *value = in.next();
  }
  try {
    const NormaController controller(NormaParameters(), kind, g);
    controller.compute(q, qd, x, y, psi, integrals, reference);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
