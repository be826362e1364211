#include "rotor_command.hpp"

#include <ostream>
#include <vector>

#include "spherical_robots/rotor/geometric_phase.hpp"
#include "spherical_robots/rotor/motion_planner.hpp"

namespace spherical_robots::sphere_sim {
namespace {

void writeState(JsonWriter& json, const char* key, const rotor::PlaneState& state) {
  json.beginObject(key).number("u", state.u_a).number("v", state.v_a).number("psi", state.psi).end();
}

int runRotorStep(const ParsedOptions& options, std::ostream& out) {
  const double k = options.number("k");
  const rotor::FigureEight curve(options.number("a"), options.number("b"), options.number("gamma"));
  const rotor::StepResult step = rotor::rotorStep(k, curve);
  OutputFile file(options.text("out"));
  JsonWriter json(file.stream());
  writeState(json, "half", step.half);
  writeState(json, "full", step.full);
  json.finish();
  file.commit();
  out << "rotor-step k " << k << ", a " << curve.a() << ", b " << curve.b() << ", gamma "
      << curve.gamma() << ": half (" << step.half.u_a << ", " << step.half.v_a << ", "
      << step.half.psi << "), full (" << step.full.u_a << ", " << step.full.v_a << ", "
      << step.full.psi << ")\n";
  return kSuccess;
}

int runRotorPlan(const ParsedOptions& options, std::ostream& out) {
  rotor::PlanRequest request;
  request.k = options.number("k");
  request.steps = options.integer("steps");
  const std::vector<double> target = options.numberList("target", 3);
  request.u_a = target[0];
  request.v_a = target[1];
  request.psi = target[2];
  request.max_radius = options.number("max-radius");
  request.heading_turns = options.integer("heading-turns");
  const rotor::PlanResult result = rotor::planRotorMotion(request);
  OutputFile file(options.text("out"));
  JsonWriter json(file.stream());
  json.beginArray("solutions");
  for (const rotor::RotorPlan& plan : result.solutions) {
    json.beginObject()
        .number("a", plan.a)
        .number("b", plan.b)
        .number("gamma", plan.gamma)
        .number("psi", plan.psi)
        .number("length", plan.length)
        .number("final_error", plan.final_error)
        .end();
  }
  json.end();
  if (result.solutions.empty()) json.text("reason", result.reason);
  json.finish();
  file.commit();
  if (result.solutions.empty()) {
    out << "rotor-plan: " << result.reason << "\n";
    return kNoSolution;
  }
  const rotor::RotorPlan& best = result.solutions.front();
  out << "rotor-plan: " << result.solutions.size() << " solution(s); shortest a " << best.a
      << ", b " << best.b << ", gamma " << best.gamma << ", length " << best.length
      << ", final error " << best.final_error << "\n";
  return kSuccess;
}

const char* const kConventions =
    R"(Units: lengths in units of the sphere radius R, angles in radians. The figure eight is two
circles on the sphere through its south pole (eq 35): first the circle of Euclidean radius a
(centre towards +y of the sphere frame), then its mirror image of radius b, both starting at the
pole heading +x; the curve is then turned by gamma about the sphere's z axis (eq 31). Turning by
gamma turns the whole plane path by +gamma and leaves psi unchanged. The contact kinematics are
the dynamically realizable ones (eqs 28-30) with inertia ratio k = J_xx / J_zz (eq 14; k = 0 is
pure rolling). Radii must be < sqrt(2)/2 = 0.70710678: a larger circle reaches the equator,
where eq 30 is singular. Integration: Runge-Kutta-Fehlberg 7(8), tolerances 1e-12.
)";

const char* const kStepDescription =
    R"(Integrates one figure eight from the zero state (u_a = v_a = psi = 0).

JSON members (numbers with 17 significant digits):
  half   {"u", "v", "psi"}: state after the first circle (theta = pi)
  full   {"u", "v", "psi"}: state after the whole figure eight (theta = 2 pi); the
         non-holonomic shift is h = sqrt(u^2 + v^2), the holonomy angle eta = psi
stdout: one line with the same figures.

Exit status: 0 success; 2 usage error; 4 invalid input (non-finite number, k < 0, a or b not in
(0, 0.70710678)): one-line error on stderr and no output file.
)";

const char* const kPlanDescription =
    R"(Finds every figure eight (a, b, gamma) with a, b <= max radius that, traced n times from
the zero state, brings the contact point to (U, V) and the heading to PSI: eta(a, b) = PSI / n
(eq 32) and h(a, b) = |sin(eta / 2) / sin(n eta / 2)| sqrt(U^2 + V^2) (eq 33, corrected), with
gamma aiming the total shift at (U, V). PSI is the accumulated turn, not reduced modulo 2 pi
(7 asks for 7 rad); --heading-turns M also plans for PSI + 2 pi m, |m| <= M.

JSON members (numbers with 17 significant digits):
  solutions  array, shortest contact path first, of objects with
             a, b         the circles' Euclidean radii [R]
             gamma        orientation of the figure eight [rad], in (-pi, pi]
             psi          the heading the plan reaches (PSI + 2 pi m) [rad]
             length       contact path length on the sphere over all n steps, 2 pi n (a + b) [R]
             final_error  max |target - reached| over (u_a, v_a, psi), integrating all n steps
  reason     only when there is no solution: why
stdout: one line (number of solutions and the shortest, or the reason).

Radii of a plan are >= 0.01 (smaller circles approach the null manoeuvre a = b = 0). Every
root is verified by integration; plans with final_error > 1e-6 are dropped.
Exit status: 0 at least one plan; 3 no plan within the limits (the file holds "solutions": []
and "reason"); 2 usage error (a fraction for --steps or --heading-turns, a target that is not
three numbers); 4 invalid input (non-finite number, k < 0, steps < 1, max radius not in
(0, 0.70710678), heading turns < 0): one-line error on stderr and no output file.
)";

/// --k, the same for rotor-step and rotor-plan.
OptionSpec inertiaRatioOption() {
  return {"k", "K", "Inertia ratio k = J_xx / J_zz (eq 14), >= 0 (k = 0: pure rolling).", "", true,
          {}};
}

}  // namespace

Subcommand rotorStepCommand() {
  Subcommand command;
  command.name = "rotor-step";
  command.summary = "One figure eight of the two-rotor sphere: state after half and one step.";
  command.description = std::string(kStepDescription) + "\n" + kConventions;
  command.options = {
      inertiaRatioOption(),
      {"a", "A", "Euclidean radius of the first circle [R], in (0, 0.70710678).", "", true, {}},
      {"b", "B", "Euclidean radius of the second circle [R], in (0, 0.70710678).", "", true, {}},
      {"gamma", "G", "Orientation of the figure eight about the sphere's z axis [rad].", "0",
       false, {}},
      outOption("JSON file to write (members below)."),
  };
  command.run = runRotorStep;
  return command;
}

Subcommand rotorPlanCommand() {
  Subcommand command;
  command.name = "rotor-plan";
  command.summary = "n-step geometric-phase motion planning of the two-rotor sphere.";
  command.description = std::string(kPlanDescription) + "\n" + kConventions;
  command.options = {
      inertiaRatioOption(),
      {"steps", "N", "Number of figure eights n, a whole number >= 1.", "", true, {}},
      {"target", "U,V,PSI",
       "Target contact point (U, V) on the plane [R] and accumulated heading PSI [rad].", "", true,
       {}},
      {"max-radius", "R", "Largest circle radius a, b [R], in (0, 0.70710678).", "0.7", false, {}},
      {"heading-turns", "M",
       "Also plan for the headings PSI + 2 pi m, |m| <= M (whole number >= 0).", "0", false, {}},
      outOption("JSON file to write (members below)."),
  };
  command.run = runRotorPlan;
  return command;
}

}  // namespace spherical_robots::sphere_sim
