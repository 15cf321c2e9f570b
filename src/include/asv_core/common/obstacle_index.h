// A spatial index over static obstacles (land): the edges of every polygon in an R-tree
// (Boost.Geometry), so that a distance or inside query costs a logarithmic search and a few exact
// tests instead of a scan of every vertex of a coastline. Answers equal the linear scans of
// geometry.h (segmentObstacleDistance, pointInPolygon) up to rounding.
#pragma once

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "asv_core/common/geometry.h"

namespace asv {

class ObstacleIndex {
public:
  ObstacleIndex();
  explicit ObstacleIndex(const std::vector<Polygon>& polygons);
  ObstacleIndex(const ObstacleIndex&) = delete;
  ObstacleIndex& operator=(const ObstacleIndex&) = delete;
  ObstacleIndex(ObstacleIndex&&) noexcept;
  ObstacleIndex& operator=(ObstacleIndex&&) noexcept;
  ~ObstacleIndex();

  bool empty() const;
  size_t edges() const;
  // True when p lies inside any polygon (crossing rule, as pointInPolygon).
  bool inside(const Eigen::Vector2d& p) const;
  // Shortest distance from p to the area of any polygon: 0 inside; infinity without polygons.
  double distance(const Eigen::Vector2d& p) const;
  // Shortest distance from the segment a-b to the area of any polygon (segmentObstacleDistance over
  // all polygons): 0 when any part of it is inside or on a boundary; infinity without polygons.
  double distance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

  // Shortest distance from the segment a-b to the polygons' boundaries (segmentPolygonDistance): a
  // segment wholly inside is as far as the boundary is.
  double boundaryDistance(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
  // Length of the segment a-b that lies inside a polygon (for an index of one polygon, or polygons
  // that do not overlap).
  double lengthInside(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;

private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace asv
