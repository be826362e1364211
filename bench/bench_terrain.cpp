// The terrain batch run that `sphere_sim terrain` performs: 200 s at dt = 5 ms (40,000 RK4 steps,
// 160,000 closed-loop evaluations) for each robot type and both tracking laws (the first
// argument is the robot, the second the law: 0 paper, 1 smooth).
//  * BM_SphereSimTerrain: the whole command in-process, through runSphereSim exactly as the
//    executable runs it (config and URDF parsing, 2,001 CSV rows written to a temporary file).
//  * BM_TerrainArithmetic: the same run without the CSV, to separate arithmetic from I/O; its
//    counter stage is the time per RK stage (4 per step: 160,000 closed-loop evaluations).
//  * BM_TerrainConfiguration: reading config/terrain.yaml and the URDF, building the run.
//  * BM_TerrainStageFloor: a lower bound, not the product. The 3R smooth closed loop on the circle
//    written as one function of straight-line arithmetic (no checks, no virtual calls, no
//    structs between the surface, the frame and the law, the desired point computed once per
//    time), from the shipped scenario; it must end where TerrainSimulation ends (1e-9 m, or the
//    benchmark fails). Its stage time is what restructuring the core could approach: the serial
//    chain from one RK stage to the next (sin and cos, the tangent frame's square root and
//    division, the law's two square roots and division) is all that is left in it.
// The CSV's cost is BM_SphereSimTerrain less the other two; scripts/run_benchmarks.sh times the
// executable as a process, and its start-up (--help) and configuration (--duration 0) alone.

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "sphere_sim_cli.hpp"
#include "spherical_robots/config/robot_description.hpp"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/config/yaml_parameter_source.hpp"
#include "spherical_robots/core/sin_cos.hpp"
#include "spherical_robots/terrain/terrain_simulation.hpp"
#include "terrain_command.hpp"

namespace {

using spherical_robots::sphere_sim::kSuccess;
using spherical_robots::sphere_sim::runSphereSim;
using spherical_robots::sphere_sim::terrainCommand;
using spherical_robots::sphere_sim::TerrainRun;
using spherical_robots::sphere_sim::TerrainRunSettings;
namespace terrain = spherical_robots::terrain;

const char* const kRobots[] = {"3R", "2R", "RT", "RS"};
const char* const kLaws[] = {"paper", "smooth"};

void BM_SphereSimTerrain(benchmark::State& state) {
  const std::string robot = kRobots[state.range(0)];
  const std::string law = kLaws[state.range(1)];
  state.SetLabel(robot + " circle 200 s, law " + law);
  const std::string out = (std::filesystem::temp_directory_path() /
                           ("bench_terrain_" + std::to_string(::getpid()) + ".csv"))
                              .string();
  const std::vector<spherical_robots::sphere_sim::Subcommand> commands = {terrainCommand()};
  const std::vector<std::string> args = {"terrain", "--robot", robot, "--path", "circle",
                                         "--law",   law,      "--out", out};
  std::ostringstream summary;
  std::ostringstream errors;
  for (auto _ : state) {
    if (runSphereSim(commands, args, summary, errors) != kSuccess) {
      state.SkipWithError(errors.str().c_str());
      break;
    }
    summary.str("");
  }
  std::remove(out.c_str());
}
BENCHMARK(BM_SphereSimTerrain)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMillisecond);

void BM_TerrainArithmetic(benchmark::State& state) {
  TerrainRunSettings settings;
  settings.robot = terrain::robotTypeFromString(kRobots[state.range(0)]);
  settings.law = terrain::pursuitLawFromString(kLaws[state.range(1)]);
  settings.config_dir = spherical_robots::config::packageShareDirectory();
  state.SetLabel(terrain::toString(settings.robot) + " circle 200 s, law " +
                 terrain::toString(settings.law) + ", no CSV");
  const TerrainRun run(settings);
  for (auto _ : state) {
    benchmark::DoNotOptimize(run.simulate(nullptr).meanAfterSettling());
  }
  // Seconds per RK stage, 4 per step (the 2,001 logged samples are a rounding error).
  const double stages = 4.0 * settings.duration / settings.dt;
  state.counters["stage"] = benchmark::Counter(stages * state.iterations(),
                                               benchmark::Counter::kIsRate |
                                                   benchmark::Counter::kInvert);
}
BENCHMARK(BM_TerrainArithmetic)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Unit(benchmark::kMillisecond);

void BM_TerrainConfiguration(benchmark::State& state) {
  TerrainRunSettings settings;
  settings.law = terrain::PursuitLaw::Smooth;
  settings.config_dir = spherical_robots::config::packageShareDirectory();
  for (auto _ : state) {
    const TerrainRun run(settings);
    benchmark::DoNotOptimize(&run);
  }
  state.SetLabel("terrain.yaml and the URDF read, the run built");
}
BENCHMARK(BM_TerrainConfiguration)->Unit(benchmark::kMicrosecond);

// The shipped 3R circle scenario's numbers, for the floor.
struct FloorScenario {
  double amplitude, frequency;                   // eq 59 surface [m], [rad/m]
  double path_radius, path_rate, window_factor;  // circle [m], [rad/s]; sin(w tau/2) / (w tau/2)
  spherical_robots::terrain::SmoothPursuitGains gains;
};

struct FloorDesired {
  double p[3];      // p_d
  double w[3];      // the windowed path velocity on the surface
  double along[3];  // w / sqrt(|w|^2 + v_e^2)
};

FloorDesired floorDesired(const FloorScenario& s, double t) {
  const auto [sin_wt, cos_wt] = spherical_robots::sinCos(s.path_rate * t);
  FloorDesired d{};
  d.p[0] = s.path_radius * cos_wt;
  d.p[1] = s.path_radius * sin_wt;
  const double speed = s.path_radius * s.path_rate * s.window_factor;
  d.w[0] = -speed * sin_wt;
  d.w[1] = speed * cos_wt;
  const auto [x, y] = spherical_robots::sinCos(s.frequency * d.p[0], s.frequency * d.p[1]);
  d.p[2] = s.amplitude * (x.cos + y.cos - 2.0);
  const double slope = -s.amplitude * s.frequency;
  d.w[2] = slope * (x.sin * d.w[0] + y.sin * d.w[1]);
  const double floor = s.gains.min_speed;
  const double inverse =
      1.0 / std::sqrt(d.w[0] * d.w[0] + d.w[1] * d.w[1] + d.w[2] * d.w[2] + floor * floor);
  for (int i = 0; i < 3; ++i) d.along[i] = d.w[i] * inverse;
  return d;
}

// (x', y', psi') of the 3R robot at (x, y, psi), paper contact model (where the radius cancels:
// the contact point moves at R theta' h - R phi' l, and the law sets theta' = u.h / R).
void floorStateRate(const FloorScenario& s, const double* state, const FloorDesired& d,
                    double* rate) {
  const auto [x, y] = spherical_robots::sinCos(s.frequency * state[0], s.frequency * state[1]);
  const spherical_robots::SinCos heading = spherical_robots::sinCos(state[2]);
  const double slope = -s.amplitude * s.frequency;
  const double gx = slope * x.sin;
  const double gy = slope * y.sin;
  const double length = std::sqrt(1.0 + gx * gx + gy * gy);
  const double dd = 1.0 / (length * (length + 1.0));
  const double c = (length + 1.0) * dd;
  const double t0[3] = {1.0 - dd * gx * gx, -dd * gx * gy, c * gx};
  const double t1[3] = {-dd * gx * gy, 1.0 - dd * gy * gy, c * gy};
  double h[3];
  double l[3];
  for (int i = 0; i < 3; ++i) {
    h[i] = heading.cos * t0[i] + heading.sin * t1[i];
    l[i] = -heading.sin * t0[i] + heading.cos * t1[i];
  }
  const double e[3] = {d.p[0] - state[0], d.p[1] - state[1],
                       d.p[2] - s.amplitude * (x.cos + y.cos - 2.0)};
  const double e_along = e[0] * d.along[0] + e[1] * d.along[1] + e[2] * d.along[2];
  const auto& g = s.gains;
  double k[3];
  for (int i = 0; i < 3; ++i) k[i] = g.cross_gain * e[i] + (g.along_gain - g.cross_gain) * e_along * d.along[i];
  const double denominator = g.approach_speed + std::sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
  double forward_d = 0.0;
  double leftward_d = 0.0;
  for (int i = 0; i < 3; ++i) {
    forward_d += denominator * d.w[i] * h[i] + g.approach_speed * k[i] * h[i];
    leftward_d += denominator * d.w[i] * l[i] + g.approach_speed * k[i] * l[i];
  }
  const double floor_d = g.min_speed * denominator;
  const double forward = forward_d / denominator;
  const double leftward = leftward_d / denominator;
  rate[0] = forward * h[0] + leftward * l[0];
  rate[1] = forward * h[1] + leftward * l[1];
  rate[2] = g.heading_gain * leftward_d /
            std::sqrt(forward_d * forward_d + leftward_d * leftward_d + floor_d * floor_d);
}

void BM_TerrainStageFloor(benchmark::State& state) {
  using namespace spherical_robots;
  const std::string share = config::packageShareDirectory();
  const config::TerrainConfig scenario =
      config::loadTerrainConfig(config::YamlParameterSource(share + "/config/terrain.yaml"));
  const double radius =
      spherical_robots::sphere_sim::radiusFromUrdf(share + "/urdf/terrain_robot.urdf", "shell");
  const terrain::RobotType type = terrain::RobotType::ThreeAxisRolling;
  const terrain::SmoothPursuitGains& gains = scenario.smooth_gains.at(type);
  if (scenario.surface.type != "cosine" || gains.lead != 0.0 || !(gains.window > 0.0)) {
    state.SkipWithError("the floor is written for the shipped scenario: a cosine surface, a 3R "
                        "window centred on t");
    return;
  }
  const double half_turn = 0.5 * scenario.circle_angular_rate * gains.window;
  const FloorScenario floor{scenario.surface.amplitude, scenario.surface.frequency,
                            scenario.circle_radius,     scenario.circle_angular_rate,
                            std::sin(half_turn) / half_turn, gains};
  constexpr double kDt = 0.005;
  constexpr int kSteps = 40000;
  const auto run = [&floor] {
    double s[3] = {0.0, 0.0, 0.0};
    FloorDesired start = floorDesired(floor, 0.0);
    for (int n = 0; n < kSteps; ++n) {
      const double t = n * kDt;
      const FloorDesired middle = floorDesired(floor, t + 0.5 * kDt);
      const FloorDesired end = floorDesired(floor, t + kDt);
      double k1[3], k2[3], k3[3], k4[3], x[3];
      floorStateRate(floor, s, start, k1);
      for (int i = 0; i < 3; ++i) x[i] = s[i] + 0.5 * kDt * k1[i];
      floorStateRate(floor, x, middle, k2);
      for (int i = 0; i < 3; ++i) x[i] = s[i] + 0.5 * kDt * k2[i];
      floorStateRate(floor, x, middle, k3);
      for (int i = 0; i < 3; ++i) x[i] = s[i] + kDt * k3[i];
      floorStateRate(floor, x, end, k4);
      for (int i = 0; i < 3; ++i) s[i] += kDt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
      start = end;
    }
    return std::array<double, 3>{s[0], s[1], s[2]};
  };

  const terrain::CosineSurface surface(floor.amplitude, floor.frequency);
  const terrain::TerrainKinematics kinematics(surface, type, radius, terrain::ContactModel::Paper,
                                              scenario.tilt_limit);
  const terrain::SmoothPursuitController controller(type, gains, radius, scenario.tilt_limit);
  const terrain::CirclePath path(floor.path_radius, floor.path_rate);
  terrain::TerrainSimulation reference(kinematics, controller, path, terrain::TerrainState{});
  for (int n = 0; n < kSteps; ++n) reference.step(kDt);
  const std::array<double, 3> end = run();
  const terrain::TerrainState& want = reference.state();
  if (std::hypot(end[0] - want.x, end[1] - want.y) > 1e-9 || std::abs(end[2] - want.psi) > 1e-9) {
    state.SkipWithError("the floor does not end where TerrainSimulation ends: not the same model");
    return;
  }
  for (auto _ : state) benchmark::DoNotOptimize(run());
  state.SetLabel("3R circle 200 s, law smooth, straight-line code: a lower bound");
  state.counters["stage"] = benchmark::Counter(4.0 * kSteps * state.iterations(),
                                               benchmark::Counter::kIsRate |
                                                   benchmark::Counter::kInvert);
}
BENCHMARK(BM_TerrainStageFloor)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
