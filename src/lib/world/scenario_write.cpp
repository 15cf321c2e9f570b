#include "asv_core/world/scenario_write.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "asv_core/common/format.h"
#include "asv_core/common/units.h"

namespace asv {
namespace {

// Every number of the file is written through strFormat with a fixed precision (header).

// A YAML double-quoted scalar: descriptions and names may hold any character.
std::string quoted(const std::string& text) {
  std::string q = "\"";
  for (char ch : text) {
    if (ch == '"' || ch == '\\')
      q += '\\';
    q += ch == '\n' ? ' ' : ch;
  }
  return q + "\"";
}

std::string point(const Eigen::Vector2d& p) {
  return strFormat("{x_m: %.1f, y_m: %.1f}", p.x(), p.y());
}

// A recorded track, one point a line.
void writeTrack(std::ostringstream& out, const std::vector<TrackPoint>& track, const std::string& i) {
  out << i << "track:\n";
  for (const auto& p : track)
    out << i << strFormat("  - {t_s: %.1f, x_m: %.1f, y_m: %.1f}\n", p.t, p.position.x(), p.position.y());
}

// A voyage plan, one waypoint a line, with the leg's speed and corridor where given.
void writeRoute(std::ostringstream& out, const Route& route, const std::string& i) {
  out << i << "route:\n";
  for (const auto& w : route) {
    out << i << strFormat("  - {x_m: %.1f, y_m: %.1f", w.position.x(), w.position.y());
    if (w.speed > 0.0)
      out << strFormat(", speed_kn: %.2f", mpsToKnots(w.speed));
    if (w.port_xtd > 0.0)
      out << strFormat(", port_xtd_m: %.1f", w.port_xtd);
    if (w.starboard_xtd > 0.0)
      out << strFormat(", starboard_xtd_m: %.1f", w.starboard_xtd);
    out << "}\n";
  }
}

void writeShip(std::ostringstream& out, const ScenarioShip& s, bool own, const std::string& indent) {
  const std::string in = indent + "  ";
  out << indent << (own ? "" : "- ") << "name: " << s.name << "\n";
  const std::string i = own ? indent : in;
  if (s.mmsi != 0)
    out << i << "mmsi: " << s.mmsi << "\n";
  out << i << "model: " << s.model << "\n";
  if (s.ais_class != 'A')
    out << i << "ais_class: " << s.ais_class << "\n";
  if (s.length > 0.0)
    out << i << strFormat("length_m: %.1f\n", s.length);
  if (s.beam > 0.0)
    out << i << strFormat("beam_m: %.1f\n", s.beam);
  out << i << "position: " << point(s.position) << "\n";
  // Rounded first, then wrapped: 359.96 deg is written 0.0, not 360.0 (outside [0, 360)).
  out << i << strFormat("course_deg: %.1f\n", wrapDeg360(std::round(radToDeg(s.course) * 10.0) / 10.0));
  out << i << strFormat("speed_kn: %.2f\n", mpsToKnots(s.speed));
  if (!s.route.empty())
    writeRoute(out, s.route, i);
  else if (s.goal)
    out << i << "goal: " << point(*s.goal) << "\n";
  if (s.goal_radius > 0.0)
    out << i << strFormat("goal_radius_m: %.1f\n", s.goal_radius);
  if (s.stays_at_goal)
    out << i << "stays_at_goal: true\n";
  if (!s.planner.empty())
    out << i << "planner: " << s.planner << "\n";
  if (own)
    return;
  out << i << "behaviour: " << toString(s.behaviour) << "\n";
  if (!s.waypoints.empty()) {
    out << i << "waypoints:\n";
    for (const auto& w : s.waypoints)
      out << i << "  - " << point(w) << "\n";
  }
  if (!s.track.empty())
    writeTrack(out, s.track, i);
}

// charts, with the scenario's obstacle clearance (written here, not under safety).
void writeCharts(std::ostringstream& out, const ChartSpec& c, double clearance) {
  out << "charts: {source: " << quoted(c.source) << ", resolution: " << c.resolution;
  if (!c.layer.empty())
    out << ", layer: " << quoted(c.layer);
  out << strFormat(", radius_m: %.0f, simplify_m: %.1f", c.radius_m, c.simplify_m);
  if (clearance > 0.0)
    out << strFormat(", clearance_m: %.1f", clearance);
  out << "}\n";
}

}  // namespace

std::string scenarioToYaml(const Scenario& s) {
  if (!s.sensor_faults.empty() || !s.planner_params.values().empty())
    throw std::invalid_argument("scenarioToYaml: sensor_faults and planner_params are not written");
  std::ostringstream out;
  out << "format: 1\nname: " << s.name << "\n";
  if (!s.description.empty())
    out << "description: " << quoted(s.description) << "\n";
  out << strFormat("duration_s: %.0f\n", s.duration);
  if (s.has_origin)
    out << strFormat("origin: {lat_deg: %.7f, lon_deg: %.7f}\n", s.origin.lat_deg, s.origin.lon_deg);
  out << strFormat("safety: {min_separation_m: %.1f", s.min_separation);
  if (s.min_obstacle_clearance > 0.0 && !s.charts)
    out << strFormat(", min_obstacle_clearance_m: %.1f", s.min_obstacle_clearance);
  out << "}\n";
  if (s.charts)
    writeCharts(out, *s.charts, s.min_obstacle_clearance);
  if (s.human)
    out << strFormat("human: {min_separation_m: %.1f, time_s: %.1f, path_m: %.1f}\n",
                     s.human->min_separation_m, s.human->time_s, s.human->path_m);
  out << "own_ship:\n";
  writeShip(out, s.own, true, "  ");
  if (!s.targets.empty())
    out << "targets:\n";
  for (const auto& t : s.targets)
    writeShip(out, t, false, "  ");
  if (!s.obstacles.empty())
    out << "static_obstacles:\n";
  for (const auto& o : s.obstacles) {
    out << "  - name: " << quoted(o.name) << "\n    polygon:\n";
    for (const auto& p : o.polygon)
      out << "      - " << point(p) << "\n";
  }
  return out.str();
}

}  // namespace asv
