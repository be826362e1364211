// n-step planning of the two-rotor sphere (spherical_robots::rotor::planRotorMotion): every plan
// of a problem found and each verified by integrating all n steps. Problems: k in {0, 1.25, 2.5,
// 3.75, 5} x n in {1, …, 5}, target (u_a, v_a, ψ) = (0.4, 0.7, 0.6) [R, R, rad], radii <= 0.7.
// Target (issue 4): every problem under 50 ms. Counters: solutions found, worst final_error.

#include <benchmark/benchmark.h>

#include <algorithm>

#include "spherical_robots/rotor/motion_planner.hpp"

namespace {

using spherical_robots::rotor::PlanRequest;
using spherical_robots::rotor::PlanResult;
using spherical_robots::rotor::planRotorMotion;

void BM_RotorPlan(benchmark::State& state) {
  PlanRequest request;
  request.k = 1.25 * state.range(0);
  request.steps = static_cast<int>(state.range(1));
  request.u_a = 0.4;
  request.v_a = 0.7;
  request.psi = 0.6;
  PlanResult result;
  for (auto _ : state) {
    result = planRotorMotion(request);
    benchmark::DoNotOptimize(result);
  }
  double worst = 0.0;
  for (const auto& plan : result.solutions) worst = std::max(worst, plan.final_error);
  state.counters["solutions"] = static_cast<double>(result.solutions.size());
  state.counters["worst_error"] = worst;
}
BENCHMARK(BM_RotorPlan)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {1, 2, 3, 4, 5}})
    ->ArgNames({"k_x1.25", "n"})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
