// Risk level and non-compliance flag of Hu et al. (2017), section 2.1: eq. (1)-(2), Algorithm 1 and
// the rule-selection decision of Table 1.
#pragma once

#include <cstdint>
#include <iterator>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "asv_core/risk/cpa.h"

namespace asv {

enum class RiskLevel : uint8_t { None = 0, Collision = 1, Urgent = 2 };

// Table 1: + (no risk, no rule), check (a rule applies), x (Rule 2: other rules may be disregarded).
enum class RuleDecision : uint8_t { NoRule = 0, RuleApplies = 1, Rule2 = 2 };

const char* toString(RiskLevel r);
const char* toString(RuleDecision d);

// The paper leaves the four thresholds to the vessel type and environment. Defaults for a ship in
// open water: a risk of collision when the CPA falls within 1 nm in the next 20 min, urgent within
// 0.5 nm in the next 10 min (t_safe < t_max and d_safe < d_min, as the paper requires).
struct HuRiskConfig {
  double t_max_s = 1200.0;  // [s] t_max of eq. (1)
  double d_min_m = 1852.0;  // [m] d_min of eq. (1)
  double t_safe_s = 600.0;  // [s] t_safe of eq. (2)
  double d_safe_m = 926.0;  // [m] d_safe of eq. (2)
  void validate() const;
};

// Instantaneous level from eq. (1)-(2): 2 when both (1) and (2) hold, 1 when only (1) holds, else 0.
RiskLevel riskLevel(double tcpa, double dcpa, const HuRiskConfig& cfg);

struct ComplianceResult {
  RiskLevel risk = RiskLevel::None;
  bool compliant = true;
  RuleDecision decision = RuleDecision::NoRule;
};

// Table 1.
RuleDecision ruleDecision(RiskLevel risk, bool compliant);

// Algorithm 1, per target: keeps each target's previous risk level. Risk 2 reached straight after
// risk 1 flags the target non-compliant when it was required to act as a give-way vessel (Hu et al.
// 2017, Sec. 2.1: "required to manoeuvre but did not ... as a give-way vessel"): the own ship stands
// on for it, or both give way (Rule 14). A target the own ship must keep out of the way of is not
// flagged: the urgency is then the own ship's doing. Risk 2 from 0 stays compliant (it appeared
// suddenly). Algorithm 1 does not say what risk 2 after risk 2 gives: the flag
// is kept, since nothing has changed that could clear it. Risk 0 or 1 returns Flag = Compliant.
class ComplianceMonitor {
public:
  explicit ComplianceMonitor(const HuRiskConfig& cfg = {});
  ComplianceResult update(const std::string& target_id, double tcpa, double dcpa, bool target_gives_way);
  void forget(const std::string& target_id) { state_.erase(target_id); }
  void clear() { state_.clear(); }
  // Drops the history of every target not in `ids` (tracks that were lost).
  void retainOnly(const std::unordered_set<std::string>& ids) {
    for (auto it = state_.begin(); it != state_.end();)
      it = ids.count(it->first) ? std::next(it) : state_.erase(it);
  }
  size_t size() const { return state_.size(); }
  const HuRiskConfig& config() const { return cfg_; }

private:
  struct State {
    RiskLevel risk = RiskLevel::None;
    bool compliant = true;
  };
  HuRiskConfig cfg_;
  std::unordered_map<std::string, State> state_;
};

}  // namespace asv
