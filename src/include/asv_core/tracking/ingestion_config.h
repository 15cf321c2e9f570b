// The parameters of the two ingestion nodes (asv_risk/config/ais_node.yaml, arpa_node.yaml), ROS-free:
// one struct per node read by fromParams(), the keys both share read by one function. The input's
// own keys (input/: UDP, TCP, serial, file) are the node's I/O glue and read there.
#pragma once

#include <cstddef>
#include <string>

#include "asv_core/codec/ais.h"
#include "asv_core/codec/arpa.h"
#include "asv_core/common/param_map.h"
#include "asv_core/tracking/ais_targets.h"
#include "asv_core/tracking/arpa_targets.h"

namespace asv {

// The keys both nodes share, with the same meaning.
struct IngestionConfig {
  // The map frame's origin when the node is given its own: origin_scenario (a scenario file whose origin
  // the node takes) or origin_lat_deg/origin_lon_deg. Neither: the node takes the run's /map_origin.
  std::string origin_scenario;
  bool has_origin = false;
  double origin_lat_deg = 0.0;
  double origin_lon_deg = 0.0;
  std::string frame_id = "map";
  double publish_rate = 10.0;     // [Hz] the node's targets topic
  double silence_warning = 30.0;  // [s] diagnostics warn when no sentence came for this long
  // [s] an empty targets array this often when nothing was reported, so that the tracker tells a quiet
  // sea from a dead node (its watch/input_timeout, 1.5 s, is three of these)
  double heartbeat_period = 0.5;
  std::size_t max_sentence_length = 512;  // [bytes] framer limit (tag block included)

  // Reads the shared keys (this struct's values are the defaults).
  void readShared(const ParamMap& params);
  // std::invalid_argument naming the first bad value; an origin is required unless origin_scenario.
  void validateShared() const;
};

// The target table's limits, keys max_range, max_targets, forget_after (this one function reads them
// for both nodes).
void readTableLimits(const ParamMap& params, double& max_range, std::size_t& max_targets,
                     double& forget_after);

struct AisNodeConfig : IngestionConfig {
  AisTargetConfig targets;         // max_range, max_targets (5000), forget_after (900 s), position sigmas
  ais::DecoderConfig decoder;      // fragment_timeout, max_pending
  std::size_t max_static = 10000;  // ships whose static data is remembered
  AidTableConfig aids;             // aids/max_aids, aids/forget_after; max_range is the ships' one
  double aids_period = 1.0;        // [s] aids/publish_period: the whole list of aids this often
  bool publish_markers = true;     // ais/markers: aids and SAR aircraft for rviz

  void validate() const;
  static AisNodeConfig fromParams(const ParamMap& params);
};

struct ArpaNodeConfig : IngestionConfig {
  // max_range, max_targets (1000), forget_after (120 s), odom_timeout, range_sigma,
  // range_sigma_fraction, bearing_sigma_deg, tll_sigma
  ArpaTargetConfig targets;
  arpa::ArpaConfig arpa;  // max_distance, max_speed

  void validate() const;
  static ArpaNodeConfig fromParams(const ParamMap& params);
};

}  // namespace asv
