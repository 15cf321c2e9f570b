// BM_MopsoFourTargets: one MOPSO re-planning (Hu et al. 2017) of the Fig. 5 situation, three moving
// targets and a static one, 50 particles x 40 generations. Goal: median <= 5 ms on one core.
#include <benchmark/benchmark.h>

#include "asv_core/papers/hu_scenarios.h"
#include "asv_core/planning/mopso/mopso_planner.h"

namespace {

void BM_MopsoFourTargets(benchmark::State& state) {
  asv::PlanningProblem problem = asv::huMultiTarget();
  asv::MopsoConfig cfg;
  cfg.particles = 50;
  cfg.generations = 40;
  asv::MopsoPlanner planner(cfg);
  uint64_t seed = 1;
  for (auto _ : state) {
    problem.seed = seed++;  // a fresh swarm each time, as on every new risk picture
    asv::Plan plan = planner.plan(problem);
    benchmark::DoNotOptimize(plan.course_setpoint);
  }
  state.counters["front"] = static_cast<double>(planner.lastParetoFront().size());
}
BENCHMARK(BM_MopsoFourTargets)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
