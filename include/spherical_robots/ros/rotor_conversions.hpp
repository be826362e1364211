#pragma once
// The rotor stack's messages: plan requests (the ~plan service's and the execute_manoeuvre
// action's) and the action's feedback and results.

#include <string>

#include "spherical_robots/ExecuteRotorManoeuvreAction.h"
#include "spherical_robots/rotor/manoeuvre_executive.hpp"
#include "spherical_robots/rotor/motion_planner.hpp"

namespace spherical_robots::conversions {

/// The planner's request (lengths in units of R) for a message with the fields of
/// srv/PlanRotorMotion.srv's request (k, steps, u_a, v_a, psi, max_radius, heading_turns; lengths
/// in m) on a sphere of radius [m]; max_radius 0 takes default_max_radius [m]. Validated by
/// rotor::planRotorMotion, not here.
template <typename Request>
rotor::PlanRequest toPlanRequest(const Request& request, double radius, double default_max_radius) {
  rotor::PlanRequest plan;
  plan.k = request.k;
  plan.steps = request.steps;
  plan.u_a = request.u_a / radius;
  plan.v_a = request.v_a / radius;
  plan.psi = request.psi;
  plan.max_radius = (request.max_radius > 0.0 ? request.max_radius : default_max_radius) / radius;
  plan.heading_turns = request.heading_turns;
  return plan;
}

/// The result of an execution that ended with `verdict`.
spherical_robots::ExecuteRotorManoeuvreResult toManoeuvreResult(
    const rotor::ManoeuvreVerdict& verdict);
/// The result of a goal rejected for `why` (nothing executed).
spherical_robots::ExecuteRotorManoeuvreResult rejectedManoeuvreResult(const std::string& why);
/// The feedback of an execution in progress.
spherical_robots::ExecuteRotorManoeuvreFeedback toManoeuvreFeedback(
    const rotor::ManoeuvreProgress& progress);

}  // namespace spherical_robots::conversions
