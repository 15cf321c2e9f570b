// The set-point leg and the autopilot sentences (codec/autopilot.h). Expected values by hand, the
// checksums computed apart (Python: XOR of the body's characters):
//  - set-point 090 from (0, 0): the leg runs east from there. The ship at (1000, 100), 100 m north
//    (left) of it, making 090 at 5 m/s: foot point 1000 m along, destination (2852, 0); bearing to it
//    atan2(1852, -100) = 93.09 deg; range hypot(1852, 100) = 1854.7 m = 1.00 nm; closing speed
//    5 cos(3.09 deg) = 4.993 m/s = 9.7 kn; cross-track 100 m = 0.054 nm, steer right.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "asv_core/codec/autopilot.h"
#include "asv_core/common/units.h"
#include "asv_core/planning/autopilot_bridge.h"

namespace ap = asv::autopilot;

namespace {

ap::Steering eastLeg(ap::SetpointLeg& leg) {
  leg.update(asv::degToRad(90.0), {0.0, 0.0}, asv::degToRad(90.0), 5.0);
  return leg.update(asv::degToRad(90.0), {1000.0, 100.0}, asv::degToRad(90.0), 5.0);
}

}  // namespace

TEST(AutopilotLeg, TheSetpointBecomesALegTheShipIsSteeredBackOnto) {
  ap::SetpointLeg leg;
  const ap::Steering s = eastLeg(leg);
  EXPECT_NEAR(s.cross_track, -100.0, 1e-9);  // left of the leg
  EXPECT_NEAR(leg.destination().x(), 2852.0, 1e-9);
  EXPECT_NEAR(leg.destination().y(), 0.0, 1e-9);
  EXPECT_NEAR(asv::radToDeg(s.bearing_to_dest), 93.0907, 1e-4);
  EXPECT_NEAR(s.heading_to_steer, s.bearing_to_dest, 1e-12);
  EXPECT_NEAR(s.range_to_dest, 1854.698, 1e-3);
  EXPECT_NEAR(s.closing_speed, 4.99273, 1e-5);
  EXPECT_EQ(s.origin_id, "ASV0");
  EXPECT_EQ(s.dest_id, "ASV1");
}

TEST(AutopilotLeg, ANewLegOnlyWhenTheCourseChangesByMoreThanOneDegree) {
  ap::SetpointLeg leg;
  eastLeg(leg);
  leg.update(asv::degToRad(90.5), {1000.0, 100.0}, asv::degToRad(90.0), 5.0);
  EXPECT_EQ(leg.legs(), 1);
  const ap::Steering s = leg.update(asv::degToRad(92.0), {1000.0, 100.0}, asv::degToRad(90.0), 5.0);
  EXPECT_EQ(leg.legs(), 2);
  EXPECT_NEAR(s.cross_track, 0.0, 1e-9);  // the new leg starts where the ship is
  EXPECT_EQ(s.origin_id, "ASV1");
  EXPECT_EQ(s.dest_id, "ASV2");
  EXPECT_THROW(ap::SetpointLeg(ap::LegConfig{0.0, 0.0175}), std::invalid_argument);
}

TEST(AutopilotSentences, ApbXteRmbHscAsLaidOut) {
  ap::SetpointLeg leg;
  ap::Steering s = eastLeg(leg);
  s.dest_lat_deg = 54.5;
  s.dest_lon_deg = -18.25;
  EXPECT_EQ(ap::encodeApb(s), "$ECAPB,A,A,0.054,R,N,V,V,90.0,T,ASV1,93.1,T,93.1,T,A*3D");
  EXPECT_EQ(ap::encodeXte(s), "$ECXTE,A,A,0.054,R,N,A*3D");
  EXPECT_EQ(ap::encodeRmb(s), "$ECRMB,A,0.05,R,ASV0,ASV1,5430.0000,N,01815.0000,W,1.0,93.1,9.7,V,A*79");
  EXPECT_EQ(ap::encodeHsc(s.heading_to_steer, asv::degToRad(5.0)), "$ECHSC,93.1,T,88.1,M*4D");
  EXPECT_EQ(ap::encodeHsc(s.heading_to_steer, std::nullopt), "$ECHSC,93.1,T,,M*52");
  s.valid = false;  // do not steer by this: status V, mode N
  EXPECT_EQ(ap::encodeApb(s), "$ECAPB,V,V,0.054,R,N,V,V,90.0,T,ASV1,93.1,T,93.1,T,N*32");
}

// A route for a chart plotter: WPL per waypoint, RTE naming them in order, split where a sentence would
// pass 82 characters (checksums: Python's XOR over the body). 40.7 N 74.0125 W: 4042.0000,N 07400.7500,W.
TEST(AutopilotSentences, WplAndRteForAPlotter) {
  EXPECT_EQ(ap::encodeWpl(40.7, -74.0125, "WP001"), "$ECWPL,4042.0000,N,07400.7500,W,WP001*7D");
  EXPECT_EQ(ap::encodeRte("ASV", {"WP001", "WP002", "WP003"}),
            std::vector<std::string>{"$ECRTE,1,1,c,ASV,WP001,WP002,WP003*79"});
  std::vector<std::string> twenty;
  for (int k = 1; k <= 20; ++k)
    twenty.push_back((k < 10 ? "WP00" : "WP0") + std::to_string(k));
  // "$ECRTE,2,1,c,ASV" and ten names of 6 characters: 79 with the checksum; an eleventh would pass 80.
  const auto rte = ap::encodeRte("ASV", twenty);
  ASSERT_EQ(rte.size(), 2u);
  EXPECT_EQ(rte[0], "$ECRTE,2,1,c,ASV,WP001,WP002,WP003,WP004,WP005,WP006,WP007,WP008,WP009,WP010*61");
  EXPECT_EQ(rte[1], "$ECRTE,2,2,c,ASV,WP011,WP012,WP013,WP014,WP015,WP016,WP017,WP018,WP019,WP020*60");
}

TEST(AutopilotSentences, PositionFields) {
  EXPECT_EQ(ap::latitudeField(-33.8568), "3351.4080,S");        // 0.8568 deg = 51.408'
  EXPECT_EQ(ap::longitudeField(151.2153), "15112.9180,E");      // 0.2153 deg = 12.918'
  EXPECT_EQ(ap::latitudeField(10.99999999999), "1100.0000,N");  // 59.9999999' rounds up a degree
  EXPECT_EQ(ap::longitudeField(-0.5), "00030.0000,W");
}

// The bridge's watchdog and arming (planning/autopilot_bridge.h), on the same east leg.
namespace {

asv::AutopilotBridgeConfig bridgeConfig(const std::string& safe_action) {
  asv::ParamMap p;
  p.set("origin_lat_deg", 54.6);
  p.set("origin_lon_deg", 18.8);
  p.set("safe_action", safe_action);
  p.set("watch/input_timeout", 1.0);
  p.set("watch/wall_floor", 0.0);
  return asv::AutopilotBridgeConfig::fromParams(p);
}

void noLatLon(const Eigen::Vector2d&, double& lat, double& lon) {
  lat = 54.6;
  lon = 18.8;
}

// Armed, set-point 090 at t = 0 from (0, 0), then the ship at (1000, 100) at t = 0.5, heading north
// (0 rad) so that the twist has a heading error to turn.
asv::AutopilotBridge steering(const std::string& safe_action) {
  asv::AutopilotBridge b(bridgeConfig(safe_action));
  b.arm(true);
  b.setpoint(asv::degToRad(90.0), 5.0, 0.0, 0.0, 0.0);
  b.own({0.0, 0.0}, asv::degToRad(90.0), 5.0, 0.0, 0.0, 0.0);
  b.tick(0.0, 0.0, noLatLon);
  b.own({1000.0, 100.0}, asv::degToRad(90.0), 5.0, 0.0, 0.5, 0.5);
  return b;
}

}  // namespace

TEST(AutopilotBridge, NothingGoesOutDisarmedOrBeforeASetpoint) {
  asv::AutopilotBridge b(bridgeConfig("hold_course"));
  EXPECT_FALSE(b.armed());  // armed_at_start is false by default
  b.own({0.0, 0.0}, 0.0, 5.0, 0.0, 0.0, 0.0);
  b.setpoint(0.0, 5.0, 0.0, 0.0, 0.0);
  EXPECT_TRUE(b.tick(0.1, 0.1, noLatLon).sentences.empty());
  asv::AutopilotBridge c(bridgeConfig("hold_course"));
  c.arm(true);
  c.own({0.0, 0.0}, 0.0, 5.0, 0.0, 0.0, 0.0);
  const auto out = c.tick(0.1, 0.1, noLatLon);
  EXPECT_TRUE(out.sentences.empty());
  EXPECT_TRUE(out.lost.empty());  // no set-point yet is waiting, not a fault
}

TEST(AutopilotBridge, SteersTheLegAndTurnsTheTwistToStarboard) {
  asv::AutopilotBridge b = steering("hold_course");
  const auto out = b.tick(0.6, 0.6, noLatLon);
  ASSERT_EQ(out.sentences.size(), 4u);  // APB, RMB, XTE, HSC
  EXPECT_EQ(out.sentences[0], "$ECAPB,A,A,0.054,R,N,V,V,90.0,T,ASV1,93.1,T,93.1,T,A*3D");
  EXPECT_EQ(out.sentences[3], "$ECHSC,93.1,T,,M*52");
  EXPECT_TRUE(out.valid);
  EXPECT_DOUBLE_EQ(out.speed, 5.0);
  // Heading 000, heading to steer 093.1: 0.5 x 1.625 rad/s, limited to 0.05; clockwise is negative in ENU.
  EXPECT_DOUBLE_EQ(out.yaw_rate, -0.05);
}

TEST(AutopilotBridge, LostSetpointsHoldTheCourseOrInvalidate) {
  asv::AutopilotBridge hold = steering("hold_course");
  hold.own({1000.0, 100.0}, asv::degToRad(90.0), 5.0, 0.0, 1.5, 1.5);
  auto out = hold.tick(1.5, 1.5, noLatLon);  // the last set-point 1.5 s ago, timeout 1 s
  ASSERT_EQ(out.lost.size(), 1u);
  EXPECT_EQ(out.lost[0].name, "set-point");
  EXPECT_EQ(out.action, "the last course is held");
  EXPECT_TRUE(out.valid);
  EXPECT_EQ(out.sentences.size(), 4u);

  asv::AutopilotBridge inval = steering("invalidate");
  inval.own({1000.0, 100.0}, asv::degToRad(90.0), 5.0, 0.0, 1.5, 1.5);
  out = inval.tick(1.5, 1.5, noLatLon);
  EXPECT_FALSE(out.valid);
  ASSERT_EQ(out.sentences.size(), 3u);  // no HSC: it has no status to mark it invalid
  EXPECT_EQ(out.sentences[0], "$ECAPB,V,V,0.054,R,N,V,V,90.0,T,ASV1,93.1,T,93.1,T,N*32");
  EXPECT_DOUBLE_EQ(out.speed, 0.0);
  // A set-point stamped 5 s ago is no sign of life.
  inval.setpoint(asv::degToRad(90.0), 5.0, -3.5, 1.5, 1.5);
  EXPECT_FALSE(inval.tick(1.6, 1.6, noLatLon).valid);
  inval.setpoint(asv::degToRad(90.0), 5.0, 1.6, 1.6, 1.6);
  EXPECT_TRUE(inval.tick(1.7, 1.7, noLatLon).valid);
}

TEST(AutopilotBridge, ReArmingStartsANewLegFromWhereTheShipIs) {
  asv::AutopilotBridge b = steering("hold_course");
  b.arm(false);
  // Steered by hand 2 km north meanwhile, then armed again on the same set-point course.
  b.own({1000.0, 2000.0}, asv::degToRad(90.0), 5.0, 0.0, 0.6, 0.6);
  b.setpoint(asv::degToRad(90.0), 5.0, 0.6, 0.6, 0.6);
  b.arm(true);
  const auto out = b.tick(0.7, 0.7, noLatLon);
  EXPECT_EQ(out.sentences[0].substr(0, 17), "$ECAPB,A,A,0.000,");  // no 2 km back to the old line
}

TEST(AutopilotBridge, LostOdometryInvalidatesTheRouteButHoldsTheHeading) {
  asv::AutopilotBridge b = steering("hold_course");
  b.setpoint(asv::degToRad(90.0), 5.0, 1.6, 1.6, 1.6);
  const auto out = b.tick(1.6, 1.6, noLatLon);  // odometry 1.1 s old
  ASSERT_EQ(out.lost.size(), 1u);
  EXPECT_EQ(out.lost[0].name, "odometry");
  EXPECT_FALSE(out.valid);
  ASSERT_EQ(out.sentences.size(), 4u);
  EXPECT_EQ(out.sentences[0].substr(0, 11), "$ECAPB,V,V,");
  EXPECT_EQ(out.sentences[3].substr(0, 17), "$ECHSC,90.0,T,,M*");  // the set-point course, not a guess
}

namespace {
std::string body(const std::string& sentence) {
  return sentence.substr(0, sentence.find('*'));
}
}  // namespace

// A voyage plan from (0, 0): WP001 2 km north, WP002 at (2000, 2500). The ship 100 m east of the first
// leg, halfway, making the follower's line-of-sight course, to the point 300 m (2 x 150 m acceptance)
// ahead of her abeam point: atan2(-100, 300) = -18.4 deg, 341.6. By hand: APB cross-track 100 m =
// 0.054 nm right of the leg, steer left; leg bearing 000.0; WP001 bears atan2(-100, 1000) = 354.3 at
// hypot(100, 1000) = 1005 m = 0.54 nm; closing 5 cos(12.7 deg) = 4.88 m/s = 9.5 kn.
TEST(AutopilotBridge, SendsTheRoutesActiveLegWhileTheStackFollowsIt) {
  asv::AutopilotBridge b(bridgeConfig("hold_course"));
  b.arm(true);
  b.own({0.0, 0.0}, 0.0, 5.0, 0.0, 0.0, 0.0);
  b.route({{0.0, 2000.0}, {2000.0, 2500.0}});
  const double los = asv::courseOf(Eigen::Vector2d(-100.0, 300.0));
  b.setpoint(los, 5.0, 0.1, 0.1, 0.1);
  b.own({100.0, 1000.0}, los, 5.0, los, 0.1, 0.1);
  auto out = b.tick(0.2, 0.2, noLatLon);
  ASSERT_EQ(out.sentences.size(), 4u);
  EXPECT_EQ(body(out.sentences[0]), "$ECAPB,A,A,0.054,L,N,V,V,0.0,T,WP001,354.3,T,341.6,T,A");
  EXPECT_EQ(body(out.sentences[1]).substr(0, 27), "$ECRMB,A,0.05,L,WP000,WP001");
  EXPECT_NE(out.sentences[1].find(",0.5,354.3,9.5,V,A"), std::string::npos) << out.sentences[1];
  // The course to WP001 itself, 12.7 deg from the follower's, is not the route's: she is manoeuvring.
  b.setpoint(asv::courseOf(Eigen::Vector2d(-100.0, 1000.0)), 5.0, 0.15, 0.15, 0.15);
  EXPECT_FALSE(b.tick(0.2, 0.2, noLatLon).route_waypoint);
  ASSERT_TRUE(out.route_waypoint);
  EXPECT_EQ(*out.route_waypoint, 0u);

  // An avoiding manoeuvre, 50 deg off the route: the set-point's own leg, started where she is.
  b.setpoint(asv::degToRad(45.0), 5.0, 0.3, 0.3, 0.3);
  out = b.tick(0.4, 0.4, noLatLon);
  EXPECT_EQ(body(out.sentences[0]).substr(0, 35), "$ECAPB,A,A,0.000,R,N,V,V,45.0,T,ASV");
  EXPECT_FALSE(out.route_waypoint);

  // Back on the route abeam of WP001 and past it, at (100, 2050): the second leg, bearing atan2(2000,
  // 500) = 076.0, from which she is 24.3 m = 0.013 nm left (steer right); WP002 bears 076.7 from her,
  // and the line-of-sight point 300 m on bears 080.6 (both by hand).
  b.own({100.0, 2050.0}, asv::degToRad(80.6), 5.0, asv::degToRad(80.6), 0.5, 0.5);
  b.setpoint(asv::degToRad(80.6), 5.0, 0.5, 0.5, 0.5);
  out = b.tick(0.6, 0.6, noLatLon);
  EXPECT_EQ(body(out.sentences[0]), "$ECAPB,A,A,0.013,R,N,V,V,76.0,T,WP002,76.7,T,80.6,T,A");
  ASSERT_TRUE(out.route_waypoint);
  EXPECT_EQ(*out.route_waypoint, 1u);

  // The route withdrawn: the set-point leg again.
  b.route({});
  EXPECT_FALSE(b.tick(0.7, 0.7, noLatLon).route_waypoint);
}

// A route that comes before any position starts where the first position puts the ship: from (0, 0)
// to WP001 3000 m east, the ship then at (1000, 100) on the follower's course atan2(300, -100) = 108.4:
// WP000 -> WP001, bearing 090.0, 100 m = 0.054 nm north of it (left of an eastward leg: steer right).
TEST(AutopilotBridge, ARouteBeforeAnyPositionStartsAtTheFirstOne) {
  asv::AutopilotBridge b(bridgeConfig("hold_course"));
  b.arm(true);
  b.route({{3000.0, 0.0}, {std::nan(""), 0.0}});  // the non-finite waypoint is dropped
  const double los = asv::courseOf(Eigen::Vector2d(300.0, -100.0));
  b.setpoint(los, 5.0, 0.0, 0.0, 0.0);
  b.own({0.0, 0.0}, asv::degToRad(90.0), 5.0, asv::degToRad(90.0), 0.0, 0.0);
  b.own({1000.0, 100.0}, los, 5.0, los, 0.1, 0.1);
  const auto out = b.tick(0.2, 0.2, noLatLon);
  ASSERT_TRUE(out.route_waypoint);
  EXPECT_EQ(body(out.sentences[0]).substr(0, 41), "$ECAPB,A,A,0.054,R,N,V,V,90.0,T,WP001,92.");
}

TEST(AutopilotBridge, ConfigNamesABadKey) {
  asv::ParamMap p;
  EXPECT_FALSE(asv::AutopilotBridgeConfig::fromParams(p).origin_lat_deg);  // none: the run's /map_origin
  p.set("origin_lat_deg", 54.6);
  EXPECT_THROW(asv::AutopilotBridgeConfig::fromParams(p), std::invalid_argument);  // half an origin
  p.set("origin_lon_deg", 18.8);
  p.set("route_tolerance_deg", 0.0);
  EXPECT_THROW(asv::AutopilotBridgeConfig::fromParams(p), std::invalid_argument);
  p.set("route_tolerance_deg", 10.0);
  p.set("route_turn_rate_deg_s", 0.0);
  EXPECT_THROW(asv::AutopilotBridgeConfig::fromParams(p), std::invalid_argument);
  p.set("route_turn_rate_deg_s", 1.0);
  p.setList("sentences", {"APB", "GGA"});
  try {
    asv::AutopilotBridgeConfig::fromParams(p);
    FAIL() << "GGA taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("GGA"), std::string::npos);
  }
}
