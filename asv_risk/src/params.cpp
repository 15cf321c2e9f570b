#include "asv_risk/params.h"

#include <cmath>
#include <vector>

#include "asv_core/scenario.h"

namespace asv_risk {

void checkUnknownParams(const ros::NodeHandle& pnh, const std::set<std::string>& known,
                        const std::string& yaml) {
  std::vector<std::string> names;
  if (!ros::param::getParamNames(names))
    return;
  const std::string prefix = pnh.getNamespace() + "/";
  for (const std::string& n : names) {
    if (n.compare(0, prefix.size(), prefix) != 0)
      continue;
    const std::string key = n.substr(prefix.size());
    if (!known.count(key))
      throw std::invalid_argument("unknown parameter '" + n + "' (typo? see " + yaml + " for the keys)");
  }
}

void getParam(const ros::NodeHandle& pnh, const std::string& key, std::size_t& value, std::size_t min) {
  if (!pnh.hasParam(key))
    return;
  int v = 0;
  if (!pnh.getParam(key, v))
    throw std::invalid_argument("parameter '" + pnh.resolveName(key) + "' must be an integer");
  if (v < 0 || static_cast<std::size_t>(v) < min)
    throw std::invalid_argument("parameter '" + pnh.resolveName(key) + "' must be >= " + std::to_string(min));
  value = static_cast<std::size_t>(v);
}

}  // namespace asv_risk

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
