// The terrain batch run that `sphere_sim terrain` performs: 200 s at dt = 5 ms (40,000 RK4 steps,
// 160,000 closed-loop evaluations) for each robot type and both tracking laws (the first
// argument is the robot, the second the law: 0 paper, 1 smooth).
//  * BM_SphereSimTerrain: the whole command in-process, through runSphereSim exactly as the
//    executable runs it (config and URDF parsing, 2,001 CSV rows written to a temporary file).
//  * BM_TerrainArithmetic: the same run without the CSV, to separate arithmetic from I/O; its
//    counter stage is the time per RK stage (4 per step: 160,000 closed-loop evaluations).
//  * BM_TerrainConfiguration: reading config/terrain.yaml and the URDF, building the run.
//  * BM_TerrainStageFloor: a lower bound, not the product (bench/terrain_floor.hpp): the 3R
//    smooth circle loop as straight-line arithmetic; it must end where TerrainSimulation, built
//    from the shipped files, ends (1e-9 m), or the benchmark fails. What is left in it is the
//    serial chain from one RK stage to the next (sin and cos, the tangent frame's square root and
//    division, the law's two square roots and division).
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
#include "spherical_robots/terrain/terrain_simulation.hpp"
#include "terrain_command.hpp"
#include "terrain_floor.hpp"

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

void BM_TerrainStageFloor(benchmark::State& state) {
  using namespace spherical_robots;
  constexpr double kDt = 0.005;
  constexpr int kSteps = 40000;
  const bench::FloorScenario floor;
  const auto run = [&floor] {
    return bench::runFloor(floor, kSteps, kDt, 0, [](double, const auto&, const auto&) {});
  };
  // The core's run of the shipped scenario, which the floor's compiled-in numbers must match.
  const std::string share = config::packageShareDirectory();
  const config::TerrainConfig scenario =
      config::loadTerrainConfig(config::YamlParameterSource(share + "/config/terrain.yaml"));
  const double radius =
      sphere_sim::radiusFromUrdf(share + "/urdf/terrain_robot.urdf", "shell");
  const terrain::RobotType type = terrain::RobotType::ThreeAxisRolling;
  const auto surface = config::makeSurface(scenario.surface);
  const terrain::TerrainKinematics kinematics(*surface, type, radius, terrain::ContactModel::Paper,
                                              scenario.tilt_limit);
  const terrain::SmoothPursuitController controller(type, scenario.smooth_gains.at(type), radius,
                                                    scenario.tilt_limit);
  const auto path = config::makePath("circle", scenario);
  terrain::TerrainSimulation reference(kinematics, controller, *path, terrain::TerrainState{});
  for (int n = 0; n < kSteps; ++n) reference.step(kDt);
  const std::array<double, 3> end = run();
  const terrain::TerrainState& want = reference.state();
  if (std::hypot(end[0] - want.x, end[1] - want.y) > 1e-9 || std::abs(end[2] - want.psi) > 1e-9) {
    state.SkipWithError("the floor does not end where TerrainSimulation ends: the shipped "
                        "scenario is not bench/terrain_floor.hpp's FloorScenario");
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
