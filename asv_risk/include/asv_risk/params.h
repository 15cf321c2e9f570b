// Parameter helpers shared by the asv_risk nodes: strict reading of the private namespace, so that a
// typo in a launch file or YAML stops the node instead of silently running on a default.
#pragma once

#include <set>
#include <stdexcept>
#include <string>

#include <ros/ros.h>

namespace asv_risk {

// Throws std::invalid_argument naming the first parameter under the private namespace of `pnh` that
// is not in `known` (keys relative to that namespace, nested ones as "input/udp/port"). `yaml` is the
// file that documents the keys, for the message.
void checkUnknownParams(const ros::NodeHandle& pnh, const std::set<std::string>& known,
                        const std::string& yaml);

// Reads `key` into `value` when it is set, keeping `value` (the default) otherwise. A value of the
// wrong type is an error (std::invalid_argument), not a silent default.
template <typename T>
void getParam(const ros::NodeHandle& pnh, const std::string& key, T& value) {
  if (!pnh.hasParam(key))
    return;
  if (!pnh.getParam(key, value))
    throw std::invalid_argument("parameter '" + pnh.resolveName(key) + "' has the wrong type");
}

// Same for unsigned sizes and ports, read as int and checked to be >= `min`.
void getParam(const ros::NodeHandle& pnh, const std::string& key, std::size_t& value, std::size_t min = 0);

// Reads the map-frame origin: `origin_scenario` (a scenario file, format 1) when set and non-empty,
// so that a launch takes the origin from the scenario it runs; else the required
// `origin_lat_deg`/`origin_lon_deg`. Throws std::invalid_argument when neither is usable.
void getOrigin(const ros::NodeHandle& pnh, double& lat_deg, double& lon_deg);

}  // namespace asv_risk
