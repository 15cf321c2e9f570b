#include "asv_core/planning/land_route.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "asv_core/common/geometry.h"
#include "asv_core/common/units.h"

namespace asv {

namespace {

constexpr double kNodeMargin = 1.2;      // vertices are pushed out this many clearances
constexpr double kMaxStretch = 5.0;      // a sharp corner's push is capped at this many clearances
constexpr double kGapSpan = 6.0;         // gaps up to this many clearances wide get a node in the middle
constexpr double kGapApproach = 2.0;     // the lining-up points lie this many clearances off a gap
constexpr size_t kMaxGapVertices = 400;  // above this many vertices in all, no gap nodes (quadratic)

// A polygon's vertices pushed out along the bisector of their edges' outward normals, so far that
// both edge lines are `offset` away (capped at sharp corners).
void pushedVertices(const Polygon& poly, double offset, std::vector<Eigen::Vector2d>& out) {
  const size_t n = poly.size();
  if (n < 3)
    return;
  double area2 = 0.0;  // twice the signed area: > 0 counter-clockwise
  for (size_t i = 0, j = n - 1; i < n; j = i++)
    area2 += cross2(poly[j], poly[i]);
  const double sense = area2 > 0.0 ? 1.0 : -1.0;
  auto outward = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d e = (b - a).normalized();
    return Eigen::Vector2d(sense * e.y(), -sense * e.x());  // right of the edge for a CCW polygon
  };
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& prev = poly[(i + n - 1) % n];
    const Eigen::Vector2d& v = poly[i];
    const Eigen::Vector2d& next = poly[(i + 1) % n];
    if ((v - prev).norm() < 1e-9 || (next - v).norm() < 1e-9)
      continue;
    if (sense * cross2(v - prev, next - v) < 0.0)
      continue;  // a reflex corner (in a bay): a shortest way round land bends only at convex ones
    const Eigen::Vector2d n1 = outward(prev, v), n2 = outward(v, next);
    const Eigen::Vector2d bis = n1 + n2;
    if (bis.norm() < 1e-9)
      continue;  // a spike folding back on itself
    const double cos_half = std::max(bis.norm() / 2.0, 1.0 / kMaxStretch);
    out.push_back(v + bis.normalized() * (offset / cos_half));
  }
}

// The middle of every gap between two obstacles (a harbour entrance, a channel between islands), and a
// point two clearances off it on either side, square to the gap: pushed corners alone miss a passage
// narrower than two pushes, though its middle keeps the clearance, and a ship must line up with it
// before she passes (from the side, her leg would cut the heads).
void gapMiddles(const std::vector<StaticObstacle>& obstacles, double clearance,
                std::vector<Eigen::Vector2d>& out) {
  size_t total = 0;
  for (const auto& o : obstacles)
    total += o.polygon.size();
  if (total > kMaxGapVertices)
    return;
  for (size_t i = 0; i < obstacles.size(); ++i)
    for (size_t j = i + 1; j < obstacles.size(); ++j)
      for (const auto& u : obstacles[i].polygon)
        for (const auto& v : obstacles[j].polygon)
          if ((u - v).norm() <= kGapSpan * clearance && (u - v).norm() > 0.0) {
            const Eigen::Vector2d mid = 0.5 * (u + v), d = (v - u).normalized();
            const Eigen::Vector2d off = Eigen::Vector2d(-d.y(), d.x()) * (kGapApproach * clearance);
            out.push_back(mid);
            out.push_back(mid + off);
            out.push_back(mid - off);
          }
}

// `boxes`: the obstacles' bounding boxes (or none), to skip those farther than `required` cheaply.
bool clearLeg(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
              const std::vector<StaticObstacle>& obstacles, double required,
              const std::vector<Eigen::AlignedBox2d>& boxes = {}) {
  const Eigen::AlignedBox2d leg(a.cwiseMin(b), a.cwiseMax(b));
  for (size_t k = 0; k < obstacles.size(); ++k) {
    if (k < boxes.size() && leg.exteriorDistance(boxes[k]) >= required)
      continue;
    if (obstacleDistance(obstacles[k], a, b) < required)
      return false;
  }
  return true;
}

}  // namespace

std::vector<Eigen::Vector2d> truncateTrack(const std::vector<Eigen::Vector2d>& track, double reach) {
  std::vector<Eigen::Vector2d> out;
  if (track.empty())
    return out;
  out.push_back(track.front());
  double left = std::max(0.0, reach);
  for (size_t i = 1; i < track.size() && left > 0.0; ++i) {
    const Eigen::Vector2d d = track[i] - track[i - 1];
    const double l = d.norm();
    out.push_back(l <= left ? track[i] : Eigen::Vector2d(track[i - 1] + d * (left / l)));
    left -= l;
  }
  return out;
}

std::vector<Eigen::Vector2d> landTrack(const Plan& plan, const Eigen::Vector2d& from, double reach) {
  std::vector<Eigen::Vector2d> track{from};
  if (plan.status != PlanStatus::Fallback && plan.waypoints.size() >= 2) {
    for (size_t i = 1; i < plan.waypoints.size(); ++i)
      track.push_back(plan.waypoints[i].position);
  } else if (std::isfinite(plan.course_setpoint) && plan.speed_setpoint > 0.0) {
    track.push_back(from + courseSpeedToVelocity(plan.course_setpoint, reach));
  }
  return truncateTrack(track, reach);
}

double trackObstacleDistance(const std::vector<Eigen::Vector2d>& track,
                             const std::vector<StaticObstacle>& obstacles) {
  double best = std::numeric_limits<double>::infinity();
  for (const StaticObstacle& o : obstacles)
    for (size_t i = 0; i < track.size() && best > 0.0; ++i)
      best = std::min(best, obstacleDistance(o, track[i], track[i + 1 < track.size() ? i + 1 : i]));
  return best;
}

double landRequirement(const Eigen::Vector2d& position, const Eigen::Vector2d& goal,
                       const std::vector<StaticObstacle>& obstacles, double clearance) {
  if (!(clearance > 0.0) || obstacles.empty())
    return 0.0;
  return std::min({clearance, 0.5 * trackObstacleDistance({position}, obstacles),
                   0.5 * trackObstacleDistance({goal}, obstacles)});
}

double landRequirement(const PlanningProblem& problem) {
  return landRequirement(problem.own.position, nextWayPoint(problem), problem.obstacles,
                         problem.min_obstacle_clearance);
}

std::optional<std::vector<Eigen::Vector2d>> landRoute(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                                                      const std::vector<StaticObstacle>& obstacles,
                                                      double clearance, double required) {
  if (obstacles.empty() || !(required > 0.0) || clearLeg(from, to, obstacles, required))
    return std::vector<Eigen::Vector2d>{};
  std::vector<Eigen::Vector2d> nodes{from, to};
  for (const StaticObstacle& o : obstacles)
    pushedVertices(o.polygon, kNodeMargin * clearance, nodes);
  gapMiddles(obstacles, clearance, nodes);
  std::vector<Eigen::AlignedBox2d> boxes;
  boxes.reserve(obstacles.size());
  for (const StaticObstacle& o : obstacles)
    boxes.push_back(boundingBox(o.polygon));
  // A* over the visibility graph (legs tested as they are reached), the straight distance to `to`
  // as the heuristic: admissible and consistent, so the path is Dijkstra's, with fewer legs tested.
  const size_t n = nodes.size();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<size_t> prev(n, n);
  std::vector<char> done(n, 0);
  using Item = std::pair<double, size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[0] = 0.0;
  open.push({(to - from).norm(), 0});
  while (!open.empty()) {
    const size_t u = open.top().second;
    open.pop();
    if (done[u])
      continue;
    done[u] = 1;
    if (u == 1)
      break;
    for (size_t v = 1; v < n; ++v) {
      const double d = dist[u] + (nodes[v] - nodes[u]).norm();
      if (done[v] || d >= dist[v] || !clearLeg(nodes[u], nodes[v], obstacles, required, boxes))
        continue;
      dist[v] = d;
      prev[v] = u;
      open.push({d + (to - nodes[v]).norm(), v});
    }
  }
  if (!done[1])
    return std::nullopt;
  std::vector<Eigen::Vector2d> route;
  for (size_t v = prev[1]; v != 0; v = prev[v])
    route.insert(route.begin(), nodes[v]);
  return route;
}

}  // namespace asv
