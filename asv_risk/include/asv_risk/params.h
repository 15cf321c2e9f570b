// Parameter helpers of the asv_risk nodes: the stack's strict reader and the map-frame origin.
#pragma once

#include <set>
#include <stdexcept>
#include <string>

#include <asv_ros/params.h>
#include <ros/ros.h>

namespace asv_risk {

// The stack's strict reader (asv_ros/params.h), by the names the asv_risk nodes use.
using asv_ros::checkUnknownParams;
using asv_ros::getParam;

// Reads the map-frame origin: `origin_scenario` (a scenario file, format 1) when set and non-empty,
// so that a launch takes the origin from the scenario it runs; else the required
// `origin_lat_deg`/`origin_lon_deg`. Throws std::invalid_argument when neither is usable.
void getOrigin(const ros::NodeHandle& pnh, double& lat_deg, double& lon_deg);

}  // namespace asv_risk
