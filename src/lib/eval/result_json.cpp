// The run result as JSON (one object per run, the format asv_batch and the evaluator node write) and
// as the one-line and table summaries printed after a run.
#include <cmath>
#include <sstream>

#include "asv_core/common/format.h"
#include "asv_core/common/units.h"
#include "asv_core/eval/evaluation.h"
#include "json_tree.h"

namespace asv {

using namespace json_tree;  // the tree, its writer and the precisions

namespace {

Json latLonJson(const LocalFrame& frame, const Eigen::Vector2d& p) {
  const GeoPoint g = frame.toGeodetic(p);
  Json o = Json::object();
  o.add("lat_deg", Json::number(g.lat_deg, kLatLon));
  o.add("lon_deg", Json::number(g.lon_deg, kLatLon));
  return o;
}

Json targetJson(const TargetResult& t, const LocalFrame& frame) {
  Json o = Json::object();
  o.add("name", Json::string(t.name));
  o.add("encounter", Json::string(toString(t.encounter)));
  o.add("own_role", Json::string(toString(t.role)));
  o.add("min_distance_m", Json::number(t.min_distance, kMetres));
  o.add("tcpa_at_start_s", Json::number(t.tcpa_at_start, kSeconds));
  o.add("dcpa_at_start_m", Json::number(t.dcpa_at_start, kMetres));
  if (std::isfinite(t.closest_time)) {
    Json c = Json::object();
    c.add("t_s", Json::number(t.closest_time, kSeconds));
    c.add("own", latLonJson(frame, t.own_at_closest));
    c.add("target", latLonJson(frame, t.target_at_closest));
    o.add("closest_approach", c);
  }
  o.add("colregs_ok", Json::boolean(t.colregs_ok));
  Json notes = Json::array();
  for (const auto& n : t.notes)
    notes.arr.push_back(Json::string(n));
  o.add("colregs_notes", notes);
  o.add("colregs_score", Json::number(t.score, kRatio));
  // The side of the own ship's first alteration of action_course_deg or more while the risk lasted.
  o.add("first_alteration", t.first_side == 0  ? Json()
                            : t.first_side > 0 ? Json::string("starboard")
                                               : Json::string("port"));
  return o;
}

Json manoeuvresJson(const std::vector<Manoeuvre>& ms) {
  Json a = Json::array();
  for (const auto& m : ms) {
    Json o = Json::object();
    o.add("t_s", Json::number(m.time, kSeconds));
    o.add("course_change_deg", Json::number(radToDeg(m.course_change), kDegrees));
    a.arr.push_back(o);
  }
  return a;
}

Json targetsJson(const std::vector<TargetResult>& ts, const LocalFrame& frame) {
  Json a = Json::array();
  for (const auto& t : ts)
    a.arr.push_back(targetJson(t, frame));
  return a;
}

}  // namespace

void zeroWallClock(RunResult& r) {
  r.wall_time = 0.0;
  if (r.plan_time.count > 0)
    r.plan_time.median_ms = r.plan_time.max_ms = 0.0;
}

std::string toJson(const RunResult& r, bool pretty) {
  const LocalFrame frame(r.origin.lat_deg, r.origin.lon_deg);
  Json o = Json::object();
  o.add("scenario", Json::string(r.scenario));
  o.add("planner", Json::string(r.planner));
  o.add("seed", Json::integer(static_cast<long long>(r.seed)));
  o.add("collision", Json::boolean(r.collision));
  o.add("collisions_between_targets", Json::integer(r.collisions_between_targets));
  o.add("grounding", Json::boolean(r.own.grounding));
  o.add("min_obstacle_distance_m", Json::number(r.own.min_obstacle_distance, kMetres));
  o.add("min_separation_m", Json::number(r.own.min_separation, kMetres));
  o.add("safety_violation", Json::boolean(r.safety_violation));
  o.add("arrived", Json::boolean(r.own.arrived));
  o.add("time_to_goal_s", Json::number(r.own.time_to_goal, kSeconds));
  o.add("path_length_m", Json::number(r.own.path_length, kMetres));
  o.add("path_ratio", Json::number(r.own.path_ratio, kRatio));
  o.add("manoeuvres", manoeuvresJson(r.own.manoeuvres));
  o.add("targets", targetsJson(r.own.targets, frame));
  o.add("colregs_score", Json::number(r.own.colregs_score, kRatio));
  Json pt = Json::object();
  pt.add("median", Json::number(r.plan_time.median_ms, kMs));
  pt.add("max", Json::number(r.plan_time.max_ms, kMs));
  pt.add("count", Json::integer(r.plan_time.count));
  o.add("plan_time_ms", pt);
  o.add("wall_time_s", Json::number(r.wall_time, kMs));
  if (r.human) {
    Json h = Json::object();
    h.add("min_separation_m", Json::number(r.human->min_separation_m, kMetres));
    h.add("time_s", Json::number(r.human->time_s, kSeconds));
    h.add("path_m", Json::number(r.human->path_m, kMetres));
    o.add("human", h);
    o.add("separation_vs_human", Json::number(r.separation_vs_human, kRatio));
    o.add("time_vs_human", Json::number(r.time_vs_human, kRatio));
  }
  if (r.route.legs > 0) {
    Json rt = Json::object();
    rt.add("legs", Json::integer(static_cast<long>(r.route.legs)));
    rt.add("max_xte_m", Json::number(r.route.max_xte, kMetres));
    rt.add("outside_corridor_s", Json::number(r.route.outside_corridor, kSeconds));
    o.add("route", rt);
  }
  if (std::isfinite(r.passing_max)) {
    Json pd = Json::object();
    pd.add("min", Json::number(r.passing_min, kMetres));
    pd.add("max", Json::number(r.passing_max, kMetres));
    o.add("passing_distance_m", pd);
  }
  if (r.multi_agent) {
    Json ships = Json::array();
    for (const auto& s : r.ships) {
      Json e = Json::object();
      e.add("name", Json::string(s.name));
      e.add("planner", Json::string(s.planner));
      e.add("collision", Json::boolean(s.collision));
      e.add("grounding", Json::boolean(s.grounding));
      e.add("min_obstacle_distance_m", Json::number(s.min_obstacle_distance, kMetres));
      e.add("min_separation_m", Json::number(s.min_separation, kMetres));
      e.add("arrived", Json::boolean(s.arrived));
      e.add("time_to_goal_s", Json::number(s.time_to_goal, kSeconds));
      e.add("path_length_m", Json::number(s.path_length, kMetres));
      e.add("path_ratio", Json::number(s.path_ratio, kRatio));
      e.add("manoeuvres", manoeuvresJson(s.manoeuvres));
      e.add("targets", targetsJson(s.targets, frame));
      e.add("colregs_score", Json::number(s.colregs_score, kRatio));
      ships.arr.push_back(e);
    }
    o.add("ships", ships);
  }
  std::string out;
  write(o, pretty, 0, out);
  return out;
}

std::string summaryLine(const RunResult& r) {
  std::ostringstream os;
  os << r.scenario << " / " << r.planner << " / seed " << r.seed << ": "
     << (r.collision ? "COLLISION" : "no collision");
  if (r.own.grounding)
    os << ", GROUNDING";
  if (std::isfinite(r.own.min_separation))
    os << strFormat(", min sep %.0f m", r.own.min_separation);
  else
    os << ", no other ship";
  if (r.safety_violation)
    os << " (SAFETY VIOLATION)";
  if (r.own.arrived)
    os << strFormat(", arrived in %.0f s", r.own.time_to_goal);
  else
    os << ", not arrived";
  if (std::isfinite(r.own.path_ratio))
    os << strFormat(", path ratio %.3f", r.own.path_ratio);
  if (r.route.legs > 0)
    os << strFormat(", off route max %.0f m", r.route.max_xte);
  if (r.human && std::isfinite(r.separation_vs_human))
    os << strFormat(", sep %.2fx the master's", r.separation_vs_human);
  if (r.human && std::isfinite(r.time_vs_human))
    os << strFormat(", time %.2fx hers", r.time_vs_human);
  os << strFormat(", COLREGs %.2f", r.own.colregs_score);
  if (r.plan_time.count > 0)
    os << strFormat(", plan %.1f ms median", r.plan_time.median_ms) << " (" << r.plan_time.count << ")";
  return os.str();
}

std::string summaryTable(const RunResult& r) {
  std::ostringstream os;
  os << summaryLine(r) << "\n";
  char buf[256];
  std::snprintf(buf, sizeof buf, "  %-12s %-16s %-9s %10s %10s %10s %6s %s\n", "target", "encounter", "role",
                "min_dist_m", "tcpa0_s", "dcpa0_m", "score", "notes");
  os << buf;
  for (const auto& t : r.own.targets) {
    std::string notes;
    for (const auto& n : t.notes)
      notes += (notes.empty() ? "" : "; ") + n;
    std::snprintf(buf, sizeof buf, "  %-12s %-16s %-9s %10.0f %10.0f %10.0f %6.2f ", t.name.c_str(),
                  toString(t.encounter), toString(t.role), t.min_distance, t.tcpa_at_start, t.dcpa_at_start,
                  t.score);
    os << buf << notes << "\n";
  }
  for (const auto& m : r.own.manoeuvres)
    os << strFormat("  manoeuvre at t=%.0f s: %+.1f deg\n", m.time, radToDeg(m.course_change));
  return os.str();
}

}  // namespace asv
