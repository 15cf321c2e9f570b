// Rule 9, narrow channels (fairway.h, plan_follower.h): the fairway across a leg, the starboard lane and
// edge, and a plan follower that keeps to the lane and slows at the edge instead of stopping in the
// channel. Expected values worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>

#include "asv_core/common/units.h"
#include "asv_core/planning/plan_follower.h"
#include "asv_core/world/fairway.h"
#include "asv_core/world/route.h"

using namespace asv;

namespace {

// A channel running north, its banks `half` metres either side of x = 0, from y = -5000 to y = 5000.
std::vector<StaticObstacle> channel(double half) {
  return {
      {"west bank", {{-half - 1000, -5000}, {-half, -5000}, {-half, 5000}, {-half - 1000, 5000}}, nullptr},
      {"east bank", {{half, -5000}, {half + 1000, -5000}, {half + 1000, 5000}, {half, 5000}}, nullptr}};
}

// The channel of 400 m closed by land across it north of y = 800 (a basin's end).
std::vector<StaticObstacle> basin() {
  auto land = channel(200.0);
  land.push_back({"head", {{-1200, 800}, {1200, 800}, {1200, 1800}, {-1200, 1800}}, nullptr});
  return land;
}

RouteWaypoint wp(double x, double y) {
  RouteWaypoint w;
  w.position = {x, y};
  return w;
}

ShipState northbound(double x, double y) {
  ShipState s;
  s.id = "own";
  s.position = {x, y};
  s.course = s.heading = 0.0;
  s.speed = 5.0;
  s.length = 50.0;
  return s;
}

// A follower of the route up the middle of the channel `land` from (0, 0) to (0, 3000), the ship at
// (x, y) heading north.
PlanFollower inChannel(const PlanFollowerConfig& cfg, const std::vector<StaticObstacle>& land, double x,
                       double y) {
  PlanFollower f(cfg);
  f.setObstacles(land);
  f.setRoute({wp(0, 0), wp(0, 3000)});
  f.updateOwn(northbound(x, y));
  return f;
}

// A plan whose waypoints are already behind her: setpoint() steers by the route's line of sight.
Plan spentPlan(const Eigen::Vector2d& at) {
  Plan p;
  p.status = PlanStatus::Ok;
  p.waypoints = {PlannedWaypoint{at, 0.0, 0.0, 5.0},
                 PlannedWaypoint{at + Eigen::Vector2d(0, 10), 2.0, 0.0, 5.0}};
  return p;
}

// The course set now [deg], in (-180, 180].
double courseDeg(PlanFollower& f) {
  double course = 0.0, speed = 0.0;
  EXPECT_TRUE(f.setpoint(course, speed));
  return radToDeg(wrapPi(course));
}

}  // namespace

TEST(Fairway, AcrossTheLegToTheBanksOrTheCorridor) {
  const Eigen::Vector2d north(0, 1);
  // Mid-channel: 200 m to either bank (to the bisection's 2^-12 of the 1852 m probe, 0.45 m).
  Fairway f = fairwayAcross({0, 0}, north, channel(200), 0.0, 0.0, 1852.0);
  EXPECT_NEAR(f.port, 200.0, 0.5);
  EXPECT_NEAR(f.starboard, 200.0, 0.5);
  EXPECT_NEAR(f.width(), 400.0, 1.0);
  // 50 m east of the middle: the west (port) bank 250 m off, the east 150 m; the middle 50 m to port.
  f = fairwayAcross({50, 0}, north, channel(200), 0.0, 0.0, 1852.0);
  EXPECT_NEAR(f.port, 250.0, 0.5);
  EXPECT_NEAR(f.starboard, 150.0, 0.5);
  EXPECT_NEAR(f.middle(), -50.0, 0.5);
  // Southbound the east bank is to port.
  f = fairwayAcross({50, 0}, -north, channel(200), 0.0, 0.0, 1852.0);
  EXPECT_NEAR(f.port, 150.0, 0.5);
  // The corridor's 100 m starboard limit is nearer than the bank.
  f = fairwayAcross({0, 0}, north, channel(200), 0.0, 100.0, 1852.0);
  EXPECT_DOUBLE_EQ(f.starboard, 100.0);
  // No land within the probe: the probe on each side; on land: 0.
  f = fairwayAcross({0, 0}, north, {}, 0.0, 0.0, 1852.0);
  EXPECT_DOUBLE_EQ(f.width(), 3704.0);
  f = fairwayAcross({300, 0}, north, channel(200), 0.0, 0.0, 1852.0);
  EXPECT_DOUBLE_EQ(f.width(), 0.0);
}

TEST(Fairway, TheStarboardLaneAndEdge) {
  // 400 m wide, from the middle: the bank clearance is a quarter of the width (100 m) rather than
  // 185.2 m; the lane's inner end the middle of the starboard half (+100 m) meets its outer end (+100).
  const Fairway narrow{200.0, 200.0};
  EXPECT_DOUBLE_EQ(fairwayBankClearance(narrow, 185.2), 100.0);
  EXPECT_DOUBLE_EQ(starboardLaneOffset(narrow, 185.2), 100.0);
  EXPECT_DOUBLE_EQ(starboardEdgeOffset(narrow, 185.2), 100.0);
  // 1000 m wide, from the middle: lane from +250 to +500 - 185.2 = +314.8; she goes to +250.
  const Fairway wide{500.0, 500.0};
  EXPECT_DOUBLE_EQ(starboardLaneOffset(wide, 185.2), 250.0);
  EXPECT_DOUBLE_EQ(starboardEdgeOffset(wide, 185.2), 314.8);
  // From 300 m east of the middle (in the lane, -50 .. +14.8 from there): she stays.
  EXPECT_DOUBLE_EQ(starboardLaneOffset(Fairway{800.0, 200.0}, 185.2), 0.0);
  // From 450 m east (50 m off the bank): back to 185.2 m off it, 135.2 m to port.
  EXPECT_NEAR(starboardLaneOffset(Fairway{950.0, 50.0}, 185.2), -135.2, 1e-9);
  // A fairway 20 m wide, its middle 5 m to starboard: the bank clearance a quarter of it, 5 m; the lane
  // shrinks to the middle of the starboard half, +10 m.
  EXPECT_DOUBLE_EQ(fairwayBankClearance(Fairway{5.0, 15.0}, 185.2), 5.0);
  EXPECT_DOUBLE_EQ(starboardLaneOffset(Fairway{5.0, 15.0}, 185.2), 10.0);
}

TEST(Fairway, TheFollowerKeepsToTheStarboardLaneOfANarrowChannel) {
  PlanFollowerConfig cfg;
  cfg.cruise_speed = 5.0;
  PlanFollower f = inChannel(cfg, channel(200), 0, -2000);
  // The planners steer for the active waypoint moved 100 m to starboard (the lane across its leg), and,
  // she being 100 m out of the lane, join it first 5 x 100 m ahead: at (100, -1500).
  const PlanningProblem pr = f.buildProblem(0.0, {});
  ASSERT_EQ(pr.route.size(), 2u);
  EXPECT_NEAR(pr.route[0].x(), 100.0, 0.5);
  EXPECT_NEAR(pr.route[0].y(), -1500.0, 2.5);  // 5 x the rays' 0.45 m
  EXPECT_NEAR(pr.route[1].x(), 100.0, 0.5);
  EXPECT_DOUBLE_EQ(pr.route[1].y(), 0.0);
  // Already in the lane (90 m to starboard of the leg, within 25 m of it): the waypoint alone.
  PlanFollower in_lane = inChannel(cfg, channel(200), 90, -2000);
  EXPECT_EQ(in_lane.buildProblem(0.0, {}).route.size(), 1u);
  // Past the plan: 300 m ahead on the leg, (0, -1700), moved to (100, -1700): atan2(100, 300) = 18.43 deg.
  f.acceptPlan(spentPlan({0, -2000}), 0.0, {}, "test");
  EXPECT_NEAR(courseDeg(f), radToDeg(std::atan2(100.0, 300.0)), 0.1);

  // In a channel 1.6 km wide the lane begins 400 m to starboard, but the ship keeps within 150 m of the
  // route (kMaxLaneShift): atan2(150, 300) = 26.57 deg.
  PlanFollower broad = inChannel(cfg, channel(800), 0, -2000);
  broad.acceptPlan(spentPlan({0, -2000}), 0.0, {}, "test");
  EXPECT_NEAR(courseDeg(broad), radToDeg(std::atan2(150.0, 300.0)), 0.1);

  // In a channel 2 km wide, wider than 1 nm, and with the rule off: straight along the leg.
  PlanFollower wide = inChannel(cfg, channel(1000), 0, -2000);
  wide.acceptPlan(spentPlan({0, -2000}), 0.0, {}, "test");
  EXPECT_NEAR(courseDeg(wide), 0.0, 1e-9);
  PlanFollowerConfig off = cfg;
  off.narrow_fairway_width_m = 0.0;
  PlanFollower no_rule = inChannel(off, channel(200), 0, -2000);
  no_rule.acceptPlan(spentPlan({0, -2000}), 0.0, {}, "test");
  EXPECT_NEAR(courseDeg(no_rule), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(no_rule.buildProblem(0.0, {}).route[0].x(), 0.0);
}

TEST(Fairway, TheLaneComesBackToTheGoalOverTheLastStretch) {
  PlanFollowerConfig cfg;
  cfg.cruise_speed = 5.0;
  PlanFollower f(cfg);
  f.setObstacles(basin());
  f.setRoute({wp(0, 500)});
  f.updateOwn(northbound(0, -100));
  // 300 m ahead, (0, 200), is 300 m from the goal: half the 600 m taper, 50 m of the 100 m lane offset:
  // atan2(50, 300) = 9.46 deg.
  f.acceptPlan(spentPlan({0, -100}), 0.0, {}, "test");
  EXPECT_NEAR(courseDeg(f), radToDeg(std::atan2(50.0, 300.0)), 0.1);
}

TEST(Fairway, TheFallbackSlowsAtTheStarboardEdgeInsteadOfStopping) {
  PlanFollowerConfig cfg;
  cfg.cruise_speed = 5.0;
  // The basin's head is 2.8 km ahead, within 2.5 m/s x 1200 s: holding course leads onto land, so the
  // open-water fallback stops her in mid-channel.
  PlanFollowerConfig off = cfg;
  off.narrow_fairway_width_m = 0.0;
  PlanFollower old_rule(off);
  old_rule.setObstacles(basin());
  old_rule.setRoute({wp(0, 500)});
  old_rule.updateOwn(northbound(0, -2000));
  EXPECT_DOUBLE_EQ(old_rule.fallback({}, "test").speed_setpoint, 0.0);

  PlanFollower f(cfg);
  f.setObstacles(basin());
  f.setRoute({wp(0, 500)});
  f.updateOwn(northbound(0, -2000));
  const Plan fb = f.fallback({}, "test");
  EXPECT_EQ(fb.status, PlanStatus::Fallback);
  EXPECT_TRUE(fb.along_fairway_edge);
  EXPECT_DOUBLE_EQ(fb.speed_setpoint, 2.5);  // half of 5 m/s, under way
  EXPECT_NE(fb.message.find("starboard edge"), std::string::npos);
  // For the edge 100 m east of (0, -1700): atan2(100, 300); the set-point renews it as she moves.
  EXPECT_NEAR(radToDeg(fb.course_setpoint), radToDeg(std::atan2(100.0, 300.0)), 0.1);
  f.acceptPlan(fb, 0.0, {}, "test");
  f.updateOwn(northbound(100, -1500));  // on the edge: straight on along it
  EXPECT_NEAR(courseDeg(f), 0.0, 0.1);

  // In extremis with a ship 500 m ahead coming down the channel: no hard turn into the bank, the same
  // slow passage along the edge.
  PlannerTarget down;
  down.state.id = "down";
  down.state.position = {0, -1000};
  down.state.course = kPi;
  down.state.speed = 5.0;
  down.risk = RiskLevel::Urgent;
  const Plan extremis = f.fallback({down}, "test");
  EXPECT_TRUE(extremis.along_fairway_edge);
  EXPECT_DOUBLE_EQ(extremis.speed_setpoint, 2.5);
  EXPECT_NE(extremis.message.find("in extremis"), std::string::npos);
}

TEST(Fairway, OvertakingWaitsForRoomInANarrowChannel) {
  PlanFollowerConfig cfg;
  cfg.cruise_speed = 5.0;
  cfg.min_separation = 100.0;  // passing 110 m with the 10 % margin
  // A tug 300 m ahead in the lane at 2 m/s, overtaken. In a channel 160 m wide the lane is 40 m east of
  // the middle (the bank clearance a quarter of the width, 40 m); beside the tug 120 m to the west bank,
  // 40 m to the east: under the 110 + 40 m needed. The own ship follows her at her speed.
  PlannerTarget tug;
  tug.state.id = "tug";
  tug.state.position = {40, -1700};
  tug.state.speed = 2.0;
  tug.encounter = Encounter::Overtaking;
  tug.role = OwnRole::GiveWay;
  Plan overtake;
  overtake.status = PlanStatus::Ok;
  overtake.course_setpoint = degToRad(340.0);
  overtake.speed_setpoint = 5.0;
  PlanFollower narrow = inChannel(cfg, channel(80), 40, -2000);
  const Plan& waiting = narrow.acceptPlan(overtake, 0.0, {tug}, "test");
  EXPECT_EQ(waiting.status, PlanStatus::Ok);
  EXPECT_DOUBLE_EQ(waiting.speed_setpoint, 2.0);
  EXPECT_NE(waiting.message.find("no room to overtake tug"), std::string::npos) << waiting.message;
  // In the 400 m channel 300 m lie beside her (lane +100 m): room enough, the plan stands.
  PlanFollower wide = inChannel(cfg, channel(200), 100, -2000);
  tug.state.position = {100, -1700};
  EXPECT_DOUBLE_EQ(wide.acceptPlan(overtake, 0.0, {tug}, "test").speed_setpoint, 5.0);
  // 600 m ahead, beyond the 500 m looked at: she closes in first.
  PlanFollower far_behind = inChannel(cfg, channel(80), 40, -2300);
  tug.state.position = {40, -1700};
  EXPECT_DOUBLE_EQ(far_behind.acceptPlan(overtake, 0.0, {tug}, "test").speed_setpoint, 5.0);
}

TEST(Fairway, NoLaneBehindAPiersEnd) {
  // A pier from the east bank to 60 m east of the middle, 260 m ahead: the way to the lane point
  // (100, -1700) runs into it (at y = -1750, x = 83 m), so she keeps the route's line of sight, north.
  PlanFollowerConfig cfg;
  cfg.cruise_speed = 5.0;
  auto land = channel(200);
  land.push_back({"pier", {{60, -1760}, {200, -1760}, {200, -1740}, {60, -1740}}, nullptr});
  PlanFollower f = inChannel(cfg, land, 0, -2000);
  f.acceptPlan(spentPlan({0, -2000}), 0.0, {}, "test");
  EXPECT_NEAR(courseDeg(f), 0.0, 1e-6);
}
