// Plane geometry shared by the planners and the simulator (ENU metres).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace asv {

// z component of the cross product a x b.
inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// The point of the closed segment a-b nearest to p (a when the segment has no length).
inline Eigen::Vector2d nearestPointOnSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                             const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double s = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return a + s * ab;
}

// Shortest distance from p to the closed segment a-b (to a when the segment has no length).
inline double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                   const Eigen::Vector2d& b) {
  return (nearestPointOnSegment(p, a, b) - p).norm();
}

// Closed segments a-b and c-d share a point (touching and collinear overlap included).
inline bool segmentsIntersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                              const Eigen::Vector2d& d) {
  const double d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a);
  const double d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  auto onSegment = [](const Eigen::Vector2d& s0, const Eigen::Vector2d& s1, const Eigen::Vector2d& r,
                      double c) { return c == 0.0 && (r - s0).dot(r - s1) <= 0.0; };
  return onSegment(a, b, c, d1) || onSegment(a, b, d, d2) || onSegment(c, d, a, d3) || onSegment(c, d, b, d4);
}

using Polygon = std::vector<Eigen::Vector2d>;  // vertices in order (either sense), ENU [m]

// `sides` vertices `r` from `centre`, counter-clockwise, the first at ENU angle `first` [rad from east].
Polygon regularPolygon(const Eigen::Vector2d& centre, double r, int sides, double first);

// Point-in-polygon by the crossing rule (even-odd); works for convex and concave simple polygons.
// Points exactly on an edge count as inside.
bool pointInPolygon(const Polygon& poly, const Eigen::Vector2d& p);

// Shortest distance between the segment p-q and the boundary of `poly` (0 when they cross or touch).
// A segment wholly inside the polygon is its distance to the boundary: see segmentObstacleDistance.
double segmentPolygonDistance(const Polygon& poly, const Eigen::Vector2d& p, const Eigen::Vector2d& q);

// Shortest distance from the segment p-q to the area of `poly`: 0 when any part of it lies inside or
// on the boundary. How far a straight leg of a track passes from an obstacle.
double segmentObstacleDistance(const Polygon& poly, const Eigen::Vector2d& p, const Eigen::Vector2d& q);

// Length [m] of the segment p->q inside the polygon (exact: edge crossings, then even-odd per piece).
double segmentLengthInside(const Polygon& poly, const Eigen::Vector2d& p, const Eigen::Vector2d& q);

// Shortest distance between the areas of two polygons: 0 when they overlap or touch (one inside the
// other included). How far a hull outline is from land.
double polygonDistance(const Polygon& a, const Polygon& b);

// The axis-aligned box round a polygon's vertices (empty for no vertices).
Eigen::AlignedBox2d boundingBox(const Polygon& poly);

// Triangles covering a simple polygon (convex or concave, either sense), by ear clipping: index
// triples into `poly`, n - 2 of them. Empty for fewer than 3 vertices. For filled drawings of land.
std::vector<std::array<int, 3>> triangulate(const Polygon& poly);

// The outline of the area within `distance` of a polygon (its clearance zone), round joins, as outer
// rings (Boost.Geometry buffer; `points_per_circle` segments a full circle). Empty for an invalid polygon.
std::vector<Polygon> offsetOutline(const Polygon& poly, double distance, int points_per_circle = 36);

// A ship's hull outline: the length x beam rectangle centred on the reference point, along `heading`
// [rad, nautical], corners in order (bow starboard, stern starboard, stern port, bow port).
Polygon hullOutline(const Eigen::Vector2d& position, double heading, double length, double beam);

}  // namespace asv
