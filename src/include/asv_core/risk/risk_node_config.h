// risk_node's parameters (asv_risk/config/risk_node.yaml), ROS-free: one struct read by fromParams(),
// so that each key and its default is defined once.
#pragma once

#include <string>

#include "asv_core/common/input_watch.h"
#include "asv_core/common/param_map.h"
#include "asv_core/risk/risk_assessment.h"

namespace asv {

// Keys risk_level/{t_max,d_min,t_safe,d_safe}, cri/{c_dcpa,c_tcpa,c_b,c_d,c_k,dlma,attention_range,
// speed_ratio_w,arena_cb,peak_bearing_deg,zero_when_diverging,domain_unit,turn90_time,advance},
// colregs/{head_on_half_angle_deg,stern_sector_start_deg,max_range}; validated.
RiskConfig riskConfigFromParams(const ParamMap& params);

struct RiskNodeConfig {
  std::string own_ship = "own";   // own ship name (labels, RiskAssessment.own_ship)
  std::string frame_id = "map";   // working frame; other frames are transformed through tf2
  double stale_after = 60.0;      // [s] targets whose stamp is older than this are skipped
  double future_tolerance = 2.0;  // [s] targets stamped further in the future are skipped
  double odom_timeout = 5.0;      // [s] no assessment while the own odometry is older than this
  bool publish_markers = true;
  double min_rate = 0.5;   // [Hz] diagnostics: expected /risk rate window
  double max_rate = 50.0;  // [Hz]
  RiskConfig risk;
  InputWatchConfig watch;  // watch/*: targets and odometry stale after watch/input_timeout: alarm

  void validate() const;  // std::invalid_argument naming the parameter
  static RiskNodeConfig fromParams(const ParamMap& params);
};

}  // namespace asv
