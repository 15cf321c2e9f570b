#include "asv_core/eval/evaluator_node_config.h"

#include <cmath>
#include <stdexcept>

namespace asv {

void EvaluatorNodeConfig::validate() const {
  if (own_ship.empty())
    throw std::invalid_argument("own_ship must be set");
  if (seed < 0)
    throw std::invalid_argument("seed must be >= 0");
  if (!std::isfinite(time_origin))
    throw std::invalid_argument("time_origin must be a finite number of seconds");
  evaluation.validate();
}

EvaluatorNodeConfig EvaluatorNodeConfig::fromParams(const ParamMap& p) {
  EvaluatorNodeConfig c;
  c.own_ship = p.getString("own_ship", c.own_ship);
  c.result = p.getString("result", c.result);
  c.geojson = p.getString("geojson", c.geojson);
  c.scenario = p.getString("scenario", c.scenario);
  c.charts = ChartOptions::fromParams(p);
  c.planner = p.getString("planner", c.planner);
  c.seed = p.getInt("seed", c.seed);
  c.time_origin = p.getDouble("time_origin", c.time_origin);
  c.shutdown_at_end = p.getBool("shutdown_at_end", c.shutdown_at_end);
  c.pretty = p.getBool("pretty", c.pretty);
  c.evaluation = EvaluationConfig::fromParams(p.sub("evaluation"));  // rejects its unknown keys
  c.validate();
  return c;
}

}  // namespace asv
