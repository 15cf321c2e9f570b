// The voyage plan (route.h): cross-track error, wheel-over point, progress along the legs, the
// scenario's route and human keys, and the route a plan follower sails (plan_follower.h). Expected
// values worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "asv_core/common/units.h"
#include "asv_core/eval/evaluation.h"
#include "asv_core/planning/plan_follower.h"
#include "asv_core/world/route.h"
#include "asv_core/world/route_file.h"
#include "asv_core/world/scenario.h"
#include "asv_core/world/scenario_write.h"

using namespace asv;

namespace {

RouteWaypoint wp(double x, double y) {
  RouteWaypoint w;
  w.position = {x, y};
  return w;
}

const char* kRouteScenario = R"(format: 1
name: route
duration_s: 1200
origin: {lat_deg: 40.60, lon_deg: -74.05}
own_ship:
  name: own
  position: {x_m: 0, y_m: 0}
  course_deg: 0
  speed_kn: 10
  route:
    - {x_m: 0, y_m: 1000, speed_kn: 8, starboard_xtd_m: 50}
    - {lat_deg: 40.61, lon_deg: -74.05, port_xtd_m: 40.5}
human: {min_separation_m: 269.5, time_s: 1260, path_m: 5600}
)";

}  // namespace

TEST(Route, CrossTrackErrorIsPositiveToStarboard) {
  // A leg due north from (0, 0) to (0, 1000): east of it is to starboard.
  EXPECT_DOUBLE_EQ(crossTrackError({0, 0}, {0, 1000}, {100, 500}), 100.0);
  EXPECT_DOUBLE_EQ(crossTrackError({0, 0}, {0, 1000}, {-50, 200}), -50.0);
  // Due east from (0, 0): south of it is to starboard; 3-4-5 leg: (0, 0) -> (400, 300), point (300, 0)
  // is 300 x 3/5 = 180 m to starboard.
  EXPECT_DOUBLE_EQ(crossTrackError({0, 0}, {1000, 0}, {500, -30}), 30.0);
  EXPECT_NEAR(crossTrackError({0, 0}, {400, 300}, {300, 0}), 180.0, 1e-9);
  EXPECT_DOUBLE_EQ(alongTrackToGo({0, 0}, {0, 1000}, {100, 500}), 500.0);
  EXPECT_DOUBLE_EQ(alongTrackToGo({0, 0}, {0, 1000}, {0, 1200}), -200.0);
}

TEST(Route, WheelOverIsTheTurnsAdvance) {
  // 5 m/s at 0.0175 rad/s: R = 285.714 m. 90 deg: R tan 45 = R; 60 deg: R tan 30 = 164.957 m.
  const double r = 5.0 / 0.0175;
  EXPECT_NEAR(wheelOverDistance(degToRad(90.0), 5.0, 0.0175), r, 1e-9);
  EXPECT_NEAR(wheelOverDistance(degToRad(-60.0), 5.0, 0.0175), r * std::tan(degToRad(30.0)), 1e-9);
  EXPECT_NEAR(wheelOverDistance(degToRad(170.0), 5.0, 0.0175), r, 1e-9);  // at most a radius
  EXPECT_EQ(wheelOverDistance(degToRad(90.0), 0.0, 0.0175), 0.0);
}

TEST(Route, ProgressPassesAWaypointAtTheWheelOverPoint) {
  // North 1000 m, then east: a 90 deg turn at 5 m/s, wheel over 285.7 m before the waypoint.
  RouteProgress pr({wp(0, 0), wp(0, 1000), wp(1000, 1000)}, {0, 0});
  EXPECT_EQ(pr.active(), 1u);                             // she starts on the first leg between waypoints
  EXPECT_FALSE(pr.update({0, 700}, 5.0, 0.0175, 150.0));  // 300 m to go
  EXPECT_EQ(pr.active(), 1u);
  EXPECT_TRUE(pr.update({0, 720}, 5.0, 0.0175, 150.0));  // 280 m to go
  EXPECT_EQ(pr.active(), 2u);
  EXPECT_TRUE(pr.onLastLeg());
  EXPECT_TRUE(pr.waypointsBeforeGoal().empty());
  // The goal is never passed.
  EXPECT_FALSE(pr.update({2000, 1000}, 5.0, 0.0175, 150.0));
  EXPECT_DOUBLE_EQ(pr.crossTrackError({500, 900}), 100.0);  // south of an eastbound leg: starboard
}

TEST(Route, ProgressPassesAWaypointLeftAbeamFarOff) {
  // Avoiding, she comes abeam of the waypoint 600 m to port of it: she goes on to the next leg rather
  // than turn back for it.
  RouteProgress pr({wp(0, 0), wp(0, 2000), wp(0, 4000)}, {0, 0});
  EXPECT_FALSE(pr.update({-600, 1900}, 5.0, 0.0175, 150.0));  // 100 m to go, straight on: no advance
  EXPECT_TRUE(pr.update({-600, 2001}, 5.0, 0.0175, 150.0));
  EXPECT_EQ(pr.active(), 2u);
}

TEST(Route, ProgressStartsBeforeTheFirstWaypoint) {
  RouteProgress pr({wp(0, 1000), wp(0, 2000)}, {0, 0});
  EXPECT_EQ(pr.active(), 0u);  // the first leg runs from where she was given the route
  EXPECT_EQ(pr.legStart(), Eigen::Vector2d(0, 0));
  ASSERT_EQ(pr.waypointsBeforeGoal().size(), 1u);
  // Line of sight 300 m ahead of her abeam point: from (100, 200) on the leg x = 0, (0, 500).
  EXPECT_EQ(pr.lineOfSight({100, 200}, 300.0), Eigen::Vector2d(0, 500));
  EXPECT_EQ(pr.lineOfSight({100, 900}, 300.0), Eigen::Vector2d(0, 1000));  // never past the waypoint
  // Given the route half-way along its second leg, she starts on it.
  EXPECT_EQ(RouteProgress({wp(0, 1000), wp(0, 2000)}, {30, 1500}).active(), 1u);
}

TEST(Route, DeviationAndCorridorPerLeg) {
  Route r{wp(0, 1000), wp(1000, 1000)};
  r[0].starboard_xtd = 50.0;
  // (80, 500): 80 m to starboard of leg 0 (north from the start), its limit 50 m.
  RouteDeviation d = routeDeviation(r, {0, 0}, {80, 500});
  EXPECT_EQ(d.leg, 0u);
  EXPECT_DOUBLE_EQ(d.xte, 80.0);
  EXPECT_TRUE(d.outside_corridor);
  // 80 m to port: no port limit on that leg.
  d = routeDeviation(r, {0, 0}, {-80, 500});
  EXPECT_DOUBLE_EQ(d.xte, -80.0);
  EXPECT_FALSE(d.outside_corridor);
  // (600, 1030): 30 m to port of leg 1 (eastbound), nearer than leg 0 (600 m away).
  d = routeDeviation(r, {0, 0}, {600, 1030});
  EXPECT_EQ(d.leg, 1u);
  EXPECT_DOUBLE_EQ(d.xte, -30.0);
}

TEST(Route, LegOnLandNamesTheFirstLegThatCrosses) {
  const StaticObstacle islet{"islet", {{400, 900}, {600, 900}, {600, 1100}, {400, 1100}}, nullptr};
  const Route r{wp(0, 1000), wp(1000, 1000), wp(1000, 2000)};
  const auto crossing = legOnLand(r, {0, 0}, {islet});
  ASSERT_TRUE(crossing);
  EXPECT_EQ(crossing->leg, 1);
  EXPECT_EQ(crossing->land, "islet");
  EXPECT_FALSE(legOnLand(r, {0, 0}, {}));
  // 150 m clearance: leg 0 (x = 0) passes the islet at 400 m, clear; at 450 m it does not.
  EXPECT_FALSE(legOnLand({wp(0, 1000)}, {0, 0}, {islet}, 150.0));
  EXPECT_EQ(legOnLand({wp(0, 1000)}, {0, 0}, {islet}, 450.0)->leg, 0);
}

TEST(Route, ScenarioRouteAndHumanKeys) {
  const Scenario s = parseScenario(kRouteScenario, "route.yaml");
  ASSERT_EQ(s.own.route.size(), 2u);
  EXPECT_EQ(s.own.route[0].position, Eigen::Vector2d(0, 1000));
  EXPECT_NEAR(s.own.route[0].speed, 8.0 * 1852.0 / 3600.0, 1e-9);
  EXPECT_DOUBLE_EQ(s.own.route[0].starboard_xtd, 50.0);
  EXPECT_DOUBLE_EQ(s.own.route[1].port_xtd, 40.5);
  // 0.01 deg of latitude north of the origin: M x 0.01 deg with WGS84's meridian radius at 40.6 N,
  // M = a (1 - e2) / (1 - e2 sin2 phi)^1.5 = 6362487 m: 1110.5 m.
  EXPECT_NEAR(s.own.route[1].position.y(), 1110.5, 0.5);
  EXPECT_NEAR(s.own.route[1].position.x(), 0.0, 0.01);
  ASSERT_TRUE(s.own.goal.has_value());
  EXPECT_EQ(*s.own.goal, s.own.route[1].position);  // the last waypoint is the goal
  ASSERT_TRUE(s.human.has_value());
  EXPECT_DOUBLE_EQ(s.human->min_separation_m, 269.5);
  EXPECT_DOUBLE_EQ(s.human->time_s, 1260.0);
  // Written and read back: the same route, corridor, speed and human figures.
  const Scenario back = parseScenario(scenarioToYaml(s), "back.yaml");
  ASSERT_EQ(back.own.route.size(), 2u);
  EXPECT_NEAR((back.own.route[1].position - s.own.route[1].position).norm(), 0.0, 0.1);
  EXPECT_NEAR(back.own.route[0].speed, s.own.route[0].speed, 0.01);
  EXPECT_DOUBLE_EQ(back.own.route[1].port_xtd, 40.5);
  ASSERT_TRUE(back.human.has_value());
  EXPECT_DOUBLE_EQ(back.human->path_m, 5600.0);
}

TEST(Route, ScenarioRouteErrorsNameFileLineAndLeg) {
  auto error = [](const std::string& text) {
    try {
      parseScenario(text, "r.yaml");
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::string base = kRouteScenario;
  // A goal beside a route.
  std::string both = base;
  both.replace(both.find("  route:"), 0, "  goal: {x_m: 5, y_m: 5}\n");
  EXPECT_NE(error(both).find("give a goal or a route, not both"), std::string::npos) << error(both);
  // A speed out of range, on line 11.
  std::string fast = base;
  fast.replace(fast.find("speed_kn: 8"), 11, "speed_kn: 80");
  EXPECT_NE(error(fast).find("r.yaml:11: 'own_ship.route[0].speed_kn'"), std::string::npos) << error(fast);
  // A route over an obstacle: its second leg (line 12) crosses the islet.
  const std::string islet =
      "static_obstacles:\n  - name: islet\n    polygon: [{x_m: -50, y_m: 1050}, {x_m: 50, y_m: 1050}, "
      "{x_m: 0, y_m: 1090}]\n";
  EXPECT_NE(error(base + islet).find("r.yaml:12: 'own_ship.route[1]': leg 2"), std::string::npos)
      << error(base + islet);
  EXPECT_NE(error(base + islet).find("crosses 'islet'"), std::string::npos);
  // The human block: an unknown key, a zero time.
  std::string h = base;
  h.replace(h.find("path_m"), 6, "path_nm");
  EXPECT_NE(error(h).find("'human.path_nm': unknown key"), std::string::npos) << error(h);
  h = base;
  h.replace(h.find("time_s: 1260"), 12, "time_s: 0");
  EXPECT_NE(error(h).find("time_s > 0"), std::string::npos) << error(h);
}

TEST(Route, FollowerPlansAlongTheRouteAndReplansAtAWaypoint) {
  PlanFollowerConfig cfg;
  cfg.cruise_speed = 5.0;
  PlanFollower f(cfg);
  Route r{wp(0, 0), wp(0, 1000), wp(1000, 1000), wp(1000, 3000)};
  r[2].speed = 3.0;  // the leg to (1000, 1000)
  f.setRoute(r);
  ShipState own;
  own.id = "own";
  own.position = {20, 100};
  own.speed = 5.0;
  f.updateOwn(own);
  // On leg 1, 20 m to starboard of it; the planners steer for its end, then the rest of the route.
  ASSERT_TRUE(f.crossTrackError().has_value());
  EXPECT_DOUBLE_EQ(*f.crossTrackError(), 20.0);
  PlanningProblem pr = f.buildProblem(0.0, {});
  ASSERT_EQ(pr.route.size(), 2u);
  EXPECT_EQ(pr.route[0], Eigen::Vector2d(0, 1000));
  EXPECT_EQ(pr.goal, Eigen::Vector2d(1000, 3000));
  EXPECT_DOUBLE_EQ(pr.cruise_speed, 5.0);
  std::string why;
  ASSERT_TRUE(f.replanNeeded(0.0, {}, why));
  Plan straight;
  straight.status = PlanStatus::Ok;
  straight.course_setpoint = 0.0;
  straight.speed_setpoint = 0.0;
  f.acceptPlan(straight, 0.0, {}, why);
  EXPECT_FALSE(f.replanNeeded(10.0, {}, why));
  // Past the wheel-over point of the 90 deg turn (285.7 m at 5 m/s): the next leg, at its speed.
  own.position = {0, 750};
  f.updateOwn(own);
  ASSERT_TRUE(f.replanNeeded(20.0, {}, why));
  EXPECT_NE(why.find("route"), std::string::npos);
  pr = f.buildProblem(20.0, {});
  ASSERT_EQ(pr.route.size(), 1u);
  EXPECT_EQ(pr.route[0], Eigen::Vector2d(1000, 1000));
  EXPECT_DOUBLE_EQ(pr.cruise_speed, 3.0);
  // With no plan waypoints to fly, she rejoins the leg by line of sight: from (0, 750), 300 m along the
  // eastbound leg from her abeam point (0, 1000) is (300, 1000): course atan2(300, 250) = 50.19 deg.
  double course = 0.0, speed = 0.0;
  Plan legs;
  legs.status = PlanStatus::Ok;
  legs.waypoints = {PlannedWaypoint{{0, 750}, 0.0, 0.0, 3.0}, PlannedWaypoint{{0, 760}, 2.0, 0.0, 3.0}};
  f.acceptPlan(legs, 20.0, {}, why);
  ASSERT_TRUE(f.setpoint(course, speed));
  EXPECT_NEAR(radToDeg(course), radToDeg(std::atan2(300.0, 250.0)), 1e-6);
  EXPECT_DOUBLE_EQ(speed, 3.0);
}

TEST(Route, ResultReportsTheRouteAndTheMasterFigures) {
  // The own ship sails north along x = 30, 30 m to starboard of a route north along x = 0 whose
  // corridor is 20 m to starboard; a stopped ship 500 m east of her at y = 1000. The master passed it
  // at 250 m and took 600 s.
  RunInfo info;
  info.scenario = "route";
  info.min_separation = 185.2;
  info.ships = {{"own", Eigen::Vector2d(0, 3000), "none"}, {"moored", std::nullopt, ""}};
  info.route = {wp(0, 3000)};
  info.route[0].starboard_xtd = 20.0;
  info.human = HumanRecord{250.0, 600.0, 3000.0};
  RunRecorder rec(EvaluationConfig{}, info);
  for (int k = 0; k <= 40; ++k) {
    ShipSample own, moored;
    own.name = "own";
    own.state.position = {30.0, 50.0 * k};
    own.state.speed = 5.0;
    moored.name = "moored";
    moored.state.position = {530.0, 1000.0};
    rec.addSample(10.0 * k, {own, moored});
  }
  const RunResult r = rec.finish();
  EXPECT_EQ(r.route.legs, 1u);
  EXPECT_DOUBLE_EQ(r.route.max_xte, 30.0);
  EXPECT_DOUBLE_EQ(r.route.outside_corridor, 400.0);  // outside from the first sample to the last
  EXPECT_DOUBLE_EQ(r.own.min_separation, 500.0);
  EXPECT_DOUBLE_EQ(r.separation_vs_human, 2.0);  // 500 / 250
  EXPECT_FALSE(r.own.arrived);
  const std::string json = toJson(r);
  EXPECT_NE(json.find("\"human\": {\"min_separation_m\": 250.0, \"time_s\": 600.0, \"path_m\": 3000.0}"),
            std::string::npos)
      << json;
  EXPECT_NE(json.find("\"separation_vs_human\": 2.0000, \"time_vs_human\": null"), std::string::npos) << json;
  EXPECT_NE(json.find("\"route\": {\"legs\": 1, \"max_xte_m\": 30.0, \"outside_corridor_s\": 400.0}"),
            std::string::npos)
      << json;
  // Keys added later come after wall_time_s.
  EXPECT_LT(json.find("wall_time_s"), json.find("\"human\""));
}

namespace {

// Restricted waters: a pier 1 km east of a 94 m ship at 10 kn at the origin.
const StaticObstacle kPier{"pier", {{1000, -100}, {1100, -100}, {1100, 100}, {1000, 100}}, nullptr};
ShipState ninetyFourMetres() {
  ShipState own;
  own.id = "own";
  own.length = 94.0;
  own.speed = 10.0 * 1852.0 / 3600.0;
  return own;
}

}  // namespace

// Restricted waters (planning.h): land within 1 nm caps the planners' safety distances at the ship's
// Kijima and Nakiri domain (94 m at 10 kn: 292.8 m to starboard, test_domain); open water and paper mode
// leave them.
TEST(Route, FollowerCapsThePassingDistanceInRestrictedWaters) {
  const StaticObstacle& pier = kPier;
  const ShipState own = ninetyFourMetres();
  EXPECT_NEAR(restrictedPassingDistance(own.position, 94.0, own.speed, {pier}), 292.8, 0.1);
  EXPECT_EQ(restrictedPassingDistance({-900, 0}, 94.0, own.speed, {pier}), 0.0);  // 1900 m off: open water
  // A 19 m launch at 3 kn: 33 m by the domain (k_AD 1.84, k_DT 1.52), the 50 m floor.
  EXPECT_EQ(restrictedPassingDistance(own.position, 19.0, 3.0 * 1852.0 / 3600.0, {pier}), 50.0);
  PlanFollowerConfig cfg;
  cfg.cruise_speed = own.speed;
  cfg.min_separation = 926.0;  // a sea-scale threshold: lowered to the domain here
  PlanFollower sea(cfg);
  sea.setObstacles({pier});
  sea.setGoal({0, 5000});
  sea.updateOwn(own);
  EXPECT_NEAR(sea.buildProblem(0.0, {}).passing_cap, 292.8, 0.1);
  EXPECT_NEAR(sea.buildProblem(0.0, {}).min_separation, 292.8, 0.1);
  applyPlannerMode(cfg, PlannerMode::Paper);
  PlanFollower paper(cfg);
  paper.setObstacles({pier});
  paper.setGoal({0, 5000});
  paper.updateOwn(own);
  EXPECT_EQ(paper.buildProblem(0.0, {}).passing_cap, 0.0);
  EXPECT_EQ(paper.buildProblem(0.0, {}).min_separation, 0.0);  // paper mode: the paper's own
}

// The plan-clearance trigger judges a plan by the separation the planners were given: there, the cap.
// A plan due north passes a ship lying 500 m east of the track at 500 m: more than the 292.8 m cap and
// plan_clearance (370.4 m), so it is kept; for the sea-scale 926 m it would be replanned every cycle.
// A ship 330 m off is inside plan_clearance: replanned.
TEST(Route, TheReplanTriggerUsesTheCappedSeparation) {
  const StaticObstacle& pier = kPier;
  const ShipState own = ninetyFourMetres();
  PlanFollowerConfig cfg;
  cfg.cruise_speed = own.speed;
  cfg.min_separation = 926.0;
  PlanFollower f(cfg);
  f.setObstacles({pier});
  f.setGoal({0, 5000});
  f.updateOwn(own);
  EXPECT_NEAR(f.separationHere(), 292.8, 0.1);
  Plan north;
  north.status = PlanStatus::Ok;
  north.waypoints = {{{0.0, 0.0}, 0.0, 0.0, own.speed}, {{0.0, 5000.0}, 5000.0 / own.speed, 0.0, own.speed}};
  auto lying = [](double x) {
    PlannerTarget t;
    t.state.id = "ts1";
    t.state.position = {x, 2000.0};
    return t;
  };
  f.acceptPlan(north, 0.0, {lying(500.0)}, "test");
  std::string why;
  EXPECT_FALSE(f.replanNeeded(10.0, {lying(500.0)}, why)) << why;
  EXPECT_TRUE(f.replanNeeded(10.0, {lying(330.0)}, why));
  EXPECT_EQ(why.rfind("plan predicted to pass within 3", 0), 0u) << why;
}

namespace {

const char* kGpx = R"(<?xml version="1.0" encoding="UTF-8"?>
<gpx version="1.1" creator="OpenCPN" xmlns="http://www.topografix.com/GPX/1/1">
  <rte>
    <name>Narrows</name>
    <rtept lat="40.600" lon="-74.050"><name>001</name></rtept>
    <rtept lat="40.610" lon="-74.050"><name>002</name></rtept>
  </rte>
</gpx>
)";

const char* kRtz = R"(<?xml version="1.0" encoding="UTF-8"?>
<route xmlns="http://www.cirm.org/RTZ/1/0" version="1.0">
  <routeInfo routeName="Kill Van Kull"/>
  <waypoints>
    <defaultWaypoint radius="0.1"><leg portsideXTD="0.1" starboardXTD="0.1"/></defaultWaypoint>
    <waypoint id="1"><position lat="40.600" lon="-74.050"/></waypoint>
    <waypoint id="2"><position lat="40.610" lon="-74.050"/><leg starboardXTD="0.05" speedMax="8"/></waypoint>
  </waypoints>
</route>
)";

}  // namespace

// Both files draw the same two waypoints: the origin, and 0.01 deg north of it (1110.5 m at 40.6 N,
// test above). RTZ's legs: XTD in nautical miles (0.1 nm = 185.2 m by default, 0.05 nm = 92.6 m on the
// second leg), speedMax in knots (8 kn = 4.1156 m/s).
TEST(Route, GpxAndRtzFilesAsPlottersWriteThem) {
  const LocalFrame frame(40.600, -74.050);
  std::vector<int> lines;
  const Route gpx = parseRouteXml(kGpx, "narrows.gpx", frame, &lines);
  ASSERT_EQ(gpx.size(), 2u);
  EXPECT_NEAR(gpx[0].position.norm(), 0.0, 1e-6);
  EXPECT_NEAR(gpx[1].position.y(), 1110.5, 0.5);
  EXPECT_EQ(gpx[1].speed, 0.0);
  EXPECT_EQ(lines, (std::vector<int>{5, 6}));
  const Route rtz = parseRouteXml(kRtz, "kvk.rtz", frame);
  ASSERT_EQ(rtz.size(), 2u);
  EXPECT_NEAR(rtz[1].position.y(), 1110.5, 0.5);
  EXPECT_DOUBLE_EQ(rtz[0].port_xtd, 185.2);
  EXPECT_DOUBLE_EQ(rtz[1].port_xtd, 185.2);  // the default
  EXPECT_DOUBLE_EQ(rtz[1].starboard_xtd, 92.6);
  EXPECT_NEAR(rtz[1].speed, 8.0 * 1852.0 / 3600.0, 1e-12);
  EXPECT_EQ(rtz[0].speed, 0.0);
}

TEST(Route, RouteFileErrorsNameFileAndLine) {
  const LocalFrame frame(40.600, -74.050);
  auto error = [&](std::string text, const std::string& from, const std::string& to) {
    if (!from.empty())
      text.replace(text.find(from), from.size(), to);
    try {
      parseRouteXml(text, "r.xml", frame);
    } catch (const RouteFileError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error(kGpx, "lat=\"40.610\"", "lat=\"91\"").find("r.xml:6: latitude/longitude out of range"),
            std::string::npos);
  EXPECT_NE(
      error(kGpx, "lon=\"-74.050\"><name>002", "><name>002").find("r.xml:6: a waypoint needs lat and lon"),
      std::string::npos);
  EXPECT_NE(error(kRtz, "speedMax=\"8\"", "speedMax=\"fast\"").find("r.xml:7: 'speedMax' is not a number"),
            std::string::npos);
  EXPECT_NE(error(kRtz, "starboardXTD=\"0.05\"", "starboardXTD=\"-1\"").find("r.xml:7: starboardXTD must be"),
            std::string::npos);
  EXPECT_NE(error(kGpx, "</rte>", "").find("r.xml:"), std::string::npos);  // not well-formed
  EXPECT_NE(error(kGpx, "<rte>", "<trk>").find("not well-formed"), std::string::npos);
  EXPECT_NE(error("<kml/>", "", "").find("r.xml:1: not a route file: root <kml>"), std::string::npos);
  EXPECT_NE(error("<gpx><rte/></gpx>", "", "").find("the route has no waypoints"), std::string::npos);
  EXPECT_THROW(readRouteFile("/nonexistent/route.rtz", frame), RouteFileError);
}

// A scenario's route_file, relative to the scenario's folder; a leg over land names the route file's line.
TEST(Route, ScenarioRouteFile) {
  const std::string dir = testing::TempDir();
  std::ofstream(dir + "kvk.rtz") << kRtz;
  std::string text = kRouteScenario;
  text.replace(text.find("  route:"), text.find("human:") - text.find("  route:"), "  route_file: kvk.rtz\n");
  const Scenario s = parseScenario(text, dir + "scenario.yaml");
  ASSERT_EQ(s.own.route.size(), 2u);
  EXPECT_NEAR(s.own.goal->y(), 1110.5, 0.5);  // the scenario's origin is the route's first waypoint
  EXPECT_DOUBLE_EQ(s.own.route[1].starboard_xtd, 92.6);
  const std::string islet =
      "static_obstacles:\n  - name: islet\n    polygon: [{x_m: -50, y_m: 500}, {x_m: 50, y_m: 500}, "
      "{x_m: 0, y_m: 600}]\n";
  try {
    parseScenario(text + islet, dir + "scenario.yaml");
    ADD_FAILURE() << "no error for a route over an islet";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find(dir + "kvk.rtz:7: 'own_ship.route[1]': leg 2"), std::string::npos)
        << e.what();
  }
  text.replace(text.find("kvk.rtz"), 7, "none.rtz");
  EXPECT_THROW(parseScenario(text, dir + "scenario.yaml"), ScenarioError);
}
