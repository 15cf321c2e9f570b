// Chart-plotter output (asv_core/tracking/plotter_output.h) and the RMC/HDT encoders. Expected sentences
// by hand, checksums computed with Python's XOR over the body; what is sent is also read back by the
// stack's own parsers (GNSS, AIS, ARPA), which their own tests check against hand-decoded sentences.
#include <gtest/gtest.h>

#include <cmath>

#include "asv_core/codec/arpa.h"
#include "asv_core/codec/gnss.h"
#include "asv_core/codec/nmea.h"
#include "asv_core/codec/nmea_encode.h"
#include "asv_core/common/units.h"
#include "asv_core/tracking/plotter_output.h"

using namespace asv;

namespace {

constexpr double kEpoch = 1.0e9;  // 2001-09-09 01:46:40 UTC (the simulator's time 0)

nmea::Sentence framed(const std::string& line, std::vector<std::string>& keep) {
  keep.push_back(line);
  nmea::Sentence s;
  EXPECT_EQ(nmea::parseSentence(keep.back(), s), nmea::Reject::kNone) << line;
  return s;
}

PlotterOwn ownAtOrigin() {
  PlotterOwn o;
  o.course = degToRad(90.0);
  o.speed = 10.0 * kMpsPerKnot;
  o.heading = degToRad(92.0);
  return o;
}

}  // namespace

TEST(PlotterOutput, RmcAndHdtByHand) {
  gnss::RmcOut r;
  r.unix_time = kEpoch;
  r.lat_deg = 54.6;  // 54 36.0000' N
  r.lon_deg = 18.8;  // 018 48.0000' E
  r.speed = 10.0 * kMpsPerKnot;
  r.course = degToRad(90.0);
  EXPECT_EQ(gnss::encodeRmc(r), "$GPRMC,014640.00,A,5436.0000,N,01848.0000,E,10.0,90.0,090901,,,A*51");
  // Southern and eastern hemispheres, the last 1/100 s of a century's last day: 33.8568 S = 33 51.408',
  // 151.2153 E = 151 12.918'.
  r.unix_time = 946684799.99;
  r.lat_deg = -33.8568;
  r.lon_deg = 151.2153;
  r.speed = 0.0;
  r.course = 0.0;
  EXPECT_EQ(gnss::encodeRmc(r), "$GPRMC,235959.99,A,3351.4080,S,15112.9180,E,0.0,0.0,311299,,,A*4D");
  EXPECT_EQ(gnss::encodeHdt(degToRad(359.96)), "$HEHDT,0.0,T*2F");  // rounds to 0.0, never "360.0"
  // Read back by the parser own_ship_node uses.
  std::vector<std::string> keep;
  gnss::Fix f;
  gnss::Motion m;
  std::optional<double> variation;
  ASSERT_EQ(gnss::parseRmc(framed(gnss::encodeRmc(r), keep), f, m, variation), gnss::Error::kNone);
  EXPECT_NEAR(f.lat_deg, -33.8568, 1e-7);
  EXPECT_NEAR(f.lon_deg, 151.2153, 1e-7);
}

TEST(PlotterOutput, OwnShipRmcHdtAndVdo) {
  PlotterConfig c;
  c.own_mmsi = 257000001;
  PlotterOutput p(c, LocalFrame(54.6, 18.8));
  const std::vector<std::string> out = p.sentences(ownAtOrigin(), {}, kEpoch + 5.0);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0], "$GPRMC,014645.00,A,5436.0000,N,01848.0000,E,10.0,90.0,090901,,,A*54");
  EXPECT_EQ(out[1], "$HEHDT,92.0,T*14");
  ASSERT_EQ(out[2].substr(0, 14), "!AIVDO,1,1,,A,");
  ais::Decoder dec;
  ais::Message msg;
  ASSERT_EQ(dec.feedLine(out[2], 0.0, msg), ais::Status::kMessage);
  EXPECT_TRUE(msg.own_ship);
  EXPECT_EQ(msg.mmsi, 257000001u);
  const auto* a = std::get_if<ais::PositionReportA>(&msg.body);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->lat, 54 * 600000 + 360000);  // 1/10000 minute
  EXPECT_EQ(a->lon, 18 * 600000 + 480000);
  EXPECT_EQ(a->speed, 100u);   // 1/10 kn
  EXPECT_EQ(a->course, 900u);  // 1/10 deg
  EXPECT_EQ(a->heading, 92u);
  EXPECT_EQ(a->second, 45);  // 01:46:45
}

TEST(PlotterOutput, NoOwnPositionIsRmcVoidAlone) {
  PlotterOutput p(PlotterConfig{}, LocalFrame(0.0, 0.0));
  PlotterTarget t;
  t.id = "ais:1";
  const std::vector<std::string> out = p.sentences(std::nullopt, {t}, kEpoch);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0], "$GPRMC,014640.00,V,0000.0000,N,00000.0000,E,0.0,0.0,090901,,,N*40");
}

// Two targets: 3 nm due north (AIS only, CPA 0.5 nm in 12 min) and 1 nm due east (radar). TTM nearest
// first: the radar target at 1.00 nm, bearing 090, then the AIS one at 3.00 nm, 000, with its CPA.
TEST(PlotterOutput, TtmNearestFirstWithStableNumbers) {
  PlotterConfig c;
  c.sentences = {"TTM"};
  PlotterOutput p(c, LocalFrame(54.6, 18.8));
  PlotterTarget north, east;
  north.id = "ais:244000001";
  north.name = "NORTH";
  north.position = {0.0, 3.0 * kMetresPerNauticalMile};
  north.course = degToRad(180.0);
  north.speed = 12.0 * kMpsPerKnot;
  north.dcpa = 0.5 * kMetresPerNauticalMile;
  north.tcpa = 720.0;
  north.reported = true;
  east.id = "arpa:7";
  east.position = {kMetresPerNauticalMile, 0.0};
  east.course = degToRad(270.0);
  east.speed = 8.0 * kMpsPerKnot;
  std::vector<std::string> out = p.sentences(ownAtOrigin(), {north, east}, kEpoch);
  ASSERT_EQ(out.size(), 2u);
  std::vector<std::string> keep;
  arpa::TrackedTarget a, b;
  ASSERT_EQ(arpa::parseTtm(framed(out[0], keep), a), arpa::Error::kNone) << out[0];
  ASSERT_EQ(arpa::parseTtm(framed(out[1], keep), b), arpa::Error::kNone) << out[1];
  // No CPA for the radar target: none in the picture. UTC 01:46:40; acquisition A (radar), R (AIS).
  EXPECT_EQ(out[0].substr(0, out[0].size() - 3), "$ECTTM,01,1.00,90.0,T,8.0,270.0,T,,,N,,T,,014640.00,A");
  EXPECT_EQ(out[1].substr(0, out[1].size() - 3),
            "$ECTTM,02,3.00,0.0,T,12.0,180.0,T,0.50,12.0,N,NORTH,T,,014640.00,R");
  ASSERT_TRUE(b.has_cpa && b.has_tcpa);
  EXPECT_NEAR(b.cpa, 0.5 * kMetresPerNauticalMile, 1.0);
  EXPECT_NEAR(b.tcpa, 720.0, 1e-6);
  EXPECT_FALSE(a.has_cpa);
  // The radar target goes; a new one comes: it does not take number 1 while 3 was never used.
  PlotterTarget west = east;
  west.id = "arpa:9";
  west.position = {-kMetresPerNauticalMile, 0.0};
  out = p.sentences(ownAtOrigin(), {north}, kEpoch + 1.0);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].substr(0, 10), "$ECTTM,02,");  // NORTH keeps 2
  out = p.sentences(ownAtOrigin(), {north, west}, kEpoch + 2.0);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].substr(0, 10), "$ECTTM,03,");  // the new one, nearest: the lowest never used
  EXPECT_EQ(out[1].substr(0, 10), "$ECTTM,02,");
}

// The route in force goes out as WPL and RTE in the period after it is set, then every route_period
// (10 s): two waypoints at the frame's origin and 0.01 deg north of it.
TEST(PlotterOutput, RouteAsWplAndRteWhenSetAndEveryPeriod) {
  PlotterConfig cfg;
  const LocalFrame frame(40.6, -74.05);
  PlotterOutput out(cfg, frame);
  auto routeLines = [](const std::vector<std::string>& lines) {
    std::vector<std::string> r;
    for (const auto& l : lines)
      if (l.rfind("$ECWPL", 0) == 0 || l.rfind("$ECRTE", 0) == 0)
        r.push_back(l);
    return r;
  };
  EXPECT_TRUE(routeLines(out.sentences(ownAtOrigin(), {}, kEpoch)).empty());  // no route yet
  out.setRoute({frame.toLocal(GeoPoint{40.6, -74.05}), frame.toLocal(GeoPoint{40.61, -74.05})});
  const auto first = routeLines(out.sentences(ownAtOrigin(), {}, kEpoch + 1.0));
  ASSERT_EQ(first.size(), 3u);
  std::vector<std::string> keep;
  EXPECT_EQ(framed(first[0], keep).field(1), "4036.0000");  // 40.6 N
  EXPECT_EQ(framed(first[1], keep).field(1), "4036.6000");  // 40.61 N
  EXPECT_EQ(framed(first[1], keep).field(5), "WP002");
  const nmea::Sentence rte = framed(first[2], keep);
  EXPECT_EQ(rte.field_count, 7u);  // RTE,1,1,c,ASV,WP001,WP002
  EXPECT_EQ(rte.field(6), "WP002");
  EXPECT_TRUE(routeLines(out.sentences(ownAtOrigin(), {}, kEpoch + 5.0)).empty());
  EXPECT_EQ(routeLines(out.sentences(ownAtOrigin(), {}, kEpoch + 11.0)).size(), 3u);
  cfg.sentences = {"RMC"};
  PlotterOutput quiet(cfg, frame);
  quiet.setRoute({Eigen::Vector2d::Zero()});
  EXPECT_TRUE(routeLines(quiet.sentences(ownAtOrigin(), {}, kEpoch)).empty());
}

TEST(PlotterOutput, ConfigRefusesWhatCannotBeSent) {
  ParamMap p;
  p.set("max_targets", 100);
  EXPECT_THROW(PlotterConfig::fromParams(p), std::invalid_argument);
  ParamMap q;
  q.setList("sentences", {"RMC", "GGA"});
  EXPECT_THROW(PlotterConfig::fromParams(q), std::invalid_argument);
}
