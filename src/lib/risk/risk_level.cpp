#include "asv_core/risk/risk_level.h"

#include <cmath>
#include <stdexcept>

namespace asv {

const char* toString(RiskLevel r) {
  switch (r) {
    case RiskLevel::Collision:
      return "collision";
    case RiskLevel::Urgent:
      return "urgent";
    case RiskLevel::None:
      break;
  }
  return "none";
}

const char* toString(RuleDecision d) {
  switch (d) {
    case RuleDecision::RuleApplies:
      return "rule_applies";
    case RuleDecision::Rule2:
      return "rule_2";
    case RuleDecision::NoRule:
      break;
  }
  return "no_rule";
}

void HuRiskConfig::validate() const {
  for (double v : {t_max_s, d_min_m, t_safe_s, d_safe_m})
    if (!std::isfinite(v) || v <= 0.0)
      throw std::invalid_argument("risk level: t_max_s, d_min_m, t_safe_s, d_safe_m must be > 0");
  if (t_safe_s >= t_max_s)
    throw std::invalid_argument("risk level: t_safe_s must be < t_max_s (Hu et al. 2017)");
  if (d_safe_m >= d_min_m)
    throw std::invalid_argument("risk level: d_safe_m must be < d_min_m (Hu et al. 2017)");
}

RiskLevel riskLevel(double tcpa, double dcpa, const HuRiskConfig& cfg) {
  const bool eq1 = tcpa >= 0.0 && tcpa <= cfg.t_max_s && dcpa <= cfg.d_min_m;    // eq. (1)
  const bool eq2 = tcpa >= 0.0 && tcpa <= cfg.t_safe_s && dcpa <= cfg.d_safe_m;  // eq. (2)
  if (eq1 && eq2)
    return RiskLevel::Urgent;
  if (eq1)
    return RiskLevel::Collision;
  return RiskLevel::None;
}

RuleDecision ruleDecision(RiskLevel risk, bool compliant) {
  if (risk == RiskLevel::None)
    return RuleDecision::NoRule;
  return compliant ? RuleDecision::RuleApplies : RuleDecision::Rule2;
}

ComplianceMonitor::ComplianceMonitor(const HuRiskConfig& cfg) : cfg_(cfg) {
  cfg_.validate();
}

ComplianceResult ComplianceMonitor::update(const std::string& target_id, double tcpa, double dcpa,
                                           bool target_gives_way) {
  State& s = state_[target_id];
  ComplianceResult out;
  out.risk = riskLevel(tcpa, dcpa, cfg_);
  switch (out.risk) {
    case RiskLevel::Urgent:
      if (s.risk == RiskLevel::Collision)
        out.compliant = !target_gives_way;  // Algorithm 1, lines 10-11, for a give-way target
      else if (s.risk == RiskLevel::None)
        out.compliant = true;  // lines 8-9
      else
        out.compliant = s.compliant;  // risk 2 after 2: not covered by Algorithm 1; keep the flag
      break;
    default:
      out.compliant = true;  // lines 5-6 and 13-14
  }
  out.decision = ruleDecision(out.risk, out.compliant);
  s.risk = out.risk;
  s.compliant = out.compliant;
  return out;
}

}  // namespace asv
