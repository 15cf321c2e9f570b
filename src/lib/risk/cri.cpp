#include "asv_core/risk/cri.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "asv_core/risk/colregs.h"

namespace asv {

void CriConfig::validate() const {
  for (double c : {c_dcpa, c_tcpa, c_b, c_d, c_k})
    if (!std::isfinite(c) || c < 0.0)
      throw std::invalid_argument("cri: weights must be finite and >= 0");
  const double sum = c_dcpa + c_tcpa + c_b + c_d + c_k;
  if (std::fabs(sum - 1.0) > 1e-6)
    throw std::invalid_argument("cri: weights c_dcpa + c_tcpa + c_b + c_d + c_k must sum to 1 (eq. 1), got " +
                                std::to_string(sum));
  if (!std::isfinite(dlma_m) || dlma_m <= 0.0)
    throw std::invalid_argument("cri: dlma_m must be > 0 m");
  if (!std::isfinite(attention_range_m) || attention_range_m <= dlma_m)
    throw std::invalid_argument("cri: attention_range_m must be > dlma_m");
  if (!std::isfinite(speed_ratio_w) || speed_ratio_w <= 0.0)
    throw std::invalid_argument("cri: speed_ratio_w must be > 0");
  if (!std::isfinite(arena_cb) || arena_cb <= 0.0)
    throw std::invalid_argument("cri: arena_cb must be > 0");
  if (!std::isfinite(peak_bearing_deg))
    throw std::invalid_argument("cri: peak_bearing_deg must be finite");
  safe_encounter.validate();
}

double criUDcpa(double dcpa, double d1, double d2) {
  // Eq. (2).
  if (dcpa <= d1)
    return 1.0;
  if (dcpa > d2)
    return 0.0;
  return 0.5 - 0.5 * std::sin(kPi / (d2 - d1) * (dcpa - (d1 + d2) / 2.0));
}

double criUTcpa(double tcpa, double t1, double t2) {
  // Eq. (3), on |TCPA|.
  const double t = std::fabs(tcpa);
  if (t <= t1)
    return 1.0;
  if (t > t2 || t2 <= t1)
    return 0.0;  // t1 < 0 when the DCPA exceeds D1
  return (t2 - t) / (t2 - t1);
}

void criTcpaBreakpoints(double dcpa, double range, double relative_speed, const CriConfig& cfg, double& t1,
                        double& t2) {
  const double inf = std::numeric_limits<double>::infinity();
  const double D1 = cfg.dlma_m, R = cfg.attention_range_m;
  if (relative_speed < kMinRelativeSpeed) {
    // Frozen geometry: the limits of eq. (3) as V_r -> 0. Inside D1 the collision time is unbounded
    // (t1 = inf, U = 1); otherwise t1 = (D - DCPA)/V_r = 0/0 is taken as 0 and t2 -> inf (U -> 1)
    // as long as the DCPA lies within the attention range.
    t1 = dcpa <= D1 ? inf : 0.0;
    t2 = dcpa <= R ? inf : 0.0;
    return;
  }
  // Eq. (3) prints t1 = (D - DCPA) / V_r for DCPA > D1, which makes U_TCPA jump from 0 to a large
  // value as the DCPA crosses D1 (a target passing wider would look more dangerous). The source of the
  // model (Zheng's fuzzy CRI) has (D1 - DCPA) / V_r, continuous at DCPA = D1: we follow that, unless
  // the configuration asks for the printed form.
  const double beyond = cfg.as_printed ? range : D1;
  t1 = dcpa <= D1 ? std::sqrt(D1 * D1 - dcpa * dcpa) / relative_speed : (beyond - dcpa) / relative_speed;
  t2 = dcpa <= R ? std::sqrt(R * R - dcpa * dcpa) / relative_speed : 0.0;
}

double criUBearing(double relative_bearing, const CriConfig& cfg) {
  // Eq. (4) as printed spans [0.5 (sqrt(C_B + 1) - 1), 0.5 (sqrt(C_B + 1) + 1)]; the text requires
  // U_B = 1 at 19 deg and 0 at 199 deg, so subtract the minimum (= 5/17 for the classic C_B = 440/289,
  // the form of Zheng's original membership function).
  const double c = std::cos(relative_bearing - degToRad(cfg.peak_bearing_deg));
  const double printed = 0.5 * (c + std::sqrt(cfg.arena_cb + c * c));
  if (cfg.as_printed)
    return printed;
  const double offset = 0.5 * (std::sqrt(cfg.arena_cb + 1.0) - 1.0);
  return std::clamp(printed - offset, 0.0, 1.0);
}

double criUDistance(double range, const CriConfig& cfg) {
  // Eq. (5): D1 = DLMA, D2 = 2 DLMA.
  const double D1 = cfg.dlma_m, D2 = 2.0 * cfg.dlma_m;
  if (range <= D1)
    return 1.0;
  if (range > D2)
    return 0.0;
  return (D2 - range) / (D2 - D1);
}

double criUSpeedRatio(double k, double course_diff, const CriConfig& cfg) {
  // Eq. (6) as typeset: U_K = 1 / (1 + W / (K sqrt(K^2 + 1) + 2 K sin C)), sin C = |sin|c_t - c_0||.
  if (std::isinf(k))
    return 1.0;  // own ship stopped: any moving target approaches at its full speed
  const double sin_c = std::fabs(std::sin(std::fabs(course_diff)));
  const double den = k * std::sqrt(k * k + 1.0) + 2.0 * k * sin_c;
  if (den <= 0.0)
    return 0.0;  // target stopped
  return 1.0 / (1.0 + cfg.speed_ratio_w / den);
}

CriResult computeCri(const ShipState& own, const ShipState& target, const Cpa& cpa, const CriConfig& cfg) {
  return computeCri(own, target, cpa, cfg, relativeBearing(own, target.position));
}

CriResult computeCri(const ShipState& own, const ShipState& target, const Cpa& cpa, const CriConfig& cfg,
                     double theta) {
  CriResult r;
  const SafeEncounter se = wuSafeEncounter(theta, target.speed, cfg.safe_encounter);
  r.d1 = se.d1_m;
  r.d2 = se.d2_m;
  criTcpaBreakpoints(cpa.dcpa, cpa.range, cpa.relative_speed, cfg, r.t1, r.t2);
  r.speed_ratio = own.speed > 0.0 ? target.speed / own.speed : std::numeric_limits<double>::infinity();
  r.u_dcpa = criUDcpa(cpa.dcpa, r.d1, r.d2);
  r.u_tcpa = criUTcpa(cpa.tcpa, r.t1, r.t2);
  r.u_b = criUBearing(theta, cfg);
  r.u_d = criUDistance(cpa.range, cfg);
  r.u_k = criUSpeedRatio(r.speed_ratio, target.course - own.course, cfg);
  // Eq. (1).
  r.cri = cfg.c_dcpa * r.u_dcpa + cfg.c_tcpa * r.u_tcpa + cfg.c_b * r.u_b + cfg.c_d * r.u_d + cfg.c_k * r.u_k;
  if (cfg.zero_when_diverging && cpa.relative_motion && cpa.tcpa < 0.0)
    r.cri = 0.0;
  // t1/t2 may be infinite for frozen geometry; keep results finite for publishing.
  const double big = 1e9;
  r.t1 = std::min(r.t1, big);
  r.t2 = std::min(r.t2, big);
  if (std::isinf(r.speed_ratio))
    r.speed_ratio = big;
  r.cri = std::clamp(r.cri, 0.0, 1.0);
  return r;
}

}  // namespace asv
