#include "asv_risk/params.h"

#include <cmath>
#include <vector>

#include "asv_core/sim/scenario.h"

namespace asv_risk {

std::set<std::string> ingestionKeys() {
  std::set<std::string> k = {"origin_lat_deg",  "origin_lon_deg",     "origin_scenario", "frame_id",
                             "publish_rate",    "max_range",          "max_targets",     "forget_after",
                             "silence_warning", "max_sentence_length"};
  addInputParamKeys(k);
  return k;
}

void loadIngestionParams(const ros::NodeHandle& pnh, IngestionParams& p) {
  getOrigin(pnh, p.origin_lat_deg, p.origin_lon_deg);
  getParam(pnh, "frame_id", p.frame_id);
  getParam(pnh, "publish_rate", p.publish_rate);
  getParam(pnh, "max_range", p.max_range);
  getParam(pnh, "max_targets", p.max_targets, 1);
  getParam(pnh, "forget_after", p.forget_after);
  getParam(pnh, "silence_warning", p.silence_warning);
  getParam(pnh, "max_sentence_length", p.max_sentence_length, asv::nmea::kStandardMaxLength);
  p.input = loadInputParams(pnh, p.input);
  if (p.frame_id.empty())
    throw std::invalid_argument("frame_id must not be empty");
  if (!(p.publish_rate > 0.0 && p.publish_rate <= 100.0))
    throw std::invalid_argument("publish_rate must be in (0, 100] Hz");
  if (!(p.max_range > 0.0) || !(p.forget_after > 0.0) || !(p.silence_warning > 0.0))
    throw std::invalid_argument("max_range, forget_after and silence_warning must be > 0");
}

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
