#include "asv_core/common/obstacle_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

namespace asv {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BSegment = bg::model::segment<BPoint>;
using Edge = std::pair<BSegment, size_t>;  // an edge and the polygon it belongs to

struct ObstacleIndex::Tree {
  // Node size 8: of 4, 8, 16 and 32, 4 and 8 answered fastest on a 10,000-edge coast (bench_land).
  bgi::rtree<Edge, bgi::rstar<8>> edges;
  Eigen::AlignedBox2d bounds;  // of every edge: where the inside test's ray ends
  size_t polygons = 0;
};

namespace {
BPoint bp(const Eigen::Vector2d& v) {
  return BPoint(v.x(), v.y());
}
}  // namespace

ObstacleIndex::ObstacleIndex() : tree_(std::make_unique<Tree>()) {}

ObstacleIndex::ObstacleIndex(const std::vector<Polygon>& polygons) : tree_(std::make_unique<Tree>()) {
  std::vector<Edge> all;
  for (size_t k = 0; k < polygons.size(); ++k) {
    const Polygon& p = polygons[k];
    for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
      all.push_back({BSegment(bp(p[j]), bp(p[i])), k});
      tree_->bounds.extend(p[i]);
    }
  }
  tree_->polygons = polygons.size();
  tree_->edges = decltype(tree_->edges)(all.begin(), all.end());  // bulk loading (packing)
}

ObstacleIndex::ObstacleIndex(ObstacleIndex&&) noexcept = default;
ObstacleIndex& ObstacleIndex::operator=(ObstacleIndex&&) noexcept = default;
ObstacleIndex::~ObstacleIndex() = default;

bool ObstacleIndex::empty() const {
  return tree_->edges.empty();
}
size_t ObstacleIndex::edges() const {
  return tree_->edges.size();
}

// The crossing rule of pointInPolygon, per polygon, over the edges that a ray from p meets. The ray
// runs to the nearest side of the bounds, to meet as few edges as possible; pointInPolygon's horizontal
// rule is kept by swapping the axes for a vertical ray.
bool ObstacleIndex::inside(const Eigen::Vector2d& p) const {
  const Eigen::AlignedBox2d& box = tree_->bounds;
  if (empty() || !box.contains(p))
    return false;
  const double to_side[4] = {box.max().x() - p.x(), p.x() - box.min().x(), box.max().y() - p.y(),
                             p.y() - box.min().y()};
  const int dir = static_cast<int>(std::min_element(to_side, to_side + 4) - to_side);
  const int axis = dir < 2 ? 0 : 1;  // along x (horizontal ray) or y
  const double sign = dir % 2 == 0 ? 1.0 : -1.0;
  Eigen::Vector2d end = p;
  end[axis] += sign * (to_side[dir] + 1.0);
  const bg::model::box<BPoint> ray(bp(p.cwiseMin(end)), bp(p.cwiseMax(end)));
  std::vector<char> odd(tree_->polygons, 0);
  for (auto it = tree_->edges.qbegin(bgi::intersects(ray)); it != tree_->edges.qend(); ++it) {
    const Eigen::Vector2d a(bg::get<0, 0>(it->first), bg::get<0, 1>(it->first));
    const Eigen::Vector2d b(bg::get<1, 0>(it->first), bg::get<1, 1>(it->first));
    if (pointSegmentDistance(p, a, b) == 0.0)
      return true;           // on the boundary: inside, as pointInPolygon
    const int o = 1 - axis;  // the other axis
    if ((a[o] > p[o]) != (b[o] > p[o])) {
      const double cross = (b[axis] - a[axis]) * (p[o] - a[o]) / (b[o] - a[o]) + a[axis];
      if (sign * (cross - p[axis]) > 0.0)
        odd[it->second] ^= 1;
    }
  }
  return std::find(odd.begin(), odd.end(), 1) != odd.end();
}

double ObstacleIndex::distance(const Eigen::Vector2d& p) const {
  return distance(p, p);
}

double ObstacleIndex::distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  if (empty())
    return std::numeric_limits<double>::infinity();
  return inside(a) ? 0.0 : boundaryDistance(a, b);
}

double ObstacleIndex::boundaryDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  const BSegment s(bp(a), bp(b));
  double best = std::numeric_limits<double>::infinity();
  for (auto it = tree_->edges.qbegin(bgi::nearest(s, 1)); it != tree_->edges.qend(); ++it)
    best = std::min(best, bg::distance(s, it->first));
  return best;
}

// The segment is cut where it crosses an edge; each piece is in or out by its middle.
double ObstacleIndex::lengthInside(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  const Eigen::Vector2d d = b - a;
  const double len = d.norm();
  if (empty() || len <= 0.0)
    return 0.0;
  std::vector<double> cuts{0.0, 1.0};
  const bg::model::box<BPoint> box(bp(a.cwiseMin(b)), bp(a.cwiseMax(b)));
  for (auto it = tree_->edges.qbegin(bgi::intersects(box)); it != tree_->edges.qend(); ++it) {
    const Eigen::Vector2d p(bg::get<0, 0>(it->first), bg::get<0, 1>(it->first));
    const Eigen::Vector2d e = Eigen::Vector2d(bg::get<1, 0>(it->first), bg::get<1, 1>(it->first)) - p;
    const double den = cross2(d, e);
    if (std::fabs(den) < 1e-12 * len * e.norm())
      continue;  // parallel: any overlap is caught by the middle tests
    const double s = cross2(p - a, e) / den, u = cross2(p - a, d) / den;
    if (s > 0.0 && s < 1.0 && u >= 0.0 && u <= 1.0)
      cuts.push_back(s);
  }
  std::sort(cuts.begin(), cuts.end());
  double in = 0.0;
  for (size_t i = 1; i < cuts.size(); ++i)
    if (cuts[i] > cuts[i - 1] && inside(a + d * (0.5 * (cuts[i] + cuts[i - 1]))))
      in += (cuts[i] - cuts[i - 1]) * len;
  return in;
}

}  // namespace asv
