#include "asv_core/world/route.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "asv_core/common/geometry.h"
#include "asv_core/common/units.h"

namespace asv {

double crossTrackError(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  const Eigen::Vector2d ab = b - a;
  const double len = ab.norm();
  // ENU: the leg's direction crossed with the offset is positive to port (counter-clockwise).
  return len > 0.0 ? -cross2(ab, p - a) / len : 0.0;
}

double alongTrackToGo(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  const Eigen::Vector2d ab = b - a;
  const double len = ab.norm();
  return len > 0.0 ? (b - p).dot(ab) / len : -(p - b).norm();
}

double wheelOverDistance(double turn, double speed, double turn_rate) {
  if (!(speed > 0.0) || !(turn_rate > 0.0))
    return 0.0;
  const double radius = speed / turn_rate;
  const double half = 0.5 * std::min(std::abs(wrapPi(turn)), kPi / 2.0);
  return radius * std::tan(half);
}

std::optional<LegOnLand> legOnLand(const Route& route, const Eigen::Vector2d& start,
                                   const std::vector<StaticObstacle>& obstacles, double clearance) {
  Eigen::Vector2d from = start;
  for (std::size_t k = 0; k < route.size(); ++k) {
    for (const StaticObstacle& o : obstacles)
      if (obstacleDistance(o, from, route[k].position) < std::max(clearance, 1e-9))
        return LegOnLand{static_cast<int>(k), o.name};
    from = route[k].position;
  }
  return std::nullopt;
}

RouteDeviation routeDeviation(const Route& route, const Eigen::Vector2d& start, const Eigen::Vector2d& p) {
  RouteDeviation best;
  double nearest = std::numeric_limits<double>::infinity();
  Eigen::Vector2d from = start;
  for (std::size_t k = 0; k < route.size(); ++k) {
    const Eigen::Vector2d& to = route[k].position;
    const double d = pointSegmentDistance(p, from, to);
    if (d < nearest) {
      nearest = d;
      best.leg = k;
      // Beyond the leg's ends the distance to the end point, signed by the side of the leg's line.
      const double xte = crossTrackError(from, to, p);
      best.xte = xte < 0.0 ? -d : d;
      const double limit = xte < 0.0 ? route[k].port_xtd : route[k].starboard_xtd;
      best.outside_corridor = limit > 0.0 && d > limit;
    }
    from = to;
  }
  return best;
}

RouteProgress::RouteProgress(Route route, const Eigen::Vector2d& from)
    : route_(std::move(route)), from_(from) {
  // The nearest leg between waypoints; before the first waypoint while she has not come abeam of it.
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < route_.size(); ++k) {
    const double d = pointSegmentDistance(from, route_[k - 1].position, route_[k].position);
    if (d < nearest) {
      nearest = d;
      active_ = k;
    }
  }
  if (active_ == 1 && alongTrackToGo(route_[0].position, route_[1].position, from) >
                          (route_[1].position - route_[0].position).norm())
    active_ = 0;
}

bool RouteProgress::update(const Eigen::Vector2d& p, double speed, double turn_rate, double acceptance) {
  const std::size_t before = active_;
  while (active_ + 1 < route_.size()) {
    const Eigen::Vector2d a = legStart(), b = route_[active_].position, c = route_[active_ + 1].position;
    const double turn = courseOf(c - b) - courseOf(b - a);
    const bool reached =
        (p - b).norm() <= acceptance || alongTrackToGo(a, b, p) <= wheelOverDistance(turn, speed, turn_rate);
    if (!reached)
      break;
    ++active_;
  }
  return active_ != before;
}

double RouteProgress::crossTrackError(const Eigen::Vector2d& p) const {
  return asv::crossTrackError(legStart(), route_[active_].position, p);
}

std::vector<Eigen::Vector2d> RouteProgress::waypointsBeforeGoal() const {
  std::vector<Eigen::Vector2d> out;
  for (std::size_t k = active_; k + 1 < route_.size(); ++k)
    out.push_back(route_[k].position);
  return out;
}

Eigen::Vector2d RouteProgress::lineOfSight(const Eigen::Vector2d& p, double lookahead) const {
  const Eigen::Vector2d a = legStart();
  Eigen::Vector2d b = route_[active_].position;
  const double len = (b - a).norm();
  if (!(len > 0.0))
    return b;
  const double along = len - alongTrackToGo(a, b, p) + lookahead;
  return along >= len ? b : Eigen::Vector2d(a + (b - a) * (std::max(along, 0.0) / len));
}

}  // namespace asv
