// A radar fix (asv_core/tracking/radar_fix.h): position from range and true bearing, and its
// covariance from independent range and bearing errors, checked against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "asv_core/tracking/radar_fix.h"

using namespace asv;

TEST(RadarFix, DueEastAtTwoMilesFromTheOwnShip) {
  const Eigen::Vector2d own(100.0, -50.0);
  const RadarFix f = radarFix(own, 3704.0, M_PI / 2, RadarSigmas{30.0, 0.01, 1.0});
  EXPECT_NEAR(f.position.x(), 100.0 + 3704.0, 1e-9);
  EXPECT_NEAR(f.position.y(), -50.0, 1e-9);
  // Along the line of sight (east): max(30, 1 % of 3704 m = 37.04 m)^2; across it (north):
  // (3704 m x 1 deg = 64.65 m)^2.
  EXPECT_NEAR(f.covariance(0, 0), 37.04 * 37.04, 1e-6);
  EXPECT_NEAR(f.covariance(1, 1), std::pow(3704.0 * M_PI / 180.0, 2), 1e-6);
  EXPECT_NEAR(f.covariance(0, 1), 0.0, 1e-9);
  EXPECT_NEAR(f.covariance(1, 0), 0.0, 1e-9);
}

TEST(RadarFix, CloseTargetUsesTheRangeFloorAndRotatesTheEllipse) {
  // 1000 m on 045: 1 % is 10 m, below the 30 m floor; cross-range 1000 x 2 deg = 34.9 m.
  const RadarFix f = radarFix(Eigen::Vector2d::Zero(), 1000.0, M_PI / 4, RadarSigmas{30.0, 0.01, 2.0});
  EXPECT_NEAR(f.position.x(), 1000.0 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(f.position.y(), 1000.0 / std::sqrt(2.0), 1e-9);
  const double sr2 = 30.0 * 30.0, sc2 = std::pow(1000.0 * 2.0 * M_PI / 180.0, 2);
  // Rotated 45 deg: both diagonal terms (sr2 + sc2) / 2, the off-diagonal (sr2 - sc2) / 2.
  EXPECT_NEAR(f.covariance(0, 0), (sr2 + sc2) / 2, 1e-6);
  EXPECT_NEAR(f.covariance(1, 1), (sr2 + sc2) / 2, 1e-6);
  EXPECT_NEAR(f.covariance(0, 1), (sr2 - sc2) / 2, 1e-6);
  EXPECT_NEAR(f.covariance(1, 0), f.covariance(0, 1), 1e-12);
}
