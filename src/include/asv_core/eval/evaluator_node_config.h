// evaluator_node's parameters (asv_sim/config/evaluator_node.yaml), ROS-free: one struct read by
// fromParams(), so that each key and its default is defined once.
#pragma once

#include <string>

#include "asv_core/charts/charts.h"
#include "asv_core/common/param_map.h"
#include "asv_core/eval/evaluation.h"

namespace asv {

struct EvaluatorNodeConfig {
  std::string own_ship = "own";  // id of the own ship in sim/ships
  std::string result;            // path of the result file ("" = do not write)
  std::string geojson;           // path of the run as GeoJSON for a GIS ("" = do not write)
  std::string scenario;          // optional scenario file: name, goals, safety threshold, ship list
  ChartOptions charts;           // charts, chart_cache_dir: the land of the scenario's charts
  std::string planner;           // planner name for the result ("" = from <own>/plan or the scenario)
  int seed = 1;                  // seed for the result (the run's planner/sim seed)
  double time_origin = 1.0e9;    // [s] ROS time of simulation time 0 (sim_node's epoch)
  bool shutdown_at_end = true;   // shut the node down once the result is written
  bool pretty = true;            // indented JSON (false: one line)
  EvaluationConfig evaluation;   // evaluation/ subtree (EvaluationConfig::fromParams' keys)

  void validate() const;  // std::invalid_argument naming the parameter
  static EvaluatorNodeConfig fromParams(const ParamMap& params);
};

}  // namespace asv
