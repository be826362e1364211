#include "terrain_command.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "spherical_robots/config/actuator_models.hpp"
#include "spherical_robots/config/layered_parameter_source.hpp"
#include "spherical_robots/config/roller_config.hpp"
#include "spherical_robots/config/robot_description.hpp"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "path_file.hpp"

namespace spherical_robots::sphere_sim {
namespace {

constexpr double kConvergedError = 0.1;  // [m]: the paper's "converged"
constexpr double kSettleTime = 40.0;     // [s]: the paper's figures settle by then
// launch/roller_stack.launch's motor limits (hardware interface max_velocity, max_acceleration).
constexpr double kRollerMotorMaxVelocity = 60.0;       // [rad/s]
constexpr double kRollerMotorMaxAcceleration = 300.0;  // [rad/s^2]

const char* const kColumns[] = {"t",  "x0",     "y0",        "z0",           "xd",       "yd",
                                "zd", "e_norm", "zeta",      "psi",          "phi",      "cx",
                                "cy", "cz",     "roll_rate", "lateral_rate", "turn_rate"};

TerrainRunSettings settingsFrom(const ParsedOptions& options) {
  TerrainRunSettings settings;
  settings.robot = terrain::robotTypeFromString(options.text("robot"));
  if (options.given("path") == options.given("path-file"))
    throw UsageError("give either --path NAME or --path-file FILE");
  if (options.given("path")) settings.path = options.text("path");
  if (options.given("path-file")) settings.path_file = options.text("path-file");
  if (options.given("speed")) {
    if (settings.path_file.empty()) throw UsageError("--speed needs --path-file (an x,y file)");
    settings.speed = options.number("speed");
  }
  settings.model = terrain::contactModelFromString(options.text("model"));
  settings.law = terrain::pursuitLawFromString(options.text("law"));
  settings.loop = options.text("loop") == "sampled" ? TerrainLoop::Sampled : TerrainLoop::Continuous;
  settings.duration = options.number("duration");
  settings.dt = options.given("dt") ? options.number("dt")
                : settings.loop == TerrainLoop::Sampled ? terrain::StackSampling{}.plant_step
                                                        : TerrainRunSettings{}.dt;
  settings.log_rate = options.number("log-rate");
  settings.config_dir = configDirectory(options);
  if (options.given("terrain")) settings.terrain = options.text("terrain");
  settings.stack = options.text("stack");
  if (settings.stack != "terrain" && settings.loop != TerrainLoop::Sampled)
    throw UsageError("--stack " + settings.stack + " needs --loop sampled (it names a launched "
                     "stack whose loop is replayed)");
  if (settings.stack == "roller" && (settings.robot != terrain::RobotType::TwoAxisRolling ||
                                     settings.model != terrain::ContactModel::Rolling))
    throw UsageError("--stack roller is a 2R robot in the rolling contact model: give --robot 2R "
                     "--model rolling");
  if (options.given("actuator-models")) {
    if (settings.loop != TerrainLoop::Sampled)
      throw UsageError("--actuator-models needs --loop sampled (the continuous loop has no actuators)");
    settings.actuator_models = options.text("actuator-models");
  }
  return settings;
}

int runTerrainCommand(const ParsedOptions& options, std::ostream& out) {
  const TerrainRun run(settingsFrom(options));
  OutputFile file(options.text("out"));
  const terrain::TrackingSummary summary = run.simulate(&file.stream());
  file.commit();
  out << run.describe(summary) << '\n';
  return kSuccess;
}

const char* const kDescription =
    R"(The run starts at the origin with psi = phi = 0 and integrates the closed loop (the tracking
law evaluated at every RK4 stage) with a fixed step. The scenario (surface, paths, the gains of
both laws, RS tilt limit) is DIR/config/terrain.yaml, its surface replaced by --terrain's height
map if given; the sphere's radius is the shell link's sphere of DIR/urdf/terrain_robot.urdf.

--loop sampled runs the loop as the launched stack (launch/terrain_stack.launch, clock:=lockstep,
hardware:=sim with the actuator models of --actuator-models, ideal without) samples it, with the core code each node calls and in the order of one
lock-step step: the plant advances with the actuators' last measured rates held, the controller
commands from the state last published, the actuators follow within their limits. Times are
whole nanoseconds from the stack's first step (t = 0 here), so every row equals the stack's
messages of the same time since its first stamp: terrain_state (contact point, centre, psi, phi,
realised rates) and tracking_error (the controller's latest desired point and error, held
between its 50 Hz steps). The stack's default run is --law smooth --loop sampled --log-rate 50.
With --stack roller the stack replayed is launch/roller_stack.launch (--robot 2R --model rolling):
config/roller.yaml loaded over config/terrain.yaml, the controller's 2R rates turned into the
rollers' motor rates (friction_drive_controller) and the motors' measured rates into the
sphere's (friction_drive_sim, with slip) on the way.

--path-file FILE: the path is the cubic spline in time through the file's points (C2, so the
velocity the laws feed forward is continuous; not-a-knot ends), the same interpolation
(terrain::SampledPath) as pure_pursuit_controller gives a nav_msgs/Path it receives. A path
whose last point is its first is closed: periodic, it repeats. An open path ends: the desired
point then holds the last point at rest. A bad file (a cell that is not a number, a non-finite
value, a time not after the one before, fewer than 2 points) is rejected naming its line.

CSV columns (SI units, radians; one row every 1/log-rate s from t = 0 through the duration):
  t             time [s]
  x0,y0,z0      contact point P0 [m]; z0 = f(x0, y0) on the surface
  xd,yd,zd      desired point p_d(t) on the surface [m]
  e_norm        tracking error |e_t| = |p_d - P0| [m] (eq 53)
  zeta          angle [rad] from the heading h to e_t's projection on the tangent plane,
                right-handed about the normal n: positive when the target is to the left
  psi           heading [rad], right-handed about n relative to the tangent frame
  phi           RS tilt [rad]; 0 for 3R, 2R and RT
  cx,cy,cz      sphere centre P0 + R n [m] (eq 51)
  roll_rate     realised theta_dot [rad/s] about l (RS: alpha_dot about the tilted axle)
  lateral_rate  realised phi_dot [rad/s] about h (sideways roll; RS: tilt rate); 0 for RT
  turn_rate     realised psi_dot [rad/s] about n; 0 for 2R; RS: -alpha_dot sin(phi) (eq 44)
Numbers are written in the shortest form that reads back as the same double.

stdout: one line: robot, path, model, law, the first logged time with |e_t| < 0.1 m ("never" if
none) and the mean and max |e_t| over the logged rows with t >= 40 s.

Exit status: 0 success; 2 usage error (unknown option, unknown robot/path/model/law, malformed
number, missing option, neither or both of --path and --path-file, --speed without an x,y
--path-file or missing with one); 4 invalid input (non-finite or out-of-range number, duration
or log period not a whole number of steps, unreadable config, a bad --path-file, named with its
line, a radius that breaks single-point contact, a run that diverges or leaves the height map):
one-line error on stderr and no output file. An 8-bit height map is smoothed, with a warning on
stderr; so is a key of config/terrain.yaml (or roller.yaml) that is no parameter of the stack (a
misspelt one would leave its default in place), named with its line.
)";

// What the terrain stack's nodes read from config/terrain.yaml and sphere_sim terrain does not:
// the run has an option instead.
const char* const kStackOnlyParameters[] = {"pure_pursuit_controller/untimed_speed"};  // --speed

/// A parameter that nothing read: a misspelt key would otherwise leave its default in place
/// without a word. files: the layers, lowest first; a key that a higher layer gives is read there.
void warnOfUnusedParameters(const std::vector<const config::YamlParameterSource*>& files) {
  for (auto file = files.begin(); file != files.end(); ++file) {
    for (const config::YamlParameterSource::Key& unused : (*file)->unreadKeys("")) {
      const auto stack_only = std::find(std::begin(kStackOnlyParameters),
                                        std::end(kStackOnlyParameters), unused.key);
      const bool overridden = std::any_of(file + 1, files.end(), [&](const auto* higher) {
        return higher->gives(unused.key);
      });
      if (stack_only != std::end(kStackOnlyParameters) || overridden) continue;
      std::cerr << "warning: " << (*file)->origin() << " line " << unused.line << ": '"
                << unused.key << "' is no parameter of the terrain stack (misspelt?); ignored\n";
    }
  }
}

}  // namespace

TerrainRun::TerrainRun(const TerrainRunSettings& settings) : settings_(settings) {
  if (!(settings.dt > 0.0)) {
    throw InvalidInput("--dt must be > 0 s, got " + formatNumber(settings.dt));
  }
  if (!(settings.duration >= 0.0)) {
    throw InvalidInput("--duration must be >= 0 s, got " + formatNumber(settings.duration));
  }
  if (!(settings.log_rate > 0.0)) {
    throw InvalidInput("--log-rate must be > 0 Hz, got " + formatNumber(settings.log_rate));
  }
  const std::string per_step = " s / --dt " + formatNumber(settings.dt) + " s";
  const long steps = wholeSteps(settings.duration, settings.dt,
                                "--duration " + formatNumber(settings.duration) + per_step);
  const double log_period = 1.0 / settings.log_rate;
  steps_per_row_ = wholeSteps(log_period, settings.dt,
                              "--log-rate " + formatNumber(settings.log_rate) + " Hz: its period " +
                                  formatNumber(log_period) + per_step);
  if (steps_per_row_ < 1) {
    throw InvalidInput("--log-rate " + formatNumber(settings.log_rate) +
                       " Hz is above the step rate 1/--dt");
  }
  if (steps % steps_per_row_ != 0) {
    throw InvalidInput("--duration " + formatNumber(settings.duration) +
                       " s is not a whole number of log periods (1/--log-rate = " +
                       formatNumber(log_period) + " s)");
  }
  rows_ = steps / steps_per_row_;

  // The parameters as the stack's nodes see them: config/roller.yaml loaded over terrain.yaml.
  std::vector<std::unique_ptr<config::ParameterSource>> layers;
  std::vector<const config::YamlParameterSource*> files;
  for (const std::string name : {"terrain", "roller"}) {
    if (name == "roller" && settings.stack != "roller") continue;
    auto file = std::make_unique<config::YamlParameterSource>(settings.config_dir + "/config/" +
                                                              name + ".yaml");
    files.push_back(file.get());
    layers.push_back(std::move(file));
  }
  const config::LayeredParameterSource parameters(std::move(layers));
  const config::TerrainConfig scenario = config::loadTerrainConfig(parameters);
  const double radius = radiusFromUrdf(settings.config_dir + "/urdf/terrain_robot.urdf", "shell");
  config::SurfaceSpec surface = scenario.surface;
  if (!settings.terrain.empty()) {
    surface.type = "height_map";
    surface.height_map = std::filesystem::absolute(settings.terrain).string();
  }
  config::SurfaceLoading loading;
  loading.base_directory = settings.config_dir;
  loading.warn = [](const std::string& warning) { std::cerr << "warning: " << warning << '\n'; };
  surface_ = config::makeSurface(surface, loading);
  if (settings.path_file.empty()) {
    path_ = config::makePath(settings.path, scenario);
  } else {
    if (settings.speed && !(*settings.speed > 0.0))
      throw InvalidInput("--speed must be > 0 m/s, got " + formatNumber(*settings.speed));
    path_ = std::make_unique<terrain::SampledPath>(readPathFile(settings.path_file, settings.speed));
  }
  kinematics_ = std::make_unique<terrain::TerrainKinematics>(*surface_, settings.robot, radius,
                                                             settings.model, scenario.tilt_limit);
  controller_ = config::makePursuitController(settings.law, settings.robot, scenario, radius);
  sampling_.plant_step = settings.dt;
  if (settings.stack == "roller") {
    drive_ = std::make_unique<roller::RollerActuation>(
        config::makeRollerActuation(config::loadRollerConfig(parameters), radius));
    sampling_.max_velocity = kRollerMotorMaxVelocity;
    sampling_.max_acceleration = kRollerMotorMaxAcceleration;
  }
  if (!settings.actuator_models.empty()) {
    const terrain::DirectDrive direct(settings.robot);
    const config::ActuatorModels models = config::loadActuatorModels(
        config::YamlParameterSource(settings.actuator_models),
        (drive_ ? *drive_ : static_cast<const terrain::ActuatorDrive&>(direct)).actuatorNames());
    sampling_.actuator_models = models.models;
    sampling_.noise_seed = models.noise_seed;
  }
  warnOfUnusedParameters(files);
}

template <typename Step, typename RowAt>
terrain::TrackingSummary TerrainRun::run(std::ostream* csv, Step step, RowAt row_at) const {
  terrain::TrackingSummary summary(kConvergedError, kSettleTime);
  std::unique_ptr<CsvWriter> writer;
  if (csv != nullptr) {
    writer = std::make_unique<CsvWriter>(
        *csv, std::vector<std::string>(std::begin(kColumns), std::end(kColumns)));
  }
  for (long row = 0;; ++row) {
    row_at([&](const Row& r) {
      summary.add(r.t, r.error.norm);
      if (!writer) return;
      const Eigen::Vector3d& p0 = r.geometry.contact_point;
      const Eigen::Vector3d& pd = r.desired.position;
      const Eigen::Vector3d& centre = r.geometry.centre;
      writer->row({r.t, p0.x(), p0.y(), p0.z(), pd.x(), pd.y(), pd.z(), r.error.norm, r.error.zeta,
                   r.state.psi, r.state.phi, centre.x(), centre.y(), centre.z(), r.rates.roll_rate,
                   r.rates.lateral_rate, r.rates.turn_rate});
    });
    if (row == rows_) break;
    for (long k = 0; k < steps_per_row_; ++k) step();
  }
  return summary;
}

terrain::TrackingSummary TerrainRun::simulate(std::ostream* csv) const {
  if (settings_.loop == TerrainLoop::Sampled) {
    terrain::SampledTerrainLoop loop(*kinematics_, *controller_, *path_, sampling_, drive_.get());
    loop.step();  // the stack's first step is its t = 0
    return run(csv, [&loop] { loop.step(); }, [&loop](const auto& write) {
      const terrain::SampledTerrainSample s = loop.sample();
      write(Row{s.t, s.state, s.geometry, s.tracked.desired, s.tracked.error, s.realised});
    });
  }
  terrain::TerrainSimulation simulation(*kinematics_, *controller_, *path_,
                                        terrain::TerrainState{});
  return run(csv, [&] { simulation.step(settings_.dt); }, [&simulation](const auto& write) {
    const terrain::TerrainSample s = simulation.sample();
    write(Row{s.t, s.state, s.geometry, s.desired, s.error, s.rates});
  });
}

std::string TerrainRun::describe(const terrain::TrackingSummary& summary) const {
  std::ostringstream line;
  line << "robot " << terrain::toString(settings_.robot) << ", path "
       << (settings_.path_file.empty() ? settings_.path : settings_.path_file)
       << ", model " << terrain::toString(settings_.model) << ", law "
       << terrain::toString(settings_.law) << ": |e_t| < " << summary.threshold()
       << " m ";
  if (std::isnan(summary.timeToConverge())) {
    line << "never";
  } else {
    line << "at t = " << summary.timeToConverge() << " s";
  }
  line << "; for t >= " << summary.settleTime() << " s ";
  if (std::isnan(summary.meanAfterSettling())) {
    line << "no rows (duration " << settings_.duration << " s)";
  } else {
    line << "mean |e_t| " << summary.meanAfterSettling() << " m, max " << summary.maxAfterSettling()
         << " m";
  }
  return line.str();
}

Subcommand terrainCommand() {
  const TerrainRunSettings defaults;
  Subcommand command;
  command.name = "terrain";
  command.summary =
      "Closed-loop run of a 3R, 2R, RT or RS robot tracking a path over eq 59 or a height map.";
  command.description = kDescription;
  command.options = {
      {"robot",
       "TYPE",
       "Robot type: 3R (rolls about l and h, turns about n), 2R (rolls about l and h),\n"
       "RT (rolls about l, turns about n), RS (rolls about a tilted axle, steers by tilting).",
       "",
       true,
       {"3R", "2R", "RT", "RS"}},
      {"path",
       "NAME",
       "Reference path: circle (radius and rate from config/terrain.yaml, eq 60 corrected) or\n"
       "diamond (counter-clockwise from (d, 0) at constant XY speed). This or --path-file.",
       "",
       false,
       {"circle", "diamond"}},
      optionalOption(
          "path-file", "FILE",
          "A path of your own instead of --path: a CSV file of rows t,x,y (a timed path, t [s]\n"
          "strictly increasing from the first row's) or x,y (untimed, followed at --speed),\n"
          "x and y [m], with an optional header row naming the columns; lines that are empty or\n"
          "start with # are skipped. Interpolated as pure_pursuit_controller interpolates a\n"
          "received nav_msgs/Path (see below)."),
      optionalOption("speed", "M/S",
                     "With an x,y --path-file: the speed [m/s] > 0 along it (its points timed by\n"
                     "the lengths between them)."),
      {"model",
       "NAME",
       "Contact model: paper (the rates move the contact point, eq 28) or rolling (they are the\n"
       "shell's body rates and move the centre; see docs/conventions.md).",
       terrain::toString(defaults.model),
       false,
       {"paper", "rolling"}},
      {"law",
       "NAME",
       "Tracking law: paper (eqs 55-58 as printed, signs corrected; the default, because this\n"
       "command reproduces the paper, whose laws chatter once converged: docs/results.md) or\n"
       "smooth (docs/conventions.md: smooth commands at convergence; the stacks' default).",
       terrain::toString(defaults.law),
       false,
       {"paper", "smooth"}},
      {"loop",
       "NAME",
       "How the loop runs: continuous (the law evaluated at every RK4 stage, as the paper's\n"
       "continuous-time feedback) or sampled (as launch/terrain_stack.launch runs it in\n"
       "lock-step: plant steps of --dt with the measured rates held, terrain_state and the\n"
       "controller at 50 Hz, ideal actuators at 100 Hz limited to 20 rad/s and 50 rad/s^2,\n"
       "times in whole nanoseconds: equal to the stack's run value for value).",
       "continuous",
       false,
       {"continuous", "sampled"}},
      optionalOption("duration", "SECONDS",
                     "Simulated time [s], >= 0; a whole number of log periods.",
                     formatNumber(defaults.duration)),
      optionalOption(
          "dt", "SECONDS",
          "continuous: fixed RK4 step [s], > 0 (default 0.005); sampled: the plant's step\n"
          "(default 0.01, the stack's). The duration must be a whole number of steps."),
      optionalOption("log-rate", "HZ",
                     "CSV rows per second [Hz], > 0; 1/log-rate must be a whole number of steps.",
                     formatNumber(defaults.log_rate)),
      {"stack",
       "NAME",
       "With --loop sampled, the launched stack replayed: terrain (launch/terrain_stack.launch)\n"
       "or roller (launch/roller_stack.launch: a 2R robot, --robot 2R --model rolling, on\n"
       "config/roller.yaml's level floor, driven through the friction drive's two rollers, motors\n"
       "limited to 60 rad/s and 300 rad/s^2).",
       "terrain",
       false,
       {"terrain", "roller"}},
      optionalOption(
          "actuator-models", "FILE",
          "With --loop sampled: the hardware interface's actuator models, the YAML file a stack\n"
          "takes as actuator_models:= (e.g. config/actuators_realistic.yaml: lag, dead time,\n"
          "encoder resolution, seeded velocity noise). Default: ideal actuators."),
      optionalOption(
          "terrain", "FILE",
          "A height map's YAML (docs/conventions.md, \"Height maps\"; e.g. maps/hills.yaml)\n"
          "instead of config/terrain.yaml's surface; a relative path is relative to the current\n"
          "directory. The run must stay on the map (else exit 4)."),
      configOption(),
      outOption("CSV file to write (columns below)."),
  };
  command.run = runTerrainCommand;
  return command;
}

}  // namespace spherical_robots::sphere_sim
