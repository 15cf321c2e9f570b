// The ARPA target table (asv_core/tracking/arpa_targets.h): which own-ship data a TTM needs, where a
// fix lies and how sure it is, the velocity and quality a report gives, lost targets, eviction and
// forgetting. Expected positions and variances are worked out by hand from the range and bearing.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "asv_core/common/units.h"
#include "asv_core/tracking/arpa_targets.h"

using namespace asv;

namespace {
constexpr double kLat = 54.6, kLon = 18.8;  // the map origin
constexpr std::int64_t kSec = 1000000000;

arpa::TrackedTarget ttm(int number, double range_m, double bearing_deg,
                        arpa::Reference ref = arpa::Reference::kTrue) {
  arpa::TrackedTarget t;
  t.number = number;
  t.has_distance = t.has_bearing = true;
  t.distance = range_m;
  t.bearing = degToRad(bearing_deg);
  t.bearing_ref = ref;
  t.status = arpa::TargetStatus::kTracking;
  return t;
}

ArpaTargetTable table(std::size_t max_targets = 100) {
  ArpaTargetConfig c;
  c.max_targets = max_targets;
  return ArpaTargetTable(c, LocalFrame(kLat, kLon));
}

std::vector<ArpaTarget> due(ArpaTargetTable& t, std::int64_t now) {
  std::vector<ArpaTarget> out;
  t.due(now, [&](const ArpaTarget& a, double) { out.push_back(a); });
  return out;
}
}  // namespace

TEST(ArpaTargets, TtmNeedsARecentOwnPositionAndForRelativeBearingsAHeading) {
  auto t = table();
  EXPECT_EQ(t.ttm(ttm(1, 1852.0, 90.0), 10 * kSec), ArpaOutcome::NoOwnPosition);
  EXPECT_EQ(t.ttm(ttm(1, 1852.0, 90.0, arpa::Reference::kRelative), 10 * kSec), ArpaOutcome::NoOwnHeading);
  t.ownShip({100.0, 200.0}, 0.0, 10 * kSec);
  EXPECT_EQ(t.ttm(ttm(1, 1852.0, 90.0), 12 * kSec), ArpaOutcome::Target);  // 2 s old: the limit
  EXPECT_EQ(t.ttm(ttm(1, 1852.0, 90.0), 12 * kSec + 1000), ArpaOutcome::NoOwnPosition);
  arpa::TrackedTarget no_range = ttm(2, 0.0, 90.0);
  no_range.has_distance = false;
  EXPECT_EQ(t.ttm(no_range, 11 * kSec), ArpaOutcome::NoPosition);
  EXPECT_EQ(t.ttm(ttm(70000, 1852.0, 90.0), 11 * kSec), ArpaOutcome::NoNumber);
}

TEST(ArpaTargets, TtmFixIsRangeAndBearingFromTheOwnShipWithItsUncertainty) {
  auto t = table();
  t.ownShip({100.0, 200.0}, 0.0, 0);
  ASSERT_EQ(t.ttm(ttm(7, 1852.0, 90.0), 0), ArpaOutcome::Target);  // due east, 1 nm
  const auto out = due(t, 0);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].position.x(), 1952.0, 1e-6);
  EXPECT_NEAR(out[0].position.y(), 200.0, 1e-6);
  // Along the line of sight (x): the range sigma, max(30 m, 1 % of 1852 m) = 30 m -> 900 m^2.
  EXPECT_NEAR(out[0].covariance(0, 0), 900.0, 1e-6);
  // Across (y): range x bearing sigma = 1852 m x 1 deg = 32.3234 m -> 1044.80 m^2.
  EXPECT_NEAR(out[0].covariance(1, 1), 1044.81, 0.01);
  EXPECT_NEAR(out[0].covariance(0, 1), 0.0, 1e-6);
  EXPECT_TRUE(out[0].has_geodetic);
  EXPECT_GT(out[0].lon_deg, kLon);  // east of the origin
}

TEST(ArpaTargets, RelativeBearingUsesTheRadarsHeadingWhenNavigationIsStale) {
  auto t = table();
  t.ownShip({0.0, 0.0}, 0.0, 0);
  t.osdHeading(degToRad(90.0), 9 * kSec);  // heading east from the radar's OSD
  // Own position (t = 0) is stale at 9 s, so the fix needs it: refused, but for position, not heading.
  EXPECT_EQ(t.ttm(ttm(3, 1000.0, 90.0, arpa::Reference::kRelative), 9 * kSec), ArpaOutcome::NoOwnPosition);
  t.ownShip({0.0, 0.0}, degToRad(180.0), 10 * kSec);  // navigation heading south wins while fresh
  ASSERT_EQ(t.ttm(ttm(3, 1000.0, 90.0, arpa::Reference::kRelative), 10 * kSec), ArpaOutcome::Target);
  const auto out = due(t, 10 * kSec);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].position.x(), -1000.0, 1e-6);  // 180 + 90 = 270: due west
  EXPECT_NEAR(out[0].position.y(), 0.0, 1e-6);
}

TEST(ArpaTargets, VelocityAndQuality) {
  auto t = table();
  t.ownShip({0.0, 0.0}, 0.0, 0);
  arpa::TrackedTarget moving = ttm(1, 1000.0, 0.0);
  moving.has_speed = moving.has_course = true;
  moving.speed = 5.0;
  moving.course = degToRad(90.0);
  moving.course_ref = arpa::Reference::kTrue;
  arpa::TrackedTarget stopped = ttm(2, 1000.0, 0.0);
  stopped.has_speed = true;
  stopped.speed = 0.0;  // no course: stopped
  arpa::TrackedTarget unknown = ttm(3, 1000.0, 0.0);
  arpa::TrackedTarget acquiring = moving;
  acquiring.number = 4;
  acquiring.status = arpa::TargetStatus::kQuery;
  for (const auto& tt : {moving, stopped, unknown, acquiring})
    ASSERT_EQ(t.ttm(tt, 0), ArpaOutcome::Target);
  const auto out = due(t, 0);
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[0].quality(), ArpaQuality::Tracking);
  EXPECT_NEAR(out[0].velocity.x(), 5.0, 1e-9);  // east
  EXPECT_NEAR(out[0].velocity.y(), 0.0, 1e-9);
  EXPECT_EQ(out[1].quality(), ArpaQuality::Tracking);
  EXPECT_TRUE(out[1].has_velocity);
  EXPECT_DOUBLE_EQ(out[1].speed, 0.0);
  EXPECT_EQ(out[2].quality(), ArpaQuality::NoVelocity);
  EXPECT_EQ(out[3].quality(), ArpaQuality::Acquiring);
}

TEST(ArpaTargets, TllPositionLostEvictionAndForgetting) {
  auto t = table(2);
  arpa::TargetPosition tp;
  tp.number = 5;
  tp.has_position = true;
  tp.lat_deg = kLat + 1.0 / 60.0;  // 1' north: about 1855 m
  tp.lon_deg = kLon;
  tp.status = arpa::TargetStatus::kTracking;
  ASSERT_EQ(t.tll(tp, 0), ArpaOutcome::Target);
  arpa::TargetPosition far = tp;
  far.lat_deg = kLat + 3.0;  // about 333 km: beyond the default 200 km
  EXPECT_EQ(t.tll(far, 0), ArpaOutcome::OutOfRange);
  auto out = due(t, 0);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(out[0].position.y(), 1855.0, 5.0);
  EXPECT_DOUBLE_EQ(out[0].covariance(0, 0), 2500.0);  // tll_sigma 50 m
  EXPECT_EQ(out[0].quality(), ArpaQuality::NoVelocity);
  t.ownShip({0.0, 0.0}, 0.0, 10 * kSec);
  ASSERT_EQ(t.ttm(ttm(6, 500.0, 0.0), 10 * kSec), ArpaOutcome::Target);
  ASSERT_EQ(t.ttm(ttm(7, 500.0, 0.0), 11 * kSec), ArpaOutcome::Target);  // full: 5 (t = 0) goes
  EXPECT_EQ(t.evicted(), 1u);
  EXPECT_EQ(t.size(), 2u);
  arpa::TrackedTarget lost = ttm(6, 0.0, 0.0);
  lost.status = arpa::TargetStatus::kLost;
  EXPECT_EQ(t.ttm(lost, 11 * kSec), ArpaOutcome::Lost);
  EXPECT_EQ(t.lost(), 1u);
  out = due(t, 11 * kSec);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].number, 7);
  EXPECT_TRUE(due(t, 12 * kSec).empty());  // nothing new
  ASSERT_EQ(t.ttm(ttm(7, 500.0, 0.0), 12 * kSec), ArpaOutcome::Target);
  EXPECT_EQ(due(t, 12 * kSec + 121 * kSec).size(), 0u);  // forget_after 120 s
  EXPECT_EQ(t.size(), 0u);
}
