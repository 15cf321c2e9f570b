#include "asv_core/risk/domain.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "asv_core/common/units.h"

namespace asv {

void HexagonDomainConfig::validate() const {
  for (double v : {a, b, c, d, e})
    if (!std::isfinite(v) || v <= 0.0)
      throw std::invalid_argument("hexagon domain: a, b, c, d, e must be finite and > 0 m");
  if (b >= a)
    throw std::invalid_argument("hexagon domain: b (full-width extent ahead) must be < a (bow)");
}

HexagonDomain::HexagonDomain(const HexagonDomainConfig& cfg) : cfg_(cfg) {
  cfg_.validate();
  local_ << cfg.a, cfg.b, 0.0, -cfg.d, 0.0, cfg.b,  // forward
      0.0, cfg.c, cfg.c, 0.0, -cfg.e, -cfg.e;       // starboard
}

Polygon HexagonDomain::polygon(const Eigen::Vector2d& centre, double course) const {
  const Eigen::Vector2d fwd(std::sin(course), std::cos(course));
  const Eigen::Vector2d stbd(std::cos(course), -std::sin(course));
  Polygon poly(6);
  for (int i = 0; i < 6; ++i)
    poly[i] = centre + fwd * local_(0, i) + stbd * local_(1, i);
  return poly;
}

bool HexagonDomain::contains(const Eigen::Vector2d& centre, double course, const Eigen::Vector2d& p) const {
  // Rotate p into the ship frame and test there: cheaper than building the polygon.
  const Eigen::Vector2d rel = p - centre;
  const double f = rel.x() * std::sin(course) + rel.y() * std::cos(course);
  const double s = rel.x() * std::cos(course) - rel.y() * std::sin(course);
  if (f > cfg_.a || f < -cfg_.d || s > cfg_.c || s < -cfg_.e)
    return false;
  Polygon local(6);
  for (int i = 0; i < 6; ++i)
    local[i] = {local_(1, i), local_(0, i)};
  return pointInPolygon(local, {s, f});
}

double wuDomainNm(double q_deg) {
  const double q = wrapDeg360(q_deg);
  // Eq. (9). The paper leaves q = 112.5 and q = 247.5 open; they join the following sector here.
  if (q < 112.5)
    return 0.85 - q / 180.0 * 0.2;
  if (q <= 180.0)
    return 1.18 - q / 180.0 * 0.73;
  if (q < 247.5)
    return 1.02 - (360.0 - q) / 180.0 * 0.57;
  return 0.85 - (360.0 - q) / 180.0 * 0.3;
}

double wuDomainStepNm(double theta_deg) {
  const double t = wrapDeg360(theta_deg);
  // Eq. (8); the boundaries 112.5 and 247.5 join the following sector.
  if (t < 112.5)
    return 0.85;
  if (t <= 247.5)
    return 0.45;
  return 0.70;
}

double wuRhoNm(double theta_deg) {
  const double t = wrapDeg360(theta_deg);
  // Eq. (12), as typeset: the sectors do not join continuously at 112.5 and 247.5 deg; the shared
  // boundary belongs to the earlier sector.
  if (t <= 112.5)
    return 1.1 - t / 180.0 * 0.2;
  if (t <= 180.0)
    return 1.0 - t / 180.0 * 0.4;
  if (t <= 247.5)
    return 1.0 - (360.0 - t) / 180.0 * 0.4;
  return 1.1 - (360.0 - t) / 180.0 * 0.4;
}

void SafeEncounterConfig::validate() const {
  if (!std::isfinite(domain_unit_m) || domain_unit_m <= 0.0)
    throw std::invalid_argument("safe encounter: domain_unit_m must be > 0 m");
  if (!std::isfinite(turn90_time_s) || turn90_time_s < 0.0)
    throw std::invalid_argument("safe encounter: turn90_time_s must be >= 0 s");
  if (!std::isfinite(advance_m) || advance_m < 0.0)
    throw std::invalid_argument("safe encounter: advance_m must be >= 0 m");
}

SafeEncounter wuSafeEncounter(double theta, double target_speed, const SafeEncounterConfig& cfg) {
  SafeEncounter s;
  s.rho_m = wuRhoNm(radToDeg(theta)) * cfg.domain_unit_m;                    // eq. (12)
  s.d1_m = 1.5 * s.rho_m;                                                    // eq. (10)
  s.td_m = std::max(0.0, target_speed) * cfg.turn90_time_s + cfg.advance_m;  // Td = V_T t + Ad
  s.d2_m = s.d1_m + s.td_m;                                                  // eq. (11)
  return s;
}

KijimaDomain kijimaDomain(double length_m, double speed_mps) {
  const double v_kn = std::max(1.0, mpsToKnots(speed_mps));
  const double lg = std::log10(v_kn);
  const double k_ad = std::pow(10.0, 0.3591 * lg + 0.0952);
  const double k_dt = std::pow(10.0, 0.5441 * lg - 0.0795);
  const double r = std::sqrt(k_ad * k_ad + 0.25 * k_dt * k_dt);
  return {(1.0 + 1.34 * r) * length_m, (1.0 + 0.67 * r) * length_m, (0.2 + k_dt) * length_m,
          (0.2 + 0.75 * k_dt) * length_m};
}

}  // namespace asv
