#include "asv_core/tracking/ingestion_config.h"

#include <cmath>
#include <stdexcept>

#include "asv_core/codec/nmea.h"
#include "asv_core/common/geodesy.h"

namespace asv {

void IngestionConfig::readShared(const ParamMap& p) {
  origin_scenario = p.getString("origin_scenario", origin_scenario);
  if (const std::optional<GeoPoint> o = originFromParams(p)) {
    has_origin = true;
    origin_lat_deg = o->lat_deg;
    origin_lon_deg = o->lon_deg;
  }
  frame_id = p.getString("frame_id", frame_id);
  publish_rate = p.getDouble("publish_rate", publish_rate);
  silence_warning = p.getDouble("silence_warning", silence_warning);
  heartbeat_period = p.getDouble("heartbeat_period", heartbeat_period);
  max_sentence_length = p.getSize("max_sentence_length", max_sentence_length, nmea::kStandardMaxLength);
}

void IngestionConfig::validateShared() const {
  if (!(std::fabs(origin_lat_deg) <= 90.0) || !(std::fabs(origin_lon_deg) <= 180.0))
    throw std::invalid_argument("origin_lat_deg/origin_lon_deg out of range");
  if (frame_id.empty())
    throw std::invalid_argument("frame_id must not be empty");
  if (!(publish_rate > 0.0 && publish_rate <= 100.0))
    throw std::invalid_argument("publish_rate must be in (0, 100] Hz");
  if (!(silence_warning > 0.0))
    throw std::invalid_argument("silence_warning must be > 0 s");
  // Three heartbeats within the tracker's watch/input_timeout (1.5 s): at most 0.5 s.
  if (!(heartbeat_period > 0.0 && heartbeat_period <= 0.5))
    throw std::invalid_argument(
        "heartbeat_period must be in (0, 0.5] s (the tracker's watch/input_timeout is 1.5 s)");
}

void readTableLimits(const ParamMap& p, double& max_range, std::size_t& max_targets, double& forget_after) {
  max_range = p.getDouble("max_range", max_range);
  max_targets = p.getSize("max_targets", max_targets, 1);
  forget_after = p.getDouble("forget_after", forget_after);
  if (!(max_range > 0.0) || !(forget_after > 0.0))
    throw std::invalid_argument("max_range and forget_after must be > 0");
}

void AisNodeConfig::validate() const {
  validateShared();
  targets.validate();
  decoder.validate();
  if (max_static < 1)
    throw std::invalid_argument("max_static must be >= 1");
  aids.validate();
  if (!(aids_period > 0.0 && aids_period <= 60.0))
    throw std::invalid_argument("aids/publish_period must be in (0, 60] s");
}

AisNodeConfig AisNodeConfig::fromParams(const ParamMap& p) {
  AisNodeConfig c;
  c.readShared(p);
  readTableLimits(p, c.targets.max_range, c.targets.max_targets, c.targets.forget_after);
  c.targets.position_sigma_high = p.getDouble("position_sigma_high", c.targets.position_sigma_high);
  c.targets.position_sigma_low = p.getDouble("position_sigma_low", c.targets.position_sigma_low);
  c.targets.own_mmsi = static_cast<std::uint32_t>(p.getSize("own_mmsi", c.targets.own_mmsi));
  c.decoder.fragment_timeout = p.getDouble("fragment_timeout", c.decoder.fragment_timeout);
  c.decoder.max_pending = p.getSize("max_pending", c.decoder.max_pending, 1);
  c.max_static = p.getSize("max_static", c.max_static, 1);
  c.aids.max_range = c.targets.max_range;
  c.aids.max_aids = p.getSize("aids/max_aids", c.aids.max_aids, 1);
  c.aids.forget_after = p.getDouble("aids/forget_after", c.aids.forget_after);
  c.aids_period = p.getDouble("aids/publish_period", c.aids_period);
  c.publish_markers = p.getBool("publish_markers", c.publish_markers);
  c.validate();
  return c;
}

void ArpaNodeConfig::validate() const {
  validateShared();
  targets.validate();
  arpa.validate();
}

ArpaNodeConfig ArpaNodeConfig::fromParams(const ParamMap& p) {
  ArpaNodeConfig c;
  c.readShared(p);
  ArpaTargetConfig& t = c.targets;
  readTableLimits(p, t.max_range, t.max_targets, t.forget_after);
  t.odom_timeout = p.getDouble("odom_timeout", t.odom_timeout);
  t.sigmas.range = p.getDouble("range_sigma", t.sigmas.range);
  t.sigmas.range_fraction = p.getDouble("range_sigma_fraction", t.sigmas.range_fraction);
  t.sigmas.bearing_deg = p.getDouble("bearing_sigma_deg", t.sigmas.bearing_deg);
  t.tll_sigma = p.getDouble("tll_sigma", t.tll_sigma);
  c.arpa.max_distance = p.getDouble("max_distance", c.arpa.max_distance);
  c.arpa.max_speed = p.getDouble("max_speed", c.arpa.max_speed);
  c.validate();
  return c;
}

}  // namespace asv
