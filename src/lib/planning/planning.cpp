#include "asv_core/planning/planning.h"

namespace asv {

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

}  // namespace asv
