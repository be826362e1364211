// Norma (Moazami et al. 2019): the cost of the model and of the paper's 1300 s scenario.
//  * BM_NormaTerms / BM_NormaAcceleration: one evaluation of M, C, G (eq 46), and of
//    q̈ = M⁻¹ (U − C q̇ − G) as the integrator calls it (target: well under a microsecond).
//  * BM_NormaPaperRun: the closed loop of eq 52 with the paper's controller at the default
//    tolerances, no CSV; its counter max_dev_mm is the largest distance of (X, Y) from a run at
//    rtol = atol = 1e-11 (dopri5) over the 1301 logged rows (target: < 1 mm).
//  * BM_SphereSimNorma: the whole `sphere_sim norma` command in-process, CSV included (the
//    process target, < 50 ms of CPU, is measured on the executable; see docs/results.md).

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "norma_command.hpp"
#include "sphere_sim_cli.hpp"
#include "spherical_robots/norma/norma_simulation.hpp"

namespace {

namespace norma = spherical_robots::norma;

const norma::Vector4 kQ(0.3, 0.5, -0.2, 0.04);
const norma::Vector4 kQd(0.2, -0.1, 0.05, 0.01);

void BM_NormaTerms(benchmark::State& state) {
  const norma::NormaDynamics dynamics{norma::NormaParameters()};
  norma::Vector4 q = kQ;
  for (auto _ : state) {
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(dynamics.terms(q, kQd));
  }
}
BENCHMARK(BM_NormaTerms);

void BM_NormaAcceleration(benchmark::State& state) {
  const norma::NormaDynamics dynamics{norma::NormaParameters()};
  norma::Vector4 q = kQ;
  const norma::Vector4 u = norma::NormaDynamics::generalizedForces(0.1, 0.2);
  for (auto _ : state) {
    benchmark::DoNotOptimize(q);
    benchmark::DoNotOptimize(dynamics.acceleration(q, kQd, u));
  }
}
BENCHMARK(BM_NormaAcceleration);

void BM_NormaPaperRun(benchmark::State& state) {
  const norma::NormaParameters parameters;
  norma::ClosedLoopConfig config;
  std::vector<norma::NormaSample> run;
  for (auto _ : state) {
    run = norma::runClosedLoop(parameters, config);
    benchmark::DoNotOptimize(run.back().x);
  }
  norma::ClosedLoopConfig tight = config;
  tight.ode.method = norma::OdeMethod::kDopri5;
  tight.ode.rtol = tight.ode.atol = 1e-11;
  const std::vector<norma::NormaSample> reference = norma::runClosedLoop(parameters, tight);
  double deviation = 0.0;
  for (std::size_t i = 0; i < run.size(); ++i) {
    deviation = std::max(deviation,
                         std::hypot(run[i].x - reference[i].x, run[i].y - reference[i].y));
  }
  state.counters["max_dev_mm"] = 1000.0 * deviation;
  state.SetLabel("1300 s, rtol " + std::to_string(config.ode.rtol) + ", atol " +
                 std::to_string(config.ode.atol));
}
BENCHMARK(BM_NormaPaperRun)->Unit(benchmark::kMillisecond);

void BM_SphereSimNorma(benchmark::State& state) {
  const std::string out = (std::filesystem::temp_directory_path() /
                           ("bench_norma_" + std::to_string(::getpid()) + ".csv"))
                              .string();
  const std::vector<spherical_robots::sphere_sim::Subcommand> commands = {
      spherical_robots::sphere_sim::normaCommand()};
  const std::vector<std::string> args = {"norma", "--out", out};
  std::ostringstream summary, errors;
  for (auto _ : state) {
    if (spherical_robots::sphere_sim::runSphereSim(commands, args, summary, errors) !=
        spherical_robots::sphere_sim::kSuccess) {
      state.SkipWithError(errors.str().c_str());
      break;
    }
    summary.str("");
  }
  std::remove(out.c_str());
  state.SetLabel("sphere_sim norma (paper, 1300 s, 1301 CSV rows)");
}
BENCHMARK(BM_SphereSimNorma)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
