// BM_PlanNewYork/<planner>: one plan of each planner (sea mode, default parameters) at the start of
// asv_bringup/scenarios/ny_upper_bay.yaml: the GSHHG full coastline of New York Harbor (12 km round
// the Upper Bay, indexed) and its ten ships, every one given as a collision risk, with the land route
// the plan follower would hand the planner. Goal: <= 50 ms per plan on one core. Needs GMT and GSHHG
// full (scripts/setup); the extraction is cached (~/.cache/asv/charts).
#include <benchmark/benchmark.h>

#include "asv_core/planning/aco/aco_planner.h"
#include "asv_core/planning/dssa/dssa.h"
#include "asv_core/planning/ga/ga_planner.h"
#include "asv_core/planning/land_route.h"
#include "asv_core/planning/mopso/mopso_planner.h"
#include "asv_core/world/scenario.h"

namespace {

const asv::PlanningProblem& newYork() {
  static const asv::PlanningProblem problem = [] {
    const asv::Scenario s =
        asv::loadScenario(std::string(ASV_SOURCE_DIR) + "/asv_bringup/scenarios/ny_upper_bay.yaml");
    asv::PlanningProblem p;
    p.own = {s.own.name, s.own.position, s.own.course, s.own.speed, s.own.course, 120.0};
    p.goal = *s.own.goal;
    p.obstacles = s.obstacles;
    p.min_separation = s.min_separation;
    p.min_obstacle_clearance = s.min_obstacle_clearance;
    p.time_budget = 10.0;  // measure whole runs: no wall-clock cut
    for (const auto& t : s.targets) {
      asv::PlannerTarget pt;
      pt.state = {t.name, t.position, t.course, t.speed, t.course, t.length};
      pt.risk = asv::RiskLevel::Collision;
      p.targets.push_back(pt);
    }
    const double required = asv::landRequirement(p);
    if (auto route = asv::landRoute(p.own.position, p.goal, p.obstacles, p.min_obstacle_clearance, required))
      p.route = *route;
    return p;
  }();
  return problem;
}

template <class Planner>
void planNewYork(benchmark::State& state, Planner planner) {
  asv::PlanningProblem problem = newYork();
  size_t vertices = 0;
  for (const auto& o : problem.obstacles)
    vertices += o.polygon.size();
  uint64_t seed = 1;
  double ok = 0.0;
  for (auto _ : state) {
    problem.seed = seed++;
    const asv::Plan plan = planner.plan(problem);
    ok = plan.status == asv::PlanStatus::Ok ? 1.0 : 0.0;  // a failed plan is fast: say so
    benchmark::DoNotOptimize(plan.course_setpoint);
  }
  state.counters["plan_ok"] = ok;
  state.counters["land_vertices"] = static_cast<double>(vertices);
  state.counters["targets"] = static_cast<double>(problem.targets.size());
}

void BM_PlanNewYork_aco(benchmark::State& s) {
  planNewYork(s, asv::AcoPlanner());
}
void BM_PlanNewYork_mopso(benchmark::State& s) {
  planNewYork(s, asv::MopsoPlanner());
}
void BM_PlanNewYork_ga(benchmark::State& s) {
  planNewYork(s, asv::GaPlanner());
}
void BM_PlanNewYork_dssa(benchmark::State& s) {
  planNewYork(s, asv::DssaPlanner("dssa"));
}
void BM_PlanNewYork_dssa_plus(benchmark::State& s) {
  planNewYork(s, asv::DssaPlanner("dssa_plus"));
}
BENCHMARK(BM_PlanNewYork_aco)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanNewYork_mopso)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanNewYork_ga)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanNewYork_dssa)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanNewYork_dssa_plus)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

// The land route itself (visibility graph over the coast's convex corners, A*), made once per plan.
void BM_LandRouteNewYork(benchmark::State& state) {
  const asv::PlanningProblem& p = newYork();
  const double required = asv::landRequirement(p);
  for (auto _ : state)
    benchmark::DoNotOptimize(
        asv::landRoute(p.own.position, p.goal, p.obstacles, p.min_obstacle_clearance, required));
}
BENCHMARK(BM_LandRouteNewYork)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
