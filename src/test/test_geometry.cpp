// Plane geometry of land (asv_core/common/geometry.h): distances between hull outlines, track legs and
// obstacle polygons, worked out by hand on squares and rectangles.
#include <gtest/gtest.h>

#include <cmath>

#include "asv_core/common/geometry.h"
#include "asv_core/common/units.h"

using namespace asv;

namespace {
const Polygon kIsland = {{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}};  // 1 km square
}

TEST(Geometry, HullOutlineIsTheRectangleAlongTheHeading) {
  // Heading east (90 deg): the 100 m length lies along x, the 20 m beam along y; starboard is south.
  const Polygon h = hullOutline({0, 0}, degToRad(90.0), 100.0, 20.0);
  ASSERT_EQ(h.size(), 4u);
  EXPECT_NEAR(h[0].x(), 50.0, 1e-9);  // bow starboard
  EXPECT_NEAR(h[0].y(), -10.0, 1e-9);
  EXPECT_NEAR(h[2].x(), -50.0, 1e-9);  // stern port
  EXPECT_NEAR(h[2].y(), 10.0, 1e-9);
}

TEST(Geometry, PolygonDistanceByHand) {
  // A 100 x 20 m hull heading north, centred 1200 m east of the island's west edge, at mid-height:
  // its port side is at x = 1190, the island's east edge at x = 1000: 190 m.
  EXPECT_NEAR(polygonDistance(hullOutline({1200, 500}, 0.0, 100.0, 20.0), kIsland), 190.0, 1e-9);
  // Diagonal: the hull's corner (1050, 1050) to the island's corner (1000, 1000): 50 sqrt(2).
  const Polygon corner = {{1050, 1050}, {1100, 1050}, {1100, 1100}, {1050, 1100}};
  EXPECT_NEAR(polygonDistance(corner, kIsland), 50.0 * std::sqrt(2.0), 1e-9);
  // Crossing the edge, wholly inside, and the island inside a big outline: all touching.
  EXPECT_DOUBLE_EQ(polygonDistance(hullOutline({1000, 500}, 0.0, 100.0, 20.0), kIsland), 0.0);
  EXPECT_DOUBLE_EQ(polygonDistance(hullOutline({500, 500}, 0.0, 100.0, 20.0), kIsland), 0.0);
  EXPECT_DOUBLE_EQ(polygonDistance(hullOutline({500, 500}, 0.0, 5000.0, 5000.0), kIsland), 0.0);
}

TEST(Geometry, SegmentObstacleDistanceCountsALegInsideAsTouching) {
  EXPECT_DOUBLE_EQ(segmentObstacleDistance(kIsland, {100, 100}, {900, 900}), 0.0);         // wholly inside
  EXPECT_NEAR(segmentPolygonDistance(kIsland, {100, 100}, {900, 900}), 100.0, 1e-9);       // boundary only
  EXPECT_DOUBLE_EQ(segmentObstacleDistance(kIsland, {-500, 500}, {1500, 500}), 0.0);       // across
  EXPECT_NEAR(segmentObstacleDistance(kIsland, {-500, 1300}, {1500, 1300}), 300.0, 1e-9);  // north of it
}

TEST(Geometry, BoundingBoxBoundsTheDistanceFromBelow) {
  const Polygon h = hullOutline({1200, 500}, degToRad(30.0), 100.0, 20.0);
  EXPECT_LE(boundingBox(h).exteriorDistance(boundingBox(kIsland)), polygonDistance(h, kIsland) + 1e-9);
}

TEST(Geometry, TriangulationCoversAConcavePolygonExactly) {
  // An L of 3 unit squares (area 3), clockwise: 4 triangles whose areas add up to it.
  const Polygon l = {{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}};
  const auto tris = triangulate(l);
  ASSERT_EQ(tris.size(), 4u);
  double area = 0.0;
  for (const auto& t : tris) {
    const double a = 0.5 * cross2(l[t[1]] - l[t[0]], l[t[2]] - l[t[0]]);
    EXPECT_GT(a, 0.0);  // counter-clockwise, none flat
    area += a;
    // No triangle covers the notch (1.5, 1.5).
    const Eigen::Vector2d p(1.5, 1.5);
    EXPECT_FALSE(cross2(l[t[1]] - l[t[0]], p - l[t[0]]) > 0 && cross2(l[t[2]] - l[t[1]], p - l[t[1]]) > 0 &&
                 cross2(l[t[0]] - l[t[2]], p - l[t[2]]) > 0);
  }
  EXPECT_NEAR(area, 3.0, 1e-12);
  EXPECT_TRUE(triangulate({{0, 0}, {1, 1}}).empty());
}

TEST(Geometry, OffsetOutlineOfASquareIsTheRoundedSquare) {
  // A 100 m square grown by 10 m: straight sides 10 m out, quarter circles at the corners; area
  // 100^2 + 4 x 100 x 10 + pi 10^2 (by hand), the 360-gon's arcs a hair short of the circle.
  const Polygon sq{{0, 0}, {100, 0}, {100, 100}, {0, 100}};
  const auto out = offsetOutline(sq, 10.0, 360);
  ASSERT_EQ(out.size(), 1u);
  double area2 = 0.0;
  for (size_t i = 0, j = out[0].size() - 1; i < out[0].size(); j = i++)
    area2 += cross2(out[0][j], out[0][i]);
  EXPECT_NEAR(std::fabs(area2) / 2, 10000 + 4000 + M_PI * 100, 1.0);
  const Eigen::AlignedBox2d box = boundingBox(out[0]);
  EXPECT_NEAR(box.min().x(), -10.0, 1e-9);
  EXPECT_NEAR(box.max().y(), 110.0, 1e-9);
  EXPECT_TRUE(offsetOutline({{0, 0}, {1, 1}}, 10.0).empty());
}
