// The scenario generator and writer: reproducible files that the loader accepts, encounters placed where
// the draw says (checked with hand formulas, not the generator's own CPA code), the feasibility search.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "asv_core/common/units.h"
#include "asv_core/sim/scenario_gen.h"
#include "asv_core/world/scenario_write.h"

using namespace asv;

namespace {

// Relative motion by hand: t* = -(r . v) / |v|^2, d = |r + v t*| (r = target - own, v = v_t - v_o).
struct HandCpa {
  double tcpa, dcpa;
};
HandCpa handCpa(const ScenarioShip& own, const ScenarioShip& t) {
  const double rx = t.position.x() - own.position.x(), ry = t.position.y() - own.position.y();
  const double vx = t.speed * std::sin(t.course) - own.speed * std::sin(own.course);
  const double vy = t.speed * std::cos(t.course) - own.speed * std::cos(own.course);
  const double tc = -(rx * vx + ry * vy) / (vx * vx + vy * vy);
  return {tc, std::hypot(rx + vx * tc, ry + vy * tc)};
}

// Relative bearing [deg, 0..360) of the target from the own bow.
double relativeBearingDeg(const ScenarioShip& own, const ScenarioShip& t) {
  const double b = std::atan2(t.position.x() - own.position.x(), t.position.y() - own.position.y());
  return std::fmod(radToDeg(b - own.course) + 720.0, 360.0);
}

double courseDiffDeg(const ScenarioShip& own, const ScenarioShip& t) {
  return std::fmod(radToDeg(t.course - own.course) + 720.0, 360.0);
}

const GeneratorConfig kCfg;

}  // namespace

TEST(ScenarioGen, SameSeedAndIndexGiveTheSameFileByteForByte) {
  for (SituationClass c : allSituationClasses()) {
    const GeneratedScenario a = generateScenario(kCfg, c, 42, 7);
    const GeneratedScenario b = generateScenario(kCfg, c, 42, 7);
    EXPECT_EQ(a.yaml, b.yaml) << toString(c);
    EXPECT_NE(a.yaml, generateScenario(kCfg, c, 42, 8).yaml) << toString(c);
    EXPECT_NE(a.yaml, generateScenario(kCfg, c, 43, 7).yaml) << toString(c);
    EXPECT_EQ(a.scenario.name, std::string("gen_") + toString(c) + "_s42_7");
    // The file is what the checks ran on: parsing it again gives the same scenario.
    EXPECT_EQ(scenarioToYaml(parseScenario(a.yaml)), a.yaml) << toString(c);
  }
}

TEST(ScenarioGen, SingleTargetEncountersAreWhereTheClassSays) {
  const double dcpa_max = kCfg.dcpa_max_m + 5.0;  // + rounding of positions, courses and speeds
  for (uint64_t i = 0; i < 12; ++i) {
    for (SituationClass c :
         {SituationClass::HeadOn, SituationClass::CrossingGiveWay, SituationClass::CrossingStandOn,
          SituationClass::Overtaking, SituationClass::BeingOvertaken}) {
      const Scenario s = generateScenario(kCfg, c, 5, i).scenario;
      ASSERT_EQ(s.targets.size(), 1u);
      const ScenarioShip& t = s.targets[0];
      const HandCpa cpa = handCpa(s.own, t);
      EXPECT_GE(cpa.tcpa, kCfg.tcpa_min_s - 5.0) << s.name;
      EXPECT_LE(cpa.tcpa, kCfg.tcpa_max_s + 5.0) << s.name;
      EXPECT_LE(cpa.dcpa, dcpa_max) << s.name;
      EXPECT_GE((t.position - s.own.position).norm(), 2.0 * 926.0) << s.name;
      const double rb = relativeBearingDeg(s.own, t), dc = courseDiffDeg(s.own, t);
      const double ratio = t.speed / s.own.speed;
      switch (c) {
        case SituationClass::HeadOn:  // nearly reciprocal, dead ahead; she gives way too
          EXPECT_NEAR(dc, 180.0, 6.1) << s.name;
          EXPECT_TRUE(rb < 15.0 || rb > 345.0) << s.name << " bearing " << rb;
          EXPECT_EQ(t.behaviour, Behaviour::GiveWay) << s.name;
          break;
        case SituationClass::CrossingGiveWay:  // on the starboard side, forward of her beam; stands on
          EXPECT_GT(rb, 0.0) << s.name;
          EXPECT_LT(rb, 112.5) << s.name;
          EXPECT_EQ(t.behaviour, Behaviour::Constant) << s.name;
          break;
        case SituationClass::CrossingStandOn:  // on the port side: she gives way
          EXPECT_GT(rb, 247.5) << s.name;
          EXPECT_EQ(t.behaviour, Behaviour::GiveWay) << s.name;
          break;
        case SituationClass::Overtaking:  // the own ship comes up from her stern sector (Rule 13), faster
          EXPECT_GT(relativeBearingDeg(t, s.own), 112.5) << s.name;
          EXPECT_LT(relativeBearingDeg(t, s.own), 247.5) << s.name;
          EXPECT_LE(ratio, kCfg.overtaking_ratio_max + 0.01) << s.name;
          break;
        default:  // overtaken: abaft the beam, faster, and she keeps out of the way
          EXPECT_GT(rb, 112.5) << s.name;
          EXPECT_LT(rb, 247.5) << s.name;
          EXPECT_GE(ratio, kCfg.overtaken_ratio_min - 0.01) << s.name;
          EXPECT_EQ(t.behaviour, Behaviour::GiveWay) << s.name;
      }
    }
  }
}

TEST(ScenarioGen, RuleBreakersConvergingTrafficAndCoasts) {
  int port_turns = 0, stand_ons = 0, channels = 0;
  for (uint64_t i = 0; i < 10; ++i) {
    const Scenario rb = generateScenario(kCfg, SituationClass::RuleBreaker, 9, i).scenario;
    ASSERT_EQ(rb.targets.size(), 1u);
    port_turns += rb.targets[0].behaviour == Behaviour::PortTurn;
    stand_ons += rb.targets[0].behaviour == Behaviour::NonCompliant;

    const Scenario cv = generateScenario(kCfg, SituationClass::Converging, 9, i).scenario;
    ASSERT_GE(cv.targets.size(), 2u);
    ASSERT_LE(cv.targets.size(), 5u);
    double lo = 1e9, hi = -1e9;
    for (const auto& t : cv.targets) {
      lo = std::min(lo, handCpa(cv.own, t).tcpa);
      hi = std::max(hi, handCpa(cv.own, t).tcpa);
    }
    EXPECT_LE(hi - lo, kCfg.converging_window_s + 10.0) << cv.name;

    const Scenario co = generateScenario(kCfg, SituationClass::Coastal, 9, i).scenario;
    ASSERT_GE(co.obstacles.size(), 1u);
    channels += co.obstacles.size() == 2;
    EXPECT_DOUBLE_EQ(co.min_obstacle_clearance, kCfg.obstacle_clearance_m);
    for (const auto& o : co.obstacles) {
      EXPECT_GE(obstacleDistance(o, *co.own.goal, *co.own.goal), kCfg.obstacle_clearance_m) << co.name;
      EXPECT_GE(obstacleDistance(o, co.own.position, co.own.position), 1852.0 - 0.2 * 1852.0 - 1.0)
          << co.name;
    }
  }
  EXPECT_EQ(port_turns + stand_ons, 10);
  EXPECT_GT(port_turns, 0);
  EXPECT_GT(stand_ons, 0);
  EXPECT_GT(channels, 0);
  EXPECT_LT(channels, 10);
}

// The families that probe the referee, checked with the hand formulas: the offset head-on passes
// 0.3-0.8 nm off if both hold on; the boundary sweep is 8-35 deg off the reciprocal, on both bows over
// the draws; the starboard side of an occupied head-on holds a ship (or a coast) and a manoeuvre
// without a port turn keeps 0.5 nm; the remote duty is a slow ship ahead, overtaken 0.5-0.9 nm abeam
// after 20-30 min, with a ship crossing from port that gives way.
TEST(ScenarioGen, FamiliesThatProbeTheReferee) {
  const double nm = 1852.0, slack = 5.0;  // rounding of positions, courses and speeds
  int bows[2] = {0, 0}, coasts = 0, anchored = 0;
  for (uint64_t i = 0; i < 10; ++i) {
    const Scenario off = generateScenario(kCfg, SituationClass::OffsetHeadOn, 3, i).scenario;
    ASSERT_EQ(off.targets.size(), 1u);
    const HandCpa c = handCpa(off.own, off.targets[0]);
    EXPECT_GE(c.dcpa, 0.3 * nm - slack) << off.name;
    EXPECT_LE(c.dcpa, 0.8 * nm + slack) << off.name;
    EXPECT_NEAR(courseDiffDeg(off.own, off.targets[0]), 180.0, 6.1) << off.name;

    const Scenario sw = generateScenario(kCfg, SituationClass::HeadOnCrossingBoundary, 3, i).scenario;
    ASSERT_EQ(sw.targets.size(), 1u);
    const double off_reciprocal = courseDiffDeg(sw.own, sw.targets[0]) - 180.0;
    EXPECT_GE(std::fabs(off_reciprocal), 8.0 - 0.1) << sw.name;
    EXPECT_LE(std::fabs(off_reciprocal), 35.0 + 0.1) << sw.name;
    ++bows[off_reciprocal > 0.0];

    const Scenario oc = generateScenario(kCfg, SituationClass::HeadOnStarboardOccupied, 3, i).scenario;
    EXPECT_NEAR(courseDiffDeg(oc.own, oc.targets[0]), 180.0, 6.1) << oc.name;
    if (oc.targets.size() == 2) {
      const double rb = relativeBearingDeg(oc.own, oc.targets[1]);
      EXPECT_GT(rb, 0.0) << oc.name;
      EXPECT_LT(rb, 90.0) << oc.name;  // on the starboard bow
      anchored += oc.targets[1].speed == 0.0;
    } else {
      ASSERT_EQ(oc.obstacles.size(), 1u) << oc.name;
      ++coasts;
    }
    EXPECT_TRUE(manoeuvreExists(oc, 0.0, kCfg.min_separation_m,
                                oc.obstacles.empty() ? 0.0 : kCfg.obstacle_clearance_m, kCfg.check_dt, false))
        << oc.name;

    const Scenario rd = generateScenario(kCfg, SituationClass::StandOnRemoteDuty, 3, i).scenario;
    ASSERT_EQ(rd.targets.size(), 2u);
    EXPECT_GT(relativeBearingDeg(rd.own, rd.targets[0]), 247.5) << rd.name;  // from port, gives way
    EXPECT_EQ(rd.targets[0].behaviour, Behaviour::GiveWay) << rd.name;
    const HandCpa duty = handCpa(rd.own, rd.targets[1]);
    EXPECT_GE(duty.tcpa, 1200.0 - slack) << rd.name;
    EXPECT_LE(duty.tcpa, 1800.0 + slack) << rd.name;
    EXPECT_GE(duty.dcpa, 0.5 * nm - slack) << rd.name;
    EXPECT_LE(duty.dcpa, 0.9 * nm + slack) << rd.name;
    EXPECT_LT(rd.targets[1].speed, rd.own.speed) << rd.name;
  }
  EXPECT_GT(bows[0], 0);
  EXPECT_GT(bows[1], 0);
  EXPECT_GT(coasts, 0);
  EXPECT_GT(anchored, 0);
}

TEST(ScenarioGen, LateGiveWayAndRouteBendFamilies) {
  const double nm = kMetresPerNauticalMile, slack = 1.0;
  int kinds[3] = {0, 0, 0};  // head-on, from port, overtaking the own ship
  int offset_behaviours[3] = {0, 0, 0};
  int bends[2] = {0, 0};  // to port, to starboard
  for (uint64_t i = 0; i < 12; ++i) {
    const Scenario lg = generateScenario(kCfg, SituationClass::LateGiveWay, 5, i).scenario;
    ASSERT_EQ(lg.targets.size(), 1u);
    EXPECT_EQ(lg.targets[0].behaviour, Behaviour::LateGiveWay) << lg.name;
    const double rb = relativeBearingDeg(lg.own, lg.targets[0]);
    const bool head_on = std::fabs(courseDiffDeg(lg.own, lg.targets[0]) - 180.0) <= 6.1;
    ++kinds[head_on ? 0 : rb > 247.5 ? 1 : 2];
    if (!head_on && rb <= 247.5) {
      EXPECT_GT(rb, 112.5) << lg.name;  // abaft the beam: overtaking
    }
    const HandCpa c = handCpa(lg.own, lg.targets[0]);
    EXPECT_LE(c.dcpa, 0.3 * nm + slack) << lg.name;

    const Behaviour b =
        generateScenario(kCfg, SituationClass::OffsetHeadOn, 5, i).scenario.targets[0].behaviour;
    ++offset_behaviours[b == Behaviour::GiveWay ? 0 : b == Behaviour::NonCompliant ? 1 : 2];
    EXPECT_TRUE(b == Behaviour::GiveWay || b == Behaviour::NonCompliant || b == Behaviour::LateGiveWay);

    // The bend: the own ship sails her course to route[0] (5-15 min), then 30-60 deg to either side
    // to route[1]; the target meets her on the second leg as if she had sailed it from the start.
    const Scenario rb_s = generateScenario(kCfg, SituationClass::RouteBendCrossing, 5, i).scenario;
    ASSERT_EQ(rb_s.own.route.size(), 2u) << rb_s.name;
    const Eigen::Vector2d leg1 = rb_s.own.route[0].position - rb_s.own.position;
    const Eigen::Vector2d leg2 = rb_s.own.route[1].position - rb_s.own.route[0].position;
    const double bend_time = leg1.norm() / rb_s.own.speed;
    EXPECT_GE(bend_time, 300.0 - 1.0) << rb_s.name;
    EXPECT_LE(bend_time, 900.0 + 1.0) << rb_s.name;
    EXPECT_NEAR(std::remainder(std::atan2(leg1.x(), leg1.y()) - rb_s.own.course, 2.0 * M_PI), 0.0, 1e-3)
        << rb_s.name;
    ScenarioShip second = rb_s.own;
    second.course = std::atan2(leg2.x(), leg2.y());
    const double turn = std::remainder(radToDeg(second.course - rb_s.own.course), 360.0);
    EXPECT_GE(std::fabs(turn), 30.0 - 0.1) << rb_s.name;
    EXPECT_LE(std::fabs(turn), 60.0 + 0.1) << rb_s.name;
    ++bends[turn > 0.0];
    second.position = rb_s.own.route[0].position - leg2.normalized() * leg1.norm();
    const HandCpa c2 = handCpa(second, rb_s.targets[0]);
    EXPECT_GE(c2.tcpa, bend_time + 300.0 - 2.0) << rb_s.name;
    EXPECT_LE(c2.tcpa, bend_time + 900.0 + 2.0) << rb_s.name;
    EXPECT_LE(c2.dcpa, 0.3 * nm + slack) << rb_s.name;
    EXPECT_EQ(rb_s.own.goal, rb_s.own.route[1].position);
    // No encounter on the first leg: held, it passes the target at 1 nm or more, or its CPA is past
    // or more than 30 min away at every instant before the bend (the hand CPA's time falls by the
    // time sailed).
    const HandCpa c1 = handCpa(rb_s.own, rb_s.targets[0]);
    EXPECT_TRUE(c1.dcpa >= nm - slack || c1.tcpa <= 0.0 || c1.tcpa - bend_time > 1800.0)
        << rb_s.name << ": DCPA " << c1.dcpa << " m at " << c1.tcpa << " s on the first leg";
  }
  for (int k : kinds)
    EXPECT_GT(k, 0);
  for (int k : offset_behaviours)
    EXPECT_GT(k, 0);
  EXPECT_GT(bends[0], 0);
  EXPECT_GT(bends[1], 0);
}

TEST(ScenarioGen, AManoeuvreExistsOnlyWhileThereIsRoomToMakeIt) {
  // Head-on, 8 km apart, closing at 12 m/s (6 + 6). Acting at once, a 30-40 deg turn keeps 926 m. At
  // t = 580 s the range is 8000 - 12 x 580 = 1040 m: nothing can keep 926 m any more.
  const Scenario s = parseScenario(
      "format: 1\nname: t\nduration_s: 1500\nsafety: {min_separation_m: 926}\nown_ship:\n  name: own\n"
      "  position: {x_m: 0, y_m: 0}\n  course_deg: 0\n  speed_mps: 6\n"
      "targets:\n  - {name: a, position: {x_m: 0, y_m: 8000}, course_deg: 180, speed_mps: 6}\n");
  EXPECT_TRUE(manoeuvreExists(s, 0.0, 926.0, 0.0));
  EXPECT_FALSE(manoeuvreExists(s, 580.0, 926.0, 0.0));
  // Keeping 100 m is still possible late: a hard turn at 1040 m.
  EXPECT_TRUE(manoeuvreExists(s, 580.0, 100.0, 0.0));
}

TEST(ScenarioGen, AnImpossibleConfigurationFailsLoudlyAfterItsRedraws) {
  GeneratorConfig cfg;
  cfg.max_redraws = 5;
  cfg.start_range_max_m = 1900.0;  // every target starts farther than this
  EXPECT_THROW(generateScenario(cfg, SituationClass::HeadOn, 1, 0), std::runtime_error);
  cfg.start_range_max_m = 1000.0;  // below twice the minimum separation: refused as a configuration
  EXPECT_THROW(cfg.validate(), std::invalid_argument);
  EXPECT_FALSE(situationClassFromString("crossing"));
  EXPECT_EQ(situationClassFromString("rule_breaker"), SituationClass::RuleBreaker);
}

TEST(ScenarioWrite, ALibraryScenarioSurvivesTheRoundTripWithinItsRounding) {
  const Scenario a =
      loadScenario(std::string(ASV_SOURCE_DIR) + "/asv_bringup/scenarios/crossing_give_way.yaml");
  const Scenario b = parseScenario(scenarioToYaml(a));
  EXPECT_EQ(b.name, a.name);
  EXPECT_EQ(b.description, a.description);
  EXPECT_DOUBLE_EQ(b.duration, a.duration);
  EXPECT_NEAR(b.origin.lat_deg, a.origin.lat_deg, 1e-7);
  ASSERT_EQ(b.targets.size(), a.targets.size());
  EXPECT_NEAR((b.targets[0].position - a.targets[0].position).norm(), 0.0, 0.1);
  EXPECT_NEAR(b.targets[0].course, a.targets[0].course, degToRad(0.05));
  EXPECT_NEAR(b.targets[0].speed, a.targets[0].speed, knotsToMps(0.005));
  EXPECT_NEAR((*b.own.goal - *a.own.goal).norm(), 0.0, 0.1);
  Scenario c = a;
  c.sensor_faults.push_back({});
  EXPECT_THROW(scenarioToYaml(c), std::invalid_argument);
}
