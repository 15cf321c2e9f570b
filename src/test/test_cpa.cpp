#include <gtest/gtest.h>

#include "asv_core/risk/cpa.h"

using namespace asv;

namespace {
ShipState ship(double x, double y, double course_deg, double speed) {
  ShipState s;
  s.position = {x, y};
  s.course = s.heading = degToRad(course_deg);
  s.speed = speed;
  return s;
}
}  // namespace

TEST(Cpa, HeadOn) {
  const double v = knotsToMps(10.0);
  const Cpa c = computeCpa(ship(0, 0, 0, v), ship(0, 10000, 180, v));
  EXPECT_NEAR(c.tcpa, 10000.0 / (2 * v), 1e-9);
  EXPECT_NEAR(c.dcpa, 0.0, 1e-9);
  EXPECT_NEAR(c.range, 10000.0, 1e-9);
  EXPECT_NEAR(c.relative_speed, 2 * v, 1e-12);
  EXPECT_NEAR(c.own_at_cpa.y(), 5000.0, 1e-6);
}

TEST(Cpa, CrossingFromStarboardAndFromPort) {
  // Both ships reach (0, 1000) at t = 100 s.
  for (double side : {1.0, -1.0}) {
    const Cpa c = computeCpa(ship(0, 0, 0, 10), ship(side * 1000, 1000, side > 0 ? 270 : 90, 10));
    EXPECT_NEAR(c.tcpa, 100.0, 1e-9);
    EXPECT_NEAR(c.dcpa, 0.0, 1e-9);
  }
  // Offset crossing: stationary own ship, target at (300, 400) going west at 10 m/s passes (0, 400).
  const Cpa c = computeCpa(ship(0, 0, 0, 0), ship(300, 400, 270, 10));
  EXPECT_NEAR(c.tcpa, 30.0, 1e-9);
  EXPECT_NEAR(c.dcpa, 400.0, 1e-9);
  EXPECT_NEAR(c.target_at_cpa.x(), 0.0, 1e-9);
}

TEST(Cpa, OvertakingAndBeingOvertaken) {
  Cpa c = computeCpa(ship(0, 0, 0, 10), ship(100, 500, 0, 5));
  EXPECT_NEAR(c.tcpa, 100.0, 1e-9);
  EXPECT_NEAR(c.dcpa, 100.0, 1e-9);
  c = computeCpa(ship(0, 0, 0, 10), ship(0, -500, 0, 15));
  EXPECT_NEAR(c.tcpa, 100.0, 1e-9);
  EXPECT_NEAR(c.dcpa, 0.0, 1e-9);
}

TEST(Cpa, ParallelSameSpeedHasNoRelativeMotion) {
  const Cpa c = computeCpa(ship(0, 0, 45, 7), ship(500, 0, 45, 7));
  EXPECT_FALSE(c.relative_motion);
  EXPECT_DOUBLE_EQ(c.tcpa, 0.0);
  EXPECT_NEAR(c.dcpa, 500.0, 1e-9);
  EXPECT_TRUE(std::isfinite(c.tcpa) && std::isfinite(c.dcpa));
  // Zero relative speed with both stopped.
  const Cpa s = computeCpa(ship(0, 0, 0, 0), ship(30, 40, 90, 0));
  EXPECT_FALSE(s.relative_motion);
  EXPECT_NEAR(s.dcpa, 50.0, 1e-12);
}

TEST(Cpa, DivergingGivesNegativeTcpa) {
  // Target 1000 m astern going south at 5 m/s, own north at 10: relative velocity (0, -15).
  const Cpa c = computeCpa(ship(0, 0, 0, 10), ship(0, -1000, 180, 5));
  EXPECT_NEAR(c.tcpa, -1000.0 / 15.0, 1e-9);
  EXPECT_NEAR(c.dcpa, 0.0, 1e-9);
}

TEST(WindowedCpa, AppendixRules) {
  const double tw = 20.0;
  // Rule 1: meeting exactly at the end of the window (X2^2 + Y2^2 + X1 X2 + Y1 Y2 = 0).
  WindowedCpa w = windowedCpa({0, 0}, {0, 500}, {0, 1000}, {0, 500}, tw);
  EXPECT_DOUBLE_EQ(w.tcpa, tw);
  EXPECT_NEAR(w.dcpa, 0.0, 1e-9);
  // Rule 1 beyond the window: still closing at its end, TCPA clamped to the window.
  w = windowedCpa({0, 0}, {0, 100}, {0, 1000}, {0, 900}, tw);
  EXPECT_DOUBLE_EQ(w.tcpa, tw);
  EXPECT_NEAR(w.dcpa, 800.0, 1e-9);
  // Rule 3: CPA inside the window, at 0.8 of it.
  w = windowedCpa({0, 0}, {0, 500}, {0, 800}, {0, 300}, tw);
  EXPECT_NEAR(w.tcpa, 16.0, 1e-12);
  EXPECT_NEAR(w.dcpa, 0.0, 1e-6);
  // Rule 3 with a miss distance: j 300 m to the east, same closing motion.
  w = windowedCpa({0, 0}, {0, 500}, {300, 800}, {300, 300}, tw);
  EXPECT_NEAR(w.tcpa, 16.0, 1e-12);
  EXPECT_NEAR(w.dcpa, 300.0, 1e-9);
  // Rule 2: diverging.
  w = windowedCpa({0, 0}, {0, -500}, {0, 800}, {0, 1300}, tw);
  EXPECT_DOUBLE_EQ(w.tcpa, 0.0);
  EXPECT_NEAR(w.dcpa, 800.0, 1e-9);
  // Rules 4/5: no relative motion; TimeWindow, distance unchanged.
  w = windowedCpa({0, 0}, {100, 0}, {0, 50}, {100, 50}, tw);
  EXPECT_DOUBLE_EQ(w.tcpa, tw);
  EXPECT_NEAR(w.dcpa, 50.0, 1e-12);
}
