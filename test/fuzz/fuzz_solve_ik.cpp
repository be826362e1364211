// FreeBOT's inverse kinematics (freebot::solveIk) over a chain of radii and a target: the number
// of radii (0 .. 8) and the radii [m], mode (0 full pose, 1 position only), the target position
// [m] and orientation (w, x, y, z), then the options' tolerances, gains, step, max joint step,
// xi, lambda_max, damping residual, stall window. One start of at most two iterations: the input
// checks and the first steps are what is fuzzed, not the search (which costs milliseconds).
#include <Eigen/Geometry>
#include <stdexcept>
#include <vector>

#include "fuzz_input.hpp"
#include "spherical_robots/freebot/src_inverse_kinematics.hpp"
#include "spherical_robots/freebot/src_manipulator.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots::freebot;
  spherical_robots::fuzz::FuzzNumbers in(data, size);
  std::vector<double> radii(static_cast<std::size_t>(in.nextCount(8)));
  for (double& radius : radii) radius = in.next();
  IkOptions options;
  options.mode = in.nextCount(1) == 0 ? IkMode::FullPose : IkMode::PositionOnly;
  const Eigen::Vector3d position{in.next(), in.next(), in.next()};  // braces: in order
  const Eigen::Quaterniond orientation{in.next(), in.next(), in.next(), in.next()};
  for (double* value : {&options.position_tolerance, &options.orientation_tolerance,
                        &options.position_gain, &options.orientation_gain, &options.step,
                        &options.max_joint_step, &options.singular_region, &options.max_damping,
                        &options.damping_residual}) {
    *value = in.next();
  }
  options.stall_window = in.nextInt();
  options.max_iterations = 1 + in.nextCount(1);
  options.restarts = 0;
  try {
    const SrcManipulator manipulator(radii);
    solveIk(manipulator, position, orientation, {}, options);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
