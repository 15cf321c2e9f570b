// A run as GeoJSON (RFC 7946) for a chart viewer: tracks, closest approaches, manoeuvres, land.
#include <cmath>

#include "asv_core/common/units.h"
#include "asv_core/eval/evaluation.h"
#include "json_tree.h"

namespace asv {

using namespace json_tree;  // the tree, its writer and the precisions

namespace {

// GeoJSON pieces (RFC 7946): positions [longitude, latitude], features with a "kind" property.
Json lonLat(const LocalFrame& frame, const Eigen::Vector2d& p) {
  const GeoPoint g = frame.toGeodetic(p);
  Json a = Json::array();
  a.arr.push_back(Json::number(g.lon_deg, kLatLon));
  a.arr.push_back(Json::number(g.lat_deg, kLatLon));
  return a;
}

Json feature(const std::string& type, Json coordinates, Json properties) {
  Json geometry = Json::object();
  geometry.add("type", Json::string(type));
  geometry.add("coordinates", std::move(coordinates));
  Json f = Json::object();
  f.add("type", Json::string("Feature"));
  f.add("geometry", std::move(geometry));
  f.add("properties", std::move(properties));
  return f;
}

Json kind(const std::string& k) {
  Json p = Json::object();
  p.add("kind", Json::string(k));
  return p;
}

Json line(const LocalFrame& frame, const std::vector<Eigen::Vector2d>& points) {
  Json a = Json::array();
  for (const auto& p : points)
    a.arr.push_back(lonLat(frame, p));
  return a;
}

// The own ship's closest approach to one target: her position (a Point) and the line to the target.
void closestApproach(const LocalFrame& frame, const TargetResult& t, Json& features) {
  if (!std::isfinite(t.closest_time))
    return;
  Json p = kind("closest_approach");
  p.add("target", Json::string(t.name));
  p.add("distance_m", Json::number(t.min_distance, kMetres));
  p.add("t_s", Json::number(t.closest_time, kSeconds));
  features.arr.push_back(feature("Point", lonLat(frame, t.own_at_closest), p));
  Json l = kind("closest_approach_line");
  l.add("target", Json::string(t.name));
  l.add("distance_m", Json::number(t.min_distance, kMetres));
  features.arr.push_back(feature("LineString", line(frame, {t.own_at_closest, t.target_at_closest}), l));
}

}  // namespace

std::string RunRecorder::geoJson(const RunResult& r) const {
  const LocalFrame frame(info_.origin.lat_deg, info_.origin.lon_deg);
  Json features = Json::array();
  for (const StaticObstacle& o : info_.obstacles) {
    std::vector<Eigen::Vector2d> ring = o.polygon;
    if (!ring.empty())
      ring.push_back(ring.front());  // a closed ring
    Json rings = Json::array();
    rings.arr.push_back(line(frame, ring));
    Json p = kind("land");
    p.add("name", Json::string(o.name));
    features.arr.push_back(feature("Polygon", std::move(rings), p));
  }
  for (size_t i = 0; i < tracks_.size(); ++i) {
    std::vector<Eigen::Vector2d> pts;
    for (const Point& pt : tracks_[i].points)
      pts.push_back(pt.s.position);
    if (pts.size() < 2)
      continue;
    Json p = kind("track");
    p.add("ship", Json::string(info_.ships[i].name));
    p.add("own", Json::boolean(i == 0));
    features.arr.push_back(feature("LineString", line(frame, pts), p));
  }
  for (const TargetResult& t : r.own.targets)
    closestApproach(frame, t, features);
  for (const Manoeuvre& m : r.own.manoeuvres) {
    const auto& own = tracks_[0].points;
    const auto at =
        std::lower_bound(own.begin(), own.end(), m.time, [](const Point& p, double t) { return p.t < t; });
    if (at == own.end())
      continue;
    Json p = kind("manoeuvre");
    p.add("t_s", Json::number(m.time, kSeconds));
    p.add("course_change_deg", Json::number(radToDeg(m.course_change), kDegrees));
    features.arr.push_back(feature("Point", lonLat(frame, at->s.position), p));
  }
  Json fc = Json::object();
  fc.add("type", Json::string("FeatureCollection"));
  fc.add("features", std::move(features));
  std::string out;
  write(fc, false, 0, out);
  return out + "\n";
}

}  // namespace asv
