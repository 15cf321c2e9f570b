// Round trip: what the simulator emits, decoded by the stack's own decoder (and by gpsd's gpsdecode
// when installed), gives back the true state within AIS quantisation.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "asv_core/codec/arpa.h"
#include "asv_core/codec/nmea.h"
#include "asv_core/codec/nmea_encode.h"
#include "asv_core/common/units.h"

using namespace asv;

namespace {
ais::Message decodeAll(const std::vector<std::string>& lines) {
  ais::Decoder dec;
  ais::Message m, out;
  int messages = 0;
  for (const auto& l : lines) {
    EXPECT_LE(l.size(), 82u) << l;  // within the NMEA limit
    if (dec.feedLine(l, 0.0, m) == ais::Status::kMessage) {
      out = m;
      ++messages;
    }
  }
  EXPECT_EQ(messages, 1);
  return out;
}
}  // namespace

TEST(NmeaEncode, ChecksumOfAKnownSentence) {
  // A sentence from the gpsd sample log, checksum 5C.
  EXPECT_EQ(nmea::withChecksum('!', "AIVDM,1,1,,B,15M67FC000G?ufbE`FepT@3n00Sa,0"),
            "!AIVDM,1,1,,B,15M67FC000G?ufbE`FepT@3n00Sa,0*5C");
}

TEST(NmeaEncode, Type1RoundTripWithinQuantisation) {
  const double lat = 54.612345, lon = 18.812345, sog = knotsToMps(10.4), cog = degToRad(66.3),
               hdg = degToRad(65.0), rot = degToRad(12.0) / 60.0;  // 12 deg/min to starboard
  ais::PositionReportA r;
  r.status = 0;
  r.lat = ais::rawLat(lat);
  r.lon = ais::rawLon(lon);
  r.speed = ais::rawSpeed(sog);
  r.course = ais::rawCourse(cog);
  r.heading = ais::rawHeading(hdg);
  r.turn = ais::rawTurn(rot);
  r.second = 17;
  const auto lines = ais::toSentences(ais::encodePositionA(1, 261000001, r), 'A', 0);
  ASSERT_EQ(lines.size(), 1u);
  const ais::Message m = decodeAll(lines);
  EXPECT_EQ(m.type, 1);
  EXPECT_EQ(m.mmsi, 261000001u);
  ais::Kinematics k;
  ASSERT_TRUE(ais::toKinematics(m, k));
  EXPECT_NEAR(k.lat_deg, lat, 0.5 / 600000.0 + 1e-12);  // 1/10000 minute
  EXPECT_NEAR(k.lon_deg, lon, 0.5 / 600000.0 + 1e-12);
  EXPECT_NEAR(k.speed, sog, knotsToMps(0.05) + 1e-9);  // 0.1 kn
  EXPECT_NEAR(k.course, cog, degToRad(0.05) + 1e-9);   // 0.1 deg
  EXPECT_NEAR(k.heading, hdg, degToRad(0.5) + 1e-9);   // 1 deg
  // ROT_AIS = 4.733 sqrt(12) = 16.4 -> 16 -> (16 / 4.733)^2 = 11.43 deg/min.
  EXPECT_EQ(std::get<ais::PositionReportA>(m.body).turn, 16);
}

TEST(NmeaEncode, SentinelsStayUnknown) {
  ais::PositionReportA r;
  r.lat = ais::rawLat(std::nullopt);
  r.lon = ais::rawLon(std::nullopt);
  r.speed = ais::rawSpeed(std::nullopt);
  r.course = ais::rawCourse(std::nullopt);
  r.heading = ais::rawHeading(std::nullopt);
  r.turn = ais::rawTurn(std::nullopt);
  const ais::Message m = decodeAll(ais::toSentences(ais::encodePositionA(3, 1, r), 'B', 0));
  ais::Kinematics k;
  ais::toKinematics(m, k);
  EXPECT_FALSE(k.has_position);
  EXPECT_FALSE(k.has_speed);
  EXPECT_FALSE(k.has_course);
  EXPECT_FALSE(k.has_heading);
  EXPECT_EQ(ais::rawSpeed(knotsToMps(150.0)), 1022u);  // "102.2 kn or more"
}

TEST(NmeaEncode, Type5TwoFragmentsRoundTrip) {
  ais::StaticVoyageData d;
  d.callsign.assign("SPAB1");
  d.shipname.assign("lazarowska ts1");
  d.shiptype = 70;
  d.to_bow = 120;
  d.to_stern = 30;
  d.to_port = 10;
  d.to_starboard = 12;
  d.draught = 75;
  d.destination.assign("GDANSK");
  d.month = 11;
  d.day = 22;
  d.hour = 6;
  d.minute = 30;
  const auto lines = ais::toSentences(ais::encodeStaticVoyage(d.to_bow + 261000000, d), 'A', 7);
  ASSERT_EQ(lines.size(), 2u);  // 424 bits = 71 characters
  EXPECT_NE(lines[0].find(",2,1,7,A,"), std::string::npos);
  const ais::Message m = decodeAll(lines);
  ASSERT_EQ(m.type, 5);
  const auto& s = std::get<ais::StaticVoyageData>(m.body);
  EXPECT_EQ(s.shipname.view(), "LAZAROWSKA TS1");  // six-bit ASCII is upper case
  EXPECT_EQ(s.callsign.view(), "SPAB1");
  EXPECT_EQ(s.destination.view(), "GDANSK");
  EXPECT_EQ(s.to_bow + s.to_stern, 150u);
  EXPECT_EQ(s.draught, 75u);
  EXPECT_EQ(s.shiptype, 70);
}

TEST(NmeaEncode, ClassBType18And24RoundTrip) {
  ais::PositionReportB r;
  r.lat = ais::rawLat(-33.85);
  r.lon = ais::rawLon(151.2);
  r.speed = ais::rawSpeed(3.0);
  r.course = ais::rawCourse(degToRad(200.0));
  r.heading = ais::rawHeading(std::nullopt);
  r.cs = true;
  ais::Message m = decodeAll(ais::toSentences(ais::encodePositionB(503000001, r), 'B', 0));
  EXPECT_EQ(m.type, 18);
  ais::Kinematics k;
  ASSERT_TRUE(ais::toKinematics(m, k));
  EXPECT_NEAR(k.lat_deg, -33.85, 1e-6);
  EXPECT_NEAR(k.speed, 3.0, knotsToMps(0.05));
  EXPECT_FALSE(k.has_heading);
  ais::StaticDataReport a;
  a.part = 0;
  a.shipname.assign("SMALL ASV");
  m = decodeAll(ais::toSentences(ais::encodeStaticDataReport(503000001, a), 'A', 0));
  EXPECT_EQ(std::get<ais::StaticDataReport>(m.body).shipname.view(), "SMALL ASV");
  ais::StaticDataReport b;
  b.part = 1;
  b.shiptype = 37;
  b.callsign.assign("VK123");
  b.to_bow = 3;
  b.to_stern = 2;
  m = decodeAll(ais::toSentences(ais::encodeStaticDataReport(503000001, b), 'A', 0));
  const auto& sb = std::get<ais::StaticDataReport>(m.body);
  EXPECT_EQ(sb.part, 1);
  EXPECT_EQ(sb.shiptype, 37);
  EXPECT_EQ(sb.callsign.view(), "VK123");
  EXPECT_EQ(sb.to_bow, 3u);
}

TEST(NmeaEncode, TtmRoundTripThroughTheArpaParser) {
  arpa::TtmOut t;
  t.number = 123;  // above 99, as real radars send
  t.distance = 2.5 * 1852.0;
  t.bearing = degToRad(45.2);
  t.speed = knotsToMps(12.3);
  t.course = degToRad(270.4);
  t.cpa = 0.4 * 1852.0;
  t.tcpa = 600.0;
  t.name = "TS1";
  t.utc_seconds_of_day = 3600 * 12 + 60 * 34 + 56.78;
  const std::string line = arpa::encodeTtm(t);
  nmea::Sentence s;
  ASSERT_EQ(nmea::parseSentence(line, s), nmea::Reject::kNone) << line;
  arpa::TrackedTarget r;
  ASSERT_EQ(arpa::parseTtm(s, r), arpa::Error::kNone) << line;
  EXPECT_EQ(r.number, 123);
  EXPECT_NEAR(r.distance, t.distance, 0.005 * 1852.0);
  EXPECT_NEAR(radToDeg(r.bearing), 45.2, 0.05 + 1e-9);
  EXPECT_NEAR(r.speed, t.speed, knotsToMps(0.05));
  EXPECT_NEAR(radToDeg(r.course), 270.4, 0.05 + 1e-9);
  EXPECT_NEAR(r.cpa, *t.cpa, 0.005 * 1852.0);
  EXPECT_NEAR(r.tcpa, 600.0, 3.0);  // 0.1 min
  EXPECT_EQ(r.status, arpa::TargetStatus::kTracking);
  EXPECT_NEAR(r.utc_seconds, t.utc_seconds_of_day, 0.01);
  // Acquiring: CPA/TCPA empty, status Q.
  t.cpa.reset();
  t.tcpa.reset();
  t.status = 'Q';
  const std::string acquiring = arpa::encodeTtm(t);  // the sentence views into this string
  ASSERT_EQ(nmea::parseSentence(acquiring, s), nmea::Reject::kNone);
  ASSERT_EQ(arpa::parseTtm(s, r), arpa::Error::kNone);
  EXPECT_FALSE(r.has_cpa);
  EXPECT_EQ(r.status, arpa::TargetStatus::kQuery);
}

TEST(NmeaEncode, GpsdecodeAgrees) {
  if (std::system("command -v gpsdecode > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "gpsdecode not installed";
  ais::PositionReportA r;
  r.status = 0;
  r.lat = ais::rawLat(54.6);
  r.lon = ais::rawLon(18.8);
  r.speed = ais::rawSpeed(knotsToMps(10.4));
  r.course = ais::rawCourse(degToRad(66.0));
  r.heading = ais::rawHeading(degToRad(66.0));
  const std::string path = testing::TempDir() + "/asv_encode.nmea";
  {
    std::ofstream f(path);
    for (const auto& l : ais::toSentences(ais::encodePositionA(1, 261000002, r), 'A', 0))
      f << l << "\r\n";
  }
  FILE* p = popen(("gpsdecode -u -j < " + path).c_str(), "r");
  ASSERT_NE(p, nullptr);
  char buf[2048];
  std::string out;
  while (fgets(buf, sizeof buf, p))
    out += buf;
  pclose(p);
  // gpsd's unscaled output: lat/lon in 1/10000 min, speed in 1/10 kn, course in 1/10 deg.
  EXPECT_NE(out.find("\"mmsi\":261000002"), std::string::npos) << out;
  EXPECT_NE(out.find("\"lat\":" + std::to_string(r.lat)), std::string::npos) << out;
  EXPECT_NE(out.find("\"lon\":" + std::to_string(r.lon)), std::string::npos) << out;
  EXPECT_NE(out.find("\"speed\":104"), std::string::npos) << out;
  EXPECT_NE(out.find("\"course\":660"), std::string::npos) << out;
}
