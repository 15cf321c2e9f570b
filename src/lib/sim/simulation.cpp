#include "asv_core/sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "asv_core/codec/nmea_encode.h"
#include "asv_core/common/geometry.h"
#include "asv_core/risk/colregs.h"
#include "asv_core/risk/cpa.h"

namespace asv {

namespace {

// [rad/s] The rate a ship without a planner turns at a route's waypoints, for the wheel-over point: the
// planners' default turn rate (OwnShipLimits), 1 deg/s.
constexpr double kRouteTurnRate = 0.0175;

void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::invalid_argument(what);
}

// MMSIs for ships the scenario leaves without one: 211xxxxxx (a ship station MID), by index.
uint32_t defaultMmsi(size_t index) {
  return 211000000u + static_cast<uint32_t>(index) + 1u;
}

}  // namespace

const char* toString(SimEvent::Type t) {
  switch (t) {
    case SimEvent::Collision:
      return "collision";
    case SimEvent::NearMiss:
      return "near_miss";
    case SimEvent::Arrival:
      return "arrival";
    case SimEvent::Grounding:
      return "grounding";
  }
  return "?";
}

void TrafficConfig::validate() const {
  require(give_way_alteration_deg >= 30.0 && give_way_alteration_deg <= 90.0,
          "traffic.give_way_alteration_deg must be in [30, 90] deg (Rule 8(b): readily apparent)");
  require(give_way_tcpa > 0.0 && std::isfinite(give_way_tcpa), "traffic.give_way_tcpa must be > 0 s");
  require(give_way_dcpa > 0.0 && std::isfinite(give_way_dcpa), "traffic.give_way_dcpa must be > 0 m");
  require(late_give_way_tcpa > 0.0 && std::isfinite(late_give_way_tcpa),
          "traffic.late_give_way_tcpa must be > 0 s");
  require(late_give_way_alteration_deg > 0.0 && late_give_way_alteration_deg <= 90.0,
          "traffic.late_give_way_alteration_deg must be in (0, 90] deg");
  require(waypoint_acceptance > 0.0 && std::isfinite(waypoint_acceptance),
          "traffic.waypoint_acceptance must be > 0 m");
}

void SimConfig::validate() const {
  require(dt > 0.0 && dt <= 10.0, "sim.dt must be in (0, 10] s");
  require(collision_distance >= 0.0 && std::isfinite(collision_distance),
          "sim.collision_distance must be >= 0 m");
  require(default_beam_ratio > 0.0 && default_beam_ratio < 1.0, "sim.default_beam_ratio must be in (0, 1)");
  environment.validate();
  traffic.validate();
}

ShipState SimVessel::shipState() const {
  ShipState s;
  s.id = name;
  s.position = position();
  s.course = cog();
  s.speed = sog();
  s.heading = state().psi;
  s.length = length;
  return s;
}

Simulation::Simulation(const Scenario& scenario, const SimConfig& config)
    : scenario_(scenario), cfg_(config), frame_(scenario.frame()) {
  cfg_.validate();
  std::vector<const ScenarioShip*> ships{&scenario_.own};
  for (const auto& t : scenario_.targets)
    ships.push_back(&t);
  vessels_.resize(ships.size());
  for (size_t i = 0; i < ships.size(); ++i) {
    const ScenarioShip& s = *ships[i];
    SimVessel& v = vessels_[i];
    v.name = s.name;
    v.mmsi = s.mmsi ? s.mmsi : defaultMmsi(i);
    v.ais_class = s.ais_class;
    v.own = i == 0;
    v.behaviour = v.own ? Behaviour::Planner : s.behaviour;
    v.planner = s.planner;
    v.model_name = s.model;
    if (s.model == "kinematic" || s.model == "point") {
      KinematicParams kp;
      kp.instant = s.model == "point";
      if (s.length > 0.0)
        kp.length = s.length;
      v.model = std::make_unique<KinematicModel>(kp);
    } else {
      auto m = std::make_unique<Mmg3DofModel>(loadVesselPreset(s.model));
      v.autopilot = std::make_unique<Autopilot>(tuneAutopilot(*m), SpeedFeedForward::fromModel(*m));
      v.model = std::move(m);
    }
    v.length = s.length > 0.0 ? s.length : v.model->length();
    v.beam = s.beam > 0.0 ? s.beam : v.length * cfg_.default_beam_ratio;
    VesselState st;
    st.x = s.position.x();
    st.y = s.position.y();
    st.psi = s.course;
    st.u = s.speed;
    v.model->setState(st);
    v.course_sp = v.cruise_course = s.course;
    v.speed_sp = v.cruise_speed = s.speed;
    v.goal = s.goal;
    v.goal_radius = s.goal_radius;
    v.stays_at_goal = s.stays_at_goal;
    v.step_from = s.position;
    v.waypoints = s.waypoints;
    v.route = s.route;
    if (!s.route.empty())
      v.route_progress = RouteProgress(s.route, s.position);
    v.track = s.track;
    v.track_start = s.position;
    if (v.autopilot)
      v.autopilot->setCourseSpeed(v.course_sp, v.speed_sp);
  }
  const size_t n = vessels_.size();
  min_dist_.assign(n, 1e12);
  in_contact_.assign(n, std::vector<char>(n, 0));
  in_near_miss_.assign(n, std::vector<char>(n, 0));
  aground_.assign(n, std::vector<char>(scenario_.obstacles.size(), 0));
  for (const auto& o : scenario_.obstacles)
    obstacle_boxes_.push_back(boundingBox(o.polygon));
  referee();
}

const SimVessel* Simulation::find(const std::string& name) const {
  for (const auto& v : vessels_)
    if (v.name == name)
      return &v;
  return nullptr;
}

bool Simulation::setSetpoint(const std::string& ship, double course, double speed) {
  if (!std::isfinite(course) || !std::isfinite(speed) || speed < 0.0)
    return false;
  for (auto& v : vessels_)
    if (v.name == ship) {
      v.course_sp = wrapTwoPi(course);
      v.speed_sp = speed;
      v.external_setpoint = true;
      v.waypoints.clear();
      return true;
    }
  return false;
}

bool Simulation::setWaypoints(const std::string& ship, const std::vector<Eigen::Vector2d>& wps,
                              double speed) {
  if (wps.empty() || !std::isfinite(speed) || speed < 0.0)
    return false;
  for (const auto& w : wps)
    if (!w.allFinite())
      return false;
  for (auto& v : vessels_)
    if (v.name == ship) {
      v.waypoints = wps;
      v.wp_index = 0;
      v.speed_sp = speed;
      v.external_setpoint = true;
      return true;
    }
  return false;
}

// The give_way ship's alteration to starboard: the smallest of give_way_alteration_deg, +10, ... 90 deg
// that, with the other ship holding on, passes her at give_way_dcpa or more (Rule 16: early and
// substantial action to keep well clear, here clear of her own risk threshold); 90 deg when none does.
// A port_turn ship breaks the rules: she makes give_way_alteration_deg to port, whatever it passes.
double Simulation::giveWayAlteration(const SimVessel& v, const ShipState& other) const {
  const double first = cfg_.traffic.give_way_alteration_deg;
  if (v.behaviour == Behaviour::PortTurn)
    return -degToRad(first);
  if (v.behaviour == Behaviour::LateGiveWay)
    return degToRad(cfg_.traffic.late_give_way_alteration_deg);
  for (double deg = first; deg < 90.0; deg += 10.0) {
    const Eigen::Vector2d velocity = courseSpeedToVelocity(v.cruise_course + degToRad(deg), v.cruise_speed);
    const Cpa cpa = computeCpa(v.position(), velocity, other.position, other.velocity());
    if (cpa.dcpa >= cfg_.traffic.give_way_dcpa || cpa.tcpa < 0.0)
      return degToRad(deg);
  }
  return degToRad(90.0);
}

void Simulation::giveWayLogic(SimVessel& v, size_t index) {
  ShipState me = v.shipState();
  if (v.giving_way) {
    // Stand back on once the other ship is past: judged on the original course, so the ship does not
    // turn back into the danger it just avoided.
    const SimVessel* other = find(v.giving_way_to);
    ShipState original = me;
    original.course = original.heading = v.cruise_course;
    original.speed = v.cruise_speed;
    if (!other || other->arrived || computeCpa(original, other->shipState()).tcpa < 0.0) {
      v.giving_way = false;
      v.course_sp = v.cruise_course;
    }
    return;
  }
  for (size_t j = 0; j < vessels_.size(); ++j) {
    if (j == index || !vessels_[j].present())
      continue;
    const ShipState other = vessels_[j].shipState();
    const Cpa cpa = computeCpa(me, other);
    const double act_tcpa =
        v.behaviour == Behaviour::LateGiveWay ? cfg_.traffic.late_give_way_tcpa : cfg_.traffic.give_way_tcpa;
    if (cpa.tcpa < 0.0 || cpa.tcpa > act_tcpa || cpa.dcpa > cfg_.traffic.give_way_dcpa)
      continue;
    const EncounterGeometry g = classifyEncounter(me, other, cpa, ColregsConfig{});
    if (g.role == OwnRole::GiveWay || g.role == OwnRole::BothGiveWay) {
      v.giving_way = true;
      v.giving_way_to = vessels_[j].name;
      v.course_sp = wrapTwoPi(v.cruise_course + giveWayAlteration(v, other));  // Rules 14, 15, 16
      return;
    }
  }
}

void Simulation::steer(SimVessel& v) {
  const Eigen::Vector2d p = v.position();
  const double accept =
      v.goal_radius > 0.0 ? v.goal_radius : std::max(cfg_.traffic.waypoint_acceptance, 2.0 * v.length);
  // Judged along the last step's track, so a fast ship cannot step over a small arrival circle.
  if (v.goal && !v.arrived && pointSegmentDistance(*v.goal, v.step_from, p) <= accept) {
    v.arrived = true;
    v.arrival_time = time_;
    events_.push_back({SimEvent::Arrival, time_, v.name, "", (p - *v.goal).norm()});
  }
  if (v.arrived) {
    v.speed_sp = 0.0;  // an arrived ship stops (and has left the scenario unless she stays_at_goal)
    return;
  }
  if (!v.waypoints.empty()) {
    while (v.wp_index + 1 < v.waypoints.size() && (p - v.waypoints[v.wp_index]).norm() <= accept)
      ++v.wp_index;
    const Eigen::Vector2d d = v.waypoints[v.wp_index] - p;
    if (d.norm() > 1e-6)
      v.course_sp = courseOf(d);
    return;
  }
  switch (v.behaviour) {
    case Behaviour::GiveWay:
    case Behaviour::PortTurn:
    case Behaviour::LateGiveWay:
      giveWayLogic(v, static_cast<size_t>(&v - vessels_.data()));
      break;
    case Behaviour::Planner:
      // Until a planner speaks (or when the ship has none), sail the route by line of sight (passing a
      // waypoint at the wheel-over point of its turn), else steer straight for the goal.
      if (!v.external_setpoint && v.route_progress) {
        v.route_progress->update(p, v.sog(), kRouteTurnRate, accept);
        v.course_sp = courseOf(v.route_progress->lineOfSight(p, 2.0 * accept) - p);
        const double leg_speed = v.route_progress->target().speed;
        v.speed_sp = leg_speed > 0.0 ? leg_speed : v.cruise_speed;
      } else if (!v.external_setpoint && v.goal) {
        v.course_sp = courseOf(*v.goal - p);
      }
      break;
    case Behaviour::Constant:
    case Behaviour::NonCompliant:  // a give-way ship that stands on (Hu et al. 2017, Fig. 6)
    case Behaviour::Waypoints:
    case Behaviour::Track:  // replayed, not steered (replayTrack)
      break;
  }
}

TrackSample sampleTrack(const Eigen::Vector2d& start, double start_course,
                        const std::vector<TrackPoint>& track, double t) {
  TrackSample s;
  s.course = start_course;
  Eigen::Vector2d from = start;
  double t_from = 0.0;
  for (const TrackPoint& p : track) {
    const Eigen::Vector2d leg = p.position - from;
    const double span = p.t - t_from;
    if (leg.norm() > 1e-9)
      s.course = courseOf(leg);
    if (t < p.t) {
      const double f = std::clamp((t - t_from) / span, 0.0, 1.0);
      s.position = from + f * leg;
      s.speed = leg.norm() / span;
      return s;
    }
    from = p.position;
    t_from = p.t;
  }
  s.position = from;
  s.ended = true;
  return s;
}

// A recorded ship is where her track puts her, whatever happens round her; after its last point she
// has left the scenario (arrived, no longer refereed), as a waypoint ship at her goal.
void Simulation::replayTrack(SimVessel& v, double t) {
  if (v.arrived)
    return;
  const TrackSample s = sampleTrack(v.track_start, v.cruise_course, v.track, t);
  VesselState st = v.state();
  st.x = s.position.x();
  st.y = s.position.y();
  st.psi = s.course;
  st.u = s.speed;
  st.v = st.r = 0.0;
  v.model->setState(st);
  v.course_sp = s.course;
  v.speed_sp = s.speed;
  if (s.ended) {
    v.arrived = true;
    v.arrival_time = t;
    events_.push_back({SimEvent::Arrival, t, v.name, "", 0.0});
  }
}

void Simulation::step() {
  const double dt = cfg_.dt;
  for (auto& v : vessels_) {
    if (v.behaviour == Behaviour::Track) {
      const Eigen::Vector2d before = v.step_from = v.position();
      replayTrack(v, time_ + dt);
      v.path_length += (v.position() - before).norm();
      continue;
    }
    steer(v);
    const Eigen::Vector2d before = v.step_from = v.position();
    VesselInput in;
    in.course = v.course_sp;
    in.speed = v.speed_sp;
    if (v.autopilot) {
      if (v.autopilot->courseSetPoint() != v.course_sp || v.autopilot->speedSetPoint() != v.speed_sp)
        v.autopilot->setCourseSpeed(v.course_sp, v.speed_sp);
      in = v.autopilot->update(v.state(), dt);
    }
    v.model->step(in, cfg_.environment, dt);
    v.path_length += (v.position() - before).norm();
  }
  time_ += dt;
  referee();
}

bool Simulation::hullsTouch(const SimVessel& a, const SimVessel& b) {
  // Separating axis theorem on two oriented rectangles (length along the heading, beam across).
  auto axes = [](const SimVessel& v) {
    const double s = std::sin(v.state().psi), c = std::cos(v.state().psi);
    return std::pair<Eigen::Vector2d, Eigen::Vector2d>{{s, c}, {c, -s}};
  };
  const auto [fa, sa] = axes(a);
  const auto [fb, sb] = axes(b);
  const Eigen::Vector2d d = b.position() - a.position();
  for (const Eigen::Vector2d& ax : {fa, sa, fb, sb}) {
    const double ra = 0.5 * a.length * std::fabs(fa.dot(ax)) + 0.5 * a.beam * std::fabs(sa.dot(ax));
    const double rb = 0.5 * b.length * std::fabs(fb.dot(ax)) + 0.5 * b.beam * std::fabs(sb.dot(ax));
    if (std::fabs(d.dot(ax)) > ra + rb)
      return false;
  }
  return true;
}

Polygon Simulation::hull(const SimVessel& v) {
  return hullOutline(v.position(), v.state().psi, v.length, v.beam);
}

// Grounding is as bad as a collision: a hull outline touching a static obstacle is an event (once per
// contact, as a collision), and the own hull's distance to land is kept for the result.
void Simulation::refereeLand() {
  const auto& obstacles = scenario_.obstacles;
  for (size_t i = 0; i < vessels_.size(); ++i) {
    const SimVessel& v = vessels_[i];
    if (v.arrived)
      continue;
    const Polygon outline = hull(v);
    const Eigen::AlignedBox2d box = boundingBox(outline);
    for (size_t k = 0; k < obstacles.size(); ++k) {
      // The boxes' distance bounds the outlines' from below: the exact test only where it can matter.
      const double bound = box.exteriorDistance(obstacle_boxes_[k]);
      const double needed = i == 0 ? min_obstacle_own_ : 0.0;
      const double d = bound > needed ? bound : polygonObstacleDistance(outline, obstacles[k], needed);
      if (i == 0)
        min_obstacle_own_ = std::min(min_obstacle_own_, d);
      const bool touch = d <= 0.0;
      if (touch && !aground_[i][k]) {
        events_.push_back({SimEvent::Grounding, time_, v.name, obstacles[k].name, 0.0});
        grounded_own_ = grounded_own_ || i == 0;
      }
      aground_[i][k] = touch;
    }
  }
}

void Simulation::referee() {
  refereeLand();
  const size_t n = vessels_.size();
  for (size_t i = 0; i < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      const SimVessel &a = vessels_[i], &b = vessels_[j];
      if (!a.present() || !b.present())
        continue;
      const double d = (a.position() - b.position()).norm();
      if (i == 0) {
        min_dist_[j] = std::min(min_dist_[j], d);
        min_sep_own_ = std::min(min_sep_own_, d);
        const bool near = d < scenario_.min_separation;
        if (near && !in_near_miss_[i][j])
          events_.push_back({SimEvent::NearMiss, time_, a.name, b.name, d});
        in_near_miss_[i][j] = near;
      }
      const bool touch = cfg_.collision_distance > 0.0
                             ? d < cfg_.collision_distance
                             : (d < 0.5 * (a.length + b.length) && hullsTouch(a, b));
      if (touch && !in_contact_[i][j]) {
        events_.push_back({SimEvent::Collision, time_, a.name, b.name, d});
        collided_ = true;
      }
      in_contact_[i][j] = touch;
    }
  }
}

// ---------------------------------------------------------------------------------------------------

void EmitterConfig::validate() const {
  require(radar_range > 0.0 && std::isfinite(radar_range), "emitter.radar_range must be > 0 m");
  require(radar_period > 0.0 && std::isfinite(radar_period), "emitter.radar_period must be > 0 s");
  for (double s : {range_noise, bearing_noise_deg, speed_noise_kn, course_noise_deg})
    require(s >= 0.0 && std::isfinite(s), "emitter noise values must be >= 0");
  require(radar_dropout >= 0.0 && radar_dropout < 1.0, "emitter.radar_dropout must be in [0, 1)");
  require(ais_dropout >= 0.0 && ais_dropout < 1.0, "emitter.ais_dropout must be in [0, 1)");
  require(static_interval > 0.0, "emitter.static_interval must be > 0 s");
}

NmeaEmitter::NmeaEmitter(const EmitterConfig& cfg, uint64_t seed) : cfg_(cfg), rng_(seed) {
  cfg_.validate();
}

double NmeaEmitter::reportingInterval(char ais_class, double sog, double rate_of_turn, uint8_t nav_status) {
  const double kn = mpsToKnots(sog);
  if (ais_class == 'B')
    return kn <= 2.0 ? 180.0 : 30.0;  // class B "CS"
  if ((nav_status == 1 || nav_status == 5) && kn <= 3.0)
    return 180.0;  // at anchor or moored
  // "Changing course": a rate of turn above 5 deg per 30 s.
  const bool turning = std::fabs(rate_of_turn) > degToRad(5.0) / 30.0;
  if (kn <= 14.0)
    return turning ? 10.0 / 3.0 : 10.0;
  if (kn <= 23.0)
    return turning ? 2.0 : 6.0;
  return 2.0;
}

namespace {

double unit01(std::mt19937_64& rng) {
  return std::uniform_real_distribution<double>(0.0, 1.0)(rng);
}

// A scenario sensor fault of `type` on vessel v is active at time t.
bool faulty(const Simulation& sim, const SimVessel& v, SensorFault::Type type, double t) {
  for (const auto& f : sim.scenario().sensor_faults)
    if (f.type == type && f.ship == v.name && f.active(t))
      return true;
  return false;
}

// Radar target number of vessel i: its index, or its partner's during a swap.
int radarNumber(const Simulation& sim, size_t i) {
  const auto& vs = sim.vessels();
  for (const auto& f : sim.scenario().sensor_faults)
    if (f.type == SensorFault::Type::RadarSwap && f.active(sim.time()) &&
        (f.ship == vs[i].name || f.with == vs[i].name))
      if (const SimVessel* other = sim.find(f.ship == vs[i].name ? f.with : f.ship))
        return static_cast<int>(other - vs.data());
  return static_cast<int>(i);
}

}  // namespace

void NmeaEmitter::update(const Simulation& sim, std::vector<std::string>& ais,
                         std::vector<std::string>& ttm) {
  if (next_pos_.size() != sim.vessels().size())
    schedule(sim);
  loss_announced_.resize(sim.scenario().sensor_faults.size(), 0);
  if (cfg_.ais)
    emitAis(sim, ais);
  if (cfg_.radar && sim.time() >= next_scan_) {
    next_scan_ = sim.time() + cfg_.radar_period;
    emitRadar(sim, ttm);
  }
}

// Staggers the first reports over one interval (and the static data over 10 s), as transponders that
// were switched on at different times would.
void NmeaEmitter::schedule(const Simulation& sim) {
  const auto& vs = sim.vessels();
  const double t = sim.time();
  next_pos_.resize(vs.size());
  next_static_.resize(vs.size());
  for (size_t i = 0; i < vs.size(); ++i) {
    next_pos_[i] = t + unit01(rng_) * reportingInterval(vs[i].ais_class, vs[i].sog(), vs[i].state().r);
    next_static_[i] = t + unit01(rng_) * 10.0;
  }
  next_scan_ = t;
}

// One AIS message on alternate channels; a multi-sentence one takes the next sequence number. The
// dropout loses it after that, as a missed reception would.
void NmeaEmitter::send(const ais::BitWriter& w, std::vector<std::string>& out) {
  channel_b_ = !channel_b_;
  const auto lines = ais::toSentences(w, channel_b_ ? 'B' : 'A', seq_);
  if (lines.size() > 1)
    seq_ = (seq_ + 1) % 10;
  if (cfg_.ais_dropout > 0.0 && unit01(rng_) < cfg_.ais_dropout)
    return;
  out.insert(out.end(), lines.begin(), lines.end());
  ++ais_sent_;
}

void NmeaEmitter::emitAis(const Simulation& sim, std::vector<std::string>& out) {
  const auto& vs = sim.vessels();
  const double t = sim.time();
  for (size_t i = 1; i < vs.size(); ++i) {
    if (!vs[i].present())
      continue;
    if (faulty(sim, vs[i], SensorFault::Type::AisSilence, t)) {
      next_static_[i] = std::max(next_static_[i], t);  // the first reports go out when she is back
      next_pos_[i] = std::max(next_pos_[i], t);
      continue;
    }
    if (t >= next_static_[i]) {
      next_static_[i] = t + cfg_.static_interval;
      sendStatic(sim, i, out);
    }
    if (t >= next_pos_[i]) {
      next_pos_[i] = t + reportingInterval(vs[i].ais_class, vs[i].sog(), vs[i].state().r);
      sendPosition(sim, i, out);
    }
  }
}

// Static data: type 5 for class A, type 24 parts A and B for class B.
void NmeaEmitter::sendStatic(const Simulation& sim, size_t i, std::vector<std::string>& out) {
  const SimVessel& v = sim.vessels()[i];
  const uint32_t bow = static_cast<uint32_t>(std::lround(v.length / 2)),
                 port = static_cast<uint32_t>(std::lround(v.beam / 2));
  if (v.ais_class == 'A') {
    ais::StaticVoyageData d;
    d.callsign.assign("SIM" + std::to_string(i));
    d.shipname.assign(v.name);
    d.shiptype = 70;  // cargo
    d.to_bow = d.to_stern = std::min(bow, 511u);
    d.to_port = d.to_starboard = std::min(port, 63u);
    d.epfd = 1;
    d.draught = static_cast<uint32_t>(std::min(255.0, std::lround(v.length / 20.0) * 10.0));
    d.destination.assign(sim.scenario().name.substr(0, 20));
    send(ais::encodeStaticVoyage(v.mmsi, d), out);
    return;
  }
  ais::StaticDataReport a;
  a.part = 0;
  a.shipname.assign(v.name);
  send(ais::encodeStaticDataReport(v.mmsi, a), out);
  ais::StaticDataReport b;
  b.part = 1;
  b.shiptype = 37;  // pleasure craft
  b.callsign.assign("SIM" + std::to_string(i));
  b.to_bow = b.to_stern = std::min(bow, 511u);
  b.to_port = b.to_starboard = std::min(port, 63u);
  send(ais::encodeStaticDataReport(v.mmsi, b), out);
}

// Position report: type 1 for class A, type 18 for class B.
void NmeaEmitter::sendPosition(const Simulation& sim, size_t i, std::vector<std::string>& out) {
  const SimVessel& v = sim.vessels()[i];
  const GeoPoint g = sim.frame().toGeodetic(v.position());
  const uint8_t second = static_cast<uint8_t>(static_cast<long>(std::floor(sim.time())) % 60);
  if (v.ais_class == 'A') {
    ais::PositionReportA r;
    r.status = 0;  // under way using engine
    r.turn = ais::rawTurn(v.state().r);
    r.speed = ais::rawSpeed(v.sog());
    r.accuracy = true;
    r.lat = ais::rawLat(g.lat_deg);
    r.lon = ais::rawLon(g.lon_deg);
    r.course = ais::rawCourse(v.cog());
    r.heading = ais::rawHeading(v.state().psi);
    r.second = second;
    send(ais::encodePositionA(1, v.mmsi, r), out);
    return;
  }
  ais::PositionReportB r;
  r.speed = ais::rawSpeed(v.sog());
  r.accuracy = true;
  r.lat = ais::rawLat(g.lat_deg);
  r.lon = ais::rawLon(g.lon_deg);
  r.course = ais::rawCourse(v.cog());
  r.heading = ais::rawHeading(v.state().psi);
  r.second = second;
  r.cs = true;
  send(ais::encodePositionB(v.mmsi, r), out);
}

// A radar loss of vessel i is active: the ARPA declares the target lost once (a TTM with status L),
// then drops it.
bool NmeaEmitter::radarLost(const Simulation& sim, size_t i, std::vector<std::string>& out) {
  const std::vector<SensorFault>& faults = sim.scenario().sensor_faults;
  const double t = sim.time();
  bool lost = false;
  for (size_t k = 0; k < faults.size(); ++k) {
    if (faults[k].type != SensorFault::Type::RadarLoss || faults[k].ship != sim.vessels()[i].name ||
        !faults[k].active(t))
      continue;
    lost = true;
    if (loss_announced_[k])
      continue;
    loss_announced_[k] = 1;
    arpa::TtmOut o;
    o.number = radarNumber(sim, i);
    o.status = 'L';
    o.utc_seconds_of_day = std::fmod(t, 86400.0);
    out.push_back(arpa::encodeTtm(o));
    ++ttm_sent_;
  }
  return lost;
}

// One radar scan: a TTM per vessel within range, with the configured measurement noise.
void NmeaEmitter::emitRadar(const Simulation& sim, std::vector<std::string>& out) {
  const auto& vs = sim.vessels();
  const double t = sim.time();
  std::normal_distribution<double> gauss(0.0, 1.0);  // one per scan: it keeps a spare draw
  const SimVessel& own = vs[0];
  const ShipState os = own.shipState();
  for (size_t i = 1; i < vs.size(); ++i) {
    const SimVessel& v = vs[i];
    if (!v.present())
      continue;
    const Eigen::Vector2d rel = v.position() - own.position();
    const double range = rel.norm();
    if (range > cfg_.radar_range || radarLost(sim, i, out))
      continue;
    if (cfg_.radar_dropout > 0.0 && unit01(rng_) < cfg_.radar_dropout)
      continue;
    arpa::TtmOut o;
    o.number = radarNumber(sim, i);
    o.distance = std::max(0.0, range + cfg_.range_noise * gauss(rng_));
    o.bearing = wrapTwoPi(courseOf(rel) + degToRad(cfg_.bearing_noise_deg) * gauss(rng_));
    o.speed = std::max(0.0, v.sog() + knotsToMps(cfg_.speed_noise_kn) * gauss(rng_));
    o.course = wrapTwoPi(v.cog() + degToRad(cfg_.course_noise_deg) * gauss(rng_));
    const Cpa c = computeCpa(os, v.shipState());
    o.cpa = c.dcpa;
    o.tcpa = c.tcpa;
    o.name = v.name.substr(0, 20);
    o.status = 'T';
    o.utc_seconds_of_day = std::fmod(t, 86400.0);
    out.push_back(arpa::encodeTtm(o));
    ++ttm_sent_;
  }
}

}  // namespace asv
