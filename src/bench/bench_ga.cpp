// BM_GaFourTargets: one GA decision (Wu et al. 2022) for the four targets of the paper's situation,
// population 150 x 150 generations (section 4). Goal: median <= 10 ms on one core.
#include <benchmark/benchmark.h>

#include "asv_core/papers/wu_scenarios.h"
#include "asv_core/planning/ga/ga_planner.h"

namespace {

void BM_GaFourTargets(benchmark::State& state) {
  asv::GaPlanner planner(asv::wuAsvGaConfig());
  asv::PlanningProblem problem = asv::wuFourTargets();
  problem.time_budget = 10.0;  // never cut the run short: measure all 150 generations
  uint64_t seed = 1;
  for (auto _ : state) {
    problem.seed = seed++;  // a fresh seed each time: no run is helped by an earlier one
    asv::Plan plan = planner.plan(problem);
    benchmark::DoNotOptimize(plan.course_setpoint);
  }
}
BENCHMARK(BM_GaFourTargets)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
