#include "asv_core/planning/planning.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "asv_core/common/units.h"

namespace asv {

double restrictedPassingDistance(const Eigen::Vector2d& position, double length, double speed,
                                 const std::vector<StaticObstacle>& obstacles) {
  double land = std::numeric_limits<double>::infinity();
  for (const StaticObstacle& o : obstacles)
    land = std::min(land, obstacleDistance(o, position, position));
  if (!(land < kOpenWater))
    return 0.0;
  return std::max(kRestrictedPassingFloor, kijimaDomain(length > 0.0 ? length : 100.0, speed).starboard);
}

const char* toString(PlanStatus s) {
  switch (s) {
    case PlanStatus::Ok:
      return "ok";
    case PlanStatus::Fallback:
      return "fallback";
    case PlanStatus::NoSolution:
      break;
  }
  return "no_solution";
}

PlannerTarget toPlannerTarget(const ShipState& target, const TargetRisk& r) {
  PlannerTarget t;
  t.state = target;
  t.risk = r.compliance.risk;
  t.compliant = r.compliance.compliant;
  t.encounter = r.geometry.encounter;
  t.role = r.geometry.role;
  t.cri = r.cri.cri;
  t.tcpa = r.cpa.tcpa;
  t.dcpa = r.cpa.dcpa;
  return t;
}

std::vector<TargetDomain> separationDomains(const PlanningProblem& problem) {
  std::vector<TargetDomain> out;
  if (!(problem.min_separation > 0.0))
    return out;
  const double r = kSeparationMargin * problem.min_separation;
  for (const PlannerTarget& t : problem.targets)
    out.push_back({t.state.id, regularPolygon(t.state.position, r, 36, kPi / 2.0)});  // from due north
  return out;
}

void PlannerAlgorithm::initialize(const ParamMap& config) {
  ParamMap merged = plannerMode(config, name()) == PlannerMode::Paper ? ParamMap{} : seaDefaults();
  for (const auto& kv : config.values())
    merged.set(kv.first, kv.second);
  configure(merged);
  parameters_ = merged;
}

PlannerMode plannerMode(const ParamMap& params, const std::string& algorithm) {
  return parsePlannerMode(params.getString("mode", "sea"), algorithm);
}

PlannerMode parsePlannerMode(const std::string& mode, const std::string& algorithm) {
  if (mode == "sea")
    return PlannerMode::Sea;
  if (mode != "paper")
    throw std::invalid_argument(algorithm + ": mode must be sea or paper, not '" + mode + "'");
  return PlannerMode::Paper;
}

}  // namespace asv
