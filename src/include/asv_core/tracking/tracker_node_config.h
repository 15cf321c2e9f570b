// The tracker node's parameters (asv_risk/config/tracker.yaml), ROS-free: one struct read by
// fromParams(), so that each key and its default is defined once.
#pragma once

#include <string>

#include "asv_core/common/input_watch.h"
#include "asv_core/common/param_map.h"
#include "asv_core/tracking/tracker.h"

namespace asv {

struct TrackerNodeConfig {
  std::string frame_id = "map";
  double publish_rate = 2.0;             // [Hz] targets
  double future_tolerance = 2.0;         // [s] reports stamped further in the future are rejected
  double default_position_sigma = 50.0;  // [m] when a report's covariance is all 0 (unknown)
  double ais_velocity_sigma = 0.2;       // [m/s] 1-sigma of an AIS velocity per axis
  double arpa_velocity_sigma = 0.5;      // [m/s] 1-sigma of an ARPA velocity per axis
  TrackerConfig tracker;   // keys gate_min ... max_tracks, ages/<class>/{coast_after,drop_after}
  InputWatchConfig watch;  // watch/*: ais/targets and arpa/targets (heartbeats) stale: alarm

  void validate() const;  // std::invalid_argument naming the parameter
  static TrackerNodeConfig fromParams(const ParamMap& params);
};

}  // namespace asv
