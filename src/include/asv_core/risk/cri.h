// Fuzzy collision risk index of Wu et al. (2022), section 2.3, eq. (1)-(6), with the safe encounter
// distances d1, d2 of eq. (10)-(12) as the DCPA breakpoints.
#pragma once

#include "asv_core/common/types.h"
#include "asv_core/risk/cpa.h"
#include "asv_core/risk/domain.h"

namespace asv {

struct CriConfig {
  // Weights of eq. (1); the paper's values, which sum to 1.
  double c_dcpa = 0.40;
  double c_tcpa = 0.367;
  double c_b = 0.033;
  double c_d = 0.167;
  double c_k = 0.033;
  // D1 = DLMA, the distance of last-minute action [m]; D2 = 2 DLMA (eq. 5); also D1 of t1 in eq. (3).
  // The paper gives no value: 1 nm suits a sea-going ship (about 12 ship lengths of a 150 m hull,
  // the usual rule of thumb); scale it to the own ship for small craft.
  double dlma_m = 1852.0;
  // The 12 in t2 of eq. (3) [m]: 12 nm, the distance at which a navigator starts watching a target.
  double attention_range_m = 12.0 * 1852.0;
  // W of eq. (6).
  double speed_ratio_w = 2.0;
  // C_B of eq. (4), the arena-model constant (R_B + D_B) / D_B^2. 440/289 is the classic value
  // (Zheng's arena) for which eq. (4), shifted by 5/17, spans exactly [0, 1].
  double arena_cb = 440.0 / 289.0;
  // Relative bearing of the highest risk (U_B = 1) [deg]; the lowest lies opposite (paper: 19 and 199).
  double peak_bearing_deg = 19.0;
  // Fig. 3: with TCPA < 0 the ships have passed and no action is needed; CRI is then 0.
  bool zero_when_diverging = true;
  // Eq. (3) and (4) exactly as Wu et al. (2022) print them (the GA's paper mode): t1 = (D - DCPA) / V_r
  // for DCPA > D1, and U_B without the shift that maps it onto [0, 1] (it then spans [0.29, 1.29] for
  // the classic C_B, so the CRI can exceed 1 by up to 0.01). false: both corrected, see cri.cpp.
  bool as_printed = false;
  SafeEncounterConfig safe_encounter;
  void validate() const;
};

struct CriResult {
  double cri = 0.0;                                                    // eq. (1), in [0, 1]
  double u_dcpa = 0.0, u_tcpa = 0.0, u_b = 0.0, u_d = 0.0, u_k = 0.0;  // eq. (2)-(6)
  double d1 = 0.0, d2 = 0.0;                                           // [m] DCPA breakpoints, eq. (10)-(11)
  double t1 = 0.0, t2 = 0.0;                                           // [s] TCPA breakpoints of eq. (3)
  double speed_ratio = 0.0;                                            // K = V_T / V_O
};

// Membership functions, each in [0, 1] (U_B up to 1.29 with as_printed).
double criUDcpa(double dcpa, double d1, double d2);                 // eq. (2)
double criUTcpa(double tcpa, double t1, double t2);                 // eq. (3)
double criUBearing(double relative_bearing, const CriConfig& cfg);  // eq. (4), bearing in rad
double criUDistance(double range, const CriConfig& cfg);            // eq. (5)
// eq. (6): K = V_T / V_O, course_diff = c_t - c_0 [rad].
double criUSpeedRatio(double k, double course_diff, const CriConfig& cfg);
// t1, t2 of eq. (3) [s] for the given DCPA, current range and relative speed.
void criTcpaBreakpoints(double dcpa, double range, double relative_speed, const CriConfig& cfg, double& t1,
                        double& t2);

CriResult computeCri(const ShipState& own, const ShipState& target, const Cpa& cpa, const CriConfig& cfg);
// The same with the target's relative bearing [rad] already known (saves an atan2 per target).
CriResult computeCri(const ShipState& own, const ShipState& target, const Cpa& cpa, const CriConfig& cfg,
                     double relative_bearing);

}  // namespace asv
