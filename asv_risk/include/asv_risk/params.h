// Parameter helpers of the asv_risk nodes: the stack's strict reader and the map-frame origin.
#pragma once

#include <set>
#include <stdexcept>
#include <string>

#include <asv_ros/params.h>
#include <ros/ros.h>

#include "asv_risk/nmea_input.h"

namespace asv_risk {

// The stack's strict reader (asv_ros/params.h), by the names the asv_risk nodes use.
using asv_ros::checkUnknownParams;
using asv_ros::getParam;

// The parameters both ingestion nodes (ais_node, arpa_node) read, with the same meaning: the map
// frame's origin and id, the publishing rate, the range and size of the target table, the silence
// warning, the framer's limit and the input (config/ais_node.yaml, config/arpa_node.yaml).
struct IngestionParams {
  double origin_lat_deg = 0.0;  // required
  double origin_lon_deg = 0.0;  // required
  std::string frame_id = "map";
  double publish_rate = 10.0;             // [Hz] the node's targets topic
  double max_range = 200000.0;            // [m] positions farther from the origin are rejected
  std::size_t max_targets = 1000;         // targets remembered; the least recently heard is forgotten
  double forget_after = 120.0;            // [s] a target not heard for this long is forgotten
  double silence_warning = 30.0;          // [s] diagnostics warn when no sentence came for this long
  std::size_t max_sentence_length = 512;  // [bytes] framer limit (tag block included)
  NmeaInputParams input;
};

// The keys of IngestionParams, the input's among them.
std::set<std::string> ingestionKeys();
// Reads IngestionParams' keys into p (keeping p's values as defaults; `input` as the input's) and
// checks them: std::invalid_argument naming the first bad one.
void loadIngestionParams(const ros::NodeHandle& pnh, IngestionParams& p);

// Reads the map-frame origin: `origin_scenario` (a scenario file, format 1) when set and non-empty,
// so that a launch takes the origin from the scenario it runs; else the required
// `origin_lat_deg`/`origin_lon_deg`. Throws std::invalid_argument when neither is usable.
void getOrigin(const ros::NodeHandle& pnh, double& lat_deg, double& lon_deg);

}  // namespace asv_risk
