// DSSA / DSSA+ (Hirayama et al. 2019): cost terms against hand computations, the domain, the
// stochastic exchange, determinism and the paper's experiments.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "asv_core/papers/dssa_experiments.h"
#include "asv_core/planning/dssa/dssa.h"
#include "asv_core/risk/cpa.h"

namespace asv {
namespace {

ShipState shipAt(double x, double y, double course_deg, double speed) {
  ShipState s;
  s.position = {x, y};
  s.course = wrapTwoPi(degToRad(course_deg));
  s.heading = s.course;
  s.speed = speed;
  return s;
}

DssaIntention intentionOf(int id, const ShipState& s, double stamp = 0.0) {
  DssaIntention m;
  m.id = id;
  m.stamp = stamp;
  m.course = s.course;
  m.speed = s.speed;
  m.position = s.position;
  m.velocity = s.velocity();
  return m;
}

DssaShipSpeeds speeds(double ref, double min, double max) {
  DssaShipSpeeds s;
  s.ref = ref;
  s.min = min;
  s.max = max;
  return s;
}

// Own ship at the origin heading north at 10 m/s, goal far north: EF of the current heading is 0.
DssaAgent northbound(const DssaConfig& c) {
  DssaAgent a(0, c, speeds(10, 0, 10));
  a.setOwn(shipAt(0, 0, 0, 10), {0, 10000});
  return a;
}

TEST(Dssa, CollisionRiskIsTimeWindowOverTcpaWhenDcpaIsSmall) {
  DssaConfig c = DssaConfig::preset("dssa");
  ASSERT_EQ(c.collision_distance, 40.0);
  DssaAgent a = northbound(c);
  // Head-on at 300 m, closing at 20 m/s: they meet at t = 15 s < TimeWindow, DCPA 0.
  a.receive(intentionOf(1, shipAt(0, 300, 180, 10)));
  EXPECT_NEAR(a.collisionRisk(0, 0), 20.0 / 15.0, 1e-12);
  EXPECT_NEAR(a.inefficiency(0, 0), 0.0, 1e-12);
  EXPECT_NEAR(a.cost(0, 0), 20.0 / 15.0, 1e-12);

  // A 45 deg turn to starboard: the continuous CPA (independent formula) passes wider than the
  // collision distance (40 m).
  const Cpa turned = computeCpa(Eigen::Vector2d(0, 0), courseSpeedToVelocity(degToRad(45), 10),
                                Eigen::Vector2d(0, 300), Eigen::Vector2d(0, -10));
  ASSERT_GT(turned.dcpa, c.collision_distance);
  ASSERT_LT(turned.tcpa, 20.0);
  EXPECT_DOUBLE_EQ(a.collisionRisk(degToRad(45), 0), 0.0);
  EXPECT_NEAR(a.cost(degToRad(45), 0), 45.0 / 180.0, 1e-12);  // alpha = 1

  // A 5 deg turn still passes within 40 m: CR = TimeWindow / TCPA with the CPA of the straight lines.
  const Cpa small = computeCpa(Eigen::Vector2d(0, 0), courseSpeedToVelocity(degToRad(5), 10),
                               Eigen::Vector2d(0, 300), Eigen::Vector2d(0, -10));
  ASSERT_LT(small.dcpa, c.collision_distance);
  EXPECT_NEAR(a.collisionRisk(degToRad(5), 0), 20.0 / small.tcpa, 1e-9);
  EXPECT_NEAR(a.cost(degToRad(5), 0), 20.0 / small.tcpa + 5.0 / 180.0, 1e-9);
}

TEST(Dssa, CollisionBeyondTheWindowCountsAtTcpaEqualToTheWindow) {
  DssaAgent a = northbound(DssaConfig::preset("dssa"));
  // Overtaking a ship 30 m ahead that makes 9 m/s: the CPA (t = 30 s) lies beyond the 20 s window, so
  // TCPA = TimeWindow (appendix rule 1) and DCPA is the distance at the window's end: 30 - 20 = 10 m.
  a.receive(intentionOf(1, shipAt(0, 30, 0, 9)));
  EXPECT_NEAR(a.collisionRisk(0, 0), 1.0, 1e-12);
  // Far ahead (1 km) the same overtaking leaves 980 m at the window's end: no collision.
  DssaAgent b = northbound(DssaConfig::preset("dssa"));
  b.receive(intentionOf(1, shipAt(0, 1000, 0, 9)));
  EXPECT_DOUBLE_EQ(b.collisionRisk(0, 0), 0.0);
}

TEST(Dssa, DivergingShipsAndTheTcpaGuards) {
  DssaConfig c = DssaConfig::preset("dssa");
  // 20 m apart (inside the collision distance) but separating: TCPA = 0, no collision ahead.
  DssaAgent a = northbound(c);
  a.receive(intentionOf(1, shipAt(0, -20, 180, 10)));
  EXPECT_DOUBLE_EQ(a.collisionRisk(0, 0), 0.0);
  // 0.1 m apart and closing at 20 m/s: TCPA = 5 ms, below the 10 ms floor, so CR = 20 / 0.01.
  DssaAgent b = northbound(c);
  b.receive(intentionOf(1, shipAt(0, 0.1, 180, 10)));
  EXPECT_NEAR(b.collisionRisk(0, 0), 2000.0, 1e-9);
  // Outside the detection range (500 m) a ship is no neighbour, whatever its course.
  DssaAgent d = northbound(c);
  // (Closing at 30 m/s they would meet after 16.7 s, inside the window.)
  d.receive(intentionOf(1, shipAt(0, 501, 180, 20)));
  EXPECT_EQ(d.neighbourCount(), 0);
  EXPECT_DOUBLE_EQ(d.collisionRisk(0, 0), 0.0);
  d.receive(intentionOf(2, shipAt(0, 499, 180, 20)));
  EXPECT_EQ(d.neighbourCount(), 1);
  EXPECT_GT(d.collisionRisk(0, 0), 0.0);
  d.forget(2);
  EXPECT_EQ(d.neighbourCount(), 0);
}

TEST(Dssa, DomainAndDestinationCourse) {
  const DssaConfig c = DssaConfig::preset("dssa");
  DssaAgent a(0, c, speeds(10, 0, 10));
  // Goal 30 deg to starboard: crs_dest is on the 5 deg grid, 19 courses.
  a.setOwn(shipAt(0, 0, 0, 10), {1000 * std::sin(degToRad(30)), 1000 * std::cos(degToRad(30))});
  EXPECT_NEAR(radToDeg(a.destinationCourseChange()), 30.0, 1e-9);
  EXPECT_EQ(a.domainSize(), 19);
  // Goal 32 deg: crs_dest joins the domain (20 courses, "at most 20", Sec. 4).
  a.setOwn(shipAt(0, 0, 0, 10), {1000 * std::sin(degToRad(32)), 1000 * std::cos(degToRad(32))});
  EXPECT_EQ(a.domainSize(), 20);
  // Goal 60 deg: outside +-45, not in the domain; the best is the 45 deg turn with EF = 15/180.
  a.setOwn(shipAt(0, 0, 0, 10), {1000 * std::sin(degToRad(60)), 1000 * std::cos(degToRad(60))});
  EXPECT_EQ(a.domainSize(), 19);
  EXPECT_NEAR(a.inefficiency(degToRad(45), 0), 15.0 / 180.0, 1e-12);
  std::mt19937_64 rng(1);
  const DssaIntention in = a.decide(1, rng);  // no neighbour: taken directly
  EXPECT_NEAR(radToDeg(in.course), 45.0, 1e-9);
  EXPECT_TRUE(a.changed());
  // Across north: heading 350 deg, goal at 10 deg true is 20 deg to starboard, EF measured the short way.
  a.setOwn(shipAt(0, 0, 350, 10), {1000 * std::sin(degToRad(10)), 1000 * std::cos(degToRad(10))});
  EXPECT_NEAR(radToDeg(a.destinationCourseChange()), 20.0, 1e-9);
  EXPECT_NEAR(a.inefficiency(0, 0), 20.0 / 180.0, 1e-12);
  EXPECT_NEAR(a.inefficiency(degToRad(-45), 0), 65.0 / 180.0, 1e-12);
  // The goal astern: EF = alpha exactly (180 deg).
  a.setOwn(shipAt(0, 0, 0, 10), {0, -1000});
  EXPECT_NEAR(a.inefficiency(0, 0), 1.0, 1e-12);

  // DSSA+: 9 speed changes per course, up to 180 pairs (Sec. 4).
  DssaAgent p(0, DssaConfig::preset("dssa_plus_sc"), speeds(10, 0, 10));
  p.setOwn(shipAt(0, 0, 0, 10), {1000 * std::sin(degToRad(32)), 1000 * std::cos(degToRad(32))});
  EXPECT_EQ(p.domainSize(), 180);
}

TEST(Dssa, SpeedInefficiencyClampsToMinAndMaxSpeed) {
  DssaConfig c = DssaConfig::preset("dssa_plus_eq");  // alpha = beta = 1
  DssaAgent a(0, c, speeds(25, 5, 30));
  a.setOwn(shipAt(0, 0, 0, 20), {0, 10000});
  // |min(max(20 + spc, 5), 30) - 25| / 30.
  EXPECT_NEAR(a.inefficiency(0, 0), 5.0 / 30.0, 1e-12);
  EXPECT_NEAR(a.inefficiency(0, 4), 1.0 / 30.0, 1e-12);
  EXPECT_NEAR(a.inefficiency(0, 8), 3.0 / 30.0, 1e-12);    // 28
  EXPECT_NEAR(a.inefficiency(0, -8), 13.0 / 30.0, 1e-12);  // 12
  a.setOwn(shipAt(0, 0, 0, 6), {0, 10000});
  EXPECT_NEAR(a.inefficiency(0, -8), 20.0 / 30.0, 1e-12);  // clamped to MinSPD 5
  a.setOwn(shipAt(0, 0, 0, 28), {0, 10000});
  EXPECT_NEAR(a.inefficiency(0, 8), 5.0 / 30.0, 1e-12);  // clamped to MaxSPD 30
  // Alone, the ship goes for the reference speed: +2 at 28 would give 30 (clamped), -2 gives 26, -4
  // gives 24 (EF 1/30 each): ties go to slowing first, the earlier domain entry.
  std::mt19937_64 rng(1);
  const DssaIntention in = a.decide(1, rng);
  EXPECT_DOUBLE_EQ(in.speed_change, -2.0);
  EXPECT_DOUBLE_EQ(in.speed, 26.0);
  // The intended speed is clamped too: from 6, -8 is 5, never below MinSPD.
  DssaConfig s = c;
  s.beta = 0.0;  // make the speed free so that only collision risk chooses
  DssaAgent b(0, s, speeds(25, 5, 30));
  b.setOwn(shipAt(0, 0, 0, 6), {0, 10000});
  EXPECT_NEAR(b.collisionRisk(0, -8), b.collisionRisk(0, -1), 1e-12);  // both sail at 5 m/s

  // DSSA ignores beta and keeps the speed.
  DssaAgent d(0, DssaConfig::preset("dssa"), speeds(25, 5, 30));
  d.setOwn(shipAt(0, 0, 0, 20), {0, 10000});
  EXPECT_NEAR(d.inefficiency(0, 0), 0.0, 1e-12);
  EXPECT_EQ(d.domainSize(), 19);
}

TEST(Dssa, DecideTakesTheMinimumCostOfTheDomain) {
  DssaConfig c = DssaConfig::preset("dssa_plus_eq");
  c.p = 1.0;
  DssaAgent a(0, c, speeds(10, 0, 10));
  a.setOwn(shipAt(0, 0, 0, 10), {0, 10000});
  a.receive(intentionOf(1, shipAt(0, 300, 180, 10)));
  a.receive(intentionOf(2, shipAt(150, 150, 270, 10)));
  // Brute force over the grid (crs_dest = 0 is on it here).
  double best = 1e300;
  for (int k = -9; k <= 9; ++k)
    for (int s = -4; s <= 4; ++s)
      best = std::min(best, a.cost(degToRad(5.0 * k), 2.0 * s));
  const double before = a.cost(0, 0);
  ASSERT_GT(before, best);
  std::mt19937_64 rng(7);
  const DssaIntention in = a.decide(1, rng);
  EXPECT_TRUE(a.changed());
  EXPECT_FALSE(a.satisfied());
  EXPECT_NEAR(a.improvement(), before - best, 1e-9);
  EXPECT_NEAR(a.cost(wrapPi(in.course), in.speed_change), best, 1e-9);
  // Nothing changed around it: the next round it is satisfied and keeps the intention.
  const DssaIntention again = a.decide(2, rng);
  EXPECT_TRUE(a.satisfied());
  EXPECT_FALSE(a.changed());
  EXPECT_DOUBLE_EQ(again.course, in.course);
  EXPECT_TRUE(again.satisfied);
  EXPECT_EQ(again.round, 2);
}

TEST(Dssa, StochasticUpdateHappensWithProbabilityP) {
  // Independent draws: a ship with a positive improvement adopts new_intention with probability p.
  DssaConfig c = DssaConfig::preset("dssa");
  c.p = 0.3;
  int adopted = 0;
  const int n = 4000;
  std::mt19937_64 rng(11);
  for (int k = 0; k < n; ++k) {
    DssaAgent a = northbound(c);
    a.receive(intentionOf(1, shipAt(0, 300, 180, 10)));
    a.decide(1, rng);
    adopted += a.changed() ? 1 : 0;
  }
  EXPECT_NEAR(static_cast<double>(adopted) / n, 0.3, 0.03);  // > 4 sigma
}

std::vector<DssaAgent> agentsFor(const std::vector<ShipState>& s, const std::vector<Eigen::Vector2d>& goals,
                                 const DssaConfig& c) {
  std::vector<DssaAgent> out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    out.emplace_back(static_cast<int>(i), c, speeds(s[i].speed, 0, s[i].speed));
    out.back().setOwn(s[i], goals[i]);
  }
  return out;
}

TEST(DssaExchange, TriviallySafeSituationIsQuiescentInTheFirstRound) {
  const DssaConfig c = DssaConfig::preset("dssa_plus_sc");
  // Two ships 200 m apart on parallel courses, each heading straight for her goal.
  auto agents = agentsFor({shipAt(0, 0, 0, 10), shipAt(200, 0, 0, 10)}, {{0, 5000}, {200, 5000}}, c);
  std::vector<std::mt19937_64> rngs{std::mt19937_64(1), std::mt19937_64(2)};
  const DssaExchange::Result r = DssaExchange(c).run(agents, rngs);
  EXPECT_TRUE(r.quiescent);
  EXPECT_EQ(r.rounds, 1);
  EXPECT_EQ(r.messages, 2);  // round 0 only
  for (const auto& a : agents) {
    EXPECT_FALSE(a.changed());
    EXPECT_TRUE(a.satisfied());
    EXPECT_DOUBLE_EQ(a.intention().course, 0.0);
    EXPECT_DOUBLE_EQ(a.intention().speed, 10.0);
  }
}

TEST(DssaExchange, HeadOnPairResolvesWithoutPredictedCollision) {
  const DssaConfig c = DssaConfig::preset("dssa");
  auto agents = agentsFor({shipAt(0, 0, 0, 10), shipAt(0, 300, 180, 10)}, {{0, 5000}, {0, -5000}}, c);
  std::vector<std::mt19937_64> rngs{std::mt19937_64(dssaAgentSeed(3, 0)),
                                    std::mt19937_64(dssaAgentSeed(3, 1))};
  const DssaExchange::Result r = DssaExchange(c).run(agents, rngs);
  ASSERT_TRUE(r.quiescent);
  const WindowedCpa w = windowedCpa(
      agents[0].position(), agents[0].position() + agents[0].intention().intendedVelocity() * 20.0,
      agents[1].position(), agents[1].position() + agents[1].intention().intendedVelocity() * 20.0, 20.0);
  EXPECT_GE(w.dcpa, c.collision_distance);
}

TEST(DssaExchange, DroppedMessageLeavesTheLastKnownIntention) {
  DssaConfig c = DssaConfig::preset("dssa");
  c.p = 1.0;
  // Ship 1 meets ship 0 head-on but is bound 30 deg to starboard of her heading, so her intention
  // after the first round differs from her initial one whatever ship 0 does.
  const ShipState s0 = shipAt(0, 0, 0, 10), s1 = shipAt(0, 300, 180, 10);
  const Eigen::Vector2d g1(-5000 * std::sin(degToRad(30)), 300 - 5000 * std::cos(degToRad(30)));
  auto agents = agentsFor({s0, s1}, {{0, 5000}, g1}, c);
  std::vector<std::mt19937_64> rngs{std::mt19937_64(1), std::mt19937_64(2)};
  DssaExchange x(c);
  // Every message of ship 1 to ship 0 after round 0 is lost: ship 0 keeps ship 1's initial intention.
  x.setDropFilter([](int round, int from, int to) { return round > 0 && from == 1 && to == 0; });
  x.run(agents, rngs);
  ASSERT_GT(std::fabs(wrapPi(agents[1].intention().course - s1.course)), degToRad(4));  // ship 1 turned

  DssaAgent reference(0, c, speeds(10, 0, 10));
  reference.setOwn(s0, {0, 5000});
  reference.receive(intentionOf(1, s1));  // what ship 0 last heard
  const double crs = wrapPi(agents[0].intention().course);
  EXPECT_NEAR(agents[0].collisionRisk(crs, 0), reference.collisionRisk(crs, 0), 1e-12);
  // And it differs from what ship 1 really intends, which ship 0 never heard.
  DssaAgent informed(0, c, speeds(10, 0, 10));
  informed.setOwn(s0, {0, 5000});
  informed.receive(agents[1].intention());
  EXPECT_NE(informed.collisionRisk(0, 0), reference.collisionRisk(0, 0));
}

TEST(DssaAgent, StaleIntentionIsCarriedForwardAndOlderMessagesIgnored) {
  const DssaConfig c = DssaConfig::preset("dssa");
  DssaAgent a(0, c, speeds(10, 0, 10));
  // Heard at t = 0: 500 m ahead, heading south at 10 m/s. At t = 10 s it is taken 400 m ahead, so the
  // head-on meeting comes after 200 / 20 = 10 s: CR = 20 / 10 (it would be 20 / 15 taken at 300 m).
  a.receive(intentionOf(1, shipAt(0, 500, 180, 10), 0.0));
  a.setOwn(shipAt(0, 200, 0, 10), {0, 10000}, 10.0);
  EXPECT_NEAR(a.collisionRisk(0, 0), 2.0, 1e-12);
  // An older message (stamp -5) does not replace it.
  a.receive(intentionOf(1, shipAt(0, 5000, 180, 10), -5.0));
  EXPECT_NEAR(a.collisionRisk(0, 0), 2.0, 1e-12);
  // Own messages are ignored.
  a.receive(intentionOf(0, shipAt(0, 210, 180, 10), 10.0));
  EXPECT_EQ(a.neighbourCount(), 1);
}

TEST(Dssa, SameSeedSameRunDifferentSeedDifferentRun) {
  const DssaScenario sc = dssaSixteenShipScenario();
  const DssaConfig c = DssaConfig::preset("dssa_plus_sc");
  DssaSimOptions o;
  o.record_trajectories = true;
  const DssaRunResult a = runDssaSimulation(sc, c, 42, o);
  const DssaRunResult b = runDssaSimulation(sc, c, 42, o);
  const DssaRunResult d = runDssaSimulation(sc, c, 43, o);
  ASSERT_EQ(a.ships.size(), 16u);
  bool differs = false;
  for (std::size_t i = 0; i < a.ships.size(); ++i) {
    ASSERT_EQ(a.ships[i].trajectory.size(), b.ships[i].trajectory.size());
    for (std::size_t k = 0; k < a.ships[i].trajectory.size(); ++k)
      EXPECT_EQ(a.ships[i].trajectory[k], b.ships[i].trajectory[k]);
    differs = differs || a.ships[i].trajectory != d.ships[i].trajectory;
  }
  EXPECT_EQ(a.total_path_length, b.total_path_length);
  EXPECT_TRUE(differs);
}

TEST(DssaConfig, PresetsParamsAndValidation) {
  const DssaConfig sc = DssaConfig::preset("dssa_plus_sc");
  const DssaConfig cs = DssaConfig::preset("dssa_plus_cs");
  const DssaConfig eq = DssaConfig::preset("dssa_plus_eq");
  const DssaConfig d = DssaConfig::preset("dssa");
  EXPECT_FALSE(d.speed_changes);
  EXPECT_TRUE(sc.speed_changes && cs.speed_changes && eq.speed_changes);
  EXPECT_NEAR(sc.alpha, 10.0 * sc.beta, 1e-12);
  EXPECT_NEAR(cs.beta, 10.0 * cs.alpha, 1e-12);
  EXPECT_EQ(eq.alpha, eq.beta);
  for (const auto& n : DssaConfig::presetNames()) {
    const DssaConfig c = DssaConfig::preset(n);
    EXPECT_EQ(c.p, 0.8);
    EXPECT_EQ(c.time_window, 20.0);
    EXPECT_EQ(c.detection_range, 500.0);
    EXPECT_NO_THROW(c.validate());
  }
  EXPECT_THROW(DssaConfig::preset("dssa_plus_fast"), std::invalid_argument);

  ParamMap p;
  p.set("preset", "dssa_plus_cs");
  p.set("p", 0.5);
  p.set("course_change_max_deg", 30.0);
  const DssaConfig c = DssaConfig::fromParams(p);
  EXPECT_TRUE(c.speed_changes);
  EXPECT_EQ(c.beta, cs.beta);
  EXPECT_EQ(c.p, 0.5);
  EXPECT_NEAR(c.course_change_max, degToRad(30.0), 1e-12);
  ParamMap bad;
  bad.set("alpah", 1.0);
  EXPECT_THROW(DssaConfig::fromParams(bad), std::invalid_argument);
  ParamMap badp;
  badp.set("p", 1.5);
  EXPECT_THROW(DssaConfig::fromParams(badp), std::invalid_argument);
  DssaConfig z;
  z.time_window = 0.0;
  EXPECT_THROW(z.validate(), std::invalid_argument);
}

TEST(DssaConfig, ShipSpeedsFromTheConfigAndTheHostLimits) {
  DssaConfig c;
  // Host limit only: RefSPD the cruise speed, MaxSPD the limit.
  DssaShipSpeeds s = dssaShipSpeeds(c, 7.0, 1.0, 10.0);
  EXPECT_DOUBLE_EQ(s.ref, 7.0);
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 10.0);
  // A cruise speed above the limit is planned at the limit; a ship at rest at the limit.
  EXPECT_DOUBLE_EQ(dssaShipSpeeds(c, 12.0, 0.0, 10.0).ref, 10.0);
  EXPECT_DOUBLE_EQ(dssaShipSpeeds(c, 0.0, 0.0, 10.0).ref, 10.0);
  // The experiments' MaxSPD = RefSPD + 8, per ship (Table 3's ships: 25, 10, 5).
  c.max_speed_over_ref = 8.0;
  EXPECT_DOUBLE_EQ(dssaShipSpeeds(c, 25.0, 0.0, 10.0).max, 33.0);
  EXPECT_DOUBLE_EQ(dssaShipSpeeds(c, 5.0, 0.0, 10.0).max, 13.0);
  EXPECT_DOUBLE_EQ(dssaShipSpeeds(c, 5.0, 0.0, 10.0).ref, 5.0);
  // ref_speed overrides the cruise speed.
  c.ref_speed = 20.0;
  s = dssaShipSpeeds(c, 5.0, 0.0, 10.0);
  EXPECT_DOUBLE_EQ(s.ref, 20.0);
  EXPECT_DOUBLE_EQ(s.max, 28.0);
  ParamMap p;
  p.set("max_speed_over_ref", "nan");
  EXPECT_THROW(DssaConfig::fromParams(p), std::invalid_argument);
}

TEST(DssaConfig, MinSpeedIsAFractionOfTheReferenceSpeed) {
  // The experiments' MinSPD = RefSPD / 2: 12.5 for the 25 (above the 10 it must overtake, Sec. 5.3),
  // 5 for the 10, 2.5 for the 5; never below the host's own limit.
  ParamMap p;
  p.set("preset", "dssa_plus");
  p.set("min_speed_fraction", 0.5);
  p.set("max_speed_over_ref", 8.0);
  const DssaConfig c = DssaConfig::fromParams(p);
  EXPECT_DOUBLE_EQ(dssaShipSpeeds(c, 25.0, 0.0, 10.0).min, 12.5);
  EXPECT_DOUBLE_EQ(dssaShipSpeeds(c, 10.0, 0.0, 10.0).min, 5.0);
  EXPECT_DOUBLE_EQ(dssaShipSpeeds(c, 5.0, 0.0, 10.0).min, 2.5);
  EXPECT_DOUBLE_EQ(dssaShipSpeeds(c, 25.0, 15.0, 10.0).min, 15.0);
  EXPECT_DOUBLE_EQ(dssaShipSpeeds(DssaConfig{}, 25.0, 0.0, 30.0).min, 0.0) << "default: the host's limit";
  // A ship at MinSPD cannot slow further: -8 from 14 is clamped to 12.5 (Sec. 4's clamp).
  DssaAgent a(0, c, dssaShipSpeeds(c, 25.0, 0.0, 10.0));
  a.setOwn(shipAt(0, 0, 0, 14), {0, 10000});
  EXPECT_NEAR(a.inefficiency(0, -8.0), 1.0 * (25.0 - 12.5) / 33.0, 1e-12);  // beta 1 (dssa_plus), MaxSPD 33
  p.set("min_speed_fraction", 1.5);
  EXPECT_THROW(DssaConfig::fromParams(p), std::invalid_argument);
}

TEST(DssaPlanner, AvoidsAConstantVelocityTargetDeterministically) {
  DssaPlanner planner("dssa_plus");
  EXPECT_EQ(planner.name(), "dssa_plus");
  DssaPlanner course_only;
  EXPECT_EQ(course_only.name(), "dssa");
  PlanningProblem pb;
  pb.own = shipAt(0, 0, 0, 10);
  pb.limits.max_speed = 10;
  pb.limits.min_speed = 0;
  pb.goal = {0, 10000};
  pb.time_budget = 60.0;  // planned to completion, however slow the machine
  PlannerTarget t;
  t.state = shipAt(0, 300, 180, 10);
  pb.targets.push_back(t);
  pb.seed = 5;
  const Plan a = planner.plan(pb);
  const Plan b = planner.plan(pb);
  EXPECT_EQ(a.status, PlanStatus::Ok);
  EXPECT_EQ(a.course_setpoint, b.course_setpoint);
  EXPECT_EQ(a.speed_setpoint, b.speed_setpoint);
  // The chosen set-points keep the target outside the collision distance over the window.
  const WindowedCpa w = windowedCpa(
      pb.own.position, pb.own.position + courseSpeedToVelocity(a.course_setpoint, a.speed_setpoint) * 20.0,
      t.state.position, t.state.position + t.state.velocity() * 20.0, 20.0);
  EXPECT_GE(w.dcpa, planner.config().collision_distance);
  ASSERT_EQ(a.waypoints.size(), 2u);
  EXPECT_NEAR((a.waypoints[1].position - pb.own.position).norm(), a.speed_setpoint * 20.0, 1e-9);
  // No target: straight for the goal at the reference speed (RefSPD: the own planning speed), cost 0.
  pb.targets.clear();
  pb.goal = {1000 * std::sin(degToRad(20)), 1000 * std::cos(degToRad(20))};
  pb.own.speed = 6;
  const Plan c = planner.plan(pb);
  EXPECT_NEAR(radToDeg(c.course_setpoint), 20.0, 1e-9);
  EXPECT_DOUBLE_EQ(c.speed_setpoint, 6.0);
  EXPECT_NEAR(c.cost, 0.0, 1e-12);
  ParamMap bad;
  bad.set("nonsense", 1.0);
  EXPECT_THROW(planner.configure(bad), std::invalid_argument);
}

TEST(DssaExperiments, TwoShipsPaperTable1) {
  // Table 1: with speed changes preferred (s>c) neither ship detours; DSSA pushes one ship out.
  const DssaScenario sc = dssaTwoShipScenario();
  EXPECT_NEAR((sc.ships[0].goal - sc.ships[0].start).norm(), 492.4, 0.05);
  const DssaExperimentSummary plus = runDssaExperiment(sc, "dssa_plus_sc", 5, 1);
  EXPECT_EQ(plus.successes, 5);
  EXPECT_NEAR(plus.detour_rate, 1.0, 0.01);
  const DssaExperimentSummary dssa = runDssaExperiment(sc, "dssa", 5, 1);
  EXPECT_EQ(dssa.successes, 5);
  EXPECT_GT(dssa.detour_rate, 1.05);
  EXPECT_GE(dssa.min_separation, DssaConfig::preset("dssa").collision_distance);
}

TEST(DssaExperiments, SimulationMetricsFollowThePaperDefinitions) {
  // One ship alone on a 100 m leg at 25 m/s: 4 moves, no detour, travel time 4 s.
  DssaScenario sc;
  sc.name = "alone";
  DssaSimShip s;
  s.start = {0, 0};
  s.goal = {0, 100};
  s.speeds = speeds(25, 0, 25);
  sc.ships = {s};
  const DssaRunResult r = runDssaSimulation(sc, DssaConfig::preset("dssa_plus_sc"), 1);
  EXPECT_TRUE(r.success);
  EXPECT_NEAR(r.total_path_length, 100.0, 1e-9);
  EXPECT_NEAR(r.mean_travel_time, 4.0, 1e-9);
  EXPECT_NEAR(r.mean_detour_rate, 1.0, 1e-12);
  EXPECT_EQ(r.search_phases, 0);
}

}  // namespace
}  // namespace asv
