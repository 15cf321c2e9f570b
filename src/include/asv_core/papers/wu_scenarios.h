// The simulation situation of Wu et al. (2022), section 4, as planning problems for the GA planner, and a
// kinematic closed-loop rollout to measure closest distances until the 3-DOF simulation exists.
//
// The paper gives the ASV (Table 1: L 40.3 m, B 13.5 m, d 3.22 m, 766.4 t), the GA settings, the CRI
// weights and, per encounter, some headings, distances and times; it gives no speeds and no positions
// beyond those. Everything else is reconstructed here (see wu_scenarios.cpp and docs/results/ga.md).
#pragma once

#include <string>
#include <vector>

#include "asv_core/planning/ga/ga_planner.h"
#include "asv_core/planning/planning.h"
#include "asv_core/risk/cri.h"

namespace asv {

constexpr double kWuAsvLength = 40.3;      // [m] Table 1
constexpr double kWuAsvSpeed = 6.1738;     // [m/s] 12 kn: steady speed of the wu_asv_40m vessel preset
constexpr double kWuAsvTurn90Time = 18.9;  // [s] 35 deg rudder from 12 kn, wu_asv_40m preset (3-DOF model)
constexpr double kWuAsvAdvance = 89.9;     // [m] advance at 90 deg heading change in that turn

// The CRI of cri.h with its distances scaled to the 40.3 m ASV (values and reasons in wu_scenarios.cpp).
CriConfig wuAsvCriConfig();
// The paper's GA settings (section 4) with wuAsvCriConfig().
GaConfig wuAsvGaConfig();

// Section 4 encounters at the moment the CRI first exceeds the threshold. Own ship at the origin
// sailing north (000 deg) at kWuAsvSpeed towards a goal 3 km ahead. Target ids "ts1".."ts4".
PlanningProblem wuHeadOn();       // 1) TS1 400 m dead ahead on 180 deg
PlanningProblem wuCrossing();     // 2) TS2 (270 deg) from starboard, TS3 (090 deg) from port
PlanningProblem wuOvertaking();   // 3) TS4 ahead on a near-parallel course, slower
PlanningProblem wuFourTargets();  // all four at once (benchmark, several-target rule)

struct RolloutTarget {
  std::string id;
  double min_distance = 0.0;  // [m] closest distance over the rollout
  double min_time = 0.0;      // [s] when
};
struct RolloutResult {
  std::vector<RolloutTarget> targets;
  double first_alteration = 0.0;  // [rad] course set-point minus original course at the first decision
  double first_cri = 0.0;         // largest CRI on the original course at the first decision
  double cri_after = 0.0;  // largest CRI (eq. 1, with Fig. 3's zeroing) one step after it, actual heading
  std::vector<double> alterations;  // [rad] set-point minus course to goal, per planning step
  double final_course_error = 0.0;  // [rad] set-point minus course to goal at the end
};

// Closed-loop kinematic rollout: every dt the planner gets the current state, the own ship takes the
// course set-point at once (no turning dynamics) at constant speed, the targets keep course and speed.
// `cri` scores the CRIs reported in the result.
RolloutResult rolloutKinematic(const PlanningProblem& problem, PlannerAlgorithm& planner, double dt,
                               double duration, const CriConfig& cri = wuAsvCriConfig());

}  // namespace asv
