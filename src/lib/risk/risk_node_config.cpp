#include "asv_core/risk/risk_node_config.h"

#include <stdexcept>

namespace asv {

RiskConfig riskConfigFromParams(const ParamMap& p) {
  RiskConfig r;
  auto& l = r.level;
  l.t_max_s = p.getDouble("risk_level/t_max", l.t_max_s);
  l.d_min_m = p.getDouble("risk_level/d_min", l.d_min_m);
  l.t_safe_s = p.getDouble("risk_level/t_safe", l.t_safe_s);
  l.d_safe_m = p.getDouble("risk_level/d_safe", l.d_safe_m);
  auto& c = r.cri;
  c.c_dcpa = p.getDouble("cri/c_dcpa", c.c_dcpa);
  c.c_tcpa = p.getDouble("cri/c_tcpa", c.c_tcpa);
  c.c_b = p.getDouble("cri/c_b", c.c_b);
  c.c_d = p.getDouble("cri/c_d", c.c_d);
  c.c_k = p.getDouble("cri/c_k", c.c_k);
  c.dlma_m = p.getDouble("cri/dlma", c.dlma_m);
  c.attention_range_m = p.getDouble("cri/attention_range", c.attention_range_m);
  c.speed_ratio_w = p.getDouble("cri/speed_ratio_w", c.speed_ratio_w);
  c.arena_cb = p.getDouble("cri/arena_cb", c.arena_cb);
  c.peak_bearing_deg = p.getDouble("cri/peak_bearing_deg", c.peak_bearing_deg);
  c.zero_when_diverging = p.getBool("cri/zero_when_diverging", c.zero_when_diverging);
  c.safe_encounter.domain_unit_m = p.getDouble("cri/domain_unit", c.safe_encounter.domain_unit_m);
  c.safe_encounter.turn90_time_s = p.getDouble("cri/turn90_time", c.safe_encounter.turn90_time_s);
  c.safe_encounter.advance_m = p.getDouble("cri/advance", c.safe_encounter.advance_m);
  auto& g = r.colregs;
  g.head_on_half_angle_deg = p.getDouble("colregs/head_on_half_angle_deg", g.head_on_half_angle_deg);
  g.stern_sector_start_deg = p.getDouble("colregs/stern_sector_start_deg", g.stern_sector_start_deg);
  g.max_range_m = p.getDouble("colregs/max_range", g.max_range_m);
  r.validate();
  return r;
}

void RiskNodeConfig::validate() const {
  if (frame_id.empty())
    throw std::invalid_argument("frame_id must not be empty");
  if (!(stale_after > 0.0))
    throw std::invalid_argument("stale_after must be > 0 s");
  if (!(future_tolerance >= 0.0))
    throw std::invalid_argument("future_tolerance must be >= 0 s");
  if (!(odom_timeout > 0.0))
    throw std::invalid_argument("odom_timeout must be > 0 s");
  if (!(min_rate > 0.0 && max_rate > min_rate))
    throw std::invalid_argument("min_rate and max_rate must satisfy 0 < min_rate < max_rate");
  risk.validate();
}

RiskNodeConfig RiskNodeConfig::fromParams(const ParamMap& p) {
  RiskNodeConfig c;
  c.own_ship = p.getString("own_ship", c.own_ship);
  c.frame_id = p.getString("frame_id", c.frame_id);
  c.stale_after = p.getDouble("stale_after", c.stale_after);
  c.future_tolerance = p.getDouble("future_tolerance", c.future_tolerance);
  c.odom_timeout = p.getDouble("odom_timeout", c.odom_timeout);
  c.publish_markers = p.getBool("publish_markers", c.publish_markers);
  c.min_rate = p.getDouble("min_rate", c.min_rate);
  c.max_rate = p.getDouble("max_rate", c.max_rate);
  c.risk = riskConfigFromParams(p);
  c.watch = InputWatchConfig::fromParams(p);
  c.validate();
  return c;
}

}  // namespace asv
