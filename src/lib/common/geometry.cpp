#include "asv_core/common/geometry.h"

#include <cmath>
#include <limits>

#include "asv_core/common/units.h"

// GCC 12 warns inside Boost's round buffer join (a point it fills by reference): not our code.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/geometry.hpp>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace asv {

Polygon regularPolygon(const Eigen::Vector2d& centre, double r, int sides, double first) {
  Polygon poly;
  for (int k = 0; k < sides; ++k) {
    const double a = first + 2.0 * kPi * k / sides;
    poly.push_back(centre + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return poly;
}

bool pointInPolygon(const Polygon& poly, const Eigen::Vector2d& p) {
  const size_t n = poly.size();
  if (n < 3)
    return false;
  bool inside = false;
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = poly[i];
    const Eigen::Vector2d& b = poly[j];
    // On-edge test: collinear and within the segment's bounding box.
    const Eigen::Vector2d ab = b - a, ap = p - a;
    const double cross = ab.x() * ap.y() - ab.y() * ap.x();
    const double scale = ab.norm() * ap.norm();
    if (std::fabs(cross) <= 1e-12 * std::max(1.0, scale) && ap.dot(p - b) <= 0.0)
      return true;
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x_cross = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x_cross)
        inside = !inside;
    }
  }
  return inside;
}

double segmentPolygonDistance(const Polygon& poly, const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  const size_t n = poly.size();
  double best = std::numeric_limits<double>::infinity();
  const Eigen::Vector2d lo = p.cwiseMin(q), hi = p.cwiseMax(q);
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = poly[j];
    const Eigen::Vector2d& b = poly[i];
    // The gap between the two segments' boxes is a lower bound of their distance: an edge whose gap
    // exceeds the best so far cannot lower it (nor cross: the boxes are apart). Skipping it leaves the
    // result unchanged and saves most of the work on a polygon far from most of its edges.
    const Eigen::Vector2d gap =
        (a.cwiseMin(b) - hi).cwiseMax(lo - a.cwiseMax(b)).cwiseMax(Eigen::Vector2d::Zero());
    if (gap.squaredNorm() > best * best * (1.0 + 1e-9))
      continue;
    if (segmentsIntersect(p, q, a, b))
      return 0.0;
    best = std::min({best, pointSegmentDistance(p, a, b), pointSegmentDistance(q, a, b),
                     pointSegmentDistance(a, p, q), pointSegmentDistance(b, p, q)});
  }
  return best;
}

double segmentObstacleDistance(const Polygon& poly, const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  if (poly.size() >= 3 && pointInPolygon(poly, p))
    return 0.0;
  return segmentPolygonDistance(poly, p, q);
}

double polygonDistance(const Polygon& a, const Polygon& b) {
  if (a.empty() || b.empty())
    return std::numeric_limits<double>::infinity();
  if (pointInPolygon(b, a.front()) || pointInPolygon(a, b.front()))
    return 0.0;  // one inside the other (or touching at that vertex)
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 0, j = a.size() - 1; i < a.size() && best > 0.0; j = i++)
    best = std::min(best, segmentPolygonDistance(b, a[j], a[i]));
  return best;
}

Eigen::AlignedBox2d boundingBox(const Polygon& poly) {
  Eigen::AlignedBox2d box;  // empty
  for (const auto& v : poly)
    box.extend(v);
  return box;
}

namespace {

// p lies inside or on the triangle a-b-c (counter-clockwise).
bool inTriangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                const Eigen::Vector2d& c) {
  return cross2(b - a, p - a) >= 0.0 && cross2(c - b, p - b) >= 0.0 && cross2(a - c, p - c) >= 0.0;
}

}  // namespace

std::vector<std::array<int, 3>> triangulate(const Polygon& poly) {
  std::vector<std::array<int, 3>> out;
  const int n = static_cast<int>(poly.size());
  if (n < 3)
    return out;
  double area2 = 0.0;
  for (int i = 0, j = n - 1; i < n; j = i++)
    area2 += cross2(poly[j], poly[i]);
  std::vector<int> idx(n);
  for (int i = 0; i < n; ++i)
    idx[i] = area2 >= 0.0 ? i : n - 1 - i;  // counter-clockwise order
  // An ear: a convex corner whose triangle holds no other vertex. A simple polygon always has one;
  // a degenerate input (self-crossing) may not, and then the rest is left uncovered.
  while (idx.size() > 3) {
    const int m = static_cast<int>(idx.size());
    bool clipped = false;
    for (int k = 0; k < m && !clipped; ++k) {
      const int a = idx[(k + m - 1) % m], b = idx[k], c = idx[(k + 1) % m];
      if (cross2(poly[b] - poly[a], poly[c] - poly[b]) <= 0.0)
        continue;  // reflex or flat
      bool empty = true;
      for (int v : idx)
        empty = empty && (v == a || v == b || v == c || !inTriangle(poly[v], poly[a], poly[b], poly[c]));
      if (!empty)
        continue;
      out.push_back({a, b, c});
      idx.erase(idx.begin() + k);
      clipped = true;
    }
    if (!clipped)
      return out;
  }
  out.push_back({idx[0], idx[1], idx[2]});
  return out;
}

Polygon hullOutline(const Eigen::Vector2d& position, double heading, double length, double beam) {
  const Eigen::Vector2d fwd(std::sin(heading), std::cos(heading));  // nautical: x east, y north
  const Eigen::Vector2d stbd(fwd.y(), -fwd.x());
  const Eigen::Vector2d l = 0.5 * length * fwd, b = 0.5 * beam * stbd;
  return {position + l + b, position - l + b, position - l - b, position + l - b};
}

double segmentLengthInside(const Polygon& poly, const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  const size_t n = poly.size();
  if (n < 3)
    return 0.0;
  const Eigen::Vector2d d = q - p;
  const double len = d.norm();
  if (len <= 0.0)
    return 0.0;
  double cuts[64];
  std::vector<double> many;
  size_t k = 0;
  auto add = [&](double s) {
    if (k < 64)
      cuts[k++] = s;
    else
      many.push_back(s);
  };
  add(0.0);
  add(1.0);
  for (size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d e = poly[i] - poly[j];
    const double den = cross2(d, e);
    if (std::fabs(den) < 1e-12 * len * e.norm())
      continue;  // parallel: any overlap is caught by the midpoint tests
    const Eigen::Vector2d ap = poly[j] - p;
    const double s = cross2(ap, e) / den;
    const double u = cross2(ap, d) / den;
    if (s > 0.0 && s < 1.0 && u >= 0.0 && u <= 1.0)
      add(s);
  }
  std::vector<double> all(cuts, cuts + k);
  all.insert(all.end(), many.begin(), many.end());
  std::sort(all.begin(), all.end());
  double inside = 0.0;
  for (size_t i = 1; i < all.size(); ++i) {
    const double ds = all[i] - all[i - 1];
    if (ds <= 0.0)
      continue;
    if (pointInPolygon(poly, p + d * (0.5 * (all[i] + all[i - 1]))))
      inside += ds * len;
  }
  return inside;
}

std::vector<Polygon> offsetOutline(const Polygon& poly, double distance, int points_per_circle) {
  namespace bg = boost::geometry;
  using BPoint = bg::model::d2::point_xy<double>;
  using BPolygon = bg::model::polygon<BPoint>;
  BPolygon in;
  for (const auto& v : poly)
    in.outer().emplace_back(v.x(), v.y());
  if (poly.size() < 3)
    return {};
  bg::correct(in);  // closes the ring and orients it as Boost expects
  bg::model::multi_polygon<BPolygon> out;
  bg::buffer(in, out, bg::strategy::buffer::distance_symmetric<double>(distance),
             bg::strategy::buffer::side_straight(), bg::strategy::buffer::join_round(points_per_circle),
             bg::strategy::buffer::end_round(points_per_circle),
             bg::strategy::buffer::point_circle(points_per_circle));
  std::vector<Polygon> rings;
  for (const auto& p : out) {
    Polygon r;
    for (const auto& v : p.outer())
      r.emplace_back(v.x(), v.y());
    if (r.size() > 1 && r.front() == r.back())
      r.pop_back();
    rings.push_back(std::move(r));
  }
  return rings;
}

}  // namespace asv
