#include "asv_core/risk/risk_assessment.h"

#include <iterator>
#include <unordered_set>

namespace asv {

RiskAssessor::RiskAssessor(const RiskConfig& cfg) : cfg_(cfg), monitor_(cfg.level) {
  cfg_.validate();
}

TargetRisk RiskAssessor::assess(const ShipState& own, const ShipState& target) {
  TargetRisk r;
  r.id = target.id;
  r.cpa = computeCpa(own, target);
  r.range = r.cpa.range;
  r.geometry = classifyEncounter(own, target, r.cpa, cfg_.colregs);
  const auto held = situation_.find(target.id);
  if (held != situation_.end() && r.geometry.encounter != Encounter::None) {
    r.geometry.encounter = held->second;
    r.geometry.role = ownRole(held->second);
  }
  r.true_bearing = wrapTwoPi(r.geometry.relative_bearing + own.heading);
  r.cri = computeCri(own, target, r.cpa, cfg_.cri, r.geometry.relative_bearing);
  const bool gives_way = r.geometry.role == OwnRole::StandOn || r.geometry.role == OwnRole::BothGiveWay;
  r.compliance = monitor_.update(target.id, r.cpa.tcpa, r.cpa.dcpa, gives_way);
  r.rule = r.compliance.decision == RuleDecision::Rule2 ? 2 : applicableRule(r.geometry.encounter);
  if (r.compliance.risk == RiskLevel::None || r.geometry.encounter == Encounter::None)
    situation_.erase(target.id);
  else
    situation_.emplace(target.id, r.geometry.encounter);  // the first stands
  return r;
}

std::vector<TargetRisk> RiskAssessor::assessAll(const ShipState& own, const std::vector<ShipState>& targets,
                                                bool prune) {
  std::vector<TargetRisk> out;
  out.reserve(targets.size());
  for (const ShipState& t : targets)
    out.push_back(assess(own, t));
  if (prune && monitor_.size() > targets.size()) {
    std::unordered_set<std::string> present;
    for (const ShipState& t : targets)
      present.insert(t.id);
    monitor_.retainOnly(present);
    for (auto it = situation_.begin(); it != situation_.end();)
      it = present.count(it->first) ? std::next(it) : situation_.erase(it);
  }
  return out;
}

}  // namespace asv
