// The AIS target table (asv_core/tracking/ais_targets.h): which messages become targets, the velocity
// and position uncertainty a report gives, eviction and forgetting. Raw field values are ITU-R M.1371-5
// units (positions in 1/10000 min, speed in 1/10 kn, course in 1/10 deg), so every expected value is
// worked out by hand from the standard.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "asv_core/tracking/ais_targets.h"

using namespace asv;

namespace {
constexpr double kLat = 40.7, kLon = -74.0;  // the map origin, New York Harbor
constexpr std::int64_t kSec = 1000000000;

ais::Message classA(std::uint32_t mmsi, std::uint32_t speed, std::uint32_t course, std::uint32_t heading,
                    bool accuracy = false) {
  ais::PositionReportA a;
  a.status = 5;                                        // moored
  a.lat = static_cast<std::int32_t>(kLat * 600000.0);  // 24 420 000
  a.lon = static_cast<std::int32_t>(kLon * 600000.0);  // -44 400 000
  a.speed = speed;                                     // 1023: not available
  a.course = course;                                   // 3600: not available
  a.heading = heading;                                 // 511: not available
  a.accuracy = accuracy;
  a.turn = -128;  // not available
  ais::Message m;
  m.type = 1;
  m.mmsi = mmsi;
  m.body = a;
  return m;
}

AisTargetTable table(std::size_t max_targets = 100) {
  AisTargetConfig c;
  c.max_targets = max_targets;
  c.forget_after = 60.0;
  return AisTargetTable(c, LocalFrame(kLat, kLon));
}

std::vector<AisTarget> due(AisTargetTable& t, std::int64_t now_ns) {
  std::vector<AisTarget> out;
  t.due(now_ns, [&](const AisTarget& s, double) { out.push_back(s); });
  return out;
}
}  // namespace

TEST(AisTargets, ClassAReportWithCourseAndSpeed) {
  AisTargetTable t = table();
  ASSERT_EQ(t.update(classA(366000001, 100, 900, 511, true), 5 * kSec), AisOutcome::Target);
  const auto d = due(t, 5 * kSec);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].ais_class, 'A');
  EXPECT_EQ(d[0].nav_status, 5);
  EXPECT_NEAR(d[0].position.norm(), 0.0, 0.01);  // reported at the origin
  EXPECT_EQ(d[0].velocity, AisVelocity::Reported);
  EXPECT_NEAR(d[0].speed, 10.0 * 1852.0 / 3600.0, 1e-9);  // 100 x 0.1 kn
  EXPECT_NEAR(d[0].course, M_PI / 2, 1e-9);               // 900 x 0.1 deg: due east
  EXPECT_FALSE(d[0].has_heading);
  EXPECT_EQ(d[0].sigma, 10.0);  // the accuracy flag: DGNSS
  EXPECT_TRUE(due(t, 6 * kSec).empty()) << "reported once, published once";
}

TEST(AisTargets, VelocityFromHeadingStoppedOrUnknown) {
  AisTargetTable t = table();
  t.update(classA(1, 50, 3600, 180), 0);    // no course: the heading (180 deg) stands in
  t.update(classA(2, 0, 3600, 511), 0);     // speed 0, no course: stopped
  t.update(classA(3, 1023, 3600, 511), 0);  // no speed: unknown
  const auto d = due(t, 0);
  ASSERT_EQ(d.size(), 3u);
  for (const auto& s : d) {
    EXPECT_EQ(s.sigma, 30.0) << "no accuracy flag: GNSS";
    if (s.mmsi == 1) {
      EXPECT_EQ(s.velocity, AisVelocity::CourseFromHeading);
      EXPECT_NEAR(s.course, M_PI, 1e-9);
      EXPECT_NEAR(s.speed, 5.0 * 1852.0 / 3600.0, 1e-9);
    } else if (s.mmsi == 2) {
      EXPECT_EQ(s.velocity, AisVelocity::Reported);
      EXPECT_EQ(s.speed, 0.0);
    } else {
      EXPECT_EQ(s.velocity, AisVelocity::Unknown);
    }
  }
}

TEST(AisTargets, WhatIsNotATargetIsSaidWhy) {
  AisTargetTable t = table();
  ais::Message own = classA(366000001, 100, 900, 511);
  own.own_ship = true;  // AIVDO
  EXPECT_EQ(t.update(own, 0), AisOutcome::OwnShip);
  ais::Message voyage;
  voyage.type = 5;
  voyage.mmsi = 366000002;
  voyage.body = ais::StaticVoyageData{};
  EXPECT_EQ(t.update(voyage, 0), AisOutcome::NotAShip);
  EXPECT_EQ(t.update(classA(0, 100, 900, 511), 0), AisOutcome::BadMmsi);
  EXPECT_EQ(t.update(classA(1000000000, 100, 900, 511), 0), AisOutcome::BadMmsi);
  ais::Message nowhere = classA(366000003, 100, 900, 511);
  std::get<ais::PositionReportA>(nowhere.body).lat = 91 * 600000;  // 91 deg: "not available"
  EXPECT_EQ(t.update(nowhere, 0), AisOutcome::NoPosition);
  ais::Message far = classA(366000004, 100, 900, 511);
  std::get<ais::PositionReportA>(far.body).lat = static_cast<std::int32_t>(43.0 * 600000.0);  // 255 km north
  EXPECT_EQ(t.update(far, 0), AisOutcome::OutOfRange);
  EXPECT_EQ(t.size(), 0u);
}

TEST(AisTargets, AFullTableEvictsTheLeastRecentlyHeardAndSilentShipsAreForgotten) {
  AisTargetTable t = table(2);
  t.update(classA(1, 100, 900, 511), 10 * kSec);
  t.update(classA(2, 100, 900, 511), 20 * kSec);
  t.update(classA(1, 100, 900, 511), 30 * kSec);  // ship 1 heard again: ship 2 is now the oldest
  t.update(classA(3, 100, 900, 511), 40 * kSec);
  EXPECT_EQ(t.size(), 2u);
  EXPECT_EQ(t.evicted(), 1u);
  std::vector<std::uint32_t> left;
  std::vector<double> ages;
  t.due(45 * kSec, [&](const AisTarget& s, double age) {
    left.push_back(s.mmsi);
    ages.push_back(age);
  });
  ASSERT_EQ(left.size(), 2u);
  EXPECT_NE(left[0], 2u);
  EXPECT_NE(left[1], 2u);
  // forget_after 60 s: ship 1 (heard at 30 s) is gone at 91 s, ship 3 (40 s) still there.
  t.update(classA(3, 100, 900, 511), 40 * kSec);
  EXPECT_EQ(due(t, 91 * kSec).size(), 1u);
  EXPECT_EQ(t.size(), 1u);
}

TEST(AisTargets, SpanSecondsRoundsAsRosDurations) {
  EXPECT_EQ(spanSeconds(1500000000), 1.5);
  EXPECT_EQ(spanSeconds(-1500000000), -2.0 + 0.5);  // sec -2, nsec 500 000 000
  EXPECT_NEAR(spanSeconds(-1), -1e-9, 1e-16);       // sec -1, nsec 999 999 999: rounded as -1 + 0.999999999
}

namespace {
ais::Message aid(std::uint32_t mmsi, double lat, double lon, bool virtual_aid) {
  ais::AidToNavigation a;
  a.aid_type = 24;  // port hand mark
  a.name.assign("BUOY 7");
  a.lat = static_cast<std::int32_t>(lat * 600000.0);
  a.lon = static_cast<std::int32_t>(lon * 600000.0);
  a.virtual_aid = virtual_aid;
  a.to_bow = a.to_stern = 1;
  ais::Message m;
  m.type = 21;
  m.mmsi = mmsi;
  m.body = a;
  return m;
}

ais::Message sarAircraft(std::uint32_t mmsi, std::uint32_t alt, std::uint32_t speed_kn) {
  ais::SarAircraftReport r;
  r.alt = alt;
  r.speed = speed_kn;
  r.course = 900;  // 90.0 deg
  r.lat = static_cast<std::int32_t>(kLat * 600000.0);
  r.lon = static_cast<std::int32_t>(kLon * 600000.0);
  ais::Message m;
  m.type = 9;
  m.mmsi = mmsi;
  m.body = r;
  return m;
}
}  // namespace

TEST(AisTargets, SarAircraftAreKeptApartFromShips) {
  // The ships' table refuses an aircraft; a table made for them keeps it, with its altitude and its
  // speed in whole knots (ITU-R M.1371 message 9: 100 kn = 51.44 m/s).
  AisTargetTable ships = table();
  EXPECT_EQ(ships.update(sarAircraft(111232511, 300, 100), 0), AisOutcome::NotAShip);
  AisTargetConfig c;
  c.sar_aircraft = true;
  AisTargetTable sar(c, LocalFrame(kLat, kLon));
  EXPECT_EQ(sar.update(classA(366000001, 100, 900, 511), 0), AisOutcome::NotAShip);
  ASSERT_EQ(sar.update(sarAircraft(111232511, 300, 100), 0), AisOutcome::Target);
  const std::vector<AisTarget> d = due(sar, 1 * kSec);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].ais_class, 'S');
  EXPECT_TRUE(d[0].has_altitude);
  EXPECT_DOUBLE_EQ(d[0].altitude, 300.0);
  EXPECT_NEAR(d[0].speed, 100.0 * 1852.0 / 3600.0, 1e-9);
  EXPECT_NEAR(d[0].course, M_PI / 2, 1e-9);
  // Altitude 4095: not available.
  sar.update(sarAircraft(111232512, 4095, 100), 2 * kSec);
  const std::vector<AisTarget> d2 = due(sar, 3 * kSec);
  ASSERT_EQ(d2.size(), 1u);
  EXPECT_FALSE(d2[0].has_altitude);
}

TEST(AisTargets, AidsToNavigationAreRememberedForgottenAndRefused) {
  AidTableConfig c;
  c.max_aids = 2;
  c.forget_after = 600.0;
  AidTable t(c, LocalFrame(kLat, kLon));
  // 0.01 deg north of the origin: 1110 m on the WGS84 ellipsoid at 40.7 N (111.03 km per degree).
  ASSERT_EQ(t.update(aid(992611001, kLat + 0.01, kLon, false), 10 * kSec), AisOutcome::Target);
  const AidRecord& a = t.aids().at(992611001);
  EXPECT_NEAR(a.position.x(), 0.0, 0.1);
  EXPECT_NEAR(a.position.y(), 1110.3, 1.0);
  EXPECT_EQ(a.name, "BUOY 7");
  EXPECT_EQ(a.aid_type, 24);
  EXPECT_DOUBLE_EQ(a.to_bow + a.to_stern, 2.0);
  EXPECT_EQ(t.update(aid(992611002, kLat, kLon + 0.01, true), 20 * kSec), AisOutcome::Target);
  EXPECT_TRUE(t.aids().at(992611002).virtual_aid);
  // A third aid evicts the least recently heard.
  EXPECT_EQ(t.update(aid(992611003, kLat, kLon, false), 30 * kSec), AisOutcome::Target);
  EXPECT_EQ(t.size(), 2u);
  EXPECT_EQ(t.evicted(), 1u);
  EXPECT_FALSE(t.aids().count(992611001));
  // forget_after 600 s: the aid heard at 20 s is gone at 621 s, the one at 30 s is not.
  t.forget(621 * kSec);
  EXPECT_EQ(t.size(), 1u);
  EXPECT_TRUE(t.aids().count(992611003));
  // Refused: no position (lat 91), invalid MMSI, beyond max_range, and a ship's report.
  EXPECT_EQ(t.update(aid(992611004, 91.0, kLon, false), 0), AisOutcome::NoPosition);
  EXPECT_EQ(t.update(aid(0, kLat, kLon, false), 0), AisOutcome::BadMmsi);
  EXPECT_EQ(t.update(aid(992611005, kLat + 2.5, kLon, false), 0), AisOutcome::OutOfRange);
  EXPECT_EQ(t.update(classA(366000001, 100, 900, 511), 0), AisOutcome::NotAShip);
}

TEST(AisTargets, TheOwnShipsAivdmIsNoTarget) {
  // own_mmsi: a shore log replayed with one of its vessels as the own ship; her AIVDM reports are
  // hers, as AIVDO would be; the others stay targets.
  AisTargetConfig c;
  c.own_mmsi = 367782880;
  AisTargetTable t(c, LocalFrame(kLat, kLon));
  EXPECT_EQ(t.update(classA(367782880, 176, 900, 511), 0), AisOutcome::OwnShip);
  EXPECT_EQ(t.update(classA(366999618, 190, 900, 511), 0), AisOutcome::Target);
  EXPECT_EQ(t.size(), 1u);
  c.own_mmsi = 1000000000;  // ten digits: not an MMSI
  EXPECT_THROW(c.validate(), std::invalid_argument);
}
