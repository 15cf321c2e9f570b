// Tracker: association, dead reckoning, coasting and expiry by class, AIS + ARPA fusion. Expected
// values are worked out by hand in the comments from the model in tracker.h (default config:
// accel_sigma 0.1 m/s^2, so q = 0.01 m^2/s^4; class A ages 30/120 s, class B 90/360 s, slow 360/600 s,
// ARPA 10/60 s; gate max(200 m, 3 sigma), velocity gate 2.5 m/s).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "asv_core/common/clock_jump.h"
#include "asv_core/tracking/tracker.h"

namespace {

using asv::AisClass;
using asv::Tracker;
using asv::TrackReport;
using asv::TrackSource;
using asv::UpdateResult;

TrackReport ais(std::uint32_t mmsi, double t, double x, double y, double vx, double vy,
                AisClass cls = AisClass::kA) {
  TrackReport r;
  r.source = TrackSource::kAis;
  r.mmsi = mmsi;
  r.ais_class = cls;
  r.time = t;
  r.position = {x, y};
  r.position_variance = 100.0;  // 10 m
  r.has_velocity = true;
  r.velocity = {vx, vy};
  r.velocity_variance = 0.04;
  return r;
}

TrackReport arpa(int number, double t, double x, double y, double vx, double vy) {
  TrackReport r;
  r.source = TrackSource::kArpa;
  r.arpa_number = number;
  r.time = t;
  r.position = {x, y};
  r.position_variance = 2500.0;  // 50 m
  r.has_velocity = true;
  r.velocity = {vx, vy};
  r.velocity_variance = 0.25;
  r.quality = 80.0;
  return r;
}

TEST(Tracker, DeadReckonsAStraightLine) {
  Tracker tr;
  EXPECT_EQ(tr.update(ais(244000001, 0.0, 100.0, 200.0, 3.0, 4.0)), UpdateResult::kCreated);
  const auto e = tr.estimates(10.0);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_NEAR(e[0].position.x(), 130.0, 1e-9);  // 100 + 3 * 10
  EXPECT_NEAR(e[0].position.y(), 240.0, 1e-9);  // 200 + 4 * 10
  EXPECT_NEAR(e[0].velocity.x(), 3.0, 1e-12);
  EXPECT_NEAR(e[0].age, 10.0, 1e-12);
  EXPECT_EQ(e[0].source, TrackSource::kAis);
  EXPECT_EQ(e[0].mmsi, 244000001u);
  EXPECT_EQ(e[0].ais_class, AisClass::kA);
  EXPECT_FALSE(e[0].coasting);
  EXPECT_DOUBLE_EQ(e[0].quality, 100.0);
  // P = 100 + Pv dt^2 + q dt^4 / 4 = 100 + 0.04 * 100 + 0.01 * 10000 / 4 = 129
  EXPECT_NEAR(e[0].position_variance, 129.0, 1e-9);
}

TEST(Tracker, NewReportOfTheSameShipUpdatesItsTrack) {
  Tracker tr;
  tr.update(ais(244000001, 0.0, 0.0, 0.0, 0.0, 5.0));
  EXPECT_EQ(tr.update(ais(244000001, 10.0, 0.0, 52.0, 0.0, 5.0)), UpdateResult::kUpdated);
  ASSERT_EQ(tr.tracks().size(), 1u);
  // Predicted (0, 50) with P = 100 + 4 + 25 = 129; K = 129 / 229; y = 50 + 2 K.
  EXPECT_NEAR(tr.tracks()[0].position.y(), 50.0 + 2.0 * 129.0 / 229.0, 1e-9);
  EXPECT_NEAR(tr.tracks()[0].position_variance, 129.0 * 100.0 / 229.0, 1e-9);
  // The same report again (same time) is not news.
  EXPECT_EQ(tr.update(ais(244000001, 10.0, 0.0, 52.0, 0.0, 5.0)), UpdateResult::kOld);
  EXPECT_EQ(tr.counters().results[static_cast<int>(UpdateResult::kOld)], 1u);
}

TEST(Tracker, ClassACoastsAfter30sAndIsDroppedAfter2min) {
  Tracker tr;
  tr.update(ais(244000001, 0.0, 0.0, 0.0, 3.0, 4.0));
  EXPECT_FALSE(tr.estimates(30.0)[0].coasting);
  EXPECT_TRUE(tr.estimates(31.0)[0].coasting);
  // Coasting quality: 0.5 * 100 * (120 - 75) / (120 - 30) = 25
  EXPECT_NEAR(tr.estimates(75.0)[0].quality, 25.0, 1e-9);
  EXPECT_EQ(tr.maintain(120.0), 0u);
  EXPECT_EQ(tr.tracks().size(), 1u);
  EXPECT_EQ(tr.maintain(120.5), 1u);
  EXPECT_TRUE(tr.tracks().empty());
  EXPECT_EQ(tr.counters().dropped, 1u);
}

TEST(Tracker, ClassBLivesLonger) {
  Tracker tr;
  tr.update(ais(338000001, 0.0, 0.0, 0.0, 0.0, 5.0, AisClass::kB));
  EXPECT_FALSE(tr.estimates(90.0)[0].coasting);
  EXPECT_TRUE(tr.estimates(91.0)[0].coasting);
  EXPECT_EQ(tr.maintain(300.0), 0u);  // a class A track would be gone at 120 s
  EXPECT_EQ(tr.tracks().size(), 1u);
  EXPECT_EQ(tr.maintain(361.0), 1u);
}

TEST(Tracker, SlowShipsUseTheSlowReportingAges) {
  Tracker tr;
  tr.update(ais(244000001, 0.0, 0.0, 0.0, 0.0, 0.5));  // 1 kn, at anchor: reports every 3 min
  EXPECT_EQ(tr.maintain(300.0), 0u);
  EXPECT_FALSE(tr.estimates(300.0)[0].coasting);
  EXPECT_TRUE(tr.estimates(361.0)[0].coasting);
  EXPECT_EQ(tr.maintain(601.0), 1u);
}

TEST(Tracker, ArpaAges) {
  Tracker tr;
  tr.update(arpa(4, 0.0, 0.0, 1000.0, 0.0, 0.0));
  const auto e = tr.estimates(5.0);
  EXPECT_EQ(e[0].source, TrackSource::kArpa);
  EXPECT_EQ(e[0].arpa_number, 4);
  EXPECT_DOUBLE_EQ(e[0].quality, 80.0);
  EXPECT_TRUE(tr.estimates(11.0)[0].coasting);
  EXPECT_EQ(tr.maintain(60.0), 0u);
  EXPECT_EQ(tr.maintain(61.0), 1u);
}

TEST(Tracker, FusesAisAndArpaOfTheSameShip) {
  Tracker tr;
  EXPECT_EQ(tr.update(arpa(3, 0.0, 1000.0, 0.0, 0.0, 5.0)), UpdateResult::kCreated);
  // AIS report 1 s later 10.4 m from the radar track dead-reckoned to (1000, 5).
  EXPECT_EQ(tr.update(ais(244000001, 1.0, 1010.0, 8.0, 0.1, 5.0)), UpdateResult::kAssociated);
  ASSERT_EQ(tr.tracks().size(), 1u);
  const auto e = tr.estimates(1.0);
  EXPECT_EQ(e[0].source, TrackSource::kFused);
  EXPECT_EQ(e[0].mmsi, 244000001u);
  EXPECT_EQ(e[0].arpa_number, 3);
  // Radar track at t = 1: P = 2500 + 0.25 * 1 + 0.01 / 4 = 2500.2525; K = P / (P + 100).
  const double k = 2500.2525 / 2600.2525;
  EXPECT_NEAR(e[0].position.x(), 1000.0 + k * 10.0, 1e-9);
  EXPECT_NEAR(e[0].position.y(), 5.0 + k * 3.0, 1e-9);
  // Velocity: Pv = 0.25 + 0.01 = 0.26, Kv = 0.26 / 0.30.
  const double kv = 0.26 / 0.30;
  EXPECT_NEAR(e[0].velocity.x(), kv * 0.1, 1e-9);
  EXPECT_DOUBLE_EQ(e[0].quality, 100.0);  // the better of AIS 100 and ARPA 80
  // Later radar reports of number 3 stay with this track.
  EXPECT_EQ(tr.update(arpa(3, 2.0, 1015.0, 12.0, 0.0, 5.0)), UpdateResult::kUpdated);
  EXPECT_EQ(tr.tracks().size(), 1u);
}

TEST(Tracker, NearestNeighbourWithinTheGate) {
  Tracker tr;
  tr.update(ais(244000001, 0.0, 0.0, 0.0, 0.0, 0.0));
  tr.update(ais(244000002, 0.0, 150.0, 0.0, 0.0, 0.0));
  // Both are within 200 m of (100, 0); the second is nearer (50 m against 100 m).
  EXPECT_EQ(tr.update(arpa(1, 0.5, 100.0, 0.0, 0.0, 0.0)), UpdateResult::kAssociated);
  ASSERT_EQ(tr.tracks().size(), 2u);
  EXPECT_EQ(tr.tracks()[0].arpa_number, -1);
  EXPECT_EQ(tr.tracks()[1].arpa_number, 1);
}

TEST(Tracker, OutsideThePositionOrVelocityGateOpensANewTrack) {
  Tracker tr;
  tr.update(ais(244000001, 0.0, 0.0, 0.0, 0.0, 5.0));
  // 3 sigma = 3 sqrt(100 + 2500) = 153 m < 200 m: the gate is 200 m; 250 m is outside.
  EXPECT_EQ(tr.update(arpa(1, 0.0, 250.0, 0.0, 0.0, 5.0)), UpdateResult::kCreated);
  // 50 m away but 4 m/s faster: outside the 2.5 m/s velocity gate.
  EXPECT_EQ(tr.update(arpa(2, 0.0, 0.0, 50.0, 0.0, 9.0)), UpdateResult::kCreated);
  EXPECT_EQ(tr.tracks().size(), 3u);
  // An MMSI never joins another MMSI's track, however close.
  EXPECT_EQ(tr.update(ais(244000002, 0.0, 1.0, 0.0, 0.0, 5.0)), UpdateResult::kCreated);
}

TEST(Tracker, TrackToTrackAssociationMergesOnceTheGatesPass) {
  Tracker tr;
  tr.update(ais(244000001, 0.0, 0.0, 0.0, 0.0, 5.0));
  tr.update(ais(244000001, 2.0, 0.0, 10.0, 0.0, 5.0));
  // The radar's first velocity is off by 4 m/s while it acquires: no association.
  EXPECT_EQ(tr.update(arpa(7, 1.0, 0.0, 55.0, 4.0, 5.0)), UpdateResult::kCreated);
  EXPECT_EQ(tr.maintain(1.0), 0u);
  EXPECT_EQ(tr.tracks().size(), 2u);
  // Next scan: velocity (4, 5) + Kv ((0, 5) - (4, 5)) with Kv = 0.26 / 0.51: vx = 1.96 m/s, in the gate.
  EXPECT_EQ(tr.update(arpa(7, 2.0, 0.0, 60.0, 0.0, 5.0)), UpdateResult::kUpdated);
  EXPECT_NEAR(tr.tracks()[1].velocity.x(), 4.0 - 4.0 * 0.26 / 0.51, 1e-9);
  const std::uint64_t ais_id = tr.tracks()[0].id;
  tr.maintain(2.0);
  ASSERT_EQ(tr.tracks().size(), 1u);
  EXPECT_EQ(tr.tracks()[0].id, ais_id);
  EXPECT_EQ(tr.tracks()[0].arpa_number, 7);
  EXPECT_EQ(tr.counters().merged, 1u);
  EXPECT_EQ(tr.estimates(2.0)[0].source, TrackSource::kFused);
}

TEST(Tracker, ARadarTargetThatKeepsDisagreeingIsSplitOff) {
  Tracker tr;
  tr.update(ais(244000001, 0.0, 0.0, 0.0, 0.0, 5.0));
  tr.update(arpa(3, 0.0, 20.0, 0.0, 0.0, 5.0));
  ASSERT_EQ(tr.tracks().size(), 1u);
  for (int i = 1; i <= 2; ++i) {
    tr.update(ais(244000001, i, 0.0, 5.0 * i, 0.0, 5.0));
    EXPECT_EQ(tr.update(arpa(3, i + 0.1, 1000.0, 5.0 * i, 0.0, 5.0)), UpdateResult::kUpdated);
    EXPECT_EQ(tr.tracks().size(), 1u);
    EXPECT_LT(tr.tracks()[0].position.x(), 1.0);  // the disagreeing radar does not pull the track
  }
  tr.update(ais(244000001, 3.0, 0.0, 15.0, 0.0, 5.0));
  EXPECT_EQ(tr.update(arpa(3, 3.1, 1000.0, 15.0, 0.0, 5.0)), UpdateResult::kCreated);
  ASSERT_EQ(tr.tracks().size(), 2u);
  EXPECT_EQ(tr.tracks()[0].arpa_number, -1);
  EXPECT_EQ(tr.tracks()[1].arpa_number, 3);
  EXPECT_EQ(tr.counters().split, 1u);
}

TEST(Tracker, AnExpiredRadarNumberIsReleased) {
  Tracker tr;
  tr.update(arpa(3, 0.0, 0.0, 0.0, 0.0, 0.0));
  tr.update(ais(244000001, 0.0, 5.0, 0.0, 0.0, 0.0));
  ASSERT_EQ(tr.tracks().size(), 1u);
  tr.update(ais(244000001, 100.0, 5.0, 0.0, 0.0, 0.0));
  tr.maintain(100.0);  // radar part 100 s old > 60 s
  ASSERT_EQ(tr.tracks().size(), 1u);
  EXPECT_EQ(tr.tracks()[0].arpa_number, -1);
  EXPECT_EQ(tr.estimates(100.0)[0].source, TrackSource::kAis);
  // The radar reuses number 3 for a ship far away: a new track, not this one.
  EXPECT_EQ(tr.update(arpa(3, 101.0, 5000.0, 0.0, 0.0, 0.0)), UpdateResult::kCreated);
}

TEST(Tracker, InvalidReportsAndTheTrackLimit) {
  asv::TrackerConfig c;
  c.max_tracks = 2;
  Tracker tr(c);
  TrackReport bad = ais(244000001, 0.0, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 0.0);
  EXPECT_EQ(tr.update(bad), UpdateResult::kInvalid);
  EXPECT_EQ(tr.update(ais(0, 0.0, 0.0, 0.0, 0.0, 0.0)), UpdateResult::kInvalid);
  EXPECT_EQ(tr.update(ais(1000000000, 0.0, 0.0, 0.0, 0.0, 0.0)), UpdateResult::kInvalid);
  EXPECT_EQ(tr.update(arpa(-1, 0.0, 0.0, 0.0, 0.0, 0.0)), UpdateResult::kInvalid);
  TrackReport inf_v = ais(244000001, 0.0, 0.0, 0.0, std::numeric_limits<double>::infinity(), 0.0);
  EXPECT_EQ(tr.update(inf_v), UpdateResult::kInvalid);
  EXPECT_EQ(tr.update(ais(244000001, 0.0, 0.0, 0.0, 0.0, 0.0)), UpdateResult::kCreated);
  EXPECT_EQ(tr.update(ais(244000002, 0.0, 5000.0, 0.0, 0.0, 0.0)), UpdateResult::kCreated);
  EXPECT_EQ(tr.update(ais(244000003, 0.0, 9000.0, 0.0, 0.0, 0.0)), UpdateResult::kFull);
  EXPECT_EQ(tr.tracks().size(), 2u);
}

TEST(Tracker, ReportWithoutVelocityStaysPut) {
  Tracker tr;
  TrackReport r = arpa(9, 0.0, 10.0, 20.0, 0.0, 0.0);
  r.has_velocity = false;
  tr.update(r);
  const auto e = tr.estimates(5.0);
  EXPECT_FALSE(e[0].has_velocity);
  EXPECT_NEAR(e[0].position.x(), 10.0, 1e-12);
  EXPECT_NEAR(e[0].position.y(), 20.0, 1e-12);
}

TEST(TrackerConfig, Validates) {
  asv::TrackerConfig c;
  EXPECT_NO_THROW(c.validate());
  c.ais_a.drop_after = 10.0;  // below coast_after
  EXPECT_THROW(c.validate(), std::invalid_argument);
  c = asv::TrackerConfig();
  c.gate_min = 0.0;
  EXPECT_THROW(Tracker{c}, std::invalid_argument);
}

}  // namespace

TEST(ClockJumpDetector, FiresOnlyWhenTimeGoesBackBeyondTheTolerance) {
  asv::ClockJumpDetector c(1.0);
  EXPECT_FALSE(c.jumpedBack(0.0));  // a ROS clock not yet received
  EXPECT_FALSE(c.jumpedBack(100.0));
  EXPECT_FALSE(c.jumpedBack(99.5));  // jitter of concurrent callbacks
  EXPECT_FALSE(c.jumpedBack(101.0));
  EXPECT_FALSE(c.jumpedBack(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_TRUE(c.jumpedBack(10.0));  // a bag loops: 91 s back
  EXPECT_DOUBLE_EQ(c.lastJump(), 91.0);
  EXPECT_EQ(c.jumps(), 1u);
  EXPECT_FALSE(c.jumpedBack(11.0));  // time runs on from the new start
  EXPECT_FALSE(c.jumpedBack(10.5));
  EXPECT_EQ(c.jumps(), 1u);
}

TEST(Tracker, ClearDropsTheTracksButNotTheCountersOrIds) {
  Tracker t;
  ASSERT_EQ(t.update(ais(1, 100.0, 0, 0, 1, 0)), UpdateResult::kCreated);
  ASSERT_EQ(t.update(ais(2, 100.0, 500, 0, 1, 0)), UpdateResult::kCreated);
  const std::uint64_t first_id = t.tracks().back().id;
  t.clear();
  EXPECT_TRUE(t.tracks().empty());
  EXPECT_TRUE(t.estimates(5.0).empty());
  // After the jump the same ship makes a new track, with a new id, from its report at the new time.
  ASSERT_EQ(t.update(ais(1, 5.0, 10, 0, 1, 0)), UpdateResult::kCreated);
  EXPECT_GT(t.tracks().back().id, first_id);
  EXPECT_NEAR(t.estimates(6.0).front().position.x(), 11.0, 1e-9);
  EXPECT_EQ(t.counters().results[static_cast<std::size_t>(UpdateResult::kCreated)], 3u);
}
