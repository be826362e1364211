// IK of a 3-joint SRC manipulator (Zong, Liang, Lam 2022, eqs 38-47) over 10,000 random
// reachable targets: each target is B_3's pose for seeded random joints, and each solve starts
// from the aligned chain (no warm start). Issue 6's targets: median under 100 µs and success
// >= 99.9 % at 1e-5 m / 1e-4 rad.
//  * BM_FreebotIkSweep: all 10,000 targets per iteration, each solve timed on its own; counters
//    give the median, 90th and 99th percentile and mean wall time per solve [µs], the median
//    thread CPU time per solve [µs] and the success rate. Arguments: radii (0 = Table II, all
//    0.034 m; 1 = unequal, 0.02-0.05 m), mode (0 = full pose, 1 = position only), damping
//    (0 = the solver's: eq 44 with Table II's λ_max = 0.01, fading with the residual; 1 = eq 44
//    as printed, damping_residual = 0).
//  * BM_FreebotIk: Google Benchmark's own mean per solve, cycling through the same targets.
//  * BM_FreebotJacobian: forward kinematics and J_{B_3} of one configuration.

#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <vector>

#include "spherical_robots/freebot/src_inverse_kinematics.hpp"
#include "spherical_robots/freebot/src_manipulator.hpp"

namespace {

using spherical_robots::freebot::IkMode;
using spherical_robots::freebot::IkOptions;
using spherical_robots::freebot::IkResult;
using spherical_robots::freebot::LinkPose;
using spherical_robots::freebot::solveIk;
using spherical_robots::freebot::SrcJointState;
using spherical_robots::freebot::SrcManipulator;

constexpr int kTargets = 10000;

std::vector<double> radiiFor(bool unequal, std::mt19937& rng) {
  std::uniform_real_distribution<double> radius(0.02, 0.05);
  std::vector<double> radii(4, 0.034);
  if (unequal) {
    for (double& r : radii) r = radius(rng);
  }
  return radii;
}

/// B_3's pose for joints rolled straight by a random rotation vector (uniform over the disc of
/// radius 0.9 π), then, with unequal radii, by a second random roll (a path-dependent state).
std::vector<LinkPose> targetsFor(const SrcManipulator& chain, bool unequal, std::mt19937& rng) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<LinkPose> targets;
  targets.reserve(kTargets);
  for (int k = 0; k < kTargets; ++k) {
    std::vector<SrcJointState> joints;
    for (std::size_t i = 0; i < chain.jointCount(); ++i) {
      Eigen::Vector2d u;
      do {
        u = {uniform(rng), uniform(rng)};
      } while (u.norm() > 1.0);
      SrcJointState state = chain.joint(i).straightRoll(0.9 * M_PI * u);
      if (unequal) {
        state = chain.joint(i).roll(state, {uniform(rng), uniform(rng)}, 1.0);
      }
      joints.push_back(state);
    }
    targets.push_back(chain.endEffector(joints));
  }
  return targets;
}

/// This thread's CPU time [µs]: unlike the wall clock, not stretched when the machine is shared.
double threadCpuMicros() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return 1e6 * static_cast<double>(now.tv_sec) + 1e-3 * static_cast<double>(now.tv_nsec);
}

struct Setup {
  SrcManipulator chain;
  std::vector<LinkPose> targets;
  IkOptions options;
};

Setup setupFor(const benchmark::State& state) {
  std::mt19937 rng(20221);  // the same targets on every run
  const bool unequal = state.range(0) == 1;
  const std::vector<double> radii = radiiFor(unequal, rng);
  SrcManipulator chain(radii);
  std::vector<LinkPose> targets = targetsFor(chain, unequal, rng);
  IkOptions options;
  options.mode = state.range(1) == 1 ? IkMode::PositionOnly : IkMode::FullPose;
  if (state.range(2) == 1) options.damping_residual = 0.0;
  return {std::move(chain), std::move(targets), options};
}

void BM_FreebotIkSweep(benchmark::State& state) {
  const Setup setup = setupFor(state);
  std::vector<double> micros(kTargets);
  std::vector<double> cpu_micros(kTargets);
  int successes = 0;
  long iterations = 0;
  for (auto _ : state) {
    successes = 0;
    iterations = 0;
    for (int k = 0; k < kTargets; ++k) {
      const LinkPose& target = setup.targets[k];
      const auto start = std::chrono::steady_clock::now();
      const double cpu_start = threadCpuMicros();
      const IkResult result =
          solveIk(setup.chain, target.position, target.orientation, {}, setup.options);
      cpu_micros[k] = threadCpuMicros() - cpu_start;
      micros[k] =
          std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
              .count();
      successes += result.success ? 1 : 0;
      iterations += result.iterations;
      benchmark::DoNotOptimize(result);
    }
  }
  std::sort(micros.begin(), micros.end());
  std::sort(cpu_micros.begin(), cpu_micros.end());
  state.counters["median_cpu_us"] = cpu_micros[kTargets / 2];
  double total = 0.0;
  for (double m : micros) total += m;
  state.counters["median_us"] = micros[kTargets / 2];
  state.counters["p90_us"] = micros[kTargets * 9 / 10];
  state.counters["p99_us"] = micros[kTargets * 99 / 100];
  state.counters["max_us"] = micros.back();
  state.counters["mean_us"] = total / kTargets;
  state.counters["success_pct"] = 100.0 * successes / kTargets;
  state.counters["iterations_mean"] = static_cast<double>(iterations) / kTargets;
  state.SetLabel(std::string(state.range(0) == 1 ? "unequal radii" : "Table II radii") +
                 (state.range(1) == 1 ? ", position only" : ", full pose") +
                 (state.range(2) == 1 ? ", eq 44 as printed" : ""));
}
BENCHMARK(BM_FreebotIkSweep)
    ->Args({0, 0, 0})
    ->Args({1, 0, 0})
    ->Args({0, 1, 0})
    ->Args({0, 0, 1})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

void BM_FreebotIk(benchmark::State& state) {
  const Setup setup = setupFor(state);
  std::size_t k = 0;
  for (auto _ : state) {
    const LinkPose& target = setup.targets[k];
    benchmark::DoNotOptimize(
        solveIk(setup.chain, target.position, target.orientation, {}, setup.options));
    k = (k + 1) % setup.targets.size();
  }
}
BENCHMARK(BM_FreebotIk)->Args({0, 0, 0})->Unit(benchmark::kMicrosecond);

void BM_FreebotJacobian(benchmark::State& state) {
  const SrcManipulator chain({0.034, 0.034, 0.034, 0.034});
  const std::vector<SrcJointState> joints = chain.straightRolls(
      {Eigen::Vector2d(0.5, 0.3), Eigen::Vector2d(-0.4, 0.6), Eigen::Vector2d(0.2, -0.7)});
  LinkPose end;
  for (auto _ : state) {
    benchmark::DoNotOptimize(chain.jacobian(joints, end));
  }
}
BENCHMARK(BM_FreebotJacobian)->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
