#include <gtest/gtest.h>

#include <algorithm>

#include "asv_core/codec/ais.h"
#include "asv_core/codec/arpa.h"
#include "asv_core/codec/nmea.h"
#include "asv_core/sim/simulation.h"

using namespace asv;

namespace {
std::string scenarioYaml(const std::string& targets, const std::string& own_extra = "") {
  return "format: 1\nname: t\nduration_s: 3600\norigin: {lat_deg: 54.6, lon_deg: 18.8}\n"
         "own_ship:\n  name: own\n  position: {x_m: 0, y_m: 0}\n  course_deg: 0\n  speed_mps: 5\n" +
         own_extra + "targets:\n" + targets;
}
void run(Simulation& sim, double seconds) {
  const int n = static_cast<int>(std::lround(seconds / sim.config().dt));
  for (int i = 0; i < n; ++i)
    sim.step();
}
}  // namespace

TEST(Simulation, ConstantTargetsMoveOnStraightLinesExactly) {
  Simulation sim(parseScenario(
      scenarioYaml("  - {name: a, position: {x_m: 1000, y_m: 0}, course_deg: 90, speed_mps: 4}\n")));
  run(sim, 100.0);
  EXPECT_NEAR(sim.time(), 100.0, 1e-9);
  EXPECT_NEAR(sim.find("a")->position().x(), 1400.0, 1e-6);
  EXPECT_NEAR(sim.find("a")->position().y(), 0.0, 1e-6);
  EXPECT_NEAR(sim.own().position().y(), 500.0, 1e-6);
  EXPECT_NEAR(sim.find("a")->path_length, 400.0, 1e-6);
}

TEST(Simulation, HeadOnWithoutActionCollidesAndIsRefereed) {
  // 2 km apart closing at 10 m/s: hulls of 100 m meet after (2000 - 100) / 10 = 190 s.
  Simulation sim(parseScenario(
      scenarioYaml("  - {name: a, position: {x_m: 0, y_m: 2000}, course_deg: 180, speed_mps: 5}\n")));
  run(sim, 185.0);
  EXPECT_FALSE(sim.collided());
  run(sim, 10.0);
  EXPECT_TRUE(sim.collided());
  ASSERT_FALSE(sim.events().empty());
  bool collision = false, near = false;
  for (const auto& e : sim.events()) {
    collision |= e.type == SimEvent::Collision;
    near |= e.type == SimEvent::NearMiss;
  }
  EXPECT_TRUE(collision);
  EXPECT_TRUE(near);
}

TEST(Simulation, PassingClearHasTheHandComputedMinimumSeparation) {
  Simulation sim(parseScenario(
      scenarioYaml("  - {name: a, position: {x_m: 1500, y_m: 4000}, course_deg: 180, speed_mps: 5}\n")));
  run(sim, 700.0);
  EXPECT_FALSE(sim.collided());
  EXPECT_NEAR(sim.minSeparationOwn(), 1500.0, 1e-6);  // abeam at t = 400 s
  EXPECT_NEAR(sim.minDistanceTo(1), 1500.0, 1e-6);
}

// An island 1 km square across the own ship's track (north at 5 m/s from the origin): its 100 x 20 m
// hull first touches the south shore at y = 500 when the bow is there, centre at y = 450: t = 90 s.
TEST(Simulation, AShipOverLandIsAGroundingAsBadAsACollision) {
  const std::string island =
      "static_obstacles:\n  - name: island\n    polygon: [{x_m: -500, y_m: 500}, {x_m: 500, y_m: 500}, "
      "{x_m: 500, y_m: 1500}, {x_m: -500, y_m: 1500}]\n";
  Simulation sim(parseScenario(scenarioYaml("  []\n", "  length_m: 100\n  beam_m: 20\n") + island));
  EXPECT_FALSE(sim.grounded());
  run(sim, 89.0);
  EXPECT_FALSE(sim.grounded());
  EXPECT_NEAR(sim.minObstacleDistanceOwn(), 500.0 - (89.0 * 5.0 + 50.0), 1e-6);  // 5 m short
  run(sim, 2.0);
  EXPECT_TRUE(sim.grounded());
  EXPECT_DOUBLE_EQ(sim.minObstacleDistanceOwn(), 0.0);
  EXPECT_FALSE(sim.collided());
  int groundings = 0;
  for (const auto& e : sim.events())
    if (e.type == SimEvent::Grounding) {
      ++groundings;
      EXPECT_EQ(e.a, "own");
      EXPECT_EQ(e.b, "island");
      EXPECT_NEAR(e.time, 90.0, 0.11);
    }
  EXPECT_EQ(groundings, 1);  // once per contact, not once per step
}

TEST(Simulation, PassingBesideAnIslandKeepsItsHandComputedDistance) {
  // The island's west shore at x = 300, the own ship's starboard side at x = 10: 290 m.
  const std::string island =
      "static_obstacles:\n  - name: island\n    polygon: [{x_m: 300, y_m: 500}, {x_m: 1300, y_m: 500}, "
      "{x_m: 1300, y_m: 1500}, {x_m: 300, y_m: 1500}]\n";
  Simulation sim(parseScenario(scenarioYaml("  []\n", "  length_m: 100\n  beam_m: 20\n") + island));
  run(sim, 600.0);
  EXPECT_FALSE(sim.grounded());
  EXPECT_NEAR(sim.minObstacleDistanceOwn(), 290.0, 1e-6);
}

TEST(Simulation, GiveWayTargetTurnsToStarboardNonCompliantStandsOn) {
  // Crossing from our port side on a collision course: we are on its starboard bow, so it gives way.
  const std::string t =
      "  - {name: gw, position: {x_m: -3000, y_m: 3000}, course_deg: 90, speed_mps: 5, behaviour: "
      "give_way}\n";
  Simulation sim(parseScenario(scenarioYaml(t)));
  run(sim, 60.0);
  const SimVessel* gw = sim.find("gw");
  EXPECT_TRUE(gw->giving_way);
  // The smallest of 40, 50, ... deg to starboard that passes the own ship (north at 5 m/s from the
  // origin) 1 nm off, both on constant velocity from the start, range (-3000, 3000) m, by hand:
  // 40 deg (course 130): relative velocity (3.830, -8.214) m/s, DCPA = |r x v| / |v| = 13142 / 9.063
  // = 1450 m; 50 deg (course 140): (3.214, -8.830), 16848 / 9.397 = 1793 m; 60 deg (course 150):
  // (2.500, -9.330), 20490 / 9.659 = 2121 m >= 1852 m. So 60 deg.
  EXPECT_NEAR(radToDeg(wrapPi(gw->course_sp - degToRad(90.0))), 60.0, 1e-9);
  run(sim, 1200.0);
  EXPECT_FALSE(sim.collided());
  EXPECT_GT(sim.minSeparationOwn(), 1852.0 - 100.0);  // the turn takes its time: a little inside
  EXPECT_FALSE(sim.find("gw")->giving_way);           // resumed after passing
  Simulation nc(
      parseScenario(scenarioYaml("  - {name: nc, position: {x_m: -3000, y_m: 3000}, course_deg: 90, "
                                 "speed_mps: 5, behaviour: non_compliant}\n")));
  run(nc, 700.0);
  EXPECT_NEAR(nc.find("nc")->cog(), degToRad(90.0), 1e-9);
  EXPECT_TRUE(nc.collided());
  // port_turn: the same alteration to the other side, 090 - 40 = 050, towards the own ship's track ahead.
  Simulation pt(
      parseScenario(scenarioYaml("  - {name: pt, position: {x_m: -3000, y_m: 3000}, course_deg: 90, "
                                 "speed_mps: 5, behaviour: port_turn}\n")));
  run(pt, 60.0);
  EXPECT_TRUE(pt.find("pt")->giving_way);
  EXPECT_NEAR(radToDeg(pt.find("pt")->course_sp), 50.0, 1e-9);
}

TEST(Simulation, LateGiveWayTargetTurnsFifteenDegreesSixMinutesBeforeTheCpa) {
  // The same crossing from port: relative position (-3000, 3000), relative velocity (5, -5), so the
  // TCPA is 600 - t s. A late_give_way ship acts only at TCPA <= 360 s (t = 240 s) and by 15 deg.
  Simulation sim(
      parseScenario(scenarioYaml("  - {name: lg, position: {x_m: -3000, y_m: 3000}, course_deg: 90, "
                                 "speed_mps: 5, behaviour: late_give_way}\n")));
  run(sim, 239.0);
  EXPECT_FALSE(sim.find("lg")->giving_way);
  run(sim, 2.0);
  ASSERT_TRUE(sim.find("lg")->giving_way);
  EXPECT_NEAR(radToDeg(sim.find("lg")->course_sp), 105.0, 1e-9);
  // From t = 240 s (own at (0, 1200), lg at (-1800, 3000)) on 105 deg: relative velocity (4.830, -6.294),
  // DCPA |(-1800)(-6.294) - 1800 x 4.830| / 7.934 = 332 m with an instant turn: inside the own
  // ship's minimum separation (926 m), clear of her hull.
  run(sim, 600.0);
  EXPECT_FALSE(sim.collided());
  EXPECT_LT(sim.minSeparationOwn(), 926.0);
  EXPECT_NEAR(sim.minSeparationOwn(), 332.0, 40.0);  // her swing at the kinematic turn rate
  EXPECT_EQ(toString(Behaviour::LateGiveWay), std::string("late_give_way"));
}

TEST(Simulation, OwnShipWithoutPlannerSteersForItsGoalAndArrives) {
  Simulation sim(parseScenario(
      scenarioYaml("  - {name: a, position: {x_m: 5000, y_m: 0}, course_deg: 0, speed_mps: 1}\n",
                   "  goal: {x_m: 3000, y_m: 3000}\n")));
  run(sim, 1000.0);
  EXPECT_TRUE(sim.own().arrived);
  EXPECT_GT(sim.own().arrival_time, 0.0);
}

TEST(Simulation, ArrivalIsJudgedAlongTheStepSoAFastShipCannotStepOverItsGoal) {
  // 25 m/s with 1 s steps passes the goal 12.5 m ahead between two samples (0 and 25 m): with a 1 m
  // arrival radius it arrives at the end of the first step, 12.5 m beyond the goal.
  const std::string own = "  model: point\n  goal: {x_m: 0, y_m: 12.5}\n  goal_radius_m: 1\n";
  std::string yaml =
      scenarioYaml("  - {name: a, position: {x_m: 5000, y_m: 0}, course_deg: 0, speed_mps: 1}\n", own);
  yaml.replace(yaml.find("speed_mps: 5"), 12, "speed_mps: 25");
  SimConfig cfg;
  cfg.dt = 1.0;
  Simulation sim(parseScenario(yaml), cfg);
  run(sim, 1.0);
  EXPECT_FALSE(sim.own().arrived);  // judged when the next step starts
  run(sim, 1.0);
  ASSERT_TRUE(sim.own().arrived);
  EXPECT_DOUBLE_EQ(sim.own().arrival_time, 1.0);
  ASSERT_FALSE(sim.events().empty());
  EXPECT_EQ(sim.events().back().type, SimEvent::Arrival);
  EXPECT_NEAR(sim.events().back().distance, 12.5, 1e-9);
  // Without a radius the default is max(200 m, 2 L): a goal 150 m off the track still counts.
  const std::string wide = "  goal: {x_m: 150, y_m: 1000}\n";
  Simulation sim2(parseScenario(
      scenarioYaml("  - {name: a, position: {x_m: 5000, y_m: 0}, course_deg: 0, speed_mps: 1}\n", wide)));
  sim2.setSetpoint("own", 0.0, 5.0);
  run(sim2, 250.0);
  EXPECT_TRUE(sim2.own().arrived);
}

TEST(Simulation, AShipThatStaysAtHerGoalIsStillThereAndRefereed) {
  // Target a sails north 200 m to her goal and stops at t = 40 s; the own ship, 5 m/s north from 500 m
  // behind (500 m apart until then), reaches that spot at t = 140 s. Staying, a is a stationary ship the own
  // ship runs into; leaving (the default), a is gone on arrival and nothing is refereed against her after it.
  const std::string a =
      "  - {name: a, model: point, position: {x_m: 0, y_m: 500}, course_deg: 0, speed_mps: 5,"
      " behaviour: planner, planner: dssa_plus, goal: {x_m: 0, y_m: 700}, goal_radius_m: 1%s}\n";
  for (const bool stays : {true, false}) {
    SCOPED_TRACE(stays ? "stays" : "leaves");
    char buf[512];
    std::snprintf(buf, sizeof buf, a.c_str(), stays ? ", stays_at_goal: true" : "");
    Simulation sim(parseScenario(scenarioYaml(buf)));
    run(sim, 60.0);
    const SimVessel& target = sim.vessels()[1];
    ASSERT_TRUE(target.arrived);
    EXPECT_NEAR(target.arrival_time, 40.0, 0.2);
    EXPECT_EQ(target.present(), stays);
    EXPECT_NEAR(target.position().y(), 700.0, 1.0);
    run(sim, 120.0);
    EXPECT_NEAR(target.position().y(), 700.0, 1.0) << "an arrived ship stops";
    EXPECT_EQ(sim.collided(), stays);
    if (stays)
      EXPECT_LT(sim.minSeparationOwn(), 1.0);
    else
      EXPECT_NEAR(sim.minSeparationOwn(), 500.0, 1.0);  // the same speed until a arrived and left
  }
}

TEST(Simulation, ThreeDofTargetFollowsASetpoint) {
  Simulation sim(parseScenario(scenarioYaml(
      "  - {name: b, model: wu_asv_40m, behaviour: planner, planner: ga, goal: {x_m: 5000, y_m: 5000},"
      " position: {x_m: 2000, y_m: 0}, course_deg: 0, speed_mps: 5}\n")));
  ASSERT_TRUE(sim.setSetpoint("b", degToRad(90.0), 5.0));
  EXPECT_FALSE(sim.setSetpoint("nobody", 0.0, 1.0));
  EXPECT_FALSE(sim.setSetpoint("b", std::nan(""), 1.0));
  run(sim, 120.0);
  EXPECT_NEAR(radToDeg(wrapPi(sim.find("b")->state().psi - degToRad(90.0))), 0.0, 2.0);
  EXPECT_NEAR(sim.find("b")->sog(), 5.0, 0.3);
}

TEST(NmeaEmitter, ItuReportingIntervals) {
  EXPECT_DOUBLE_EQ(NmeaEmitter::reportingInterval('A', knotsToMps(10), 0.0), 10.0);
  EXPECT_NEAR(NmeaEmitter::reportingInterval('A', knotsToMps(10), degToRad(1.0)), 10.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(NmeaEmitter::reportingInterval('A', knotsToMps(20), 0.0), 6.0);
  EXPECT_DOUBLE_EQ(NmeaEmitter::reportingInterval('A', knotsToMps(20), degToRad(1.0)), 2.0);
  EXPECT_DOUBLE_EQ(NmeaEmitter::reportingInterval('A', knotsToMps(25), 0.0), 2.0);
  EXPECT_DOUBLE_EQ(NmeaEmitter::reportingInterval('A', 0.5, 0.0, 1), 180.0);  // at anchor
  EXPECT_DOUBLE_EQ(NmeaEmitter::reportingInterval('B', knotsToMps(5), 0.0), 30.0);
  EXPECT_DOUBLE_EQ(NmeaEmitter::reportingInterval('B', knotsToMps(1), 0.0), 180.0);
}

TEST(NmeaEmitter, DecodedReportsGiveBackTheTrueStates) {
  Simulation sim(parseScenario(scenarioYaml(
      "  - {name: a, mmsi: 244000001, position: {x_m: 3000, y_m: 1000}, course_deg: 270, speed_kn: 10}\n"
      "  - {name: b, ais_class: B, position: {x_m: -2000, y_m: 500}, course_deg: 45, speed_kn: 6}\n")));
  EmitterConfig ec;
  ec.radar_dropout = 0.0;
  NmeaEmitter em(ec, 7);
  ais::Decoder dec;
  int reports_a = 0, reports_b = 0, statics = 0, ttms = 0;
  for (int k = 0; k < 1200; ++k) {  // 120 s
    std::vector<std::string> ais_lines, ttm_lines;
    em.update(sim, ais_lines, ttm_lines);
    ttms += static_cast<int>(ttm_lines.size());
    for (const auto& l : ais_lines) {
      ais::Message m;
      const ais::Status st = dec.feedLine(l, sim.time(), m);
      if (st != ais::Status::kMessage) {
        EXPECT_EQ(st, ais::Status::kPending) << l;
        continue;
      }
      ais::Kinematics kin;
      if (!ais::toKinematics(m, kin)) {
        ++statics;
        continue;
      }
      const SimVessel* v = m.mmsi == 244000001u ? sim.find("a") : sim.find("b");
      ASSERT_TRUE(kin.has_position);
      const Eigen::Vector2d p = sim.frame().toLocal(kin.lat_deg, kin.lon_deg);
      // Emitted now from the current state: within the 1/10000' quantisation (~0.19 m north, 0.11 m east).
      EXPECT_NEAR(p.x(), v->position().x(), 0.2);
      EXPECT_NEAR(p.y(), v->position().y(), 0.2);
      EXPECT_NEAR(kin.speed, v->sog(), knotsToMps(0.05) + 1e-9);
      EXPECT_NEAR(radToDeg(wrapPi(kin.course - v->cog())), 0.0, 0.05 + 1e-9);
      (m.mmsi == 244000001u ? reports_a : reports_b)++;
    }
    sim.step();
  }
  EXPECT_NEAR(reports_a, 12, 1);  // class A at 10 kn: every 10 s
  EXPECT_NEAR(reports_b, 4, 1);   // class B at 6 kn: every 30 s
  EXPECT_EQ(statics, 3);          // one type 5, one 24A, one 24B within the first 10 s
  EXPECT_NEAR(ttms, 2 * 48, 2);   // both within radar range, one TTM each per 2.5 s scan
}

TEST(NmeaEmitter, SameSeedSameSentences) {
  auto stream = [](uint64_t seed) {
    Simulation sim(parseScenario(
        scenarioYaml("  - {name: a, position: {x_m: 3000, y_m: 1000}, course_deg: 270, speed_kn: 10}\n")));
    NmeaEmitter em(EmitterConfig{}, seed);
    std::vector<std::string> all, ttm;
    for (int k = 0; k < 600; ++k) {
      em.update(sim, all, ttm);
      sim.step();
    }
    all.insert(all.end(), ttm.begin(), ttm.end());
    return all;
  };
  EXPECT_EQ(stream(3), stream(3));
  EXPECT_NE(stream(3), stream(4));  // the noise differs
}

TEST(NmeaEmitter, SensorFaultsSilenceLoseAndSwap) {
  // a is silent on AIS in [10, 40) s, lost by the radar in [50, 60) s, and swaps radar numbers with b in
  // [70, 80) s. Every other report of the 100 s goes out as without faults.
  std::string yaml = scenarioYaml(
      "  - {name: a, mmsi: 244000001, position: {x_m: 3000, y_m: 1000}, course_deg: 270, speed_kn: 10}\n"
      "  - {name: b, mmsi: 244000002, position: {x_m: -2000, y_m: 500}, course_deg: 45, speed_kn: 10}\n");
  yaml +=
      "sensor_faults:\n"
      "  - {type: ais_silence, ship: a, start_s: 10, duration_s: 30}\n"
      "  - {type: radar_loss, ship: a, start_s: 50, duration_s: 10}\n"
      "  - {type: radar_swap, ship: a, with: b, start_s: 70, duration_s: 10}\n";
  Simulation sim(parseScenario(yaml));
  EmitterConfig ec;
  ec.radar_dropout = 0.0;
  NmeaEmitter em(ec, 7);
  ais::Decoder dec;
  std::vector<double> a_reports;
  int lost_a = 0, tracked_a_in_loss = 0, swapped = 0, unswapped_in_swap = 0, normal = 0;
  for (int k = 0; k < 1000; ++k) {  // 100 s
    const double t = sim.time();
    std::vector<std::string> ais_lines, ttm_lines;
    em.update(sim, ais_lines, ttm_lines);
    for (const auto& l : ais_lines) {
      ais::Message m;
      ais::Kinematics kin;
      if (dec.feedLine(l, t, m) == ais::Status::kMessage && m.mmsi == 244000001u && ais::toKinematics(m, kin))
        a_reports.push_back(t);
    }
    for (const auto& l : ttm_lines) {
      nmea::Sentence s;
      ASSERT_EQ(nmea::parseSentence(l, s), nmea::Reject::kNone) << l;
      arpa::TrackedTarget tt;
      ASSERT_EQ(arpa::parseTtm(s, tt), arpa::Error::kNone) << l;
      const int own_number = tt.name == "a" ? 1 : 2;  // the name field says which ship it really is
      if (tt.status == arpa::TargetStatus::kLost) {
        EXPECT_EQ(tt.number, 1);
        EXPECT_TRUE(t >= 50.0 && t < 60.0) << t;
        ++lost_a;
      } else if (tt.name == "a" && t >= 50.0 && t < 60.0) {
        ++tracked_a_in_loss;
      } else if (t >= 70.0 && t < 80.0) {
        (tt.number == 3 - own_number ? swapped : unswapped_in_swap)++;
      } else {
        EXPECT_EQ(tt.number, own_number) << "t " << t << ": " << l;
        ++normal;
      }
    }
    sim.step();
  }
  for (double t : a_reports)
    EXPECT_FALSE(t >= 10.0 && t < 40.0) << "an AIS report of a at " << t << " s, inside the silence";
  EXPECT_GE(std::count_if(a_reports.begin(), a_reports.end(), [](double t) { return t >= 40.0 && t < 42.0; }),
            1)
      << "the transponder reports as soon as the silence ends";
  EXPECT_EQ(lost_a, 1);
  EXPECT_EQ(tracked_a_in_loss, 0);
  EXPECT_EQ(swapped, 8);  // 4 scans of 2.5 s, both ships
  EXPECT_EQ(unswapped_in_swap, 0);
  EXPECT_GT(normal, 50);
  // Errors name the fault.
  EXPECT_THROW(
      parseScenario(
          scenarioYaml("  - {name: a, position: {x_m: 3000, y_m: 0}, course_deg: 0, speed_kn: 1}\n") +
          "sensor_faults: [{type: radar_swap, ship: a, start_s: 1, duration_s: 1}]\n"),
      ScenarioError);
  EXPECT_THROW(
      parseScenario(
          scenarioYaml("  - {name: a, position: {x_m: 3000, y_m: 0}, course_deg: 0, speed_kn: 1}\n") +
          "sensor_faults: [{type: ais_silence, ship: nobody, start_s: 1, duration_s: 1}]\n"),
      ScenarioError);
}
