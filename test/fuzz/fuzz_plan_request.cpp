// The rotor planner's input checks (rotor::requireValid, what planRotorMotion checks first) over
// a target as rotor_planner's service and `sphere_sim rotor-plan` pass it: k, steps, u_a, v_a,
// psi, max_radius, heading_turns. Plans themselves cost milliseconds and are not fuzzed.
#include <stdexcept>

#include "fuzz_input.hpp"
#include "spherical_robots/rotor/motion_planner.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace spherical_robots;
  fuzz::FuzzNumbers in(data, size);
  rotor::PlanRequest request;
  request.k = in.next();
  request.steps = in.nextInt();
  request.u_a = in.next();
  request.v_a = in.next();
  request.psi = in.next();
  request.max_radius = in.next();
  request.heading_turns = in.nextInt();
  try {
    rotor::requireValid(request);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
