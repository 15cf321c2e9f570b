// Static obstacles of the world (land, islets, aids to navigation as point hazards) and the distance
// queries every planner, the plan follower and the simulator ask of them.
#pragma once

#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/common/geometry.h"
#include "asv_core/common/obstacle_index.h"

namespace asv {

struct StaticObstacle {
  std::string name;
  Polygon polygon;  // ENU [m], convex or concave, closed implicitly
  // A spatial index of the polygon's edges, shared by the copies (indexObstacles builds it for
  // coastlines); without it the queries below scan every vertex.
  std::shared_ptr<const ObstacleIndex> index = nullptr;
};

// A point hazard (an aid to navigation) as an obstacle: the octagon round the circle of `radius` [m]
// about `centre`, so that a plan keeping min_obstacle_clearance_m from the octagon keeps at least
// radius + min_obstacle_clearance_m from the centre. The circle's radius is that of a point for
// radius 0 (a 1 m octagon).
StaticObstacle pointHazard(const std::string& name, const Eigen::Vector2d& centre, double radius);
// The radius giving a point hazard a clearance of at least `clearance` when plans keep
// `min_obstacle_clearance` from obstacles: clearance - min_obstacle_clearance, never below 0.
double pointHazardRadius(double clearance, double min_obstacle_clearance);

// Polygons of at least this many vertices get an index: below it a scan is as fast (bench_land).
constexpr size_t kIndexedObstacleVertices = 64;
// Builds the index of every obstacle of kIndexedObstacleVertices or more vertices that has none.
void indexObstacles(std::vector<StaticObstacle>& obstacles);
// The geometry.h queries on one obstacle, through its index when it has one.
bool insideObstacle(const StaticObstacle& o, const Eigen::Vector2d& p);
// p lies inside (or on the edge of) one of the obstacles: on land.
bool insideAnyObstacle(const std::vector<StaticObstacle>& obstacles, const Eigen::Vector2d& p);
double obstacleDistance(const StaticObstacle& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b);  // area
double obstacleBoundaryDistance(const StaticObstacle& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b);
double obstacleLengthInside(const StaticObstacle& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b);
// polygonDistance from a small polygon (a hull outline) to the obstacle when it is at most `needed`;
// otherwise any lower bound above `needed` (the cheap bound from the outline's centre, so that a ship
// far from a coastline costs one query). With an index, the outline's edges' distances (a coastline
// does not fit inside a hull).
double polygonObstacleDistance(const Polygon& outline, const StaticObstacle& o,
                               double needed = std::numeric_limits<double>::infinity());

// A position that the chart puts on land, moved to the nearest water: p itself when no obstacle holds
// it; else, of the points `margin` beyond an obstacle's edge straight out from p, through an edge at
// most max_depth from p, the nearest that no obstacle holds; nullopt when there is none (p lies deeper
// inland than max_depth).
std::optional<Eigen::Vector2d> nearestWater(const std::vector<StaticObstacle>& land, const Eigen::Vector2d& p,
                                            double max_depth, double margin);

}  // namespace asv
