// BM_AcoLazarowska1/2: one full ACO plan (graph, 20 iterations x 10 ants, waypoint reduction) for the
// two scenarios of Lazarowska (2015) with the paper's parameters, sea mode; BM_AcoLazarowska1/2Paper the
// same in paper mode (the square grid with long edges, no reduction). Goal: median <= 20 ms and <= 50 ms
// on one core; the paper's MATLAB means were 15.69 s and 26.93 s (Intel Core i5 M430).
#include <benchmark/benchmark.h>

#include "asv_core/papers/lazarowska_scenarios.h"
#include "asv_core/planning/aco/aco_planner.h"

namespace {

void runPlanner(benchmark::State& state, const asv::PlanningProblem& problem, bool paper_mode = false) {
  // Both modes: tau0 1, rho 0.1, alpha = beta = 1, 20 iterations, 10 ants.
  asv::ParamMap params;
  if (paper_mode)
    params.set("mode", "paper");
  asv::AcoPlanner planner(asv::AcoConfig::fromParams(params));
  double cost = 0.0;
  for (auto _ : state) {
    const asv::Plan plan = planner.plan(problem);
    if (plan.status != asv::PlanStatus::Ok) {
      state.SkipWithError(plan.message.c_str());
      break;
    }
    cost = plan.cost;
    benchmark::DoNotOptimize(plan.waypoints.data());
  }
  state.counters["path_m"] = cost;
  state.counters["ants_ok"] = planner.diagnostics().ants_completed;
}

void BM_AcoLazarowska1(benchmark::State& state) {
  runPlanner(state, asv::lazarowskaScenario1());
}
BENCHMARK(BM_AcoLazarowska1)->Unit(benchmark::kMillisecond)->Repetitions(10)->ReportAggregatesOnly(true);

void BM_AcoLazarowska2(benchmark::State& state) {
  runPlanner(state, asv::lazarowskaScenario2());
}
BENCHMARK(BM_AcoLazarowska2)->Unit(benchmark::kMillisecond)->Repetitions(10)->ReportAggregatesOnly(true);

void BM_AcoLazarowska1Paper(benchmark::State& state) {
  runPlanner(state, asv::lazarowskaScenario1(), true);
}
BENCHMARK(BM_AcoLazarowska1Paper)->Unit(benchmark::kMillisecond)->Repetitions(10)->ReportAggregatesOnly(true);

void BM_AcoLazarowska2Paper(benchmark::State& state) {
  runPlanner(state, asv::lazarowskaScenario2(), true);
}
BENCHMARK(BM_AcoLazarowska2Paper)->Unit(benchmark::kMillisecond)->Repetitions(10)->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
