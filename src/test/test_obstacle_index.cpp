// ObstacleIndex answers as the linear scans of geometry.h do (those are checked by hand in
// test_geometry): by hand on a square with a notch, then on random star-shaped coasts against the scans.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "asv_core/common/obstacle_index.h"
#include "asv_core/planning/planning.h"

namespace {

using asv::ObstacleIndex;
using asv::Polygon;
using Eigen::Vector2d;

TEST(ObstacleIndex, ByHandOnASquareWithANotch) {
  // 0..100 square with a notch cut from the top down to y = 40 between x = 40 and 60.
  const Polygon p{{0, 0}, {100, 0}, {100, 100}, {60, 100}, {60, 40}, {40, 40}, {40, 100}, {0, 100}};
  const ObstacleIndex idx({p});
  EXPECT_EQ(idx.edges(), 8u);
  EXPECT_TRUE(idx.inside({10, 10}));
  EXPECT_FALSE(idx.inside({50, 70}));                       // in the notch
  EXPECT_TRUE(idx.inside({100, 50}));                       // on the boundary
  EXPECT_DOUBLE_EQ(idx.distance(Vector2d(50, 70)), 10.0);   // to either side of the notch
  EXPECT_DOUBLE_EQ(idx.distance(Vector2d(50, 45)), 5.0);    // to its bottom
  EXPECT_DOUBLE_EQ(idx.distance(Vector2d(103, 104)), 5.0);  // 3-4-5 to the corner
  EXPECT_DOUBLE_EQ(idx.distance(Vector2d(20, 20)), 0.0);
  // A leg down the notch's middle from above: 10 m from its sides, then 5 m above its bottom.
  EXPECT_DOUBLE_EQ(idx.distance(Vector2d(50, 150), Vector2d(50, 45)), 5.0);
  EXPECT_DOUBLE_EQ(idx.distance(Vector2d(-10, 50), Vector2d(110, 50)), 0.0);  // crosses
  EXPECT_TRUE(std::isinf(ObstacleIndex().distance(Vector2d(0, 0))));
}

Polygon starCoast(std::mt19937& rng, Vector2d centre, int n) {
  std::uniform_real_distribution<double> r(600.0, 1400.0);
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    const double rr = r(rng);
    p.push_back(centre + rr * Vector2d(std::cos(a), std::sin(a)));
  }
  return p;
}

TEST(ObstacleIndex, AgreesWithTheLinearScansOnRandomCoasts) {
  std::mt19937 rng(7);
  const std::vector<Polygon> land{starCoast(rng, {0, 0}, 300), starCoast(rng, {2500, 500}, 200),
                                  starCoast(rng, {1000, 2600}, 50)};
  const ObstacleIndex idx(land);
  std::uniform_real_distribution<double> u(-2000.0, 4500.0), l(-600.0, 600.0);
  for (int k = 0; k < 2000; ++k) {
    const Vector2d a(u(rng), u(rng)), b = a + Vector2d(l(rng), l(rng));
    bool in = false;
    double d = std::numeric_limits<double>::infinity();
    for (const Polygon& p : land) {
      in = in || asv::pointInPolygon(p, a);
      d = std::min(d, asv::segmentObstacleDistance(p, a, b));
    }
    ASSERT_EQ(idx.inside(a), in) << a.transpose();
    ASSERT_NEAR(idx.distance(a, b), d, 1e-9) << a.transpose() << " " << b.transpose();
  }
}

}  // namespace

TEST(PointHazard, AnAidIsAnOctagonRoundItsClearanceCircle) {
  // aid_clearance 300 m with min_obstacle_clearance_m 185.2 m: the octagon has an inscribed radius
  // of 114.8 m, so a plan kept 185.2 m off it stays at least 300 m from the aid.
  const double r = asv::pointHazardRadius(300.0, 185.2);
  EXPECT_NEAR(r, 114.8, 1e-9);
  EXPECT_DOUBLE_EQ(asv::pointHazardRadius(100.0, 185.2), 0.0);  // land's clearance is the larger
  const Eigen::Vector2d c(1000.0, 2000.0);
  const asv::StaticObstacle o = asv::pointHazard("aid:1", c, r);
  ASSERT_EQ(o.polygon.size(), 8u);
  for (const auto& v : o.polygon)  // vertices at r / cos(22.5 deg)
    EXPECT_NEAR((v - c).norm(), r / std::cos(M_PI / 8), 1e-9);
  EXPECT_TRUE(asv::insideObstacle(o, c));
  EXPECT_TRUE(asv::insideObstacle(o, c + Eigen::Vector2d(0.0, r - 0.01)));  // the circle is inside
  EXPECT_FALSE(asv::insideObstacle(o, c + Eigen::Vector2d(0.0, r / std::cos(M_PI / 8) + 0.01)));
  // A leg passing 300 m from the aid is 185.2 m from the octagon at least (here: at an edge's middle).
  const double d =
      asv::obstacleDistance(o, c + Eigen::Vector2d(-5000.0, 300.0), c + Eigen::Vector2d(5000.0, 300.0));
  EXPECT_NEAR(d, 300.0 - r, 1e-6);
  // Radius 0 still gives a point an inside (1 m).
  EXPECT_TRUE(asv::insideObstacle(asv::pointHazard("aid:2", c, 0.0), c + Eigen::Vector2d(0.5, 0.0)));
}

// A logged place on chart land, moved to the nearest water (asv_scenario_from_ais): by hand on a pier
// 200 m wide (x from 0 to 200) and 1000 m long (y from 0 to 1000), with an islet 30 m east of it.
TEST(NearestWater, OutThroughTheNearestEdgeThatLeadsToWater) {
  std::vector<asv::StaticObstacle> land{
      {"pier", {Vector2d(0, 0), Vector2d(200, 0), Vector2d(200, 1000), Vector2d(0, 1000)}},
      {"islet", {Vector2d(230, 400), Vector2d(300, 400), Vector2d(300, 600), Vector2d(230, 600)}}};
  // Afloat already: unchanged.
  EXPECT_EQ(*asv::nearestWater(land, Vector2d(-5, 500), 250.0, 10.0), Vector2d(-5, 500));
  // 40 m inside the west edge (x = 0): 10 m past it, 50 m from where she was.
  const auto west = asv::nearestWater(land, Vector2d(40, 100), 250.0, 10.0);
  ASSERT_TRUE(west);
  EXPECT_NEAR((*west - Vector2d(-10, 100)).norm(), 0.0, 1e-9);
  // 20 m inside the east edge: 10 m past it is x = 210, in the 30 m gap before the islet, afloat.
  const auto gap = asv::nearestWater(land, Vector2d(180, 500), 250.0, 10.0);
  ASSERT_TRUE(gap);
  EXPECT_NEAR((*gap - Vector2d(210, 500)).norm(), 0.0, 1e-9);
  // A quay drawn as a second polygon along the whole east edge (x from 200 to 260): out through it,
  // 80 m to its far edge and 10 m past (90 m), nearer than the pier's west edge (180 m).
  land[1] = {"quay", {Vector2d(200, 0), Vector2d(260, 0), Vector2d(260, 1000), Vector2d(200, 1000)}};
  const auto quay = asv::nearestWater(land, Vector2d(180, 500), 250.0, 10.0);
  ASSERT_TRUE(quay);
  EXPECT_NEAR((*quay - Vector2d(270, 500)).norm(), 0.0, 1e-9);
  // The pier's middle (without the quay) is 100 m from its long edges: deeper than a 90 m accuracy.
  land.pop_back();
  EXPECT_FALSE(asv::nearestWater(land, Vector2d(100, 500), 90.0, 10.0));
  EXPECT_TRUE(asv::nearestWater(land, Vector2d(100, 500), 100.0, 10.0));
}
