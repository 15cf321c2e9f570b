// The recording's last frame (run_summary.h): the box the view is fitted to, each target's closest
// approach, the own ship's manoeuvres. Expected values by hand in each test's comment.
#include <gtest/gtest.h>

#include <cmath>

#include "asv_core/sim/run_summary.h"

namespace {

constexpr double kDeg = asv::kPi / 180.0;

}  // namespace

// Own ship (0, 0) north at 5 m/s, goal (0, 5000): she would arrive after 1000 s. A target at (3000, 2500)
// sailing west at 5 m/s: relative position (3000, 2500), relative velocity (-5, -5), TCPA 27500 / 50 =
// 550 s; 600 s later is past the arrival, so her track counts to 1000 s: (-2000, 2500). The own ship's
// band, 0.4 x 5000 = 2000 m either side of x = 0, is inside that. Box x [-2000, 3000], y [0, 5000],
// widened by 10 % of its size (500 m) on each side: x [-2500, 3500], y [-500, 5500]. The duration
// (3600 s) does not count.
TEST(RunSummary, SceneBoxCoversTheEncounter) {
  asv::Scenario sc;
  sc.duration = 3600.0;
  sc.own.position = {0.0, 0.0};
  sc.own.course = 0.0;
  sc.own.speed = 5.0;
  sc.own.goal = Eigen::Vector2d(0.0, 5000.0);
  asv::ScenarioShip t;
  t.position = {3000.0, 2500.0};
  t.course = 270.0 * kDeg;
  t.speed = 5.0;
  sc.targets.push_back(t);
  const asv::SceneBox b = asv::sceneBox(sc);
  EXPECT_NEAR(b.min.x(), -2500.0, 1e-6);
  EXPECT_NEAR(b.max.x(), 3500.0, 1e-6);
  EXPECT_NEAR(b.min.y(), -500.0, 1e-6);
  EXPECT_NEAR(b.max.y(), 5500.0, 1e-6);

  // The same target from (1000, 500): TCPA (5000 + 2500) / 50 = 150 s, her track counted to 750 s:
  // (-2750, 500). The band reaches x = 2000. Box x [-2750, 2000] (+-475), y [0, 5000] (+-500).
  sc.targets[0].position = {1000.0, 500.0};
  const asv::SceneBox c = asv::sceneBox(sc);
  EXPECT_NEAR(c.min.x(), -3225.0, 1e-6);
  EXPECT_NEAR(c.max.x(), 2475.0, 1e-6);
  EXPECT_NEAR(c.min.y(), -500.0, 1e-6);
  EXPECT_NEAR(c.max.y(), 5500.0, 1e-6);

  // An own ship lying still at (100, 200) with no goal and nothing round her: 1 nm either side.
  asv::Scenario still;
  still.duration = 600.0;
  still.own.position = {100.0, 200.0};
  const asv::SceneBox s = asv::sceneBox(still);
  EXPECT_NEAR(s.min.x(), 100.0 - 1852.0, 1e-6);
  EXPECT_NEAR(s.max.y(), 200.0 + 1852.0, 1e-6);
}

// Own ship north at 10 m/s from (0, 0), sampled every second; a wiggle of 3 deg at 20-22 s (under the
// 5 deg that make a manoeuvre); from 100 s a turn to starboard at 2 deg/s to 030, steady from 115 s.
// The manoeuvre begins when the course is 5 deg or more off 000: 006 at 103 s; it is 000 -> 030. A target
// lying still at (500, 600) is closest at 60 s, abeam, with the own ship at (1.57, 599.96); after the turn
// she heads away from it (course 030 points away from the bearing 129 deg of the target at 100 s).
TEST(RunSummary, ClosestApproachAndManoeuvres) {
  asv::RunSummary s;
  Eigen::Vector2d own(0.0, 0.0);
  Eigen::Vector2d at103 = Eigen::Vector2d::Zero();
  for (int t = 0; t <= 200; ++t) {
    double course = 0.0;
    if (t >= 20 && t <= 22)
      course = 3.0 * kDeg;
    if (t >= 100)
      course = std::min(30.0, 2.0 * (t - 100.0)) * kDeg;
    if (t > 0)
      own += 10.0 * Eigen::Vector2d(std::sin(course), std::cos(course));
    if (t == 103)
      at103 = own;
    s.update(t, own, course, {{"T1", Eigen::Vector2d(500.0, 600.0)}});
  }
  ASSERT_EQ(s.closest().count("T1"), 1u);
  const asv::ClosestApproach& c = s.closest().at("T1");
  // The wiggle set her 3 x 10 sin 3 deg = 1.570 m east (and 3 x 10 (1 - cos 3 deg) = 0.04 m short).
  EXPECT_NEAR(c.distance, 500.0 - 30.0 * std::sin(3.0 * kDeg), 0.01);
  EXPECT_NEAR(c.t, 60.0, 1e-9);
  EXPECT_NEAR(c.own.y(), 600.0 - 30.0 * (1.0 - std::cos(3.0 * kDeg)), 1e-6);
  ASSERT_EQ(s.manoeuvres().size(), 1u);
  const asv::CourseAlteration& m = s.manoeuvres()[0];
  EXPECT_NEAR(m.t, 103.0, 1e-9);
  EXPECT_NEAR((m.position - at103).norm(), 0.0, 1e-9);
  EXPECT_NEAR(m.course_from, 0.0, 1e-9);
  EXPECT_NEAR(m.course_to, 30.0 * kDeg, 1e-9);
}
