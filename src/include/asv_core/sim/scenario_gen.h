// Scenario generator: format-1 scenarios of the standard encounters, drawn from a seed, for measuring
// planners on situations nobody tuned them for (asv_scenario_gen, make benchmark; docs/evaluation.md).
//
// Each target is placed so that, with both ships holding course and speed, it reaches its closest point
// of approach (CPA) after a drawn time at a drawn distance; its encounter is then confirmed with the same
// classification the risk node and the evaluator use. A draw is refused and drawn again (counted by
// reason) when a target starts too close, the encounter is not the one intended, two targets collide on
// their own, a track or the goal meets land, or no manoeuvre of the own ship could keep the minimum
// separation: a brute-force search over course changes and speed reductions made at the moment the last
// rule-breaking target's breach becomes apparent.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "asv_core/world/scenario.h"

namespace asv {

// The situation families. One target: HeadOn, CrossingGiveWay (target from starboard, own gives way),
// CrossingStandOn (target from port gives way), Overtaking (own overtakes), BeingOvertaken (a faster target
// from astern gives way), RuleBreaker (a target that should give way stands on or turns to port).
// Several targets: Multi (2-5, independent CPA times), Converging (2-5 CPAs within a few minutes of
// each other). Coastal: 1-3 targets with a coast on one side or a channel. The families that probe the
// referee's judgement (docs/evaluation.md): OffsetHeadOn (DCPA 0.3-0.8 nm either side; the target gives
// way or never acts), HeadOnStarboardOccupied (head-on with an anchored ship, a slow ship or a coast on
// the starboard side, a starboard manoeuvre still open), HeadOnCrossingBoundary (8-35 deg off the
// reciprocal, either bow), StandOnRemoteDuty (crossing from port, and a slow ship ahead the own ship
// overtakes 0.5-0.9 nm abeam 20-30 min out), LateGiveWay (a ship that should give way, head-on, from
// port or overtaking, acts only 6 min before the CPA and by 15 deg), RouteBendCrossing (the own route
// bends 30-60 deg either way 5-15 min out, and a ship crossing the new leg from either side meets her
// 5-15 min after the bend).
enum class SituationClass : uint8_t {
  HeadOn,
  CrossingGiveWay,
  CrossingStandOn,
  Overtaking,
  BeingOvertaken,
  RuleBreaker,
  Multi,
  Converging,
  Coastal,
  OffsetHeadOn,
  HeadOnStarboardOccupied,
  HeadOnCrossingBoundary,
  StandOnRemoteDuty,
  LateGiveWay,
  RouteBendCrossing
};
const std::vector<SituationClass>& allSituationClasses();
const char* toString(SituationClass c);
std::optional<SituationClass> situationClassFromString(const std::string& name);

// Every range of the draw; the defaults are the benchmark's (our choice where the literature gives
// none; docs/evaluation.md).
struct GeneratorConfig {
  double own_speed_min_kn = 8.0, own_speed_max_kn = 16.0;
  double speed_ratio_min = 0.3, speed_ratio_max = 2.0;  // target / own speed (crossing, head-on)
  double overtaking_ratio_max = 0.7;                    // the ship overtaken is at most this fast
  double overtaken_ratio_min = 1.3;                     // the ship overtaking is at least this fast
  double tcpa_min_s = 480.0, tcpa_max_s = 1800.0;       // time to the CPA at the start (8-30 min)
  double dcpa_max_m = 0.3 * 1852.0;                     // distance at the CPA (0-0.3 nm)
  int max_targets = 5;                                  // Multi, Converging: 2..max_targets
  double converging_window_s = 180.0;                   // Converging: every CPA within this window
  double rule_breaker_share = 0.2;      // Multi, Converging: share of give-way targets that break the rules
  double three_dof_share = 0.25;        // share of own ships on the 3-DOF wu_asv_40m preset (12 kn)
  double min_separation_m = 926.0;      // the scenario's safety.min_separation_m (0.5 nm)
  double obstacle_clearance_m = 185.2;  // Coastal: safety.min_obstacle_clearance_m (0.1 nm)
  double start_range_min_factor = 2.0;  // ships start at least this x min_separation apart
  double start_range_max_m = 11.0 * 1852.0;  // and inside the classifier's 12 nm horizon
  // RouteBendCrossing: the target must not meet the first leg. Were the own ship to hold it, no risk of
  // collision may form before the bend: a CPA nearer than first_leg_clear_m with a TCPA within
  // first_leg_window_s at some time before the bend (the referee's default entry, 1 nm and 30 min).
  // Otherwise the encounter latches on the first leg (an overtaking, say; Rule 13(d)) and the crossing
  // of the second leg the class draws never forms.
  double first_leg_clear_m = 1852.0;
  double first_leg_window_s = 1800.0;
  double check_dt = 1.0;   // [s] time step of the feasibility search
  int max_redraws = 2000;  // per situation, then std::runtime_error
  void validate() const;
};

struct GeneratedScenario {
  SituationClass situation = SituationClass::HeadOn;
  std::string yaml;                    // the file
  Scenario scenario;                   // the file parsed back: what the checks ran on
  std::map<std::string, int> refused;  // draws refused before this one, by reason
};

// The scenario of situation `index` of the run with `seed`: the same (config, class, seed, index)
// gives the same file, byte for byte. Its name is gen_<class>_s<seed>_<index>.
GeneratedScenario generateScenario(const GeneratorConfig& cfg, SituationClass situation, uint64_t seed,
                                   uint64_t index);

// Whether some manoeuvre of the own ship (course change to either side up to 120 deg from her course
// then, speed kept, halved or stopped), made at `act_time` after holding course and speed (or sailing
// her route, when she has one) until then, keeps every target at least `min_separation` away and, with
// obstacles, keeps `clearance` off them. port_too false: only to starboard (or no course change).
bool manoeuvreExists(const Scenario& s, double act_time, double min_separation, double clearance,
                     double dt = 1.0, bool port_too = true);

}  // namespace asv
