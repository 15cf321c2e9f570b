#include "asv_core/risk/colregs.h"

#include <cmath>
#include <stdexcept>

namespace asv {

const char* toString(Encounter e) {
  switch (e) {
    case Encounter::HeadOn:
      return "head_on";
    case Encounter::CrossingGiveWay:
    case Encounter::CrossingStandOn:
      return "crossing";
    case Encounter::Overtaking:
      return "overtaking";
    case Encounter::BeingOvertaken:
      return "being_overtaken";
    case Encounter::None:
      break;
  }
  return "none";
}

const char* toString(OwnRole r) {
  switch (r) {
    case OwnRole::GiveWay:
    case OwnRole::BothGiveWay:
      return "give_way";
    case OwnRole::StandOn:
      return "stand_on";
    case OwnRole::None:
      break;
  }
  return "none";
}

OwnRole ownRole(Encounter e) {
  switch (e) {
    case Encounter::HeadOn:
      return OwnRole::BothGiveWay;
    case Encounter::CrossingGiveWay:
    case Encounter::Overtaking:
      return OwnRole::GiveWay;
    case Encounter::CrossingStandOn:
    case Encounter::BeingOvertaken:
      return OwnRole::StandOn;
    case Encounter::None:
      break;
  }
  return OwnRole::None;
}

int applicableRule(Encounter e) {
  switch (e) {
    case Encounter::HeadOn:
      return 14;
    case Encounter::CrossingGiveWay:
      return 15;
    case Encounter::Overtaking:
      return 13;
    case Encounter::CrossingStandOn:
    case Encounter::BeingOvertaken:
      return 17;
    case Encounter::None:
      break;
  }
  return 0;
}

void ColregsConfig::validate() const {
  if (!(head_on_half_angle_deg > 0.0 && head_on_half_angle_deg < 90.0))
    throw std::invalid_argument("colregs: head_on_half_angle_deg must be in (0, 90) deg");
  if (!(stern_sector_start_deg > 90.0 && stern_sector_start_deg < 180.0))
    throw std::invalid_argument("colregs: stern_sector_start_deg must be in (90, 180) deg");
  if (!(max_range_m > 0.0) || !std::isfinite(max_range_m))
    throw std::invalid_argument("colregs: max_range_m must be finite and > 0 m");
}

double relativeBearing(const ShipState& from, const Eigen::Vector2d& to) {
  return wrapTwoPi(trueBearing(from.position, to) - from.heading);
}

EncounterGeometry classifyEncounter(const ShipState& own, const ShipState& target, const Cpa& cpa,
                                    const ColregsConfig& cfg) {
  EncounterGeometry g;
  g.relative_bearing = relativeBearing(own, target.position);
  g.aspect = relativeBearing(target, own.position);
  if (!cpa.relative_motion || cpa.tcpa < 0.0 || cpa.range > cfg.max_range_m)
    return g;

  const double head_on = degToRad(cfg.head_on_half_angle_deg);
  const double stern_lo = degToRad(cfg.stern_sector_start_deg);
  const double stern_hi = kTwoPi - stern_lo;
  auto ahead = [&](double rb) { return rb < head_on || rb > kTwoPi - head_on; };
  auto astern = [&](double rb) { return rb > stern_lo && rb < stern_hi; };

  if (ahead(g.relative_bearing) && ahead(g.aspect)) {
    g.encounter = Encounter::HeadOn;
  } else if (astern(g.aspect) && !astern(g.relative_bearing)) {
    g.encounter = Encounter::Overtaking;  // the own ship comes up from the target's stern sector
  } else if (astern(g.relative_bearing) && !astern(g.aspect)) {
    g.encounter = Encounter::BeingOvertaken;
  } else if (astern(g.relative_bearing) && astern(g.aspect)) {
    // Each abaft the other's beam yet closing: stern-to-stern geometry that only drift produces.
    // No rule assigns roles; it stays None so that no planner acts on a rule that does not exist.
    g.encounter = Encounter::None;
  } else if (g.relative_bearing < kPi) {
    g.encounter = Encounter::CrossingGiveWay;  // target on the starboard side (Rule 15)
  } else {
    g.encounter = Encounter::CrossingStandOn;
  }
  g.role = ownRole(g.encounter);
  return g;
}

}  // namespace asv
