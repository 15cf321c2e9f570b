// One planning cycle, the same wherever the stack plans: planner_node (on a boat, or in the simulator
// through ROS) and asv_batch call it at each set-point. The follower's replanning policy decides
// whether to plan; the problem is built from the picture (targets with their risk); the planner runs
// in its mode; a planner that throws, or overruns its budget where wall time matters, gives way to the
// follower's fallback; the shared rules accept the plan (PlanFollower::acceptPlan); the set-point is
// steered from the plan in force.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "asv_core/planning/plan_follower.h"
#include "asv_core/planning/planning.h"

namespace asv {

struct CycleOptions {
  // A plan that took longer than this many time budgets is not flown, the fallback is (the picture it
  // was made for is that old); 0: never (lockstep and batch runs, where planning costs no ship time).
  double overrun_factor = 0.0;
  // Called after the planner returns, inside the timed part: planner_node's fault injection (a planner
  // that overruns). Empty: nothing.
  std::function<void()> after_plan;
};

struct CycleResult {
  bool replanned = false;
  std::string why;       // the follower's reason to replan
  Plan proposed;         // the planner's plan (or the fallback in its place), with its compute time
  std::string error;     // the planner's exception, when it threw
  bool overran = false;  // the planner overran: `proposed` is the fallback
  bool has_setpoint = false;
  double course = 0.0;  // [rad] the set-point from the plan in force
  double speed = 0.0;   // [m/s]
};

// One cycle at time `now` [s] with the picture `targets`: replans when the follower asks, then takes
// the set-point. The caller has given the follower the own ship's state (PlanFollower::updateOwn).
CycleResult planningCycle(PlanFollower& follower, PlannerAlgorithm& planner, PlannerMode mode, double now,
                          const std::vector<PlannerTarget>& targets, const CycleOptions& options = {});

}  // namespace asv
