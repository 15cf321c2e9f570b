// The ingestion nodes' (ais_node, arpa_node) parameters: the core's config (asv_core/tracking/
// ingestion_config.h) and, as ROS glue, the input they read from (input/ subtree).
#pragma once

#include <optional>
#include <string>

#include <asv_core/tracking/ingestion_config.h>
#include <asv_ros/map_origin.h>
#include <asv_ros/params.h>
#include <ros/ros.h>

#include "asv_risk/nmea_input.h"

namespace asv_risk {

// When origin_scenario is set, takes the origin from that scenario file (format 1); throws
// std::invalid_argument when the file has none (and naming the file, line and key when it is bad).
void resolveOrigin(asv::IngestionConfig& c);

// The node's map origin (asv_ros/map_origin.h): its own (`c`'s origin, resolved) when it has one, else
// the run's /map_origin.
inline std::optional<asv::GeoPoint> givenOrigin(const asv::IngestionConfig& c) {
  if (!c.has_origin)
    return std::nullopt;
  return asv::GeoPoint{c.origin_lat_deg, c.origin_lon_deg};
}

template <typename CoreConfig>
struct IngestionNodeParams : CoreConfig {
  NmeaInputParams input;
};

// The node's parameters from its private namespace: the core config by its fromParams(), the input
// from input/ (`input_defaults` the node's own), the origin resolved (origin_scenario: the origin of
// that scenario file); an unknown key anywhere is std::invalid_argument naming it and `yaml`.
template <typename CoreConfig>
IngestionNodeParams<CoreConfig> loadIngestionParams(const ros::NodeHandle& pnh,
                                                    const NmeaInputParams& input_defaults,
                                                    const std::string& yaml) {
  const asv::ParamMap params = asv_ros::readParams(pnh);
  IngestionNodeParams<CoreConfig> p;
  try {
    static_cast<CoreConfig&>(p) = CoreConfig::fromParams(params);
  } catch (const std::invalid_argument&) {
    asv_ros::rejectTypoBehindError(params, yaml, {"input/"});
    throw;
  }
  const asv::ParamMap input = params.sub("input");
  p.input = inputFromParams(input, input_defaults);
  asv_ros::rejectUnknown(params, yaml, {"input/"});
  asv_ros::rejectUnknown(input, yaml);
  resolveOrigin(p);
  return p;
}

}  // namespace asv_risk
