// A route round land: the shortest way from the ship to her goal that keeps a clearance from every
// static obstacle, for the planners that steer for the next point of PlanningProblem::route (GA, ACO,
// MOPSO) and for the plan follower's way back to the goal. The planners then handle the traffic along
// it. Land is static: the route is the visibility graph's shortest path.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "asv_core/planning/planning.h"

namespace asv {

// The first `reach` metres of a polyline (the whole of a shorter one).
std::vector<Eigen::Vector2d> truncateTrack(const std::vector<Eigen::Vector2d>& track, double reach);
// The track a plan makes good from `from`, its first `reach` metres (speed x prediction horizon: land
// farther along is judged by a later plan, nearer to it): its waypoints; without them (or for a
// fallback, or a plan that stops), its course.
std::vector<Eigen::Vector2d> landTrack(const Plan& plan, const Eigen::Vector2d& from, double reach);
// Smallest distance from a polyline to the area of any obstacle; infinity without obstacles.
double trackObstacleDistance(const std::vector<Eigen::Vector2d>& track,
                             const std::vector<StaticObstacle>& obstacles);
// How close to land a plan from `position` to `goal` may come: the clearance, or half the present
// distance when the ship is already inside it (a narrow channel), or half the goal's when the goal is
// (a berth), so that she may still move and arrive. 0: no land.
double landRequirement(const Eigen::Vector2d& position, const Eigen::Vector2d& goal,
                       const std::vector<StaticObstacle>& obstacles, double clearance);
// The same for a planning problem, toward the point it steers for next (nextWayPoint): the planners
// and the follower judge land against the same point.
double landRequirement(const PlanningProblem& problem);

// The points to pass between `from` and `to` (neither included): none when the straight leg keeps
// `required` from every obstacle; otherwise the shortest path over the obstacles' vertices pushed out
// by 1.2 x `clearance` along their outward bisectors and the middles of the gaps between obstacles
// (up to 6 clearances wide: a harbour entrance) with a lining-up point 2 clearances off either side,
// every leg keeping `required`. nullopt when no such
// path exists (the goal enclosed, a passage narrower than twice the requirement).
std::optional<std::vector<Eigen::Vector2d>> landRoute(const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                                                      const std::vector<StaticObstacle>& obstacles,
                                                      double clearance, double required);

}  // namespace asv
