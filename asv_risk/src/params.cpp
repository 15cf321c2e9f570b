#include "asv_risk/params.h"

#include <cmath>
#include <vector>

#include "asv_core/sim/scenario.h"

namespace asv_risk {

void getOrigin(const ros::NodeHandle& pnh, double& lat_deg, double& lon_deg) {
  std::string scenario;
  getParam(pnh, "origin_scenario", scenario);
  if (!scenario.empty()) {
    const asv::Scenario s = asv::loadScenario(scenario);  // throws naming the file, line and key
    if (!s.has_origin)
      throw std::invalid_argument("origin_scenario '" + scenario + "' has no origin");
    lat_deg = s.origin.lat_deg;
    lon_deg = s.origin.lon_deg;
    return;
  }
  if (!pnh.hasParam("origin_lat_deg") || !pnh.hasParam("origin_lon_deg"))
    throw std::invalid_argument(
        "origin_lat_deg and origin_lon_deg (or origin_scenario) are required (origin of the map frame)");
  getParam(pnh, "origin_lat_deg", lat_deg);
  getParam(pnh, "origin_lon_deg", lon_deg);
  if (!(std::fabs(lat_deg) <= 90.0) || !(std::fabs(lon_deg) <= 180.0))
    throw std::invalid_argument("origin_lat_deg/origin_lon_deg out of range");
}

}  // namespace asv_risk
