#include "asv_core/world/obstacles.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "asv_core/common/units.h"

namespace asv {

StaticObstacle pointHazard(const std::string& name, const Eigen::Vector2d& centre, double radius) {
  constexpr int kSides = 8;
  constexpr double kMinRadius = 1.0;  // [m] a point still has an inside
  // A regular polygon whose edges touch the circle: its vertices are r / cos(pi / n) from the centre.
  const double r = std::max(radius, kMinRadius) / std::cos(kPi / kSides);
  return {name, regularPolygon(centre, r, kSides, kPi / kSides)};
}

double pointHazardRadius(double clearance, double min_obstacle_clearance) {
  return std::max(0.0, clearance - min_obstacle_clearance);
}

void indexObstacles(std::vector<StaticObstacle>& obstacles) {
  for (StaticObstacle& o : obstacles)
    if (!o.index && o.polygon.size() >= kIndexedObstacleVertices)
      o.index = std::make_shared<const ObstacleIndex>(std::vector<Polygon>{o.polygon});
}

bool insideObstacle(const StaticObstacle& o, const Eigen::Vector2d& p) {
  return o.index ? o.index->inside(p) : pointInPolygon(o.polygon, p);
}

double obstacleDistance(const StaticObstacle& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return o.index ? o.index->distance(a, b) : segmentObstacleDistance(o.polygon, a, b);
}

double obstacleBoundaryDistance(const StaticObstacle& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return o.index ? o.index->boundaryDistance(a, b) : segmentPolygonDistance(o.polygon, a, b);
}

double obstacleLengthInside(const StaticObstacle& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return o.index ? o.index->lengthInside(a, b) : segmentLengthInside(o.polygon, a, b);
}

double polygonObstacleDistance(const Polygon& outline, const StaticObstacle& o, double needed) {
  if (outline.empty())
    return polygonDistance(outline, o.polygon);
  if (!o.index) {
    const double box = boundingBox(outline).exteriorDistance(boundingBox(o.polygon));
    return box > needed ? box : polygonDistance(outline, o.polygon);
  }
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& v : outline)
    centre += v / static_cast<double>(outline.size());
  double radius = 0.0;
  for (const auto& v : outline)
    radius = std::max(radius, (v - centre).norm());
  const double bound = o.index->distance(centre) - radius;
  if (bound > needed)
    return bound;
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++)
    d = std::min(d, o.index->distance(outline[j], outline[i]));
  return d;
}

bool insideAnyObstacle(const std::vector<StaticObstacle>& obstacles, const Eigen::Vector2d& p) {
  return std::any_of(obstacles.begin(), obstacles.end(),
                     [&](const StaticObstacle& o) { return insideObstacle(o, p); });
}

std::optional<Eigen::Vector2d> nearestWater(const std::vector<StaticObstacle>& land, const Eigen::Vector2d& p,
                                            double max_depth, double margin) {
  if (!insideAnyObstacle(land, p))
    return p;
  // Candidates: past each edge within reach, straight out from p through its nearest point there.
  std::vector<std::pair<double, Eigen::Vector2d>> out;
  for (const StaticObstacle& o : land)
    for (size_t i = 0, j = o.polygon.size() - 1; i < o.polygon.size(); j = i++) {
      const Eigen::Vector2d c = nearestPointOnSegment(p, o.polygon[j], o.polygon[i]);
      const double d = (c - p).norm();
      if (d > 0.0 && d <= max_depth)
        out.emplace_back(d + margin, c + (c - p) / d * margin);
    }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [d, q] : out)
    if (!insideAnyObstacle(land, q))
      return q;
  return std::nullopt;
}

}  // namespace asv
