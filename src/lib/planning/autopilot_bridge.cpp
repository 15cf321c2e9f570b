#include "asv_core/planning/autopilot_bridge.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "asv_core/codec/gnss.h"
#include "asv_core/common/format.h"
#include "asv_core/common/geodesy.h"
#include "asv_core/common/units.h"

namespace asv {

namespace {

constexpr const char* kSetpoint = "set-point";
constexpr const char* kOwn = "odometry";

}  // namespace

void AutopilotBridgeConfig::validate() const {
  static const std::set<std::string> known{"APB", "RMB", "XTE", "HSC"};
  if (talker.size() != 2)
    throw std::invalid_argument("talker must be two characters (e.g. EC, GP)");
  for (const std::string& s : sentences)
    if (!known.count(s))
      throw std::invalid_argument("sentences: unknown sentence '" + s + "' (APB, RMB, XTE, HSC)");
  if (!(rate > 0.0 && rate <= 10.0))
    throw std::invalid_argument("rate must be in (0, 10] Hz");
  if (safe_action != "hold_course" && safe_action != "invalidate")
    throw std::invalid_argument("safe_action must be hold_course or invalidate");
  if (!(twist_gain >= 0.0) || !(max_yaw_rate > 0.0))
    throw std::invalid_argument("twist_gain must be >= 0 and max_yaw_rate > 0");
  if (!(route_acceptance > 0.0) || !std::isfinite(route_acceptance))
    throw std::invalid_argument("route_acceptance must be > 0 m");
  if (!(route_turn_rate > 0.0) || !std::isfinite(route_turn_rate))
    throw std::invalid_argument("route_turn_rate_deg_s must be > 0");
  if (!(route_tolerance > 0.0 && route_tolerance < kPi))
    throw std::invalid_argument("route_tolerance_deg must be in (0, 180)");
  leg.validate();
  watch.validate();
}

AutopilotBridgeConfig AutopilotBridgeConfig::fromParams(const ParamMap& p) {
  AutopilotBridgeConfig c;
  c.origin_scenario = p.getString("origin_scenario", c.origin_scenario);
  if (const std::optional<GeoPoint> o = originFromParams(p)) {
    c.origin_lat_deg = o->lat_deg;
    c.origin_lon_deg = o->lon_deg;
  }
  c.talker = p.getString("talker", c.talker);
  c.sentences = p.getStringList("sentences", c.sentences);
  c.rate = p.getDouble("rate", c.rate);
  c.safe_action = p.getString("safe_action", c.safe_action);
  c.armed_at_start = p.getBool("armed_at_start", c.armed_at_start);
  c.variation = gnss::variationFromParams(p);
  c.twist_gain = p.getDouble("twist_gain", c.twist_gain);
  c.max_yaw_rate = p.getDouble("max_yaw_rate", c.max_yaw_rate);
  c.leg.lookahead = p.getDouble("lookahead", c.leg.lookahead);
  c.leg.leg_change = degToRad(p.getDouble("leg_change_deg", radToDeg(c.leg.leg_change)));
  c.route_acceptance = p.getDouble("route_acceptance", c.route_acceptance);
  c.route_tolerance = degToRad(p.getDouble("route_tolerance_deg", radToDeg(c.route_tolerance)));
  c.route_turn_rate = degToRad(p.getDouble("route_turn_rate_deg_s", radToDeg(c.route_turn_rate)));
  c.watch = InputWatchConfig::fromParams(p, c.watch);
  c.validate();
  return c;
}

AutopilotBridge::AutopilotBridge(const AutopilotBridgeConfig& config)
    : cfg_(config), watch_(config.watch), leg_(config.leg), armed_(config.armed_at_start) {
  cfg_.validate();
  watch_.add(kSetpoint);
  watch_.add(kOwn);
}

void AutopilotBridge::route(const std::vector<Eigen::Vector2d>& waypoints) {
  Route route;
  for (const Eigen::Vector2d& w : waypoints)
    if (allFinite({w.x(), w.y()}))
      route.push_back({w});
  progress_ = RouteProgress();
  pending_route_.clear();
  if (route.empty())
    return;
  if (position_)
    progress_ = RouteProgress(route, *position_);
  else
    pending_route_ = route;
}

void AutopilotBridge::arm(bool armed) {
  if (armed && !armed_)
    leg_.reset();
  armed_ = armed;
}

void AutopilotBridge::setpoint(double course, double speed, double stamp, double now, double wall) {
  if (!allFinite({course, speed}))
    return;
  course_ = wrapTwoPi(course);
  speed_ = std::max(0.0, speed);
  // A set-point stamped long ago (a planner whose clock stopped) is no sign of life.
  if (now - stamp <= cfg_.watch.input_timeout)
    watch_.received(kSetpoint, now, wall);
}

void AutopilotBridge::own(const Eigen::Vector2d& position, double course_over_ground, double speed,
                          double heading, double now, double wall) {
  if (!allFinite({position.x(), position.y(), course_over_ground, speed, heading}))
    return;
  position_ = position;
  if (!pending_route_.empty()) {
    progress_ = RouteProgress(pending_route_, position);
    pending_route_.clear();
  }
  cog_ = course_over_ground;
  sog_ = speed;
  heading_ = heading;
  watch_.received(kOwn, now, wall);
}

AutopilotBridge::Output AutopilotBridge::tick(
    double now, double wall, const std::function<void(const Eigen::Vector2d&, double&, double&)>& to_latlon) {
  Output out;
  for (const StaleInput& s : watch_.stale(now, wall))
    if (s.name == kOwn || watch_.everReceived(s.name))  // no set-point yet is waiting, not a fault
      out.lost.push_back(s);
  bool setpoint_lost = false, own_lost = !position_.has_value();
  for (const StaleInput& s : out.lost)
    (s.name == kSetpoint ? setpoint_lost : own_lost) = true;
  // Back from a loss: the old leg's line may be far astern; steer a new one from here.
  if (was_lost_ && out.lost.empty())
    leg_.reset();
  was_lost_ = !out.lost.empty();
  if (!armed_ || !course_)
    return out;
  const bool invalidate = setpoint_lost && cfg_.safe_action == "invalidate";
  out.action = setpoint_lost
                   ? (invalidate ? "sentences sent invalid (status V): the autopilot drops track mode"
                                 : "the last course is held")
                   : (own_lost ? "no own position: APB, RMB, XTE invalid, HSC holds the last course" : "");
  Eigen::Vector2d destination = Eigen::Vector2d::Zero();
  autopilot::Steering s = steering(setpoint_lost, &destination, &out.route_waypoint);
  s.valid = !invalidate && !own_lost;
  to_latlon(destination, s.dest_lat_deg, s.dest_lon_deg);
  for (const std::string& name : cfg_.sentences) {
    if (name == "APB")
      out.sentences.push_back(autopilot::encodeApb(s, cfg_.talker));
    else if (name == "RMB")
      out.sentences.push_back(autopilot::encodeRmb(s, cfg_.talker));
    else if (name == "XTE")
      out.sentences.push_back(autopilot::encodeXte(s, cfg_.talker));
    else if (!invalidate)  // HSC has no status field: an invalid heading command is not sent
      out.sentences.push_back(
          autopilot::encodeHsc(own_lost ? *course_ : s.heading_to_steer, cfg_.variation, cfg_.talker));
  }
  out.valid = s.valid;
  if (!invalidate) {
    out.speed = *speed_;
    const double error = wrapPi(s.heading_to_steer - heading_);  // > 0: turn to starboard (clockwise)
    out.yaw_rate = -std::clamp(cfg_.twist_gain * error, -cfg_.max_yaw_rate, cfg_.max_yaw_rate);
  }
  return out;
}

autopilot::Steering AutopilotBridge::steering(bool setpoint_lost, Eigen::Vector2d* destination,
                                              std::optional<size_t>* route_waypoint) {
  autopilot::Steering s;
  if (!position_) {
    s.bearing_leg = s.bearing_to_dest = s.heading_to_steer = *course_;
    *destination = leg_.destination();
    return s;
  }
  // A lost set-point holds the last course on its own leg: the route is no longer being steered.
  if (const std::optional<autopilot::Steering> r = setpoint_lost ? std::nullopt : routeSteering(*course_)) {
    leg_.reset();  // back off the route, a new set-point leg starts from where the ship is then
    *destination = progress_.target().position;
    *route_waypoint = progress_.active();
    return *r;
  }
  s = leg_.update(*course_, *position_, cog_, sog_);
  *destination = leg_.destination();
  return s;
}

std::optional<autopilot::Steering> AutopilotBridge::routeSteering(double setpoint_course) {
  if (progress_.empty())
    return std::nullopt;
  progress_.update(*position_, sog_, cfg_.route_turn_rate, cfg_.route_acceptance);
  const Eigen::Vector2d p = *position_, a = progress_.legStart(), b = progress_.target().position;
  const Eigen::Vector2d los = progress_.lineOfSight(p, kLineOfSightLookahead * cfg_.route_acceptance);
  if ((los - p).norm() < 1e-6 || std::abs(wrapPi(setpoint_course - courseOf(los - p))) > cfg_.route_tolerance)
    return std::nullopt;
  autopilot::Steering s;
  s.cross_track = progress_.crossTrackError(p);  // > 0 to starboard of the leg, as APB/XTE want
  s.bearing_leg = trueBearing(a, b);
  s.bearing_to_dest = trueBearing(p, b);
  s.heading_to_steer = setpoint_course;  // the stack's own steering back onto the leg
  s.range_to_dest = (b - p).norm();
  s.closing_speed = sog_ * std::cos(cog_ - s.bearing_to_dest);
  s.origin_id = strFormat("WP%03zu", progress_.active());
  s.dest_id = strFormat("WP%03zu", progress_.active() + 1);
  return s;
}

}  // namespace asv
