// Real-traffic scenarios: the MarineCadastre reader and its repairs, recorded tracks in the simulator,
// and the window-to-scenario conversion, against values worked out by hand.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "asv_core/common/units.h"
#include "asv_core/sim/scenario_from_ais.h"
#include "asv_core/sim/simulation.h"
#include "asv_core/world/route.h"
#include "asv_core/world/scenario_write.h"

using namespace asv;

namespace {

const char* const kHeader =
    "BaseDateTime,LON,LAT,MMSI,SOG,COG,Heading,VesselName,IMO,CallSign,VesselType,Status,Length,Width,"
    "Draft,Cargo,TranscieverClass,ETA\n";

std::vector<AisLogReport> readCsv(const std::string& rows, AisLogStats& stats) {
  std::istringstream in(std::string(kHeader) + rows);
  return readMarineCadastreCsv(in, stats);
}

// A row of the log at minute:second past 00:00 of 2020-06-30.
std::string row(int min, int sec, double lat, double lon, uint32_t mmsi, double sog, double cog,
                const std::string& name = "", const std::string& length = "") {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "2020-06-30T00:%02d:%02d,%.5f,%.5f,%u,%.1f,%.1f,511.0,%s,,,60.0,0.0,%s,,,,A,\n", min, sec,
                lon, lat, mmsi, sog, cog, name.c_str(), length.c_str());
  return buf;
}

const double kT0 = 1593475200.0;  // 2020-06-30T00:00:00Z (date -u -d ... +%s)

}  // namespace

TEST(ScenarioFromAis, UtcTimesAreSecondsSince1970) {
  EXPECT_DOUBLE_EQ(parseUtcTime("2020-06-30T00:00:00"), kT0);
  EXPECT_DOUBLE_EQ(parseUtcTime("2020-06-30 00:05:00Z"), kT0 + 300.0);
  EXPECT_DOUBLE_EQ(parseUtcTime("1970-01-01T00:00:00"), 0.0);
  EXPECT_DOUBLE_EQ(parseUtcTime("2000-03-01T00:00:00"), 951868800.0);  // after a leap day (date -u)
  for (const char* bad : {"2020-06-30", "2020-13-01T00:00:00", "2020-06-30T00:00:00+02", "yesterday"})
    EXPECT_THROW(parseUtcTime(bad), std::invalid_argument) << bad;
}

// The source's defects (its README and NOAA's): COG < 0 wrapped as 12 bits, 360 / 511 / 102.3 "not
// available"; unreadable rows refused and counted, valid ones all kept.
TEST(ScenarioFromAis, ReaderRepairsTheSourcesDefectsAndCountsRefusals) {
  AisLogStats st;
  const auto log = readCsv(row(0, 0, 40.64409, -74.07157, 367000140, 0.0, -60.6, "SAMUEL I NEWHOUSE") +
                               row(0, 1, 40.6, -74.0, 367000141, 5.0, -49.6) +  // COG not available
                               row(0, 2, 40.6, -74.0, 367000142, 5.0, 123.4, "\"A, B\"") +
                               row(0, 3, 40.6, -74.0, 367000143, 102.3, 10.0) +  // SOG not available
                               row(0, 4, 91.0, -74.0, 367000144, 5.0, 10.0) +    // latitude 91
                               "2020-06-30T00:00:05,-74.0,40.6,367000145\n" +    // short row
                               "2020-06-30T00:00:06,-74.0,40.6,abc,1,1,1,,,,,,,,,,A,\n",
                           st);
  EXPECT_EQ(st.rows, 7u);
  EXPECT_EQ(st.kept, 3u);
  ASSERT_EQ(log.size(), 3u);
  EXPECT_EQ(st.rejected.at("SOG missing or not available"), 1u);
  EXPECT_EQ(st.rejected.at("position missing or out of range"), 1u);
  EXPECT_EQ(st.rejected.at("wrong number of columns"), 1u);
  EXPECT_EQ(st.rejected.at("MMSI not a 9-digit number"), 1u);
  EXPECT_NEAR(*log[0].cog_deg, 349.0, 1e-9);  // -60.6 + 409.6
  EXPECT_FALSE(log[0].heading_deg);           // 511
  EXPECT_FALSE(log[1].cog_deg);               // -49.6 + 409.6 = 360
  EXPECT_EQ(log[2].name, "A, B");
  EXPECT_NEAR(log[0].position.lat_deg, 40.64409, 1e-12);
  EXPECT_DOUBLE_EQ(log[1].time, kT0 + 1.0);
  std::istringstream no_cog("BaseDateTime,LON,LAT,MMSI,SOG,Heading\n");
  EXPECT_THROW(readMarineCadastreCsv(no_cog, st), std::invalid_argument);
}

// From (0, 0) at t = 0: 500 m north by t = 100 s, then 500 m east by t = 200 s.
TEST(ScenarioFromAis, TrackSampleIsOnTheLegAtItsSpeed) {
  const std::vector<TrackPoint> track{{100.0, {0.0, 500.0}}, {200.0, {500.0, 500.0}}};
  TrackSample s = sampleTrack({0.0, 0.0}, 1.0, track, 50.0);
  EXPECT_NEAR(s.position.y(), 250.0, 1e-9);
  EXPECT_NEAR(s.course, 0.0, 1e-12);
  EXPECT_NEAR(s.speed, 5.0, 1e-12);
  s = sampleTrack({0.0, 0.0}, 1.0, track, 150.0);
  EXPECT_NEAR(s.position.x(), 250.0, 1e-9);
  EXPECT_NEAR(s.course, kPi / 2.0, 1e-12);
  EXPECT_FALSE(s.ended);
  s = sampleTrack({0.0, 0.0}, 1.0, track, 250.0);
  EXPECT_TRUE(s.ended);
  EXPECT_NEAR(s.position.x(), 500.0, 1e-9);
  EXPECT_EQ(s.speed, 0.0);
  // A leg of no length (a ship lying still between reports) keeps the course before it.
  s = sampleTrack({0.0, 0.0}, 1.0, {{100.0, {0.0, 0.0}}}, 50.0);
  EXPECT_NEAR(s.course, 1.0, 1e-12);
  EXPECT_EQ(s.speed, 0.0);
}

TEST(ScenarioFromAis, SimulatorReplaysATrackAndTheShipLeavesAfterIt) {
  Simulation sim(parseScenario(R"(format: 1
name: t
duration_s: 600
own_ship: {name: own, position: {x_m: -3000, y_m: 0}, course_deg: 270, speed_mps: 5}
targets:
  - name: rec
    position: {x_m: 0, y_m: 0}
    course_deg: 0
    speed_kn: 9.7
    behaviour: track
    track: [{t_s: 100, x_m: 0, y_m: 500}, {t_s: 200, x_m: 500, y_m: 500}]
)"));
  for (int i = 0; i < 1500; ++i)  // 150 s of 0.1 s steps
    sim.step();
  const SimVessel& rec = *sim.find("rec");
  EXPECT_NEAR(rec.position().x(), 250.0, 1e-6);
  EXPECT_NEAR(rec.position().y(), 500.0, 1e-6);
  EXPECT_NEAR(rec.sog(), 5.0, 1e-9);
  EXPECT_NEAR(radToDeg(rec.cog()), 90.0, 1e-9);
  EXPECT_NEAR(rec.path_length, 750.0, 1e-6);
  EXPECT_FALSE(rec.arrived);
  for (int i = 0; i < 600; ++i)
    sim.step();
  EXPECT_TRUE(sim.find("rec")->arrived);
  EXPECT_NEAR(sim.find("rec")->arrival_time, 200.0, 0.11);
}

TEST(ScenarioFromAis, TrackKeyErrorsNameTheKey) {
  const std::string head =
      "format: 1\nname: t\nduration_s: 600\nown_ship: {name: own, position: {x_m: 0, y_m: 0}, course_deg: 0, "
      "speed_kn: 5}\ntargets:\n  - {name: a, position: {x_m: 900, y_m: 0}, course_deg: 0, speed_kn: 1, ";
  auto error = [&](const std::string& rest) {
    try {
      parseScenario(head + rest + "}\n");
    } catch (const ScenarioError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("behaviour: track, track: [{t_s: 20, x_m: 0, y_m: 0}, {t_s: 10, x_m: 1, y_m: 0}]")
                .find("'targets[0].track[1].t_s': times must be > 0"),
            std::string::npos);
  EXPECT_NE(error("behaviour: track").find("'targets[0].track': behaviour track needs"), std::string::npos);
  EXPECT_NE(error("track: [{t_s: 1, x_m: 0, y_m: 0}]").find("only for behaviour: track"), std::string::npos);
  EXPECT_NE(error("behaviour: track, track: [{t_s: 1, x_m: 0, z_m: 0}]").find("unknown key"),
            std::string::npos);
}

// Vessel 1 sails north on the meridian of the origin, reporting 30 s before and after the start (so at
// t = 0 she is midway); vessel 2 lies still; 3 first reports after the start; 4 is 20 km away.
TEST(ScenarioFromAis, WindowBecomesTargetsPlacedByInterpolation) {
  AisLogStats st;
  const auto log = readCsv(
      row(4, 30, 40.600, -74.0, 111111111, 12.0, 0.0, "NORTH BOUND", "50") +
          row(5, 30, 40.602, -74.0, 111111111, 12.0, 0.0, "NORTH BOUND", "50") +
          row(6, 30, 40.604, -74.0, 111111111, 12.0, 0.0, "NORTH BOUND", "50") +
          row(3, 0, 40.610, -74.01, 222222222, 0.0, 10.0) + row(8, 0, 40.610, -74.01, 222222222, 0.1, 10.0) +
          row(5, 10, 40.605, -74.0, 333333333, 8.0, 90.0) + row(6, 10, 40.605, -73.99, 333333333, 8.0, 90.0) +
          row(4, 0, 40.800, -74.0, 444444444, 8.0, 90.0) + row(6, 0, 40.800, -73.99, 444444444, 8.0, 90.0),
      st);
  AisScenarioOptions o;
  o.start = kT0 + 300.0;
  o.duration = 600.0;
  o.own_start = GeoPoint{40.590, -74.005};
  o.own_goal = GeoPoint{40.620, -74.005};
  o.origin = GeoPoint{40.600, -74.0};
  const AisScenarioResult r = scenarioFromAis(log, o);
  EXPECT_EQ(r.vessels_seen, 4u);
  EXPECT_EQ(r.tracks, 1u);
  EXPECT_EQ(r.stationary, 1u);
  EXPECT_EQ(r.skipped.at("first report after the start (ships exist from t = 0)"), 1u);
  EXPECT_EQ(r.skipped.at("farther than the radius from the own ship's route"), 1u);
  ASSERT_EQ(r.scenario.targets.size(), 2u);
  const ScenarioShip& north = r.scenario.targets[0];
  EXPECT_EQ(north.name, "north_bound");
  EXPECT_EQ(north.behaviour, Behaviour::Track);
  EXPECT_DOUBLE_EQ(north.length, 50.0);
  const LocalFrame f = r.scenario.frame();
  const Eigen::Vector2d mid = 0.5 * (f.toLocal(40.600, -74.0) + f.toLocal(40.602, -74.0));
  EXPECT_NEAR((north.position - mid).norm(), 0.0, 1e-6);
  ASSERT_EQ(north.track.size(), 2u);  // 00:05:30 and 00:06:30, relative to the start at 00:05:00
  EXPECT_DOUBLE_EQ(north.track[0].t, 30.0);
  EXPECT_DOUBLE_EQ(north.track[1].t, 90.0);
  // 0.002 deg of latitude per minute is 222 m / 60 s = 3.70 m/s (111.0 km per degree near 40.6 N).
  EXPECT_NEAR(north.speed, 3.70, 0.02);
  EXPECT_NEAR(wrapPi(north.course), 0.0, 1e-3);  // due north (just under 2 pi is north too)
  const ScenarioShip& still = r.scenario.targets[1];
  EXPECT_EQ(still.name, "mmsi_222222222");
  EXPECT_EQ(still.behaviour, Behaviour::Constant);
  EXPECT_EQ(still.speed, 0.0);
  EXPECT_DOUBLE_EQ(still.length, o.default_length_m);
  // Written and read back: the same tracks to the file's 0.1 m.
  const Scenario back = parseScenario(scenarioToYaml(r.scenario));
  ASSERT_EQ(back.targets[0].track.size(), 2u);
  EXPECT_NEAR((back.targets[0].track[1].position - north.track[1].position).norm(), 0.0, 0.1);
  EXPECT_EQ(back.targets[0].mmsi, 111111111u);
  // A berth the chart draws as land: the stopped vessel on it is left out (not moved: a moored ship
  // would become a phantom in the fairway), the moving one is kept.
  const Eigen::Vector2d berth = still.position;
  o.land = {{"land 1",
             {berth + Eigen::Vector2d(-50, -50), berth + Eigen::Vector2d(50, -50),
              berth + Eigen::Vector2d(50, 50), berth + Eigen::Vector2d(-50, 50)}}};
  const AisScenarioResult on_land = scenarioFromAis(log, o);
  ASSERT_EQ(on_land.scenario.targets.size(), 1u);
  EXPECT_EQ(on_land.scenario.targets[0].name, "north_bound");
  EXPECT_EQ(on_land.skipped.at("stopped on chart land (a berth the chart draws as land)"), 1u);
  EXPECT_TRUE(on_land.warnings.empty());
  // The own ship's start 30 m inside a quay (x > 30 m east of it is land): moved 30 m west and 60 m
  // past (half her 120 m length), heading for the goal from there; her goal on land deeper than the
  // accuracy is an error that names it.
  const Eigen::Vector2d start = on_land.scenario.own.position;
  o.land = {{"quay",
             {start + Eigen::Vector2d(-30, -500), start + Eigen::Vector2d(500, -500),
              start + Eigen::Vector2d(500, 100), start + Eigen::Vector2d(-30, 100)}}};
  const AisScenarioResult own = scenarioFromAis(log, o);
  EXPECT_NEAR((own.scenario.own.position - (start + Eigen::Vector2d(-90, 0))).norm(), 0.0, 1e-6);
  EXPECT_EQ(own.warnings.at(0), "own start moved 90 m off chart land");
  EXPECT_NEAR(own.scenario.own.course,
              wrapTwoPi(std::atan2(own.scenario.own.goal->x() - own.scenario.own.position.x(),
                                   own.scenario.own.goal->y() - own.scenario.own.position.y())),
              1e-12);
  const Eigen::Vector2d goal = *own.scenario.own.goal;  // 1000 m inside a square island
  o.land[0].polygon = {goal + Eigen::Vector2d(-1000, -1000), goal + Eigen::Vector2d(1000, -1000),
                       goal + Eigen::Vector2d(1000, 1000), goal + Eigen::Vector2d(-1000, 1000)};
  EXPECT_THROW(
      {
        try {
          scenarioFromAis(log, o);
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find(
                        "the own ship's goal is on chart land with no water within its accuracy"),
                    std::string::npos)
              << e.what();
          throw;
        }
      },
      std::invalid_argument);
}

TEST(ScenarioFromAis, OwnShipTakesALoggedVesselsPlace) {
  AisLogStats st;
  const auto log = readCsv(row(4, 30, 40.600, -74.0, 111111111, 12.0, 0.0, "FERRY", "84") +
                               row(5, 30, 40.602, -74.0, 111111111, 12.0, 0.0, "FERRY", "84") +
                               row(15, 30, 40.622, -74.0, 111111111, 12.0, 0.0, "FERRY", "84") +
                               row(4, 0, 40.605, -74.003, 222222222, 9.0, 0.0) +
                               row(6, 0, 40.608, -74.003, 222222222, 9.0, 0.0),
                           st);
  AisScenarioOptions o;
  o.start = kT0 + 300.0;
  o.duration = 600.0;
  o.own_mmsi = 111111111;
  const AisScenarioResult r = scenarioFromAis(log, o);
  ASSERT_EQ(r.scenario.targets.size(), 1u);
  EXPECT_EQ(r.scenario.targets[0].mmsi, 222222222u);
  const ScenarioShip& own = r.scenario.own;
  EXPECT_EQ(own.mmsi, 111111111u);
  EXPECT_DOUBLE_EQ(own.length, 84.0);
  const LocalFrame f = r.scenario.frame();
  // t = 0 at 00:05:00, midway between 00:04:30 and 00:05:30; the goal is her place at 00:15:00,
  // 570 s into the 600 s leg from 00:05:30 to 00:15:30.
  EXPECT_NEAR((own.position - f.toLocal(40.601, -74.0)).norm(), 0.0, 0.5);
  EXPECT_NEAR((*own.goal - f.toLocal(40.602 + 0.020 * 570.0 / 600.0, -74.0)).norm(), 0.0, 0.5);
  // The master: 0.020 deg of latitude due north in 600 s, 2220.9 m (WGS84 meridian radius at 40.611 N,
  // 6362.6 km), 3.7015 m/s (she reported 12 kn: the log's SOG is not her way made good). She arrives
  // where she comes within 200 m of her goal (max(200, 2 x 84)): after 2020.9 m, at 545.97 s.
  ASSERT_TRUE(r.scenario.human.has_value());
  EXPECT_NEAR(r.scenario.human->path_m, 2020.9, 0.5);
  EXPECT_NEAR(r.scenario.human->time_s, 2020.9 / (2220.9 / 600.0), 0.2);
  EXPECT_NEAR(own.speed, 2220.9 / 600.0, 1e-3);
  EXPECT_DOUBLE_EQ(r.scenario.duration, 710.0);  // ceil(545.97 s x 1.3)
  // Her track is straight: the route is her goal alone.
  ASSERT_EQ(own.route.size(), 1u);
  EXPECT_EQ(own.route[0].position, *own.goal);
  // Her closest approach to the target (its last report at 00:06:00, 40.608 N 74.003 W, where she is at
  // 40.603 N): 0.005 deg north (555.2 m) and 0.003 deg east (253.9 m at 40.606 N), 610.5 m; earlier the
  // target, slower, is farther ahead.
  EXPECT_NEAR(r.scenario.human->min_separation_m, 610.5, 1.0);
  // Without a route: her goal only.
  AisScenarioOptions no_route = o;
  no_route.own_route = false;
  EXPECT_TRUE(scenarioFromAis(log, no_route).scenario.own.route.empty());
  o.own_mmsi = 999;  // not in the log
  EXPECT_THROW(scenarioFromAis(log, o), std::invalid_argument);
  o.own_mmsi = 0;
  o.own_start = GeoPoint{40.590, -74.005};
  o.own_goal = GeoPoint{40.620, -74.005};
  o.start = kT0 + 86400.0;  // a day later: nobody there, and the message says where the log is
  try {
    scenarioFromAis(log, o);
    ADD_FAILURE() << "no error for an empty window";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("2020-06-30T00:04:00Z to 2020-06-30T00:15:30Z"), std::string::npos)
        << e.what();
  }
}

// The real New York hour (skips visibly without it): a ferry's recorded report is a point of her
// track, its COG repaired (-179.6 -> 230.0).
// Her track thinned into the route: points within 50 m of a straight line go, a bend stays, and a
// thinned leg that would pass land closer than she did keeps her points.
TEST(ScenarioFromAis, HerTrackBecomesTheRouteThinnedOffLand) {
  AisLogStats st;
  const std::string other =
      row(4, 0, 40.605, -74.010, 222222222, 9.0, 0.0) + row(16, 0, 40.615, -74.010, 222222222, 9.0, 0.0);
  // North 0.007 deg (reports on the way), then east 0.018 deg: one bend.
  const auto bend = readCsv(row(4, 30, 40.600, -74.0, 111111111, 8.0, 0.0) +
                                row(5, 30, 40.602, -74.0, 111111111, 8.0, 0.0) +
                                row(8, 30, 40.608, -74.0, 111111111, 8.0, 90.0) +
                                row(11, 30, 40.608, -73.992, 111111111, 8.0, 90.0) +
                                row(15, 30, 40.608, -73.982, 111111111, 8.0, 90.0) + other,
                            st);
  AisScenarioOptions o;
  o.start = kT0 + 300.0;
  o.duration = 600.0;
  o.own_mmsi = 111111111;
  const AisScenarioResult r = scenarioFromAis(bend, o);
  const LocalFrame f = r.scenario.frame();
  const Route& route = r.scenario.own.route;
  ASSERT_EQ(route.size(), 2u);
  EXPECT_NEAR((route[0].position - f.toLocal(40.608, -74.0)).norm(), 0.0, 0.5);  // the bend
  EXPECT_EQ(route[1].position, *r.scenario.own.goal);
  // A bow 34 m west (0.0004 deg of longitude at 40.6 N, 33.8 m) in a straight run north: thinned away
  // in open water. With land 8-15 m west of the straight line abeam of the bow, the straight leg would
  // pass it at 8 m where she passed it at about 19 m: the bow is kept.
  const auto bow = readCsv(row(4, 30, 40.600, -74.0, 111111111, 8.0, 0.0) +
                               row(9, 30, 40.6045, -74.0004, 111111111, 8.0, 0.0) +
                               row(15, 30, 40.610, -74.0, 111111111, 8.0, 0.0) + other,
                           st);
  o.origin = GeoPoint{40.6045, -74.0};
  EXPECT_EQ(scenarioFromAis(bow, o).scenario.own.route.size(), 1u);
  o.land = {StaticObstacle{"land 1", {{-15, -5}, {-8, -5}, {-8, 5}, {-15, 5}}, nullptr}};
  const Route kept = scenarioFromAis(bow, o).scenario.own.route;
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_NEAR(kept[0].position.x(), -33.8, 0.5);
  // A pier 100 m long and 20 m wide across her run 200 m south of the bow, which a coarse chart draws
  // where she sailed: the route goes round it instead of being dropped, every leg off the land, and
  // says so.
  o.land = {StaticObstacle{"pier", {{-60, -210}, {40, -210}, {40, -190}, {-60, -190}}, nullptr}};
  const AisScenarioResult round = scenarioFromAis(bow, o);
  const Route& r2 = round.scenario.own.route;
  ASSERT_GE(r2.size(), 2u);
  EXPECT_EQ(r2.back().position, *round.scenario.own.goal);
  EXPECT_FALSE(legOnLand(r2, round.scenario.own.position, o.land));
  bool said = false;
  for (const auto& w : round.warnings)
    said |= w.find("routed round it") != std::string::npos;
  EXPECT_TRUE(said);
}

TEST(ScenarioFromAis, NewYorkFerryFollowsHerReports) {
  const std::string csv = std::string(ASV_SHARED_DIR) + "/data/ais/real/NYHarbor_2020_06_30_first_hour.csv";
  std::ifstream in(csv);
  if (!in)
    GTEST_SKIP() << "the New York AIS file is not present (" << csv << ")";
  AisLogStats st;
  const auto log = readMarineCadastreCsv(in, st);
  EXPECT_EQ(st.rows, 8689u);  // the file's README
  bool seen = false;
  for (const auto& rep : log)
    if (rep.mmsi == 367000150 && rep.time == kT0 + 380.0) {  // ANDREW J BARBERI at 00:06:20
      seen = true;
      EXPECT_NEAR(*rep.cog_deg, 230.0, 1e-9);
    }
  EXPECT_TRUE(seen);
  AisScenarioOptions o;
  o.start = kT0 + 240.0;
  o.duration = 1500.0;
  o.own_mmsi = 367000190;  // JOHN F KENNEDY, St George to Whitehall
  const AisScenarioResult r = scenarioFromAis(log, o);
  const LocalFrame f = r.scenario.frame();
  const ScenarioShip* barberi = nullptr;
  for (const auto& t : r.scenario.targets)
    if (t.mmsi == 367000150)
      barberi = &t;
  ASSERT_NE(barberi, nullptr);
  EXPECT_EQ(barberi->name, "andrew_j_barberi");
  bool point = false;
  for (const auto& p : barberi->track)
    if (p.t == 140.0)
      point = (p.position - f.toLocal(40.69194, -74.03128)).norm() < 1e-6;
  EXPECT_TRUE(point);
}
