// The own ship's navigation sentences (codec/gnss.h) and her state from them (tracking/own_ship.h).
// Sentences: the classic NMEA examples (GGA, RMC, VTG as published with their checksums) and others
// with checksums computed apart (Python XOR). Expected values by hand:
//  - GGA 4807.038 N 01131.000 E: 48 + 7.038/60 = 48.1173 deg, 11 + 31/60 = 11.516667 deg; quality 1,
//    8 satellites, HDOP 0.9; position 1-sigma 0.9 x 4 m = 3.6 m;
//  - RMC: 22.4 kn = 11.5236 m/s at 084.4 deg; variation 3.1 W = -3.1 deg; no HDOP: 1.5 x 4 m = 6 m;
//  - VTG: 054.7 deg true, 5.5 kn = 2.8294 m/s;
//  - HDG 101.1 magnetic, variation 7.1 W: 94.0 deg true; ROT -12.5 deg/min = -0.0036361 rad/s.
#include <gtest/gtest.h>

#include <cmath>

#include "asv_core/codec/gnss.h"
#include "asv_core/common/units.h"
#include "asv_core/tracking/own_ship.h"

namespace g = asv::gnss;

namespace {

asv::nmea::Sentence framed(const std::string& line) {
  static std::vector<std::string> keep;  // the sentence's views point into the line
  keep.push_back(line);
  asv::nmea::Sentence s;
  EXPECT_EQ(asv::nmea::parseSentence(keep.back(), s), asv::nmea::Reject::kNone) << line;
  return s;
}

const char* kGga = "$GPGGA,123519,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47";
const char* kRmc = "$GPRMC,123519,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*6A";

asv::OwnShipConfig config() {
  asv::ParamMap p;
  p.set("origin_lat_deg", 48.1173);
  p.set("origin_lon_deg", 11.0 + 31.0 / 60.0);
  p.set("watch/wall_floor", 0.0);
  return asv::OwnShipConfig::fromParams(p);
}

}  // namespace

TEST(Gnss, GgaRmcVtgGnsByHand) {
  g::Fix f;
  ASSERT_EQ(g::parseGga(framed(kGga), f), g::Error::kNone);
  EXPECT_NEAR(f.lat_deg, 48.1173, 1e-9);
  EXPECT_NEAR(f.lon_deg, 11.516666667, 1e-8);
  EXPECT_EQ(f.quality, g::Quality::kGnss);
  EXPECT_EQ(*f.satellites, 8);
  EXPECT_DOUBLE_EQ(*f.hdop, 0.9);
  g::Motion m;
  std::optional<double> variation;
  ASSERT_EQ(g::parseRmc(framed(kRmc), f, m, variation), g::Error::kNone);
  EXPECT_NEAR(*m.speed, 11.5236, 1e-4);
  EXPECT_NEAR(asv::radToDeg(*m.course), 84.4, 1e-9);
  EXPECT_NEAR(asv::radToDeg(*variation), -3.1, 1e-9);
  EXPECT_FALSE(f.hdop);
  ASSERT_EQ(g::parseVtg(framed("$GPVTG,054.7,T,034.4,M,005.5,N,010.2,K*48"), m), g::Error::kNone);
  EXPECT_NEAR(asv::radToDeg(*m.course), 54.7, 1e-9);
  EXPECT_NEAR(*m.speed, 2.8294, 1e-4);
  ASSERT_EQ(g::parseGns(framed("$GPGNS,112257.00,3844.24011,N,00908.43828,W,AN,03,10.5,,,,*57"), f),
            g::Error::kNone);
  EXPECT_NEAR(f.lat_deg, 38.0 + 44.24011 / 60.0, 1e-9);
  EXPECT_NEAR(f.lon_deg, -(9.0 + 8.43828 / 60.0), 1e-9);
  EXPECT_EQ(f.quality, g::Quality::kGnss);  // A on GPS, N on GLONASS: the better
  ASSERT_EQ(g::parseRmc(framed("$GPRMC,123520,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W,D*08"), f,
                        m, variation),
            g::Error::kNone);
  EXPECT_EQ(f.quality, g::Quality::kDifferential);
}

TEST(Gnss, NoFixAndInvalidAreNeverValues) {
  g::Fix f;
  g::Motion m;
  std::optional<double> v;
  double h = 0.0;
  EXPECT_EQ(g::parseGga(framed("$GPGGA,123519,4807.038,N,01131.000,E,0,00,,,M,,M,,*52"), f),
            g::Error::kNoFix);
  EXPECT_EQ(
      g::parseRmc(framed("$GPRMC,123519,V,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*7D"), f, m, v),
      g::Error::kNoFix);
  EXPECT_EQ(g::parseGns(framed("$GPGNS,112257.00,3844.24011,N,00908.43828,W,NN,00,,,,,*41"), f),
            g::Error::kNoFix);
  EXPECT_EQ(g::parseThs(framed("$HETHS,123.4,V*3E"), h), g::Error::kInvalid);
  EXPECT_EQ(g::parseHdg(framed("$HCHDG,101.1,,,,*43"), std::nullopt, h),
            g::Error::kInvalid);  // magnetic only
  EXPECT_EQ(g::parseHdt(framed(kGga), h), g::Error::kWrongType);
}

TEST(Gnss, HeadingsAndRateOfTurn) {
  double h = 0.0;
  ASSERT_EQ(g::parseHdt(framed("$HEHDT,274.07,T*19"), h), g::Error::kNone);
  EXPECT_NEAR(asv::radToDeg(h), 274.07, 1e-9);
  ASSERT_EQ(g::parseThs(framed("$HETHS,123.4,A*29"), h), g::Error::kNone);
  EXPECT_NEAR(asv::radToDeg(h), 123.4, 1e-9);
  ASSERT_EQ(g::parseHdg(framed("$HCHDG,101.1,,,7.1,W*3C"), std::nullopt, h), g::Error::kNone);
  EXPECT_NEAR(asv::radToDeg(h), 94.0, 1e-9);
  ASSERT_EQ(g::parseHdg(framed("$HCHDG,101.1,,,,*43"), asv::degToRad(2.0), h), g::Error::kNone);
  EXPECT_NEAR(asv::radToDeg(h), 103.1, 1e-9);  // the configured variation, 2 E
  ASSERT_EQ(g::parseRot(framed("$TIROT,-12.5,A*20"), h), g::Error::kNone);
  EXPECT_NEAR(h, -0.0036361, 1e-7);
}

TEST(OwnShip, FixCourseHeadingDeadReckonedWithTheirSigmas) {
  const asv::OwnShipConfig c = config();
  asv::OwnShipEstimator e(c, asv::LocalFrame(c.origin_lat_deg, c.origin_lon_deg));
  std::string why;
  EXPECT_EQ(e.feed(framed(kRmc), 0.0, 0.0, why), asv::OwnShipEstimator::Use::kUsed);
  EXPECT_EQ(e.feed(framed("$HEHDT,274.07,T*19"), 0.0, 0.0, why), asv::OwnShipEstimator::Use::kUsed);
  auto s = e.state(0.5);
  ASSERT_TRUE(s);
  // 0.5 s at 11.5236 m/s on 084.4: east 11.5236 sin(84.4) x 0.5 = 5.734, north 11.5236 cos(84.4) x 0.5 =
  // 0.562.
  EXPECT_NEAR(s->position.x(), 5.734, 0.01);
  EXPECT_NEAR(s->position.y(), 0.562, 0.01);
  EXPECT_DOUBLE_EQ(s->position_sigma, 6.0);
  EXPECT_NEAR(asv::radToDeg(s->heading), 274.07, 1e-9);
  EXPECT_FALSE(s->heading_from_cog);
  EXPECT_EQ(s->position_source, "RMC");
  e.feed(framed(kGga), 0.6, 0.6, why);
  s = e.state(0.6);
  EXPECT_DOUBLE_EQ(s->position_sigma, 3.6);  // HDOP 0.9 x 4 m
  EXPECT_EQ(e.feed(framed("$GPZDA,123519,01,01,2026,,*43"), 0.7, 0.7, why),
            asv::OwnShipEstimator::Use::kNotNavigation);
}

// A receiver read as ROS messages (own_ship_node's navsat): position with its own 1-sigma, velocity and
// heading through the same rules. 0.001 deg north of the origin (48.1173 N) is the meridian arc
// M x 0.001 deg, M = a (1 - e^2) / (1 - e^2 sin^2 48.1178)^1.5 = 6370867.5 m: 111.193 m.
TEST(OwnShip, ReceiverFixVelocityAndHeadingFromOtherSources) {
  const asv::OwnShipConfig c = config();
  asv::OwnShipEstimator e(c, asv::LocalFrame(c.origin_lat_deg, c.origin_lon_deg));
  g::Fix f;
  f.lat_deg = 48.1173 + 0.001;
  f.lon_deg = c.origin_lon_deg;
  f.quality = g::Quality::kGnss;
  f.sigma = 3.0;
  std::string why;
  ASSERT_EQ(e.position(f, "NavSatFix", 0.0, 0.0, why), asv::OwnShipEstimator::Use::kUsed);
  EXPECT_FALSE(e.state(0.0)) << "no velocity yet: no odometry";
  e.motion(g::Motion{0.0, 5.0}, 0.0);  // due north at 5 m/s
  e.heading(asv::degToRad(10.0), 0.0, 0.0);
  auto s = e.state(1.0);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->position.x(), 0.0, 0.01);
  EXPECT_NEAR(s->position.y(), 111.193 + 5.0, 0.01);  // dead-reckoned 1 s
  EXPECT_DOUBLE_EQ(s->position_sigma, 3.0);           // the receiver's, not HDOP x 4 m
  EXPECT_EQ(s->position_source, "NavSatFix");
  EXPECT_NEAR(asv::radToDeg(s->heading), 10.0, 1e-9);
  EXPECT_FALSE(s->heading_from_cog);
  // No fix, or no position: rejected and counted, never a value.
  f.quality = g::Quality::kNone;
  EXPECT_EQ(e.position(f, "NavSatFix", 1.0, 1.0, why), asv::OwnShipEstimator::Use::kRejected);
  EXPECT_EQ(why, "NavSatFix: no fix");
  f.quality = g::Quality::kGnss;
  f.lat_deg = std::nan("");
  EXPECT_EQ(e.position(f, "NavSatFix", 1.0, 1.0, why), asv::OwnShipEstimator::Use::kRejected);
  EXPECT_EQ(e.rejected(), 2u);
  // 0.1 deg (11 km) away 1 s later is a jump, as for a sentence.
  f.lat_deg = 48.2173;
  EXPECT_EQ(e.position(f, "NavSatFix", 1.0, 1.0, why), asv::OwnShipEstimator::Use::kRejected);
  EXPECT_EQ(e.jumps(), 1u);
}

TEST(OwnShip, WithoutAHeadingSensorTheCourseStandsInWhileMaking) {
  const asv::OwnShipConfig c = config();
  asv::OwnShipEstimator e(c, asv::LocalFrame(c.origin_lat_deg, c.origin_lon_deg));
  std::string why;
  e.feed(framed(kRmc), 0.0, 0.0, why);
  auto s = e.state(0.1);
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->heading_from_cog);
  EXPECT_NEAR(asv::radToDeg(s->heading), 84.4, 1e-9);
  EXPECT_NEAR(s->heading_sigma, asv::degToRad(10.0), 1e-12);
  EXPECT_TRUE(e.stale(0.1, 0.1).empty());  // no heading sensor while making way: no alarm
  // Stopped (0.2 kn), no heading sensor: her heading is unknown, no state.
  e.feed(framed("$GPRMC,123520,A,4807.038,N,01131.000,E,000.2,084.4,230394,003.1,W*66"), 1.0, 1.0, why);
  EXPECT_FALSE(e.state(1.0));
}

TEST(OwnShip, JumpsAreRejectedUntilTheyAgree) {
  const asv::OwnShipConfig c = config();
  asv::OwnShipEstimator e(c, asv::LocalFrame(c.origin_lat_deg, c.origin_lon_deg));
  std::string why;
  // Stopped, with a heading sensor: the state stands on the fix alone.
  auto still = [&](double t) {
    e.feed(framed("$GPVTG,000.0,T,,M,000.0,N,000.0,K*60"), t, t, why);
    e.feed(framed("$HEHDT,274.07,T*19"), t, t, why);
  };
  e.feed(framed(kGga), 0.0, 0.0, why);
  still(0.0);
  // 4807.538 N: 0.5' = 926 m north 1 s later: 926 m/s, a jump.
  const std::string far = "$GPGGA,123520,4807.538,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*";
  auto withSum = [](std::string s) {
    const std::string body = s.substr(1, s.size() - 2);
    char b[4];
    std::snprintf(b, sizeof b, "%02X", asv::nmea::checksum(body));
    return s + b;
  };
  EXPECT_EQ(e.feed(framed(withSum(far)), 1.0, 1.0, why), asv::OwnShipEstimator::Use::kRejected);
  EXPECT_NE(why.find("jumped 92"), std::string::npos) << why;
  EXPECT_EQ(e.feed(framed(withSum(far)), 2.0, 2.0, why), asv::OwnShipEstimator::Use::kRejected);
  still(2.0);
  ASSERT_TRUE(e.state(2.0));
  EXPECT_NEAR(e.state(2.0)->position.y(), 0.0, 1e-6);
  // The third in a row, agreeing with the two before: the receiver was right.
  EXPECT_EQ(e.feed(framed(withSum(far)), 3.0, 3.0, why), asv::OwnShipEstimator::Use::kUsed);
  still(3.0);
  ASSERT_TRUE(e.state(3.0));
  EXPECT_NEAR(e.state(3.0)->position.y(), 926.6, 1.0);  // 0.5' of latitude at 48 N: 926.6 m
  EXPECT_EQ(e.jumps(), 3u);
}

TEST(OwnShip, StaleFixIsAnAlarmAndHerAisReportsAreTheFallback) {
  const asv::OwnShipConfig c = config();
  asv::OwnShipEstimator e(c, asv::LocalFrame(c.origin_lat_deg, c.origin_lon_deg));
  std::string why;
  e.feed(framed(kRmc), 0.0, 0.0, why);
  e.feed(framed("$HEHDT,274.07,T*19"), 0.0, 0.0, why);
  auto lost = e.stale(2.5, 2.5);  // 2.5 s without a fix or a heading (timeout 2 s)
  ASSERT_EQ(lost.size(), 2u);
  EXPECT_EQ(lost[0].name, "fix");
  EXPECT_EQ(lost[1].name, "heading");
  // Her AIS transponder: 100 m north of the origin, 10 kn on 000, heading 001.
  const asv::LocalFrame frame(c.origin_lat_deg, c.origin_lon_deg);
  const asv::GeoPoint p = frame.toGeodetic({0.0, 100.0});
  e.aisReport(p.lat_deg, p.lon_deg, true, 0.0, asv::knotsToMps(10.0), asv::degToRad(1.0), 3.0);
  const auto s = e.state(3.0);
  ASSERT_TRUE(s);
  EXPECT_EQ(s->position_source, "AIS");
  EXPECT_NEAR(s->position.y(), 100.0, 1e-6);
  EXPECT_DOUBLE_EQ(s->position_sigma, 10.0);
  EXPECT_NEAR(asv::radToDeg(s->heading), 1.0, 1e-9);
  lost = e.stale(3.0, 3.0);
  ASSERT_EQ(lost.size(), 1u);  // the fix is alive again (from AIS); the heading sensor is not
  EXPECT_EQ(lost[0].name, "heading");
  // Her reports stand in for ais_timeout (30 s), then the fix is lost again.
  EXPECT_TRUE(e.state(32.9));
  EXPECT_EQ(e.stale(32.9, 32.9).size(), 1u);
  EXPECT_FALSE(e.state(33.1));
  EXPECT_EQ(e.stale(33.1, 33.1)[0].name, "fix");
}

TEST(Gnss, VariationKeyInRadiansAndRefusedBeyondNinetyDegrees) {
  asv::ParamMap p;
  EXPECT_FALSE(g::variationFromParams(p));
  p.set("variation_deg", -3.5);
  EXPECT_NEAR(*g::variationFromParams(p), -3.5 * asv::kPi / 180.0, 1e-15);
  p.set("variation_deg", 95.0);
  EXPECT_THROW(g::variationFromParams(p), std::invalid_argument);
}
