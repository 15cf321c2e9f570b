#include "asv_core/sim/sim_node_config.h"

#include <cmath>
#include <stdexcept>

#include "asv_core/common/units.h"

namespace asv {

namespace {

void readSim(const ParamMap& p, SimConfig& s) {
  s.dt = p.getDouble("dt", s.dt);
  s.collision_distance = p.getDouble("collision_distance", s.collision_distance);
  s.environment.wind_speed = p.getDouble("wind_speed", s.environment.wind_speed);
  s.environment.wind_direction =
      degToRad(p.getDouble("wind_direction_deg", radToDeg(s.environment.wind_direction)));
  s.environment.wave_direction =
      degToRad(p.getDouble("wave_direction_deg", radToDeg(s.environment.wave_direction)));
  s.environment.wave_height = p.getDouble("wave_height", s.environment.wave_height);
  s.environment.wave_length = p.getDouble("wave_length", s.environment.wave_length);
  s.traffic.give_way_alteration_deg =
      p.getDouble("give_way_alteration_deg", s.traffic.give_way_alteration_deg);
  s.traffic.give_way_tcpa = p.getDouble("give_way_tcpa", s.traffic.give_way_tcpa);
  s.traffic.give_way_dcpa = p.getDouble("give_way_dcpa", s.traffic.give_way_dcpa);
  s.traffic.late_give_way_tcpa = p.getDouble("late_give_way_tcpa", s.traffic.late_give_way_tcpa);
  s.traffic.late_give_way_alteration_deg =
      p.getDouble("late_give_way_alteration_deg", s.traffic.late_give_way_alteration_deg);
  s.traffic.waypoint_acceptance = p.getDouble("waypoint_acceptance", s.traffic.waypoint_acceptance);
}

void readEmitter(const ParamMap& p, EmitterConfig& e) {
  e.ais = p.getBool("ais", e.ais);
  e.radar = p.getBool("radar", e.radar);
  e.radar_range = p.getDouble("radar_range", e.radar_range);
  e.radar_period = p.getDouble("radar_period", e.radar_period);
  e.range_noise = p.getDouble("range_noise", e.range_noise);
  e.bearing_noise_deg = p.getDouble("bearing_noise_deg", e.bearing_noise_deg);
  e.speed_noise_kn = p.getDouble("speed_noise_kn", e.speed_noise_kn);
  e.course_noise_deg = p.getDouble("course_noise_deg", e.course_noise_deg);
  e.radar_dropout = p.getDouble("radar_dropout", e.radar_dropout);
  e.ais_dropout = p.getDouble("ais_dropout", e.ais_dropout);
  e.static_interval = p.getDouble("static_interval", e.static_interval);
}

}  // namespace

void SimNodeConfig::validate() const {
  if (scenario.empty())
    throw std::invalid_argument("~scenario (path of a scenario file) is required");
  if (!(rate >= 0.0) || !std::isfinite(rate))
    throw std::invalid_argument("rate must be >= 0 (0: as fast as possible)");
  if (!(odom_rate > 0.0) || !(ships_rate > 0.0))
    throw std::invalid_argument("odom_rate and ships_rate must be > 0 Hz");
  if (udp_port <= 0 || udp_port > 65535)
    throw std::invalid_argument("udp_port must be in 1..65535");
  if (!(keep_up_lead > 0.0) || !(keep_up_timeout > 0.0))
    throw std::invalid_argument("keep_up_lead and keep_up_timeout must be > 0 s");
  if (!(max_sim_time >= 0.0))
    throw std::invalid_argument("max_sim_time must be >= 0 s (0: the scenario's duration)");
  sim.validate();
  emitter.validate();
}

SimNodeConfig SimNodeConfig::fromParams(const ParamMap& p) {
  SimNodeConfig c;
  c.scenario = p.getString("scenario", c.scenario);
  c.charts = ChartOptions::fromParams(p);
  c.seed = p.getSize("seed", c.seed);
  c.rate = p.getDouble("rate", c.rate);
  c.publish_clock = p.getBool("publish_clock", c.publish_clock);
  c.odom_rate = p.getDouble("odom_rate", c.odom_rate);
  c.ships_rate = p.getDouble("ships_rate", c.ships_rate);
  c.emit_topic = p.getBool("emit_topic", c.emit_topic);
  c.watch = InputWatchConfig::fromParams(p, c.watch);
  c.emit_udp = p.getBool("emit_udp", c.emit_udp);
  c.udp_host = p.getString("udp_host", c.udp_host);
  c.udp_port = p.getInt("udp_port", c.udp_port);
  c.stop_on_collision = p.getBool("stop_on_collision", c.stop_on_collision);
  c.shutdown_at_end = p.getBool("shutdown_at_end", c.shutdown_at_end);
  c.linger_for = p.getString("linger_for", c.linger_for);
  c.linger_max = p.getDouble("linger_max", c.linger_max);
  c.start_delay = p.getDouble("start_delay", c.start_delay);
  c.max_sim_time = p.getDouble("max_sim_time", c.max_sim_time);
  c.keep_up_topic = p.getString("keep_up_topic", c.keep_up_topic);
  c.keep_up_lead = p.getDouble("keep_up_lead", c.keep_up_lead);
  c.keep_up_timeout = p.getDouble("keep_up_timeout", c.keep_up_timeout);
  c.lockstep_participants = p.getStringList("lockstep_participants", c.lockstep_participants);
  c.lockstep_clock_every_step = p.getBool("lockstep_clock_every_step", c.lockstep_clock_every_step);
  readSim(p, c.sim);
  readEmitter(p, c.emitter);
  c.validate();
  return c;
}

}  // namespace asv
