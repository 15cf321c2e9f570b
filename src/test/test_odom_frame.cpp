// REP 105's odom frame (odom_frame.h): odom -> base_link continuous, map -> odom takes the fixes' jumps.
#include <gtest/gtest.h>

#include "asv_core/tracking/odom_frame.h"

namespace {

constexpr double kTol = 1e-9;

}  // namespace

// A ship at 5 m/s north from (100, 200), updated every 0.1 s: at 9.9 s she is at (100, 249.5). At 10 s
// a fix puts her 20 m east and 3 m south of where she sailed, (100, 250): the estimate is (120, 247).
// Odom moves on by 5 x 0.1 = 0.5 m north only, to (100, 250); map -> odom becomes (20, -3), the jump;
// and the chain map -> odom -> base_link is the estimate.
TEST(OdomFrame, OdomIsContinuousAndMapToOdomTakesTheJump) {
  asv::OdomFrame f;
  EXPECT_FALSE(f.started());
  const Eigen::Vector2d v(0.0, 5.0);
  for (int k = 0; k < 100; ++k)
    f.update(0.1 * k, Eigen::Vector2d(100.0, 200.0 + 0.5 * k), v);
  ASSERT_TRUE(f.started());
  EXPECT_NEAR(f.inOdom().x(), 100.0, kTol);
  EXPECT_NEAR(f.inOdom().y(), 249.5, 1e-6);
  EXPECT_NEAR(f.mapToOdom().norm(), 0.0, 1e-6);  // no correction yet: odom is map

  f.update(10.0, Eigen::Vector2d(120.0, 247.0), v);
  EXPECT_NEAR(f.inOdom().x(), 100.0, kTol);
  EXPECT_NEAR(f.inOdom().y(), 250.0, 1e-6);  // 249.5 + 0.5: no jump
  EXPECT_NEAR(f.mapToOdom().x(), 20.0, 1e-6);
  EXPECT_NEAR(f.mapToOdom().y(), -3.0, 1e-6);
  const Eigen::Vector2d chain = f.mapToOdom() + f.inOdom();
  EXPECT_NEAR(chain.x(), 120.0, 1e-6);
  EXPECT_NEAR(chain.y(), 247.0, 1e-6);
}

// A clock that goes back (a bag played again) starts odom again at the map position.
TEST(OdomFrame, ClockBackRestarts) {
  asv::OdomFrame f;
  f.update(5.0, Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(1.0, 0.0));
  f.update(6.0, Eigen::Vector2d(50.0, 0.0), Eigen::Vector2d(1.0, 0.0));
  EXPECT_NEAR(f.mapToOdom().x(), 49.0, kTol);  // odom at 1 m, map at 50 m
  f.update(1.0, Eigen::Vector2d(7.0, 8.0), Eigen::Vector2d(1.0, 0.0));
  EXPECT_NEAR(f.inOdom().x(), 7.0, kTol);
  EXPECT_NEAR(f.inOdom().y(), 8.0, kTol);
  EXPECT_NEAR(f.mapToOdom().norm(), 0.0, kTol);
}
