#include "asv_core/tracking/tracker_node_config.h"

#include <stdexcept>

namespace asv {

namespace {

void readAges(const ParamMap& p, const std::string& name, TrackAges& a) {
  a.coast_after = p.getDouble("ages/" + name + "/coast_after", a.coast_after);
  a.drop_after = p.getDouble("ages/" + name + "/drop_after", a.drop_after);
}

}  // namespace

void TrackerNodeConfig::validate() const {
  tracker.validate();
  if (frame_id.empty())
    throw std::invalid_argument("frame_id must not be empty");
  if (!(publish_rate > 0.0 && publish_rate <= 100.0))
    throw std::invalid_argument("publish_rate must be in (0, 100] Hz");
  if (!(future_tolerance >= 0.0))
    throw std::invalid_argument("future_tolerance must be >= 0 s");
  if (!(default_position_sigma > 0.0 && ais_velocity_sigma > 0.0 && arpa_velocity_sigma > 0.0))
    throw std::invalid_argument(
        "default_position_sigma, ais_velocity_sigma and arpa_velocity_sigma must be > 0");
}

TrackerNodeConfig TrackerNodeConfig::fromParams(const ParamMap& p) {
  TrackerNodeConfig n;
  n.frame_id = p.getString("frame_id", n.frame_id);
  n.publish_rate = p.getDouble("publish_rate", n.publish_rate);
  n.future_tolerance = p.getDouble("future_tolerance", n.future_tolerance);
  n.default_position_sigma = p.getDouble("default_position_sigma", n.default_position_sigma);
  n.ais_velocity_sigma = p.getDouble("ais_velocity_sigma", n.ais_velocity_sigma);
  n.arpa_velocity_sigma = p.getDouble("arpa_velocity_sigma", n.arpa_velocity_sigma);
  n.watch = InputWatchConfig::fromParams(p);
  TrackerConfig& c = n.tracker;
  c.gate_min = p.getDouble("gate_min", c.gate_min);
  c.gate_sigmas = p.getDouble("gate_sigmas", c.gate_sigmas);
  c.velocity_gate = p.getDouble("velocity_gate", c.velocity_gate);
  c.split_after = p.getInt("split_after", c.split_after);
  c.accel_sigma = p.getDouble("accel_sigma", c.accel_sigma);
  c.slow_speed = p.getDouble("slow_speed", c.slow_speed);
  c.max_tracks = p.getSize("max_tracks", c.max_tracks, 1);
  readAges(p, "ais_a", c.ais_a);
  readAges(p, "ais_b", c.ais_b);
  readAges(p, "ais_slow", c.ais_slow);
  readAges(p, "arpa", c.arpa);
  n.validate();
  return n;
}

}  // namespace asv
