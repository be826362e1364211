#include "rotor_command.hpp"

#include <Eigen/Geometry>
#include <ostream>
#include <vector>

#include "spherical_robots/config/actuator_models.hpp"
#include "spherical_robots/config/rotor_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "spherical_robots/rotor/geometric_phase.hpp"
#include "spherical_robots/rotor/motion_planner.hpp"
#include "spherical_robots/rotor/sampled_rotor_loop.hpp"

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

/// Option `name` as a number above `minimum` (or at it, with `inclusive`).
/// @throw InvalidInput naming the option, the value and the limit.
double numberAbove(const ParsedOptions& options, const std::string& name, double minimum,
                   bool inclusive) {
  const double value = options.number(name);
  if (inclusive ? value < minimum : value <= minimum) {
    throw InvalidInput("--" + name + " must be " + (inclusive ? ">= " : "> ") +
                       formatNumber(minimum) + ", got " + formatNumber(value));
  }
  return value;
}

const char* const kExecuteColumns[] = {"t",         "x",         "y",          "qw",
                                       "qx",        "qy",        "qz",         "u_o",
                                       "v_o",       "psi",       "command_1",  "command_2",
                                       "measured_1", "measured_2", "state"};

int runRotorExecute(const ParsedOptions& options, std::ostream& out) {
  const double radius = radiusFromUrdf(configDirectory(options) + "/urdf/rotor_sphere.urdf", "base_link");
  // The stack's parameters as its nodes read them, the options overriding them.
  const config::YamlParameterSource stack(configDirectory(options) + "/config/rotor.yaml");
  rotor::ManoeuvreExecutive::Parameters parameters =
      config::rotorExecutiveParameters(stack, stack, config::kRotorPlannerKeys);
  const config::RotorManoeuvre planned = config::rotorManoeuvre(stack, "manoeuvre/");
  rotor::RotorStackSampling sampling;
  rotor::PlanRequest request;
  if (options.given("k")) {
    sampling.k = numberAbove(options, "k", 0.0, false);
    request.k = sampling.k;
  } else {
    sampling.k = config::positiveNumber(stack, "inertia_ratio", sampling.k);
    request.k = planned.k;
  }
  request.steps = options.given("steps") ? options.integer("steps") : planned.steps;
  if (request.steps < 1) {
    throw InvalidInput("--steps must be >= 1, got " + std::to_string(request.steps));
  }
  const std::vector<double> target = options.given("target")
                                         ? options.numberList("target", 3)
                                         : std::vector<double>{planned.u, planned.v, planned.psi};
  request.u_a = target[0] / radius;  // as rotor_planner takes ~manoeuvre/u, v [m]
  request.v_a = target[1] / radius;
  request.psi = target[2];
  request.max_radius = 0.7 * radius / radius;  // rotor_planner's default ~max_radius, 0.7 R [m]
  parameters.radius = radius;
  if (options.given("curve-rate"))
    parameters.curve_rate = numberAbove(options, "curve-rate", 0.0, false);
  if (options.given("max-rotor-speed"))
    parameters.max_rotor_speed = numberAbove(options, "max-rotor-speed", 0.0, true);
  if (options.given("actuator-time-constant"))
    parameters.actuator_time_constant = numberAbove(options, "actuator-time-constant", 0.0, true);
  if (options.given("corrections")) {
    parameters.corrections = options.integer("corrections");
    if (parameters.corrections < 0) {
      throw InvalidInput("--corrections must be >= 0, got " +
                         std::to_string(parameters.corrections));
    }
  }
  if (options.given("correction-tolerance"))
    parameters.correction_tolerance = numberAbove(options, "correction-tolerance", 0.0, false);
  if (options.given("correction-tilt-tolerance")) {
    parameters.correction_tilt_tolerance =
        numberAbove(options, "correction-tilt-tolerance", 0.0, false);
  }
  if (options.given("actuator-models")) {
    const config::ActuatorModels models = config::loadActuatorModels(
        config::YamlParameterSource(options.text("actuator-models")), {"rotor_1", "rotor_2"});
    sampling.actuator_models = models.models;
    sampling.noise_seed = models.noise_seed;
  }
  // launch/rotor_stack.launch's default duration: 20 s and 10 s per correction.
  const double duration = options.given("duration")
                              ? numberAbove(options, "duration", 0.0, true)
                              : 20.0 + 10.0 * parameters.corrections;
  const double log_rate = numberAbove(options, "log-rate", 0.0, false);
  const std::string per_step = " s / the plant's step " + formatNumber(sampling.plant_step) + " s";
  const long steps_per_row = wholeSteps(1.0 / log_rate, sampling.plant_step,
                                        "--log-rate " + formatNumber(log_rate) + " Hz: its period " +
                                            formatNumber(1.0 / log_rate) + per_step);
  const long steps = wholeSteps(duration, sampling.plant_step,
                                "--duration " + formatNumber(duration) + per_step);
  if (steps_per_row < 1 || steps % steps_per_row != 0) {
    throw InvalidInput("--duration " + formatNumber(duration) +
                       " s is not a whole number of log periods (1/--log-rate = " +
                       formatNumber(1.0 / log_rate) + " s)");
  }

  const rotor::PlanResult plans = rotor::planRotorMotion(request);
  OutputFile file(options.text("out"));
  CsvWriter csv(file.stream(),
                std::vector<std::string>(std::begin(kExecuteColumns), std::end(kExecuteColumns)));
  if (plans.solutions.empty()) {
    file.commit();
    out << "rotor-execute: " << plans.reason << "\n";
    return kNoSolution;
  }
  rotor::SampledRotorLoop loop(sampling, parameters, request, plans);
  loop.step();  // the stack's first step is its t = 0
  for (long row = 0;; ++row) {
    const rotor::SampledRotorSample s = loop.sample();
    const Eigen::Quaterniond attitude =
        Eigen::Quaterniond(rotor::orientation(s.state.u_o, s.state.v_o, s.state.psi)).normalized();
    csv.row({s.t, radius * s.state.u_a, radius * s.state.v_a, attitude.w(), attitude.x(),
             attitude.y(), attitude.z(), s.state.u_o, s.state.v_o, s.state.psi, s.command.phi1,
             s.command.phi2, s.measured.phi1, s.measured.phi2,
             static_cast<double>(s.executive)});
    if (row == steps / steps_per_row) break;
    for (long k = 0; k < steps_per_row; ++k) loop.step();
  }
  file.commit();
  const rotor::SampledRotorSample end = loop.sample();
  out << "rotor-execute k " << request.k << ", " << request.steps << " steps, target ("
      << target[0] << " m, " << target[1] << " m, " << target[2] << " rad): at t = " << end.t
      << " s the centre is "
      << radius * std::hypot(end.state.u_a - request.u_a, end.state.v_a - request.v_a)
      << " m off the target, " << loop.executive().correctionsMade() << " correction(s), "
      << rotor::toString(end.executive) << "\n";
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

const char* const kExecuteDescription =
    R"(Runs the rotor stack (launch/rotor_stack.launch with execute:=true, clock:=lockstep) as a
batch: the plan for --k, --steps, --target is made at the start and executed from the first step
by the same rotor manoeuvre executive as rotor_planner, through the hardware interface's rotors
(ideal, 30 rad/s and 300 rad/s^2, or with --actuator-models) and the rotor_plant model
(eq 11 solved for omega, eqs 6-10, RK4 at 1 ms), in the order of one lock-step step: the plant
advances with the last measured rotor speeds held and publishes odometry at 50 Hz, the executive
commands every 10 ms from the rest measured from it, the actuators follow at 100 Hz. Times are
whole nanoseconds from the stack's first step (t = 0 here). The sphere's radius R is the
base_link sphere of DIR/urdf/rotor_sphere.urdf. The robot's inertia ratio and J_zz / J_r, the
manoeuvre, and the executive's parameters (curve rate, ramps, command rate, rotor limit, settle,
corrections and their tolerances) not given here are DIR/config/rotor.yaml's (--config DIR), the
file the rotor stack's nodes read (inertia_ratio, rotor_inertia_scale, manoeuvre/...,
rotor_planner/...); shipped: J_zz / J_r = 12, settle 1 s, ramps 1 s, heading tolerance
1e-3 rad, one-step corrections.

CSV columns (SI units, radians; one row every 1/log-rate s from t = 0 through the duration):
  t                     time [s]
  x, y                  sphere centre on the plane [m] (the centre is at height R)
  qw, qx, qy, qz        attitude of the sphere, R_z^T(psi) R_x^T(v_o) R_y^T(u_o) (eq 2)
  u_o, v_o, psi         contact angles on the sphere and contact angle psi [rad]
  command_1, command_2  the latest rotor set-points commanded [rad/s] (0 before the first)
  measured_1, measured_2  the measured rotor speeds that drive the plant [rad/s]
  state                 the executive's state: 0 idle, 1 executing, 2 returning to pole,
                        3 correcting, 4 settling
Numbers are written in the shortest form that reads back as the same double.
stdout: one line: how far the centre ended from the target, the corrections made, the state.

Exit status: 0 success; 3 no plan for the target (the file holds the header only; stdout says
why); 2 usage error (unknown option, malformed number, a target that is not three numbers);
4 invalid input (non-finite or out-of-range number, duration or log period not a whole number
of steps, unreadable config, a bad value in config/rotor.yaml or actuator models): one-line
error on stderr and no output file.
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

Subcommand rotorExecuteCommand() {
  Subcommand command;
  command.name = "rotor-execute";
  command.summary = "The rotor stack's run: a plan executed through the rotors, optionally corrected.";
  command.description = kExecuteDescription;
  command.options = {
      {"k", "K",
       "Inertia ratio k = J_xx / J_zz of the robot and the plan (eq 14), > 0.\n"
       "Default: inertia_ratio (the robot) and manoeuvre/k (the plan) of config/rotor.yaml (2.5).",
       "", false, {}},
      {"steps", "N",
       "Number of figure eights n of the plan, a whole number >= 1.\n"
       "Default: manoeuvre/steps of config/rotor.yaml (2).",
       "", false, {}},
      {"target", "U,V,PSI",
       "Target from the start: contact point (U, V) on the plane [m], heading PSI [rad].\n"
       "Default: manoeuvre/{u,v,psi} of config/rotor.yaml (0.05,0.03,0.4).",
       "", false, {}},
      {"curve-rate", "RATE",
       "Curve rate theta_dot of the cruise [rad/s], > 0.\n"
       "Default: rotor_planner/curve_rate of config/rotor.yaml (1).",
       "", false, {}},
      {"max-rotor-speed", "SPEED",
       "Largest rotor set-point [rad/s], >= 0 (0: no limit): the curve rate is lowered to fit.\n"
       "Default: rotor_planner/max_rotor_speed of config/rotor.yaml (25).",
       "", false, {}},
      {"actuator-time-constant", "TAU",
       "Feed-forward of a first-order rotor lag of TAU [s], >= 0 (0: none).\n"
       "Default: rotor_planner/actuator_time_constant of config/rotor.yaml (0).",
       "", false, {}},
      {"corrections", "N",
       "Corrective manoeuvres after the plan, a whole number >= 0 (0: open loop).\n"
       "Default: rotor_planner/corrections of config/rotor.yaml (0).",
       "", false, {}},
      {"correction-tolerance", "METRES",
       "A smaller miss on the plane is not corrected [m], > 0.\n"
       "Default: rotor_planner/correction_tolerance of config/rotor.yaml (1e-05).",
       "", false, {}},
      {"correction-tilt-tolerance", "RAD",
       "The contact this close to the south pole needs no arc back to it [rad], > 0.\n"
       "Default: rotor_planner/correction_tilt_tolerance of config/rotor.yaml (0.0001).",
       "", false, {}},
      {"duration", "SECONDS",
       "Simulated time [s] after the first step, >= 0, a whole number of log periods\n"
       "(default: 20 + 10 per correction, as the stack).",
       "", false, {}},
      {"log-rate", "HZ", "CSV rows per second [Hz], > 0; 1/log-rate a whole number of 1 ms steps.",
       "50", false, {}},
      {"actuator-models", "FILE",
       "The hardware interface's actuator models, the YAML file the stack takes as\n"
       "actuator_models:= (e.g. config/actuators_realistic.yaml). Default: ideal rotors.",
       "", false, {}},
      configOption(),
      outOption("CSV file to write (columns below)."),
  };
  command.run = runRotorExecute;
  return command;
}

}  // namespace spherical_robots::sphere_sim
