// planner_node's parameters (asv_planning/config/planner_node.yaml), ROS-free: one struct, read by
// fromParams() from the node's private namespace, so that the node, the batch runner and the tests
// share one definition of each key and its default.
#pragma once

#include <string>

#include <Eigen/Core>

#include "asv_core/charts/charts.h"
#include "asv_core/common/input_watch.h"
#include "asv_core/common/param_map.h"
#include "asv_core/planning/plan_follower.h"

namespace asv {

struct PlannerNodeConfig {
  std::string planner = "aco";  // plugin short name; "" = the scenario's choice; "none" = no planning
  std::string mode;          // the plugin's mode (planning.h): "" = its own (planner_params, ~<planner>/mode)
  std::string ship = "own";  // ship this node plans for (frames, plan.ship)
  std::string frame_id = "map";
  std::string scenario;  // optional scenario file: goal, static obstacles, planner_params
  ChartOptions charts;   // charts, chart_cache_dir: the land of the scenario's charts (charts.h)
  bool has_goal = false;
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();  // [m] goal_x, goal_y (both or neither)
  double lockstep_time_budget = 10.0;  // [s] follower.time_budget in lockstep (the simulation waits)
  double overrun_factor = 2.0;    // a plan that took longer than this x time_budget is discarded: fallback
  double fault_plan_delay = 0.0;  // [s, wall] fault injection (tests): sleep this long in every plan
  double setpoint_rate = 1.0;     // [Hz] set-points are re-sent this often
  double stale_after = 10.0;      // [s] risk/targets older than this are ignored
  bool distributed = false;       // dssa, dssa_plus: exchange intentions with the other DSSA ships
  PlanFollowerConfig follower;    // replanning, fallback and own-ship limits (the same keys, top level)
  InputWatchConfig watch;         // watch/*: odometry, risk and targets stale after watch/input_timeout
  // watch/upstream_nodes: nodes (by name, any namespace) whose ERROR alarm on `alarms` means the
  // picture is incomplete: degraded operation as for a stale input
  std::vector<std::string> upstream_nodes{"tracker", "risk_node"};
  // Aids to navigation (AIS message 21, aids_to_navigation): static hazards every plan keeps at least
  // max(aid_clearance, min_obstacle_clearance_m) from. 185.2 m (a cable) by default: a buoy or beacon
  // stands on shoal water.
  bool use_aids = true;
  double aid_clearance = 185.2;  // [m]

  // Throws std::invalid_argument naming the first value out of range.
  void validate() const;
  // Keys: the field names (goal as goal_x, goal_y) and PlanFollowerConfig's; the plugin's subtree
  // <planner>/ and exchange/ are left to their readers.
  static PlannerNodeConfig fromParams(const ParamMap& params);
};

}  // namespace asv
