#include "norma_command.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <ostream>
#include <vector>

#include "spherical_robots/config/norma_config.hpp"
#include "spherical_robots/config/norma_description.hpp"
#include "spherical_robots/config/robot_description.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "spherical_robots/norma/norma_simulation.hpp"
#include "spherical_robots/norma/sampled_norma_loop.hpp"

namespace spherical_robots::sphere_sim {
namespace {

constexpr double kClosedLoopDuration = 1300.0;  // [s], the paper's run
constexpr double kClosedLoopLogRate = 1.0;      // [Hz]
constexpr double kOpenLoopDuration = 5.0;       // [s]
constexpr double kOpenLoopLogRate = 100.0;      // [Hz]
// --loop sampled: the Norma stack's plant step and hardware interface period
// (launch/norma_stack.launch).
constexpr double kSampledStep = 0.001;  // [s]

const std::vector<std::string> kContinuousOnly = {"rtol", "atol"};
const std::vector<std::string> kSampledOnly = {"max-torque", "max-force", "command-timeout",
                                               "state-timeout"};

const char* const kColumns[] = {"t",      "theta",  "alpha",  "phi", "delta", "thetad",
                                "alphad", "phid",   "deltad", "X",   "Y",     "psi",
                                "Xd",     "Yd",     "err",    "T",   "F",     "energy"};

Eigen::Vector4d vector4(const std::vector<double>& values) {
  return Eigen::Vector4d(values[0], values[1], values[2], values[3]);
}

/// The robot of DIR/urdf/norma.urdf.
norma::NormaParameters parametersFrom(const ParsedOptions& options) {
  const std::string path = configDirectory(options) + "/urdf/norma.urdf";
  const std::string xml = config::readTextFile(path);  // its error names the path
  try {
    return config::normaParametersFromUrdf(xml);
  } catch (const std::invalid_argument& error) {
    throw InvalidInput(path + ": " + error.what());
  }
}

norma::OdeOptions odeOptionsFrom(const ParsedOptions& options) {
  norma::OdeOptions ode;
  ode.rtol = options.number("rtol");
  ode.atol = options.number("atol");
  return ode;
}

/// The Norma stack's model and controller parameters as its nodes read them:
/// DIR/config/norma.yaml (norma_plant/..., norma_controller/...); none if DIR has no such file
/// (a directory of a URDF only, which must then be there), whose defaults equal the shipped file.
std::optional<config::YamlParameterSource> normaConfig(const ParsedOptions& options) {
  const std::string path = configDirectory(options) + "/config/norma.yaml";
  if (!std::filesystem::exists(path)) return std::nullopt;
  return config::YamlParameterSource(path);
}

/// The plant's model of the configuration, --variant overriding its variant.
config::NormaModelParameters modelFrom(const ParsedOptions& options) {
  config::NormaModelParameters model;
  model.initial_psi = norma::pathStartHeading();  // config/norma.yaml's
  if (const auto source = normaConfig(options))
    model = config::normaModelParameters(*source, config::kNormaPlantKeys, model);
  if (options.given("variant"))
    model.variant = norma::lagrangianVariantFromString(options.text("variant"));
  return model;
}

/// The controller and effort limits of the configuration, the options overriding them.
config::NormaControlParameters controlFrom(const ParsedOptions& options) {
  config::NormaControlParameters control;
  if (const auto source = normaConfig(options))
    control = config::normaControlParameters(*source, config::kNormaControllerKeys);
  if (options.given("controller"))
    control.controller = norma::controllerKindFromString(options.text("controller"));
  if (options.given("max-torque")) control.limits.max_torque = options.number("max-torque");
  if (options.given("max-force")) control.limits.max_force = options.number("max-force");
  return control;
}

void writeCsv(std::ostream& out, const std::vector<norma::NormaSample>& samples) {
  CsvWriter writer(out, std::vector<std::string>(std::begin(kColumns), std::end(kColumns)));
  for (const norma::NormaSample& s : samples) {
    writer.row({s.t, s.q(0), s.q(1), s.q(2), s.q(3), s.qd(0), s.qd(1), s.qd(2), s.qd(3), s.x, s.y,
                s.psi, s.x_d, s.y_d, s.error, s.torque, s.force, s.energy});
  }
}

/// The first logged row at which the slider is off the shaft, which spans ±R about the centre.
const norma::NormaSample* leftShaft(const norma::NormaParameters& p,
                                    const std::vector<norma::NormaSample>& samples) {
  for (const norma::NormaSample& s : samples) {
    if (std::abs(p.delta0 + s.q(3)) > p.R) return &s;
  }
  return nullptr;
}

/// A usage error (exit 2) naming the first of `names` given, with why it does not belong.
void requireAbsent(const ParsedOptions& options, const std::vector<std::string>& names,
                   const std::string& why) {
  for (const std::string& name : names) {
    if (options.given(name)) throw UsageError("--" + name + " " + why);
  }
}

int runOpenLoop(const ParsedOptions& options, std::ostream& out) {
  std::vector<std::string> closed_only = {"controller", "loop"};
  closed_only.insert(closed_only.end(), kSampledOnly.begin(), kSampledOnly.end());
  requireAbsent(options, closed_only, "is for the closed loop, not --open-loop");
  if (!options.given("q0") || !options.given("qd0")) {
    throw UsageError("--open-loop needs --q0 and --qd0");
  }
  norma::OpenLoopConfig config;
  config.variant = modelFrom(options).variant;
  config.q0 = vector4(options.numberList("q0", 4));
  config.qd0 = vector4(options.numberList("qd0", 4));
  config.duration = options.given("duration") ? options.number("duration") : kOpenLoopDuration;
  config.log_rate = options.given("log-rate") ? options.number("log-rate") : kOpenLoopLogRate;
  config.ode = odeOptionsFrom(options);
  const norma::NormaParameters parameters = parametersFrom(options);
  const std::vector<norma::NormaSample> samples = norma::runOpenLoop(parameters, config);
  OutputFile file(options.text("out"));
  writeCsv(file.stream(), samples);
  file.commit();
  if (const norma::NormaSample* off = leftShaft(parameters, samples)) {
    std::cerr << "warning: the free slider left the shaft (|delta0 + delta| > R) at t = "
              << formatNumber(off->t) << " s (delta = " << formatNumber(off->q(3))
              << " m); the paper's model does not stop it\n";
  }
  double drift = 0.0;
  for (const norma::NormaSample& s : samples) {
    drift = std::max(drift, std::abs(s.energy - samples.front().energy));
  }
  out << "open loop, variant " << norma::toString(config.variant) << ": " << samples.size()
      << " rows, energy " << formatNumber(samples.front().energy) << " J at t = 0, max |change| "
      << formatNumber(drift) << " J\n";
  return kSuccess;
}

/// How many steps of `step` [s] apart the CSV rows at log_rate [Hz] are: rows come at whole steps.
/// @throw InvalidInput if 1 / log_rate is no whole number of steps.
long stepsPerRow(double log_rate, double step) {
  const double steps = log_rate > 0.0 ? 1.0 / (log_rate * step) : 0.0;
  const long whole = std::lround(steps);
  if (whole < 1 || std::abs(steps - static_cast<double>(whole)) > 1e-9 * steps) {
    throw InvalidInput("--log-rate " + formatNumber(log_rate) + " Hz: with --loop sampled rows " +
                       "come a whole number of " + formatNumber(step * 1e3) +
                       " ms steps apart (e.g. 1000, 500, 100 or 1 Hz)");
  }
  return whole;
}

/// --loop sampled: the Norma stack's loop, step by step (norma/sampled_norma_loop.hpp).
std::vector<norma::NormaSample> runSampled(const ParsedOptions& options,
                                           const norma::ClosedLoopConfig& closed,
                                           const config::NormaModelParameters& model,
                                           const config::NormaControlParameters& control) {
  norma::SampledLoopConfig config;
  config.variant = closed.variant;
  config.controller = closed.controller;
  config.gains = closed.gains;
  config.duration = closed.duration;
  config.step = kSampledStep;
  config.initial_psi = model.initial_psi;
  config.limits = control.limits;
  config.command_timeout = options.number("command-timeout");
  config.state_timeout = options.number("state-timeout");
  return norma::runSampledLoop(parametersFrom(options), config,
                               stepsPerRow(closed.log_rate, config.step));
}

int runClosedLoop(const ParsedOptions& options, std::ostream& out) {
  requireAbsent(options, {"q0", "qd0"}, "is for --open-loop only");
  const bool sampled = options.text("loop") == "sampled";
  if (sampled)
    requireAbsent(options, kContinuousOnly, "is for --loop continuous (the adaptive integrator)");
  else
    requireAbsent(options, kSampledOnly, "is for --loop sampled");
  const config::NormaModelParameters model = modelFrom(options);
  const config::NormaControlParameters control = controlFrom(options);
  norma::ClosedLoopConfig config;
  config.variant = model.variant;
  config.controller = control.controller;
  config.gains = control.gains;
  config.duration = options.given("duration") ? options.number("duration") : kClosedLoopDuration;
  config.log_rate = options.given("log-rate") ? options.number("log-rate") : kClosedLoopLogRate;
  std::vector<norma::NormaSample> samples;
  if (sampled) {
    samples = runSampled(options, config, model, control);
  } else {
    config.ode = odeOptionsFrom(options);
    samples = norma::runClosedLoop(parametersFrom(options), config);
  }
  OutputFile file(options.text("out"));
  writeCsv(file.stream(), samples);
  file.commit();
  // The issue's measure: ‖e‖ over the second half of the run.
  double sum_sq = 0.0, worst = 0.0, stroke = 0.0;
  long count = 0;
  for (const norma::NormaSample& s : samples) {
    stroke = std::max(stroke, std::abs(s.q(3)));
    if (s.t < 0.5 * config.duration) continue;
    sum_sq += s.error * s.error;
    worst = std::max(worst, s.error);
    ++count;
  }
  if (sampled) out << "sampled loop (" << formatNumber(kSampledStep * 1e3) << " ms steps), ";
  out << "controller " << norma::toString(config.controller) << ", variant "
      << norma::toString(config.variant)
      << ": for t >= " << formatNumber(0.5 * config.duration) << " s RMS |e| "
      << formatNumber(std::sqrt(sum_sq / std::max(count, 1L))) << " m, max |e| "
      << formatNumber(worst) << " m; max |delta| " << formatNumber(stroke) << " m\n";
  return kSuccess;
}

int runNormaCommand(const ParsedOptions& options, std::ostream& out) {
  return options.flag("open-loop") ? runOpenLoop(options, out) : runClosedLoop(options, out);
}

const char* const kDescription =
    R"(Closed loop (default): the path of eq 52, X_d = 2 sin(0.01 t), Y_d = 1.5 sin(0.02 t), from
X = Y = 0 with all q and q_dot zero, the heading along the desired initial velocity and the
controller's integrals zero. --controller paper is the published two-layer controller (eqs
48-51, k1 = 0.1, k2 = -0.1, k3 = 5; PID1 (1,0,0), PID2 (10,7,3), PID3 (15,3,10) with the
gravity feed-forward g m_Sl sin(phi)); --controller tracking is this project's
(docs/conventions.md, "Norma", "Controller").
Open loop (--open-loop): zero inputs from --q0 and --qd0 at X = Y = psi = 0. Nothing stops the
free slider at the ends of the shaft (a warning on stderr says when a logged row has it off).

The model is M(q) q_ddot + C(q, q_dot) q_dot + G(q) = [0, T, 0, F] from the text's Lagrangian
(eq 45; --variant appendix drops the sphere's yaw kinetic energy from M11 as A.3 does). The
robot's masses and lengths are read from DIR/urdf/norma.urdf (shipped: section 5's robot,
R = 0.2 m, L = 0.15 m, L0 = 0.1 m, delta0 = 0.1 m, m_Sp = 3 kg = shell 2.5 + shaft 0.5,
m_P = m_Sl = 0.5 kg); g = 9.81 m/s^2. It is integrated with Boost.Odeint's
rosenbrock4 (L-stable, adaptive; the inner pendulum loop's poles are near -130 s^-1) with
dense output at the log times; the default tolerances keep X, Y within 1 mm of a run at
rtol = atol = 1e-11 on the paper's scenario.
The variant, the controller, its gains, the effort limits and (--loop sampled) the initial
heading not given here are DIR/config/norma.yaml's (--config DIR), the file the Norma stack's
nodes read (norma_plant/variant, norma_plant/initial_psi, norma_controller/controller, gains/...,
max_torque, max_force); a DIR without it takes the shipped file's values (the gains above).

--loop sampled runs the closed loop as the Norma stack (launch/norma_stack.launch, in lock-step,
the default clock, with ideal actuators) samples it, the same core code in the same order, in
steps of 1 ms (fixed: the stack's plant step and hardware rate). At each step t (the first at
1 ms, as the stack's first stamp): the plant advances from the previous step by t minus it
(fixed-step RK4) with the efforts the actuators applied at the previous step held, or none once
they are older than --state-timeout; the controller computes from the state at t and its command
is held until the next step; the hardware interface clamps it to --max-torque and --max-force
(with its --command-timeout watchdog). Times are whole nanoseconds, turned into seconds as
ros::Time does. Its X, Y, psi, q and q_dot equal the stack's norma_state at the same time since
its first stamp, bit for bit (test/norma_batch_equality.test). The defaults of --max-torque,
--max-force, --command-timeout and --state-timeout are the stack's; --rtol and --atol do not
apply. --duration 0 runs the first step only. A state that turns non-finite ends the run (exit
4); the stack's plant would hold it.

CSV columns (SI units, radians; one row every 1/log-rate s from t = 0 through the duration
inclusive):
  t                          time [s]; --loop sampled: since the first step (the stack's stamp
                             minus its first)
  theta,alpha,phi,delta      q: roll of the shell about the shaft, pendulum relative to the
                             shell, tilt of the shaft, slider displacement from delta0 [m]
  thetad,alphad,phid,deltad  q_dot
  X,Y,psi                    centre of the sphere [m] and heading [rad] (eqs 6, 12)
  Xd,Yd                      desired point [m] (eq 52); 0 in open loop
  err                        |(X, Y) - (Xd, Yd)| [m]; 0 in open loop
  T,F                        pendulum torque [N m] and slider force [N]; 0 in open loop;
                             --loop sampled: as the actuators apply them from t on
  energy                     total mechanical energy [J], zero at rest at q = 0
Numbers are written in the shortest form that reads back as the same double.

stdout: one line. Closed loop: RMS and max |e| over t >= duration / 2, max |delta|. Open loop:
the energy at t = 0 and its largest change.

Exit status: 0 success; 2 usage error (unknown option or choice, malformed number, --q0/--qd0
without --open-loop, --controller or --loop with it, an option of the other --loop); 4 invalid
input (non-finite or out-of-range number, a --log-rate that is no whole number of steps with
--loop sampled, an unreadable or inconsistent URDF, a bad value in config/norma.yaml, a state
that turns non-finite): one-line error on stderr and no output file.
)";

}  // namespace

Subcommand normaCommand() {
  const norma::OdeOptions ode;
  Subcommand command;
  command.name = "norma";
  command.summary =
      "Norma (slider and pendulum): closed loop on the path of eq 52, or open loop.";
  command.description = kDescription;
  command.options = {
      {"controller",
       "NAME",
       "Closed-loop controller: paper (eqs 48-51 and Table 1, as published) or tracking.\n"
       "Default: norma_controller/controller of config/norma.yaml (paper).",
       "",
       false,
       {"paper", "tracking"}},
      {"variant",
       "NAME",
       "Inertia matrix: text (eq 45) or appendix (A.3-A.21: M11 without the sphere's yaw term).\n"
       "Default: norma_plant/variant of config/norma.yaml (text).",
       "",
       false,
       {"text", "appendix"}},
      {"loop",
       "NAME",
       "Closed loop: continuous (plant and controller as one ODE, adaptive) or sampled (as the "
       "Norma stack samples it, in 1 ms steps; see below).",
       "continuous",
       false,
       {"continuous", "sampled"}},
      {"max-torque", "N_M", "--loop sampled: the pendulum motor's effort limit [N m], > 0.\n"
       "Default: norma_controller/max_torque of config/norma.yaml (20), the stack's.", "", false,
       {}},
      {"max-force", "N", "--loop sampled: the slider's effort limit [N], > 0.\n"
       "Default: norma_controller/max_force of config/norma.yaml (200), the stack's.", "", false,
       {}},
      {"command-timeout", "SECONDS", "--loop sampled: the hardware interface's watchdog [s], > 0 "
       "(the stack's command_timeout).", "0.1", false, {}},
      {"state-timeout", "SECONDS", "--loop sampled: no effort drives the plant once the last "
       "actuator state is older than this [s], > 0 (the stack's state_timeout).", "0.05", false,
       {}},
      {"open-loop", "", "Zero inputs from --q0, --qd0 instead of the closed loop.", "", false, {}},
      {"q0", "TH,AL,PHI,DELTA", "Open loop: initial theta, alpha, phi [rad], delta [m].", "",
       false, {}},
      {"qd0", "THD,ALD,PHID,DELTAD", "Open loop: initial rates [rad/s, m/s].", "", false, {}},
      {"rtol", "R", "Relative tolerance of the adaptive integrator (--loop continuous), > 0.", formatNumber(ode.rtol),
       false, {}},
      {"atol", "A", "Absolute tolerance of the adaptive integrator (--loop continuous), > 0.", formatNumber(ode.atol),
       false, {}},
      {"duration", "SECONDS",
       "Simulated time [s], >= 0. Default 1300 (closed loop) or 5 (--open-loop).", "", false, {}},
      {"log-rate", "HZ", "CSV rows per second [Hz], > 0. Default 1 (closed loop) or 100 "
       "(--open-loop). --loop sampled: 1 / log-rate a whole number of 1 ms steps.", "", false, {}},
      configOption(),
      outOption("CSV file to write (columns below)."),
  };
  command.run = runNormaCommand;
  return command;
}

}  // namespace spherical_robots::sphere_sim
