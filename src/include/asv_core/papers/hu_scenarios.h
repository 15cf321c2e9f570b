// The simulation situations of Hu et al. (2017), section 4 (Figs. 4-6), as PlanningProblems. The paper's
// figures are lost and its text gives no coordinates, speeds or distances, so the geometry below is
// reconstructed from the prose; every number is our choice and is stated where it is set. Common to
// all: ENU metres, own ship at the origin heading due east (090, as Fig. 2: "from waypoint A towards
// waypoint C due east") at 12 kn, the risk picture (eq. 1-2, Algorithm 1, encounter and role) filled
// by RiskAssessor with its default thresholds (t_max 20 min, d_min 1 nm, t_safe 10 min, d_safe 0.5 nm).
#pragma once

#include "asv_core/planning/planning.h"
#include "asv_core/risk/risk_assessment.h"

namespace asv {

// Own speed of every situation [m/s] (12 kn).
constexpr double kHuOwnSpeed = 12.0 * kMpsPerKnot;

// Fills risk, compliance, encounter, role, CRI, TCPA and DCPA of every target from the ship states,
// through `assessor` (whose compliance history it updates). Targets slower than 0.1 m/s are static
// objects: no COLREGs encounter or role (the rules govern vessels under way), so the own ship keeps
// clear of them whatever the zones say.
void assessTargets(PlanningProblem& problem, RiskAssessor& assessor);

// Fig. 4(a), overtaking in open water: target 1.5 nm dead ahead on the same course at 6 kn, goal 10 nm
// east. TCPA 900 s, DCPA 0: risk 1, the own ship overtakes (Rule 13) and gives way; starboard expected.
PlanningProblem huOvertakingOpenWater();

// Fig. 4(b), the same overtaking in restricted water: land to starboard, a coast whose edge runs
// 0.6 nm south of the track (from 2 nm west to 12 nm east, 5 nm deep). A starboard pass at d_min = 1 nm
// from the target would put the own ship ashore, so port is expected.
PlanningProblem huOvertakingRestrictedWater();

// Fig. 5, three moving targets and one static obstacle; goal 12 nm east.
//  B: 1.5 nm ahead, same course, 6 kn: overtaken (risk 1 now), Fig. 5(a).
//  A: from starboard, heading north at 10 kn, crossing the track 6 nm ahead in 30 min (no risk yet,
//     TCPA beyond t_max): the crossing of Fig. 5(b), in which the own ship gives way.
//  C: 8 kn heading west on a track 1.5 nm south of ours, 14 nm ahead: clear of the straight track, but
//     in the way of a small starboard alteration round D (Fig. 5(c)).
//  D: a static target (drifting buoy, zero speed) on the track 9 nm ahead.
// The paper's snapshots (a)-(d) come from re-planning as the targets move; this is the situation at
// t = 0, which the planner must solve with all four in view.
PlanningProblem huMultiTarget();

// Fig. 6, a give-way target that does not give way: target A 3 nm east and 3 nm north (on the own
// port bow) heading south at 12 kn, collision course (TCPA 900 s, DCPA 0). The own ship is stand-on
// (Rule 17, crossing from port); both keep course and speed for `elapsed_s` seconds, the risk being
// assessed every 10 s (Algorithm 1). At elapsed_s = 0 the target is compliant at risk 1 (stand on);
// from 300 s its TCPA is within t_safe, risk 2 follows risk 1 and the flag turns non-compliant
// (Rule 2(b), evade).
PlanningProblem huNonCompliantTarget(double elapsed_s = 0.0);

}  // namespace asv
