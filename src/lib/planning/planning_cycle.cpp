#include "asv_core/planning/planning_cycle.h"

#include <algorithm>
#include <chrono>
#include <exception>

#include "asv_core/common/format.h"

namespace asv {

namespace {

// The planner's plan for the follower's problem, or the fallback when it throws or overruns.
void plan(PlanFollower& follower, PlannerAlgorithm& planner, PlannerMode mode, double now,
          const std::vector<PlannerTarget>& targets, const CycleOptions& options, CycleResult& r) {
  const PlanningProblem problem = follower.buildProblem(now, targets);
  const auto start = std::chrono::steady_clock::now();
  try {
    r.proposed = planInMode([&](const PlanningProblem& p) { return planner.plan(p); }, problem, mode);
  } catch (const std::exception& e) {
    r.error = e.what();
    r.proposed = follower.fallback(targets, "plugin error: " + r.error);
  }
  if (options.after_plan)
    options.after_plan();
  const double spent = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double budget = follower.config().time_budget;
  if (options.overrun_factor > 0.0 && spent > options.overrun_factor * budget) {
    r.overran = true;
    r.proposed =
        follower.fallback(targets, strFormat("plugin overran its time budget: %.3f s > %.1f x %.3f s", spent,
                                             options.overrun_factor, budget));
  }
  r.proposed.compute_time = spent;
  if (problem.passing_cap > 0.0)
    r.proposed.passing_distance = std::max(problem.passing_cap, kSeparationMargin * problem.min_separation);
}

}  // namespace

CycleResult planningCycle(PlanFollower& follower, PlannerAlgorithm& planner, PlannerMode mode, double now,
                          const std::vector<PlannerTarget>& targets, const CycleOptions& options) {
  CycleResult r;
  if (follower.replanNeeded(now, targets, r.why)) {
    r.replanned = true;
    plan(follower, planner, mode, now, targets, options, r);
    follower.acceptPlan(r.proposed, now, targets, r.why);
  }
  r.has_setpoint = follower.setpoint(r.course, r.speed);
  return r;
}

}  // namespace asv
