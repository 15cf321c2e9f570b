// The whole per-target risk picture: CPA, Wu's CRI, Hu's risk level and compliance flag, and the
// COLREGs encounter with the own ship's role. Used by risk_node and by the batch runner.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "asv_core/risk/colregs.h"
#include "asv_core/risk/cpa.h"
#include "asv_core/risk/cri.h"
#include "asv_core/risk/risk_level.h"

namespace asv {

struct RiskConfig {
  HuRiskConfig level;
  CriConfig cri;
  ColregsConfig colregs;
  void validate() const {
    level.validate();
    cri.validate();
    colregs.validate();
  }
};

struct TargetRisk {
  std::string id;
  Cpa cpa;
  CriResult cri;
  EncounterGeometry geometry;
  ComplianceResult compliance;
  double range = 0.0;         // [m]
  double true_bearing = 0.0;  // [rad] nautical, from the own ship
  int rule = 0;               // COLREGs rule governing the own ship; 2 when Rule 2(b) overrides
};

class RiskAssessor {
public:
  explicit RiskAssessor(const RiskConfig& cfg = {});
  // Assesses one target and updates its compliance history. The encounter stands as it was when the
  // risk of collision arose (Hu's risk level 1 or 2), while that risk lasts and the target is not past:
  // a crossing does not turn into an overtaking, or a head-on into a crossing, because one of the ships
  // altered course (Rule 13(d) states it for overtaking; the same reading for the others). Both the
  // compliance history and the standing encounter are kept by the target's id: ids must be unique, and a
  // ship whose track is renumbered starts afresh.
  TargetRisk assess(const ShipState& own, const ShipState& target);
  // Assesses every target; forgets the history of targets no longer present when prune is set.
  std::vector<TargetRisk> assessAll(const ShipState& own, const std::vector<ShipState>& targets,
                                    bool prune = true);
  void reset() {
    monitor_.clear();
    situation_.clear();
  }
  const RiskConfig& config() const { return cfg_; }

private:
  RiskConfig cfg_;
  ComplianceMonitor monitor_;
  std::unordered_map<std::string, Encounter> situation_;  // per target: the encounter the risk arose in
};

}  // namespace asv
