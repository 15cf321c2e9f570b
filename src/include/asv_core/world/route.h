// A voyage plan: the route of waypoints a ship sails (an ECDIS or chart plotter's route), free of ROS.
// The ship sails from where she is to the first waypoint, then leg by leg; the last waypoint is her goal.
// Leg k ends at waypoint k and carries that waypoint's speed and corridor (as RTZ's legs do: IEC 61174
// gives each waypoint the leg that leads to it).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/world/obstacles.h"

namespace asv {

struct RouteWaypoint {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] ENU
  double speed = 0.0;          // [m/s] on the leg ending here; 0: the ship's cruise speed
  double port_xtd = 0.0;       // [m] corridor to port of that leg (cross-track limit); 0: none given
  double starboard_xtd = 0.0;  // [m] corridor to starboard; 0: none given
};
using Route = std::vector<RouteWaypoint>;

// Signed cross-track error of p from the line through a and b: positive to starboard of the leg (to the
// right looking from a to b), as an ECDIS shows it. 0 when a and b coincide.
double crossTrackError(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p);
// Distance still to run along the leg a->b from p's abeam point to b (negative once past b).
double alongTrackToGo(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p);
// Where to put the wheel over before a waypoint at which the course changes by `turn` [rad]: the
// advance of a steady turn of radius R = speed / turn_rate, R tan(|turn| / 2), at most R (a turn of
// 90 deg or more starts a radius before the waypoint). 0 without speed or rate.
double wheelOverDistance(double turn, double speed, double turn_rate);

// The first leg of the route (sailed from `start`) that comes closer than `clearance` to an obstacle,
// and that obstacle's name; nullopt when every leg is clear. Leg k runs from waypoint k-1 (from `start`
// for k = 0) to waypoint k.
struct LegOnLand {
  int leg = 0;
  std::string land;  // the obstacle's name (may be empty)
};
std::optional<LegOnLand> legOnLand(const Route& route, const Eigen::Vector2d& start,
                                   const std::vector<StaticObstacle>& obstacles, double clearance = 0.0);

// How far a point is from the route, and whether it lies outside the leg's corridor: the leg nearest to
// p (the first of equals), its signed cross-track error and whether that exceeds the leg's limit on
// that side (a side without a limit is never exceeded).
struct RouteDeviation {
  std::size_t leg = 0;
  double xte = 0.0;  // [m] positive to starboard
  bool outside_corridor = false;
};
RouteDeviation routeDeviation(const Route& route, const Eigen::Vector2d& start, const Eigen::Vector2d& p);

// Progress along a route: the waypoint the ship steers for and the leg she is on.
class RouteProgress {
public:
  RouteProgress() = default;
  // Starts at `from` (the ship's place when she is given the route): on the nearest leg; before the
  // first waypoint when she has not yet reached it.
  RouteProgress(Route route, const Eigen::Vector2d& from);

  // Passes every waypoint the ship at p (speed [m/s], turn rate [rad/s]) has reached: within
  // `acceptance` of it, or at the wheel-over point of its turn, or abeam of it and beyond (she is past).
  // The last waypoint (the goal) is never passed. Returns whether the active waypoint changed.
  bool update(const Eigen::Vector2d& p, double speed, double turn_rate, double acceptance);

  bool empty() const { return route_.empty(); }
  const Route& route() const { return route_; }
  std::size_t active() const { return active_; }  // index of the waypoint steered for
  const RouteWaypoint& target() const { return route_[active_]; }
  Eigen::Vector2d legStart() const { return active_ == 0 ? from_ : route_[active_ - 1].position; }
  bool onLastLeg() const { return active_ + 1 >= route_.size(); }
  double crossTrackError(const Eigen::Vector2d& p) const;
  // The waypoints still to pass before the goal, the active one first (empty on the last leg).
  std::vector<Eigen::Vector2d> waypointsBeforeGoal() const;
  const Eigen::Vector2d& goal() const { return route_.back().position; }
  // A point on the active leg `lookahead` ahead of p's abeam point (at most the waypoint): what a
  // line-of-sight guidance law steers for to bring the ship back onto the leg.
  Eigen::Vector2d lineOfSight(const Eigen::Vector2d& p, double lookahead) const;

private:
  Route route_;
  Eigen::Vector2d from_ = Eigen::Vector2d::Zero();
  std::size_t active_ = 0;
};

}  // namespace asv
