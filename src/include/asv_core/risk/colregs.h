// COLREGs geometry: relative bearing, aspect, and the encounter classification.
#pragma once

#include <string>

#include "asv_core/common/types.h"
#include "asv_core/risk/cpa.h"

namespace asv {

enum class Encounter : uint8_t {
  None = 0,             // no encounter: diverging, out of range, or no relative motion
  HeadOn = 1,           // Rule 14: reciprocal or nearly reciprocal courses
  CrossingGiveWay = 2,  // Rule 15: target on the own starboard side, own ship keeps out of the way
  CrossingStandOn = 3,  // Rule 15/17: target on the own port side, own ship stands on
  Overtaking = 4,       // Rule 13: the own ship overtakes the target
  BeingOvertaken = 5,   // Rule 13/17: the target overtakes the own ship
};

enum class OwnRole : uint8_t {
  None = 0,
  GiveWay = 1,      // Rules 13, 15, 16
  StandOn = 2,      // Rule 17
  BothGiveWay = 3,  // Rule 14: each alters course to starboard
};

// The names every output uses (the run result's encounter and own_role, messages, logs, the scenario
// generator): head_on | crossing | overtaking | being_overtaken | none, and give_way | stand_on | none.
// A crossing's side is its role; head-on, each ship gives way (Rule 14): give_way.
const char* toString(Encounter e);
const char* toString(OwnRole r);
OwnRole ownRole(Encounter e);
// The own ship has to keep out of the way (Rules 13-16), alone or, head-on, with the other ship (Rule 14).
inline bool givesWay(OwnRole r) {
  return r == OwnRole::GiveWay || r == OwnRole::BothGiveWay;
}
// The rule that governs the own ship in this encounter: 13, 14, 15 (give-way crossing, with 16),
// 17 (stand-on), 0 for none.
int applicableRule(Encounter e);

// Thresholds (degrees at the configuration edge, as the papers state them).
struct ColregsConfig {
  // Head-on: each ship sees the other within +-15 deg of its bow (Wu et al. 2022 section 2.1: relative
  // bearing < 15 or > 345 deg; required of both ships so that the courses are nearly reciprocal).
  double head_on_half_angle_deg = 15.0;
  // Stern sector from 112.5 to 247.5 deg relative (22.5 deg abaft the beam, Rule 13; Hu et al. 2017
  // Fig. 1): a ship seen from another inside it is overtaking that other.
  double stern_sector_start_deg = 112.5;
  // Beyond this range no encounter is classified [m] (12 nm, the attention horizon t2 of Wu eq. 3).
  double max_range_m = 12.0 * 1852.0;
  void validate() const;
};

// Relative bearing [rad, 0..2 pi) of `to` seen from `from` (clockwise from from's heading).
double relativeBearing(const ShipState& from, const Eigen::Vector2d& to);

struct EncounterGeometry {
  double relative_bearing = 0.0;  // [rad] of the target from the own heading, [0, 2 pi)
  double aspect = 0.0;            // [rad] relative bearing of the own ship from the target's heading
  Encounter encounter = Encounter::None;
  OwnRole role = OwnRole::None;
};

// Classifies the encounter from the own ship's point of view. A pair that is diverging (TCPA < 0),
// has no relative motion, or is farther than max_range_m is None.
EncounterGeometry classifyEncounter(const ShipState& own, const ShipState& target, const Cpa& cpa,
                                    const ColregsConfig& cfg);

}  // namespace asv
