#include "asv_core/world/scenario.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "asv_core/common/units.h"
#include "asv_core/world/route_file.h"

namespace asv {

namespace {

// Plausibility bounds that catch unit mistakes (a speed in m/s written as knots, metres as miles).
constexpr double kMaxSpeedKn = 60.0;
constexpr double kMaxRangeNm = 200.0;
constexpr double kMaxCoordinateM = 2.0e6;

class Ctx {
public:
  explicit Ctx(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const YAML::Node& n, const std::string& key, const std::string& what) const {
    std::ostringstream s;
    s << source_;
    if (n.IsDefined() && n.Mark().line >= 0)
      s << ":" << n.Mark().line + 1;
    s << ": " << (key.empty() ? "" : "'" + key + "': ") << what;
    throw ScenarioError(s.str());
  }

  void onlyKeys(const YAML::Node& map, const std::string& where, const std::set<std::string>& allowed) const {
    if (!map.IsMap())
      fail(map, where, "expected a mapping");
    for (const auto& kv : map) {
      const std::string k = kv.first.as<std::string>();
      if (!allowed.count(k)) {
        std::string list;
        for (const auto& a : allowed)
          list += (list.empty() ? "" : ", ") + a;
        fail(kv.first, where.empty() ? k : where + "." + k, "unknown key (allowed here: " + list + ")");
      }
    }
  }

  double number(const YAML::Node& map, const std::string& key, const std::string& where) const {
    const YAML::Node n = map[key];
    if (!n.IsDefined() || n.IsNull())
      fail(map, where + key, "missing");
    double v;
    try {
      v = n.as<double>();
    } catch (const YAML::Exception&) {
      fail(n, where + key, "not a number: '" + n.as<std::string>("?") + "'");
    }
    if (!std::isfinite(v))
      fail(n, where + key, "must be finite");
    return v;
  }

  std::string text(const YAML::Node& map, const std::string& key, const std::string& where) const {
    const YAML::Node n = map[key];
    if (!n.IsDefined() || n.IsNull())
      fail(map, where + key, "missing");
    if (!n.IsScalar())
      fail(n, where + key, "expected a string");
    return n.as<std::string>();
  }

  const std::string& source() const { return source_; }

private:
  std::string source_;
};

struct PointSpec {
  enum Kind { Xy, LatLon, BearingRange } kind;
  Eigen::Vector2d xy;             // Xy
  GeoPoint geo;                   // LatLon
  double bearing = 0, range = 0;  // BearingRange [rad], [m]
};

PointSpec readPoint(const Ctx& c, const YAML::Node& n, const std::string& where, bool allow_relative) {
  if (!n.IsMap())
    c.fail(n, where,
           "expected {x_m, y_m}, {lat_deg, lon_deg}" +
               std::string(allow_relative ? " or {bearing_deg, range_nm}" : ""));
  std::set<std::string> allowed{"x_m", "y_m", "lat_deg", "lon_deg"};
  if (allow_relative)
    allowed.insert({"bearing_deg", "range_nm"});
  c.onlyKeys(n, where, allowed);
  const int forms = (n["x_m"] || n["y_m"] ? 1 : 0) + (n["lat_deg"] || n["lon_deg"] ? 1 : 0) +
                    (n["bearing_deg"] || n["range_nm"] ? 1 : 0);
  if (forms != 1)
    c.fail(n, where,
           "give exactly one position form: {x_m, y_m}, {lat_deg, lon_deg} or {bearing_deg, range_nm}");
  PointSpec p;
  const std::string w = where + ".";
  if (n["x_m"] || n["y_m"]) {
    p.kind = PointSpec::Xy;
    p.xy = {c.number(n, "x_m", w), c.number(n, "y_m", w)};
    if (p.xy.cwiseAbs().maxCoeff() > kMaxCoordinateM)
      c.fail(n, where, "coordinate beyond 2000 km from the origin: a unit mistake?");
  } else if (n["lat_deg"] || n["lon_deg"]) {
    p.kind = PointSpec::LatLon;
    p.geo = {c.number(n, "lat_deg", w), c.number(n, "lon_deg", w)};
    if (!validLatLon(p.geo.lat_deg, p.geo.lon_deg))
      c.fail(n, where, "latitude/longitude out of range");
  } else {
    p.kind = PointSpec::BearingRange;
    const double deg = c.number(n, "bearing_deg", w);
    if (deg < 0.0 || deg > 360.0)  // unbounded, a huge bearing made a NaN position
      c.fail(n["bearing_deg"], w + "bearing_deg", "must be in [0, 360] deg");
    p.bearing = degToRad(deg);
    const double nm = c.number(n, "range_nm", w);
    if (nm < 0.0 || nm > kMaxRangeNm)
      c.fail(n["range_nm"], w + "range_nm", "must be in [0, 200] nm (metres given as miles?)");
    p.range = nmToMetres(nm);
  }
  return p;
}

Eigen::Vector2d resolve(const PointSpec& p, const LocalFrame& frame, const Eigen::Vector2d& own_start) {
  switch (p.kind) {
    case PointSpec::Xy:
      return p.xy;
    case PointSpec::LatLon:
      return frame.toLocal(p.geo);
    case PointSpec::BearingRange:
      return own_start + courseSpeedToVelocity(p.bearing, p.range);
  }
  return p.xy;
}

double readCourse(const Ctx& c, const YAML::Node& n, const std::string& where) {
  const double deg = c.number(n, "course_deg", where);
  if (deg < 0.0 || deg >= 360.0)
    c.fail(n["course_deg"], where + "course_deg", "must be in [0, 360) deg");
  return degToRad(deg);
}

double readSpeed(const Ctx& c, const YAML::Node& n, const std::string& where) {
  const bool kn = n["speed_kn"].IsDefined(), mps = n["speed_mps"].IsDefined();
  if (kn == mps)
    c.fail(n, where + "speed_kn", "give exactly one of speed_kn or speed_mps");
  if (kn) {
    const double v = c.number(n, "speed_kn", where);
    if (v < 0.0 || v > kMaxSpeedKn)
      c.fail(n["speed_kn"], where + "speed_kn", "must be in [0, 60] kn");
    return knotsToMps(v);
  }
  const double v = c.number(n, "speed_mps", where);
  if (v < 0.0 || v > knotsToMps(kMaxSpeedKn))
    c.fail(n["speed_mps"], where + "speed_mps", "must be in [0, 30.9] m/s");
  return v;
}

// Nodes flatten() visits at most. YAML aliases let a small file name one mapping many times (26
// nested aliases of 2 KB make 2^26 parameters, "billion laughs"): the cap keeps loading linear.
constexpr std::size_t kMaxPlannerParamNodes = 10000;
// Nesting levels below planner_params (a plugin's own keys use two or three). A mapping that holds an
// alias of itself nests without end: each level lengthens every key, so 10000 nodes would be hundreds
// of MB of key text before the node cap stops it.
constexpr std::size_t kMaxPlannerParamDepth = 8;

void flatten(const Ctx& c, const YAML::Node& n, const std::string& prefix, ParamMap& out, std::size_t& budget,
             std::size_t depth = 0) {
  if (budget == 0)
    c.fail(n, "planner_params", "more than 10000 entries (aliases expanding recursively?)");
  --budget;
  if (n.IsMap()) {
    if (depth == kMaxPlannerParamDepth)
      c.fail(n, "planner_params." + prefix,
             "nested deeper than " + std::to_string(kMaxPlannerParamDepth) +
                 " levels (a mapping holding an alias of itself?)");
    for (const auto& kv : n)
      flatten(c, kv.second,
              prefix.empty() ? kv.first.as<std::string>() : prefix + "/" + kv.first.as<std::string>(), out,
              budget, depth + 1);
  } else if (n.IsScalar()) {
    out.set(prefix, n.as<std::string>());
  } else if (!n.IsNull()) {
    c.fail(n, "planner_params." + prefix, "expected a number, string or nested mapping");
  }
}

struct RawShip {
  ScenarioShip ship;
  PointSpec pos;
  std::optional<PointSpec> goal;
  std::vector<PointSpec> waypoints;
  std::vector<std::pair<double, PointSpec>> track;  // (t_s, point)
  std::vector<PointSpec> route;
  std::string route_file;  // own_ship.route_file, resolved against the scenario's folder
  YAML::Node node;
};

// track: [{t_s, x_m, y_m} or {t_s, lat_deg, lon_deg}, ...], times > 0 and strictly increasing (the
// ship's position is its place at t = 0).
std::vector<std::pair<double, PointSpec>> readTrack(const Ctx& c, const YAML::Node& n, const std::string& w) {
  const YAML::Node tr = n["track"];
  if (!tr || !tr.IsSequence() || tr.size() == 0)
    c.fail(n, w + "track", "behaviour track needs a non-empty list of {t_s, position} points");
  std::vector<std::pair<double, PointSpec>> out;
  for (size_t i = 0; i < tr.size(); ++i) {
    const std::string wi = w + "track[" + std::to_string(i) + "]";
    if (!tr[i].IsMap())
      c.fail(tr[i], wi, "expected {t_s, x_m, y_m} or {t_s, lat_deg, lon_deg}");
    YAML::Node point = YAML::Clone(tr[i]);
    const double t = c.number(tr[i], "t_s", wi + ".");
    if (!(t > (out.empty() ? 0.0 : out.back().first)) || t > 7 * 86400.0)
      c.fail(tr[i]["t_s"], wi + ".t_s",
             "times must be > 0, at most 604800 s and strictly increasing along the track");
    point.remove("t_s");
    out.emplace_back(t, readPoint(c, point, wi, false));
  }
  return out;
}

// route: [{x_m, y_m} or {lat_deg, lon_deg}, with optional speed_kn, port_xtd_m, starboard_xtd_m}, ...];
// the positions are resolved later (the frame is known then), the rest goes into r.ship.route.
void readRoute(const Ctx& c, const YAML::Node& n, const std::string& w, RawShip& r) {
  const YAML::Node rt = n["route"];
  if (!rt.IsSequence() || rt.size() == 0)
    c.fail(rt, w + "route", "expected a non-empty list of waypoints");
  if (n["goal"])
    c.fail(n["goal"], w + "goal", "give a goal or a route, not both (the route's last waypoint is the goal)");
  for (size_t i = 0; i < rt.size(); ++i) {
    const std::string wi = w + "route[" + std::to_string(i) + "]";
    if (!rt[i].IsMap())
      c.fail(rt[i], wi,
             "expected {x_m, y_m} or {lat_deg, lon_deg}, optionally speed_kn, port_xtd_m, starboard_xtd_m");
    YAML::Node point = YAML::Clone(rt[i]);
    RouteWaypoint wp;
    if (rt[i]["speed_kn"]) {
      const double kn = c.number(rt[i], "speed_kn", wi + ".");
      if (!(kn > 0.0) || kn > kMaxSpeedKn)
        c.fail(rt[i]["speed_kn"], wi + ".speed_kn", "must be in (0, 60] kn");
      wp.speed = knotsToMps(kn);
    }
    for (auto [key, field] :
         {std::pair{"port_xtd_m", &wp.port_xtd}, std::pair{"starboard_xtd_m", &wp.starboard_xtd}})
      if (rt[i][key]) {
        *field = c.number(rt[i], key, wi + ".");
        if (!(*field > 0.0) || *field > 20000.0)
          c.fail(rt[i][key], wi + "." + key, "must be in (0, 20000] m");
      }
    for (const char* key : {"speed_kn", "port_xtd_m", "starboard_xtd_m"})
      point.remove(key);
    r.route.push_back(readPoint(c, point, wi, false));
    r.ship.route.push_back(wp);
    r.ship.route_lines.push_back(rt[i].Mark().line + 1);
  }
}

// How the ship arrives: goal_radius_m and stays_at_goal, both only for a ship with a goal or a route.
void readArrival(const Ctx& c, const YAML::Node& n, const std::string& w, ScenarioShip& s) {
  if (n["goal_radius_m"]) {
    if (!n["goal"] && !n["route"] && !n["route_file"])
      c.fail(n["goal_radius_m"], w + "goal_radius_m", "needs a goal or a route");
    s.goal_radius = c.number(n, "goal_radius_m", w);
    if (!(s.goal_radius > 0.0) || s.goal_radius > 10000.0)
      c.fail(n["goal_radius_m"], w + "goal_radius_m", "must be in (0, 10000] m");
  }
  if (n["stays_at_goal"]) {
    if (!n["goal"] && !n["route"] && !n["route_file"])
      c.fail(n["stays_at_goal"], w + "stays_at_goal", "needs a goal or a route");
    const std::string v = c.text(n, "stays_at_goal", w);
    if (v != "true" && v != "false")
      c.fail(n["stays_at_goal"], w + "stays_at_goal", "must be true or false");
    s.stays_at_goal = v == "true";
  }
}

RawShip readShip(const Ctx& c, const YAML::Node& n, const std::string& where, bool own) {
  std::set<std::string> allowed{"name",   "mmsi",     "model",         "ais_class",    "length_m",
                                "beam_m", "position", "course_deg",    "speed_kn",     "speed_mps",
                                "goal",   "planner",  "goal_radius_m", "stays_at_goal"};
  if (own)
    allowed.insert({"route", "route_file"});
  else
    allowed.insert({"behaviour", "waypoints", "track"});
  c.onlyKeys(n, where, allowed);
  RawShip r;
  r.node = n;
  const std::string w = where + ".";
  ScenarioShip& s = r.ship;
  s.name = c.text(n, "name", w);
  if (s.name.empty() || s.name.find_first_of(" /\t") != std::string::npos)
    c.fail(n["name"], w + "name",
           "must be non-empty without spaces or '/' (it names ROS namespaces and frames)");
  if (n["mmsi"]) {
    const double m = c.number(n, "mmsi", w);
    if (m < 0 || m > 999999999 || m != std::floor(m))
      c.fail(n["mmsi"], w + "mmsi", "must be a 9-digit integer");
    s.mmsi = static_cast<uint32_t>(m);
  }
  if (n["model"])
    s.model = c.text(n, "model", w);
  if (n["ais_class"]) {
    const std::string k = c.text(n, "ais_class", w);
    if (k != "A" && k != "B")
      c.fail(n["ais_class"], w + "ais_class", "must be A or B");
    s.ais_class = k[0];
  }
  if (n["length_m"]) {
    s.length = c.number(n, "length_m", w);
    if (s.length <= 0.0 || s.length > 500.0)
      c.fail(n["length_m"], w + "length_m", "must be in (0, 500] m");
  }
  if (n["beam_m"]) {
    s.beam = c.number(n, "beam_m", w);
    if (s.beam <= 0.0 || s.beam > 80.0)
      c.fail(n["beam_m"], w + "beam_m", "must be in (0, 80] m");
  }
  if (!n["position"])
    c.fail(n, w + "position", "missing");
  r.pos = readPoint(c, n["position"], w + "position", !own);
  s.course = readCourse(c, n, w);
  s.speed = readSpeed(c, n, w);
  if (n["goal"])
    r.goal = readPoint(c, n["goal"], w + "goal", true);
  if (n["route"])
    readRoute(c, n, w, r);
  if (n["route_file"]) {
    if (n["route"] || n["goal"])
      c.fail(n["route_file"], w + "route_file", "give one of goal, route or route_file");
    r.route_file = c.text(n, "route_file", w);
    const auto slash = c.source().find_last_of('/');
    if (!r.route_file.empty() && r.route_file[0] != '/' && slash != std::string::npos)
      r.route_file = c.source().substr(0, slash + 1) + r.route_file;
  }
  readArrival(c, n, w, s);
  if (n["planner"]) {
    s.planner = c.text(n, "planner", w);
    if (!validPlannerName(s.planner))
      c.fail(n["planner"], w + "planner",
             "not a planner name: a short name (aco, dssa, dssa_plus, mopso, ga) or a plugin's pluginlib "
             "name (package/class)");
  }
  if (!own) {
    const std::string b = n["behaviour"] ? c.text(n, "behaviour", w) : "constant";
    if (b == "constant")
      s.behaviour = Behaviour::Constant;
    else if (b == "waypoints")
      s.behaviour = Behaviour::Waypoints;
    else if (b == "give_way")
      s.behaviour = Behaviour::GiveWay;
    else if (b == "non_compliant")
      s.behaviour = Behaviour::NonCompliant;
    else if (b == "port_turn")
      s.behaviour = Behaviour::PortTurn;
    else if (b == "late_give_way")
      s.behaviour = Behaviour::LateGiveWay;
    else if (b == "planner")
      s.behaviour = Behaviour::Planner;
    else if (b == "track")
      s.behaviour = Behaviour::Track;
    else
      c.fail(n["behaviour"], w + "behaviour",
             "must be constant, waypoints, give_way, non_compliant, port_turn, late_give_way, planner or "
             "track");
    if (s.behaviour == Behaviour::Waypoints) {
      const YAML::Node wps = n["waypoints"];
      if (!wps || !wps.IsSequence() || wps.size() == 0)
        c.fail(n, w + "waypoints", "behaviour waypoints needs a non-empty list of waypoints");
      for (size_t i = 0; i < wps.size(); ++i)
        r.waypoints.push_back(readPoint(c, wps[i], w + "waypoints[" + std::to_string(i) + "]", false));
    } else if (n["waypoints"]) {
      c.fail(n["waypoints"], w + "waypoints", "only for behaviour: waypoints");
    }
    if (s.behaviour == Behaviour::Track)
      r.track = readTrack(c, n, w);
    else if (n["track"])
      c.fail(n["track"], w + "track", "only for behaviour: track");
    if (s.behaviour == Behaviour::Planner) {
      if (s.planner.empty())
        c.fail(n, w + "planner", "behaviour planner needs a planner");
      if (!r.goal)
        c.fail(n, w + "goal", "behaviour planner needs a goal");
    } else if (!s.planner.empty()) {
      c.fail(n["planner"], w + "planner", "a target's planner needs behaviour: planner");
    }
  }
  return r;
}

}  // namespace

const char* toString(Behaviour b) {
  switch (b) {
    case Behaviour::Waypoints:
      return "waypoints";
    case Behaviour::GiveWay:
      return "give_way";
    case Behaviour::NonCompliant:
      return "non_compliant";
    case Behaviour::PortTurn:
      return "port_turn";
    case Behaviour::LateGiveWay:
      return "late_give_way";
    case Behaviour::Planner:
      return "planner";
    case Behaviour::Track:
      return "track";
    case Behaviour::Constant:
      break;
  }
  return "constant";
}

bool validPlannerName(const std::string& name) {
  // A ROS package name (lower case, digits, underscores, a letter first) or two joined by one slash.
  const auto word = [](const std::string& w) {
    return !w.empty() && std::islower(static_cast<unsigned char>(w[0])) &&
           std::all_of(w.begin(), w.end(), [](char ch) {
             return std::islower(static_cast<unsigned char>(ch)) ||
                    std::isdigit(static_cast<unsigned char>(ch)) || ch == '_';
           });
  };
  const size_t slash = name.find('/');
  if (slash == std::string::npos)
    return word(name);
  return word(name.substr(0, slash)) && word(name.substr(slash + 1));
}

std::vector<const ScenarioShip*> Scenario::planningShips() const {
  std::vector<const ScenarioShip*> out;
  if (!own.planner.empty())
    out.push_back(&own);
  for (const auto& t : targets)
    if (t.behaviour == Behaviour::Planner)
      out.push_back(&t);
  return out;
}

namespace {

// format, name, description, duration_s, origin and safety.
void readHeader(const Ctx& c, const YAML::Node& root, Scenario& s) {
  // Compared as a double: casting an arbitrary number (1e300) to int first is undefined behaviour.
  if (c.number(root, "format", "") != 1.0)
    c.fail(root["format"], "format", "unsupported format (this stack reads format 1)");
  s.format = 1;
  s.name = c.text(root, "name", "");
  if (root["description"])
    s.description = c.text(root, "description", "");
  s.duration = c.number(root, "duration_s", "");
  if (s.duration <= 0.0 || s.duration > 7 * 86400.0)
    c.fail(root["duration_s"], "duration_s", "must be in (0, 604800] s");
  if (root["origin"]) {
    const YAML::Node o = root["origin"];
    c.onlyKeys(o, "origin", {"lat_deg", "lon_deg"});
    s.origin = {c.number(o, "lat_deg", "origin."), c.number(o, "lon_deg", "origin.")};
    if (!validLatLon(s.origin.lat_deg, s.origin.lon_deg))
      c.fail(o, "origin", "latitude/longitude out of range");
    s.has_origin = true;
  }
  if (root["safety"]) {
    const YAML::Node sf = root["safety"];
    c.onlyKeys(sf, "safety", {"min_separation_m", "min_obstacle_clearance_m"});
    if (sf["min_separation_m"] || !sf["min_obstacle_clearance_m"]) {
      s.min_separation = c.number(sf, "min_separation_m", "safety.");
      if (s.min_separation <= 0.0)
        c.fail(sf, "safety.min_separation_m", "must be > 0 m");
    }
    if (sf["min_obstacle_clearance_m"]) {
      s.min_obstacle_clearance = c.number(sf, "min_obstacle_clearance_m", "safety.");
      if (s.min_obstacle_clearance <= 0.0)
        c.fail(sf, "safety.min_obstacle_clearance_m", "must be > 0 m");
    }
  }
}

// Ships that start overlapping: closer than half their lengths summed (or 10 m for unknown lengths).
void checkOverlap(const Ctx& c, const Scenario& s, const RawShip& own, const std::vector<RawShip>& targets) {
  std::vector<std::pair<const ScenarioShip*, const RawShip*>> all{{&s.own, &own}};
  for (size_t i = 0; i < s.targets.size(); ++i)
    all.push_back({&s.targets[i], &targets[i]});
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j) {
      const double need = std::max(10.0, 0.5 * (all[i].first->length + all[j].first->length));
      const double d = (all[i].first->position - all[j].first->position).norm();
      if (d < need)
        c.fail(all[j].second->node["position"], all[j].first->name + ".position",
               "starts overlapping '" + all[i].first->name + "' (" + std::to_string(d) + " m apart)");
    }
}

// own_ship and targets, with positions resolved in the map frame (relative ones from the own ship's
// start); names unique, no two ships overlapping.
void readShips(const Ctx& c, const YAML::Node& root, Scenario& s) {
  if (!root["own_ship"])
    c.fail(root, "own_ship", "missing");
  RawShip own = readShip(c, root["own_ship"], "own_ship", true);
  std::vector<RawShip> targets;
  if (root["targets"]) {
    const YAML::Node t = root["targets"];
    if (!t.IsSequence())
      c.fail(t, "targets", "expected a list");
    for (size_t i = 0; i < t.size(); ++i)
      targets.push_back(readShip(c, t[i], "targets[" + std::to_string(i) + "]", false));
  }
  const LocalFrame frame = s.frame();
  const Eigen::Vector2d own_start = resolve(own.pos, frame, Eigen::Vector2d::Zero());
  auto finish = [&](RawShip& r) {
    r.ship.position = resolve(r.pos, frame, own_start);
    if (r.goal)
      r.ship.goal = resolve(*r.goal, frame, own_start);
    for (const auto& w : r.waypoints)
      r.ship.waypoints.push_back(resolve(w, frame, own_start));
    for (const auto& [t, p] : r.track)
      r.ship.track.push_back({t, resolve(p, frame, own_start)});
    for (size_t k = 0; k < r.route.size(); ++k)
      r.ship.route[k].position = resolve(r.route[k], frame, own_start);
    if (!r.route_file.empty()) {
      try {
        r.ship.route = readRouteFile(r.route_file, frame, &r.ship.route_lines);
      } catch (const RouteFileError& e) {
        c.fail(r.node["route_file"], "own_ship.route_file", e.what());
      }
      r.ship.route_source = r.route_file;
    }
    if (!r.ship.route.empty())
      r.ship.goal = r.ship.route.back().position;
    return r.ship;
  };
  s.own = finish(own);
  std::set<std::string> names{s.own.name};
  for (auto& r : targets) {
    s.targets.push_back(finish(r));
    if (!names.insert(r.ship.name).second)
      c.fail(r.node["name"], "name", "duplicate ship name '" + r.ship.name + "'");
  }
  checkOverlap(c, s, own, targets);
}

// static_obstacles: named polygons (3 or more vertices) that the own ship does not start inside.
void readObstacles(const Ctx& c, const YAML::Node& root, Scenario& s) {
  if (!root["static_obstacles"])
    return;
  const YAML::Node obs = root["static_obstacles"];
  if (!obs.IsSequence())
    c.fail(obs, "static_obstacles", "expected a list");
  const LocalFrame frame = s.frame();
  for (size_t i = 0; i < obs.size(); ++i) {
    const std::string w = "static_obstacles[" + std::to_string(i) + "]";
    c.onlyKeys(obs[i], w, {"name", "polygon"});
    StaticObstacle o;
    o.name = c.text(obs[i], "name", w + ".");
    const YAML::Node poly = obs[i]["polygon"];
    if (!poly || !poly.IsSequence() || poly.size() < 3)
      c.fail(obs[i], w + ".polygon", "needs at least 3 vertices");
    for (size_t k = 0; k < poly.size(); ++k)
      o.polygon.push_back(resolve(readPoint(c, poly[k], w + ".polygon[" + std::to_string(k) + "]", false),
                                  frame, s.own.position));
    if (pointInPolygon(o.polygon, s.own.position))
      c.fail(obs[i], w, "the own ship starts inside this obstacle");
    s.obstacles.push_back(std::move(o));
  }
}

// charts: where land comes from (charts.h). A chart needs the scenario's origin; its clearance_m is
// the scenario's obstacle clearance, given here or under safety, not both.
void readCharts(const Ctx& c, const YAML::Node& root, Scenario& s) {
  if (!root["charts"])
    return;
  const YAML::Node n = root["charts"];
  c.onlyKeys(n, "charts", {"source", "resolution", "layer", "radius_m", "simplify_m", "clearance_m"});
  if (!s.has_origin)
    c.fail(n, "charts", "charts need the scenario's origin (origin.lat_deg, origin.lon_deg)");
  ChartSpec spec;
  spec.source = c.text(n, "source", "charts.");
  if (spec.source != "gshhg" && !spec.source.empty() && spec.source[0] != '/') {
    const auto slash = s.source.find_last_of('/');
    if (slash != std::string::npos)
      spec.source = s.source.substr(0, slash + 1) + spec.source;
  }
  if (n["resolution"]) {
    spec.resolution = c.text(n, "resolution", "charts.");
    try {
      gshhgResolutionCode(spec.resolution);
    } catch (const ChartError& e) {
      c.fail(n["resolution"], "charts.resolution", e.what());
    }
  }
  if (n["layer"])
    spec.layer = c.text(n, "layer", "charts.");
  if (n["radius_m"])
    spec.radius_m = c.number(n, "radius_m", "charts.");
  if (n["simplify_m"])
    spec.simplify_m = c.number(n, "simplify_m", "charts.");
  try {
    spec.validate();  // the loader's own rule (charts.h): radius_m, simplify_m
  } catch (const ChartError& e) {
    c.fail(n, "charts", e.what());
  }
  if (n["clearance_m"]) {
    if (s.min_obstacle_clearance > 0.0)
      c.fail(n["clearance_m"], "charts.clearance_m", "the clearance is given under safety already");
    s.min_obstacle_clearance = c.number(n, "clearance_m", "charts.");
    if (!(s.min_obstacle_clearance > 0.0))
      c.fail(n["clearance_m"], "charts.clearance_m", "must be > 0 m");
  }
  s.charts = spec;
}

// One sensor_faults entry: type, the target(s) it concerns, start and duration.
SensorFault readSensorFault(const Ctx& c, const YAML::Node& n, const std::string& w, const Scenario& s) {
  c.onlyKeys(n, w, {"type", "ship", "with", "start_s", "duration_s"});
  SensorFault f;
  const std::string type = c.text(n, "type", w + ".");
  if (type == "ais_silence")
    f.type = SensorFault::Type::AisSilence;
  else if (type == "radar_loss")
    f.type = SensorFault::Type::RadarLoss;
  else if (type == "radar_swap")
    f.type = SensorFault::Type::RadarSwap;
  else
    c.fail(n["type"], w + ".type", "must be ais_silence, radar_loss or radar_swap");
  auto target = [&](const std::string& key) {
    std::string name = c.text(n, key, w + ".");
    for (const auto& t : s.targets)
      if (t.name == name)
        return name;
    c.fail(n[key], w + "." + key, "no target named '" + name + "'");
  };
  f.ship = target("ship");
  if (f.type == SensorFault::Type::RadarSwap) {
    f.with = target("with");
    if (f.with == f.ship)
      c.fail(n["with"], w + ".with", "a ship cannot swap with herself");
  } else if (n["with"]) {
    c.fail(n["with"], w + ".with", "only for radar_swap");
  }
  f.start = c.number(n, "start_s", w + ".");
  f.duration = c.number(n, "duration_s", w + ".");
  if (!(f.start >= 0.0) || !(f.duration > 0.0) || f.start + f.duration > 1e7)
    c.fail(n, w, "needs start_s >= 0 and duration_s > 0");
  return f;
}

// human: the logged master's figures, each finite and not negative (times and paths > 0).
std::optional<HumanRecord> readHuman(const Ctx& c, const YAML::Node& root) {
  if (!root["human"])
    return std::nullopt;
  const YAML::Node n = root["human"];
  c.onlyKeys(n, "human", {"min_separation_m", "time_s", "path_m"});
  HumanRecord h;
  h.min_separation_m = c.number(n, "min_separation_m", "human.");
  h.time_s = c.number(n, "time_s", "human.");
  h.path_m = c.number(n, "path_m", "human.");
  if (h.min_separation_m < 0.0 || !(h.time_s > 0.0) || !(h.path_m > 0.0))
    c.fail(n, "human", "needs min_separation_m >= 0, time_s > 0 and path_m > 0");
  return h;
}

Scenario parseYaml(const std::string& yaml_text, const std::string& source) {
  const Ctx c(source);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    throw ScenarioError(source + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
  if (!root.IsMap())
    throw ScenarioError(source + ": a scenario file must be a YAML mapping");
  c.onlyKeys(root, "",
             {"format", "name", "description", "duration_s", "origin", "safety", "own_ship", "targets",
              "static_obstacles", "charts", "planner_params", "sensor_faults", "human"});
  Scenario s;
  s.source = source;
  readHeader(c, root, s);
  readShips(c, root, s);
  readObstacles(c, root, s);
  checkRouteOffLand(s);
  readCharts(c, root, s);
  s.human = readHuman(c, root);
  if (root["sensor_faults"]) {
    const YAML::Node fl = root["sensor_faults"];
    if (!fl.IsSequence())
      c.fail(fl, "sensor_faults", "expected a list");
    for (size_t i = 0; i < fl.size(); ++i)
      s.sensor_faults.push_back(readSensorFault(c, fl[i], "sensor_faults[" + std::to_string(i) + "]", s));
  }
  if (root["planner_params"]) {
    std::size_t budget = kMaxPlannerParamNodes;
    flatten(c, root["planner_params"], "", s.planner_params, budget);
  }
  return s;
}

}  // namespace

const char* toString(SensorFault::Type t) {
  switch (t) {
    case SensorFault::Type::AisSilence:
      return "ais_silence";
    case SensorFault::Type::RadarLoss:
      return "radar_loss";
    case SensorFault::Type::RadarSwap:
      return "radar_swap";
  }
  return "?";
}

void checkRouteOffLand(const Scenario& s) {
  const Route& route = s.own.route;
  const auto on_land = legOnLand(route, s.own.position, s.obstacles);
  if (!on_land)
    return;
  const int leg = on_land->leg;
  const std::string& land = on_land->land;
  const auto line = static_cast<size_t>(leg) < s.own.route_lines.size() ? s.own.route_lines[leg] : 0;
  const std::string& file = s.own.route_source.empty() ? s.source : s.own.route_source;
  throw ScenarioError(file + (line > 0 ? ":" + std::to_string(line) : "") + ": 'own_ship.route[" +
                      std::to_string(leg) + "]': leg " + std::to_string(leg + 1) +
                      " (to this waypoint from " +
                      (leg == 0 ? std::string("the start") : "waypoint " + std::to_string(leg - 1)) +
                      ") crosses '" + land + "'");
}

Scenario parseScenario(const std::string& yaml_text, const std::string& source) {
  try {
    return parseYaml(yaml_text, source);
  } catch (const YAML::Exception& e) {
    // yaml-cpp's own conversion errors (a sequence or a mapping used as a key, ...): a ScenarioError
    // naming the file like every other error, as scenario.h promises.
    throw ScenarioError(source + (e.mark.is_null() ? "" : ":" + std::to_string(e.mark.line + 1)) + ": " +
                        e.msg);
  }
}

}  // namespace asv
