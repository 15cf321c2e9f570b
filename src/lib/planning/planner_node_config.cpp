#include "asv_core/planning/planner_node_config.h"

#include <stdexcept>

namespace asv {

void PlannerNodeConfig::validate() const {
  if (!(lockstep_time_budget > 0))
    throw std::invalid_argument("lockstep_time_budget must be > 0 s");
  if (!(overrun_factor >= 1))
    throw std::invalid_argument("overrun_factor must be >= 1");
  if (!(fault_plan_delay >= 0 && fault_plan_delay <= 60))
    throw std::invalid_argument("fault_plan_delay must be in [0, 60] s");
  if (!(setpoint_rate > 0))
    throw std::invalid_argument("setpoint_rate must be > 0 Hz");
  if (!(stale_after > 0))
    throw std::invalid_argument("stale_after must be > 0 s");
  if (!goal.allFinite())
    throw std::invalid_argument("goal_x and goal_y must be finite");
  if (!(aid_clearance >= 0 && aid_clearance <= 5000))
    throw std::invalid_argument("aid_clearance must be in [0, 5000] m");
  follower.validate();
}

PlannerNodeConfig PlannerNodeConfig::fromParams(const ParamMap& p) {
  PlannerNodeConfig c;
  c.planner = p.getString("planner", c.planner);
  c.mode = p.getString("mode", c.mode);
  c.ship = p.getString("ship", c.ship);
  c.frame_id = p.getString("frame_id", c.frame_id);
  c.scenario = p.getString("scenario", c.scenario);
  c.charts = ChartOptions::fromParams(p);
  if (p.has("goal_x") != p.has("goal_y"))
    throw std::invalid_argument("give both goal_x and goal_y (metres, map frame)");
  c.has_goal = p.has("goal_x");
  c.goal = {p.getDouble("goal_x", 0.0), p.getDouble("goal_y", 0.0)};
  c.lockstep_time_budget = p.getDouble("lockstep_time_budget", c.lockstep_time_budget);
  c.overrun_factor = p.getDouble("overrun_factor", c.overrun_factor);
  c.fault_plan_delay = p.getDouble("fault_plan_delay", c.fault_plan_delay);
  c.setpoint_rate = p.getDouble("setpoint_rate", c.setpoint_rate);
  c.stale_after = p.getDouble("stale_after", c.stale_after);
  c.distributed = p.getBool("distributed", c.distributed);
  c.follower = PlanFollowerConfig::fromParams(p);
  c.watch = InputWatchConfig::fromParams(p);
  c.upstream_nodes = p.getStringList("watch/upstream_nodes", c.upstream_nodes);
  c.use_aids = p.getBool("use_aids", c.use_aids);
  c.aid_clearance = p.getDouble("aid_clearance", c.aid_clearance);
  c.validate();
  return c;
}

}  // namespace asv
