// Tests of the ACO planner of Lazarowska (2015) and of the paper's two scenarios. Safety is checked
// independently of the planner's own (exact, clipping-based) leg test: the planned trajectory is
// sampled every second against HexagonDomain::contains and pointInPolygon.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>

#include "asv_core/eval/evaluation.h"
#include "asv_core/papers/lazarowska_scenarios.h"
#include "asv_core/planning/aco/aco_planner.h"
#include "planner_target.h"

using namespace asv;

namespace {

PlanningProblem openSea(double own_course_deg, double speed, const Eigen::Vector2d& goal) {
  PlanningProblem p;
  p.own.id = "own";
  p.own.course = p.own.heading = degToRad(own_course_deg);
  p.own.speed = speed;
  p.limits.max_speed = speed;
  p.goal = goal;
  p.time_budget = 30.0;
  return p;
}

PlannerTarget target(const std::string& id, const Eigen::Vector2d& pos, double course_deg, double speed) {
  return plannerTarget(id, pos, course_deg, speed);
}

StaticObstacle box(const std::string& name, double x0, double y0, double x1, double y1) {
  return {name, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

// Own-ship position at time t by linear interpolation between the timed waypoints.
Eigen::Vector2d positionAt(const Plan& plan, double t) {
  const auto& w = plan.waypoints;
  for (size_t i = 1; i < w.size(); ++i)
    if (t <= w[i].time) {
      const double f = (t - w[i - 1].time) / (w[i].time - w[i - 1].time);
      return w[i - 1].position + f * (w[i].position - w[i - 1].position);
    }
  return w.back().position;
}

// Number of 1 s samples of the plan inside some target's hexagon (paper dimensions) or obstacle.
int violations(const Plan& plan, const PlanningProblem& p) {
  const HexagonDomain hex;
  int bad = 0;
  for (double t = 0.0; t <= plan.waypoints.back().time; t += 1.0) {
    const Eigen::Vector2d own = positionAt(plan, t);
    for (const auto& tg : p.targets)
      bad += hex.contains(tg.state.position + tg.state.velocity() * t, tg.state.course, own);
    for (const auto& o : p.obstacles)
      bad += pointInPolygon(o.polygon, own);
  }
  return bad;
}

// Course alterations [deg], positive to starboard, from the present course through every leg.
std::vector<double> alterationsDeg(const Plan& plan) {
  std::vector<double> out;
  for (size_t i = 1; i + 1 < plan.waypoints.size(); ++i)
    out.push_back(radToDeg(wrapPi(plan.waypoints[i + 1].course - plan.waypoints[i].course)));
  return out;
}

std::string coursesDeg(const Plan& plan) {
  std::string s;
  for (size_t i = 0; i < plan.waypoints.size(); ++i) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%s%03.0f", i ? " -> " : "",
                  radToDeg(wrapTwoPi(plan.waypoints[i].course)));
    s += buf;
  }
  return s;
}

double pathLength(const Plan& plan) {
  double l = 0.0;
  for (size_t i = 1; i < plan.waypoints.size(); ++i)
    l += (plan.waypoints[i].position - plan.waypoints[i - 1].position).norm();
  return l;
}

// Head-on: a target 6 nm dead ahead on the reciprocal course, final waypoint 12 nm ahead.
PlanningProblem headOn() {
  PlanningProblem p = openSea(0.0, 6.0, {0.0, nmToMetres(12.0)});
  p.targets.push_back(target("ts", {0.0, nmToMetres(6.0)}, 180.0, 6.0));
  return p;
}

// Eq. (6) written out independently of the planner.
double eq6(double dpsi, const OwnShipLimits& l) {
  return l.turn_delay + std::abs(dpsi) / l.turn_rate - std::tan(std::abs(dpsi) / 2.0) / l.turn_rate;
}

}  // namespace

TEST(AcoConfig, DefaultsAreThePapers) {
  const AcoConfig c;
  EXPECT_DOUBLE_EQ(c.tau0, 1.0);
  EXPECT_DOUBLE_EQ(c.rho, 0.1);
  EXPECT_DOUBLE_EQ(c.alpha, 1.0);
  EXPECT_DOUBLE_EQ(c.beta, 1.0);
  EXPECT_EQ(c.iterations, 20);
  EXPECT_EQ(c.ants, 10);
  EXPECT_NEAR(c.domain.a, 1852.0, 1e-9);
  EXPECT_NEAR(c.domain.b, 0.6 * 1852.0, 1e-9);
  EXPECT_NEAR(c.domain.c, 0.6 * 1852.0, 1e-9);
  EXPECT_NEAR(c.domain.d, 0.25 * 1852.0, 1e-9);
  EXPECT_NEAR(c.domain.e, 0.25 * 1852.0, 1e-9);
  EXPECT_NO_THROW(c.validate());
  EXPECT_EQ(AcoPlanner().name(), "aco");
}

TEST(AcoConfig, PaperModeIsTheSquareGridWithLongEdgesAndThePrintedStep3) {
  ParamMap pm;
  pm.set("mode", "paper");
  const AcoConfig paper = AcoConfig::fromParams(pm);
  EXPECT_NEAR(paper.row_spacing, 0.75 * 1852.0, 1e-9);  // wp_e 6.75 nm / 9 cells
  EXPECT_NEAR(paper.column_spacing, paper.row_spacing, 1e-9);
  EXPECT_EQ(paper.lateral_steps, 1);
  EXPECT_TRUE(paper.long_edges);
  EXPECT_TRUE(paper.danger_by_course);
  EXPECT_FALSE(paper.smooth);
  const AcoConfig sea;
  EXPECT_FALSE(sea.long_edges);
  EXPECT_FALSE(sea.danger_by_course);
  pm.set("lateral_steps", 5.0);  // long edges of 32 rows x 5 columns: too wide a neighbourhood
  EXPECT_THROW(AcoConfig::fromParams(pm), std::invalid_argument);
  pm.set("long_edges", "false");
  EXPECT_FALSE(AcoConfig::fromParams(pm).long_edges);  // the keys override the mode
  EXPECT_EQ(AcoConfig::fromParams(pm).lateral_steps, 5);
}

TEST(AcoConfig, FromParamsConvertsUnitsAndRejectsUnknownKeys) {
  ParamMap pm;
  pm.set("ants", 5.0);
  pm.set("min_first_alteration_deg", 30.0);
  pm.set("row_spacing_m", 500.0);
  pm.set("smooth", "false");
  const AcoConfig c = AcoConfig::fromParams(pm);
  EXPECT_EQ(c.ants, 5);
  EXPECT_NEAR(c.min_first_alteration, kPi / 6.0, 1e-12);
  // The sea default is 30 deg, the evaluator's readily apparent alteration (EvaluationConfig).
  EXPECT_NEAR(AcoConfig().min_first_alteration, degToRad(EvaluationConfig().apparent_course_deg), 1e-12);
  EXPECT_DOUBLE_EQ(c.row_spacing, 500.0);
  EXPECT_FALSE(c.smooth);

  ParamMap typo;
  typo.set("antz", 5.0);
  EXPECT_THROW(AcoConfig::fromParams(typo), std::invalid_argument);
  ParamMap bad;
  bad.set("rho", 0.0);
  EXPECT_THROW(AcoConfig::fromParams(bad), std::invalid_argument);
  ParamMap bad2;
  bad2.set("lateral_steps", 0.0);
  EXPECT_THROW(AcoConfig::fromParams(bad2), std::invalid_argument);
  AcoPlanner planner;
  EXPECT_THROW(planner.configure(typo), std::invalid_argument);
}

TEST(AcoGraph, ExcludesObstacleVerticesAndDomainVerticesInTime) {
  PlanningProblem p = openSea(0.0, 5.0, {0.0, 12000.0});
  p.obstacles.push_back(box("islet", -1000.0, 5000.0, 600.0, 6500.0));
  // A target crossing west to east through the middle of the lattice.
  p.targets.push_back(target("ts", {-4000.0, 3000.0}, 90.0, 5.0));
  const AcoConfig cfg;
  const AcoEnvironment env(p, cfg.domain);
  const AcoGraph g(p, cfg, env);
  ASSERT_GT(g.rows(), 2);
  EXPECT_EQ(g.position(g.startId()), p.own.position);
  EXPECT_EQ(g.position(g.goalId()), p.goal);
  int inside = 0, excluded_inside = 0;
  for (int v = 0; v < g.vertexCount(); ++v)
    if (pointInPolygon(p.obstacles[0].polygon, g.position(v))) {
      ++inside;
      excluded_inside += !g.inGraph(v);
    }
  EXPECT_GT(inside, 4);
  EXPECT_EQ(excluded_inside, inside);
  // Free water right next to the own ship stays in the graph.
  EXPECT_TRUE(g.inGraph(g.id(1, 0)));
  EXPECT_TRUE(g.inGraph(g.id(2, 1)));

  // Domains: a vertex is usable at time t exactly when it is in the graph and outside the hexagon of
  // the target where the target is at t.
  const HexagonDomain hex;
  for (double t : {0.0, 300.0, 800.0}) {
    const Eigen::Vector2d centre = p.targets[0].state.position + p.targets[0].state.velocity() * t;
    int in_domain = 0;
    for (int v = 0; v < g.vertexCount(); ++v) {
      const bool dom = hex.contains(centre, p.targets[0].state.course, g.position(v));
      in_domain += dom && g.inGraph(v);
      EXPECT_EQ(g.vertexFreeAt(v, t, env), g.inGraph(v) && !dom) << "vertex " << v << " t " << t;
    }
    if (t == 800.0) {
      EXPECT_GT(in_domain, 0);  // the domain does sweep over graph vertices
    }
  }
}

TEST(AcoEnvironment, LegCheckSeesADomainCrossedBetweenVertices) {
  // Own leg (0, 0) at t = 0 -> (0, 4000) at t = 800; a target running west along y = 2000 at 10 m/s is
  // on the own ship at t = 400, mid-leg, while both ends are well clear of its domain.
  PlanningProblem p = openSea(0.0, 5.0, {0.0, 10000.0});
  p.targets.push_back(target("ts", {4000.0, 2000.0}, 270.0, 10.0));
  const AcoEnvironment env(p, HexagonDomainConfig{});
  const Eigen::Vector2d a(0.0, 0.0), b(0.0, 4000.0);
  const HexagonDomain hex;
  EXPECT_FALSE(hex.contains({4000.0, 2000.0}, degToRad(270.0), a));
  EXPECT_FALSE(hex.contains({-4000.0, 2000.0}, degToRad(270.0), b));
  EXPECT_TRUE(env.pointDynamicFree(a, 0.0));
  EXPECT_TRUE(env.pointDynamicFree(b, 800.0));
  EXPECT_FALSE(env.pointDynamicFree({0.0, 2000.0}, 400.0));
  EXPECT_FALSE(env.segmentDynamicFree(a, 0.0, b, 800.0));
  EXPECT_FALSE(env.segmentHitsTarget(0, a, 3600.0, b, 4400.0));  // an hour later: long gone
  EXPECT_TRUE(env.segmentDynamicFree(a, 3600.0, b, 4400.0));
  // Static side: a leg whose ends are clear but which cuts a concave polygon's arm.
  p.obstacles.push_back(
      {"L", {{-100, 1000}, {100, 1000}, {100, 1100}, {2000, 1100}, {2000, 1300}, {-100, 1300}}});
  const AcoEnvironment env2(p, HexagonDomainConfig{});
  EXPECT_TRUE(env2.pointStaticFree(a));
  EXPECT_TRUE(env2.pointStaticFree(b));
  EXPECT_FALSE(env2.segmentStaticFree(a, b));
  EXPECT_FALSE(env2.segmentStaticFree({1000.0, 0.0}, {1000.0, 4000.0}));  // through the arm
  EXPECT_TRUE(env2.segmentStaticFree({2500.0, 0.0}, {2500.0, 4000.0}));   // past its end
}

TEST(AcoPlanner, SameSeedGivesTheSameTrajectoryHundredTimes) {
  const PlanningProblem p = lazarowskaScenario1();
  AcoPlanner planner;
  const Plan ref = planner.plan(p);
  ASSERT_EQ(ref.status, PlanStatus::Ok) << ref.message;
  ASSERT_FALSE(planner.diagnostics().direct_route);
  for (int rep = 0; rep < 100; ++rep) {
    AcoPlanner fresh;
    const Plan again = fresh.plan(p);
    ASSERT_EQ(again.waypoints.size(), ref.waypoints.size()) << "repetition " << rep;
    for (size_t i = 0; i < ref.waypoints.size(); ++i) {
      ASSERT_EQ(again.waypoints[i].position, ref.waypoints[i].position) << "repetition " << rep;
      ASSERT_EQ(again.waypoints[i].time, ref.waypoints[i].time);
      ASSERT_EQ(again.waypoints[i].course, ref.waypoints[i].course);
    }
    ASSERT_EQ(again.cost, ref.cost);
  }
  // The seed is really used: another seed explores other paths.
  PlanningProblem q = p;
  bool differs = false;
  for (uint64_t seed = 2; seed < 12 && !differs; ++seed) {
    q.seed = seed;
    const Plan other = planner.plan(q);
    ASSERT_EQ(other.status, PlanStatus::Ok);
    differs = other.cost != ref.cost;
  }
  EXPECT_TRUE(differs);
}

TEST(AcoPlanner, StaticObstacleForcesADetour) {
  PlanningProblem p = openSea(0.0, 5.0, {0.0, 12000.0});
  p.obstacles.push_back(box("islet", -800.0, 5000.0, 800.0, 6000.0));
  AcoPlanner planner;
  const Plan plan = planner.plan(p);
  ASSERT_EQ(plan.status, PlanStatus::Ok) << plan.message;
  EXPECT_FALSE(planner.diagnostics().direct_route);
  EXPECT_GT(plan.cost, 12000.0 + 1.0);
  EXPECT_NEAR(plan.cost, pathLength(plan), 1e-6);  // eq. (9)
  EXPECT_EQ(plan.waypoints.front().position, p.own.position);
  EXPECT_EQ(plan.waypoints.back().position, p.goal);
  // Dense check of every leg against the polygon, 5 m steps.
  for (size_t i = 1; i < plan.waypoints.size(); ++i) {
    const Eigen::Vector2d a = plan.waypoints[i - 1].position, b = plan.waypoints[i].position;
    const int n = static_cast<int>((b - a).norm() / 5.0) + 1;
    for (int k = 0; k <= n; ++k)
      ASSERT_FALSE(pointInPolygon(p.obstacles[0].polygon, a + (b - a) * (double(k) / n)))
          << "leg " << i << " enters the islet";
  }
  // The detour passes beside the islet, so the path leaves the straight line by at least 800 m.
  double max_off = 0.0;
  for (const auto& w : plan.waypoints)
    max_off = std::max(max_off, std::abs(w.position.x()));
  EXPECT_GE(max_off, 800.0);
}

TEST(AcoPlanner, BoxedInReturnsNoSolution) {
  // Walls all round the own ship (the ship itself is in open water inside them).
  PlanningProblem p = openSea(0.0, 5.0, {0.0, 12000.0});
  p.obstacles.push_back(box("north", -3000.0, 2000.0, 3000.0, 2200.0));
  p.obstacles.push_back(box("south", -3000.0, -2200.0, 3000.0, -2000.0));
  p.obstacles.push_back(box("east", 2000.0, -2200.0, 2200.0, 2200.0));
  p.obstacles.push_back(box("west", -2200.0, -2200.0, -2000.0, 2200.0));
  AcoPlanner planner;
  const Plan plan = planner.plan(p);
  EXPECT_EQ(plan.status, PlanStatus::NoSolution);
  EXPECT_TRUE(plan.waypoints.empty());
  EXPECT_NE(plan.message.find("aco:"), std::string::npos);
  EXPECT_DOUBLE_EQ(plan.course_setpoint, p.own.course);

  // Boxed in by moving domains: targets closing from every side leave no feasible path.
  PlanningProblem q = openSea(0.0, 5.0, {0.0, 12000.0});
  for (int k = 0; k < 12; ++k) {
    const double brg = kTwoPi * k / 12.0;
    q.targets.push_back(target("ring" + std::to_string(k), courseSpeedToVelocity(brg, 2600.0),
                               radToDeg(wrapTwoPi(brg + kPi)), 4.0));
  }
  const Plan boxed = planner.plan(q);
  EXPECT_EQ(boxed.status, PlanStatus::NoSolution) << boxed.message;
  EXPECT_GT(planner.diagnostics().ants_dead, 0);

  // Already inside a domain at t = 0: no feasible start.
  PlanningProblem r = openSea(0.0, 5.0, {0.0, 12000.0});
  r.targets.push_back(target("close", {0.0, 500.0}, 180.0, 5.0));
  const Plan inside = planner.plan(r);
  EXPECT_EQ(inside.status, PlanStatus::NoSolution);
  EXPECT_NE(inside.message.find("close"), std::string::npos);
}

TEST(AcoPlanner, HeadOnAltersToStarboard) {
  const PlanningProblem p = headOn();
  AcoPlanner planner;
  const Plan plan = planner.plan(p);
  ASSERT_EQ(plan.status, PlanStatus::Ok) << plan.message;
  const auto alt = alterationsDeg(plan);
  ASSERT_FALSE(alt.empty());
  std::printf("head-on: %s\n", coursesDeg(plan).c_str());
  EXPECT_GT(alt.front(), 0.0) << "Rule 14: alter to starboard";
  EXPECT_GE(alt.front(), radToDeg(AcoConfig().min_first_alteration) - 1e-6);
  EXPECT_EQ(violations(plan, p), 0);
  // And for several seeds: the hexagon's larger starboard side makes a port pass the longer one.
  PlanningProblem q = p;
  for (uint64_t seed = 2; seed <= 6; ++seed) {
    q.seed = seed;
    const Plan other = planner.plan(q);
    ASSERT_EQ(other.status, PlanStatus::Ok);
    EXPECT_GT(alterationsDeg(other).front(), 0.0) << "seed " << seed << ": " << coursesDeg(other);
  }
}

TEST(AcoPlanner, MinimumFirstAlterationIsEnforced) {
  PlanningProblem p = headOn();
  for (double min_deg : {20.0, 35.0}) {
    AcoConfig cfg;
    cfg.min_first_alteration = degToRad(min_deg);
    AcoPlanner planner(cfg);
    const Plan plan = planner.plan(p);
    ASSERT_EQ(plan.status, PlanStatus::Ok) << plan.message;
    const auto alt = alterationsDeg(plan);
    ASSERT_FALSE(alt.empty());
    EXPECT_GE(std::abs(alt.front()), min_deg - 1e-6) << coursesDeg(plan);
  }
}

TEST(AcoPlanner, TurnsRespectTheManoeuvreTime) {
  // Every turning point lies at least V t_m (eq. 6) past the previous one (or past the own position
  // for the first), and the plan's times are those of constant speed along the legs (eq. 4).
  for (const PlanningProblem& p : {headOn(), lazarowskaScenario1(), lazarowskaScenario2()}) {
    AcoPlanner planner;
    const Plan plan = planner.plan(p);
    ASSERT_EQ(plan.status, PlanStatus::Ok) << plan.message;
    const double v = p.own.speed;
    const auto& w = plan.waypoints;
    EXPECT_DOUBLE_EQ(w.front().time, 0.0);
    EXPECT_DOUBLE_EQ(w.front().course, p.own.course);
    for (size_t i = 1; i < w.size(); ++i) {
      const double leg = (w[i].position - w[i - 1].position).norm();
      EXPECT_NEAR(w[i].time - w[i - 1].time, leg / v, 1e-6);
      EXPECT_NEAR(w[i].course, courseOf(w[i].position - w[i - 1].position), 1e-9);
      EXPECT_DOUBLE_EQ(w[i].speed, v);
      if (i + 1 < w.size()) {
        EXPECT_GE(leg, v * eq6(wrapPi(w[i + 1].course - w[i].course), p.limits) - 1e-3) << "turn " << i;
      }
    }
    // The first alteration is ordered t_m before its turning point, not before now.
    ASSERT_FALSE(planner.diagnostics().command_times.empty());
    EXPECT_GE(planner.diagnostics().command_times.front(), -1e-3);
    if (planner.diagnostics().command_times.front() < 0.5)
      EXPECT_NEAR(plan.course_setpoint, w[2].course, 1e-12);
    else
      EXPECT_NEAR(plan.course_setpoint, p.own.course, 1e-12);
  }
}

TEST(AcoPlanner, PlansAvoidEveryDomainInTime) {
  // The checker itself sees the collision course: straight on through the head-on target.
  {
    const PlanningProblem p = headOn();
    Plan straight;
    straight.waypoints = {{p.own.position, 0.0, 0.0, 6.0}, {p.goal, p.goal.norm() / 6.0, 0.0, 6.0}};
    EXPECT_GT(violations(straight, p), 0);
  }
  std::vector<PlanningProblem> problems{headOn(), lazarowskaScenario1(), lazarowskaScenario2()};
  // Crossing from starboard (Rule 15) and an overtaking target ahead.
  PlanningProblem crossing = openSea(0.0, 6.0, {0.0, nmToMetres(10.0)});
  crossing.targets.push_back(target("cross", {nmToMetres(4.0), nmToMetres(4.0)}, 270.0, 6.0));
  crossing.targets.push_back(target("slow", {0.0, nmToMetres(2.0)}, 0.0, 2.0));
  problems.push_back(crossing);
  for (size_t k = 0; k < problems.size(); ++k)
    for (uint64_t seed : {1, 7, 42}) {
      PlanningProblem p = problems[k];
      p.seed = seed;
      AcoPlanner planner;
      const Plan plan = planner.plan(p);
      ASSERT_EQ(plan.status, PlanStatus::Ok) << "problem " << k << ": " << plan.message;
      EXPECT_FALSE(planner.diagnostics().direct_route) << "problem " << k;
      EXPECT_EQ(violations(plan, p), 0) << "problem " << k << " seed " << seed << ": " << coursesDeg(plan);
      EXPECT_EQ(plan.waypoints.back().position, p.goal);
    }
}

TEST(AcoPlanner, ClearWaterGivesTheDirectRoute) {
  PlanningProblem p = openSea(10.0, 5.0, {2000.0, 10000.0});
  p.targets.push_back(target("far", {-20000.0, -20000.0}, 225.0, 5.0));
  AcoPlanner planner;
  const Plan plan = planner.plan(p);
  ASSERT_EQ(plan.status, PlanStatus::Ok);
  EXPECT_TRUE(planner.diagnostics().direct_route);
  EXPECT_EQ(planner.diagnostics().dangerous_targets, 0);
  // Goal 1.3 deg off the present course: one turning point V t_m ahead, then straight to the goal.
  ASSERT_EQ(plan.waypoints.size(), 3u);
  EXPECT_NEAR(plan.waypoints.back().course, courseOf(p.goal - plan.waypoints[1].position), 1e-12);
}

TEST(LazarowskaScenarios, TablesConvertToEnuAndSi) {
  const PlanningProblem s1 = lazarowskaScenario1();
  ASSERT_EQ(s1.targets.size(), 4u);
  EXPECT_NEAR(s1.own.course, degToRad(66.0), 1e-12);
  EXPECT_NEAR(s1.own.speed, 10.4 * 1852.0 / 3600.0, 1e-9);
  // Target 1: bearing 090, 7.9 nm -> due east.
  EXPECT_NEAR(s1.targets[0].state.position.x(), 7.9 * 1852.0, 1e-6);
  EXPECT_NEAR(s1.targets[0].state.position.y(), 0.0, 1e-6);
  EXPECT_NEAR(s1.targets[0].state.course, degToRad(294.0), 1e-12);
  // Target 4: bearing 025, 5.5 nm, 18.4 kn.
  EXPECT_NEAR(s1.targets[3].state.position.x(), 5.5 * 1852.0 * std::sin(degToRad(25.0)), 1e-6);
  EXPECT_NEAR(s1.targets[3].state.position.y(), 5.5 * 1852.0 * std::cos(degToRad(25.0)), 1e-6);
  EXPECT_NEAR(s1.targets[3].state.speed, 18.4 * 1852.0 / 3600.0, 1e-9);
  // The final waypoint lies on the initial course line, 6.75 nm out (calibrated, see below).
  EXPECT_NEAR(s1.goal.norm(), 6.75 * 1852.0, 1e-6);
  EXPECT_NEAR(courseOf(s1.goal), s1.own.course, 1e-12);

  const PlanningProblem s2 = lazarowskaScenario2();
  ASSERT_EQ(s2.targets.size(), 7u);
  EXPECT_NEAR(s2.own.speed, 15.4 * 1852.0 / 3600.0, 1e-9);
  EXPECT_NEAR(s2.targets[6].state.position.norm(), 9.0 * 1852.0, 1e-6);
  EXPECT_NEAR(trueBearing(s2.own.position, s2.targets[6].state.position), degToRad(37.0), 1e-12);
  // Table 3 target 1 crosses from starboard: the own ship gives way (Rule 15).
  EXPECT_EQ(s1.targets[0].role, OwnRole::GiveWay);
}

namespace {
// paper_side: check that the first alteration is to the paper's side.
void checkScenario(int n, const PlanningProblem& p, const std::vector<double>& paper, bool paper_side) {
  AcoPlanner planner;
  const Plan plan = planner.plan(p);
  ASSERT_EQ(plan.status, PlanStatus::Ok) << plan.message;
  EXPECT_EQ(violations(plan, p), 0);
  const auto alt = alterationsDeg(plan);
  ASSERT_FALSE(alt.empty());
  std::string paper_s;
  for (size_t i = 0; i < paper.size(); ++i) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%s%03.0f", i ? " -> " : "", paper[i]);
    paper_s += buf;
  }
  const double straight = (p.goal - p.own.position).norm();
  std::printf("Scenario %d: ours %s (%.0f m, %.2f x straight, %.0f s, %.2f ms) | paper %s\n", n,
              coursesDeg(plan).c_str(), plan.cost, plan.cost / straight, plan.waypoints.back().time,
              plan.compute_time * 1e3, paper_s.c_str());
  // The paper's first alteration: side, and a size between the apparent minimum and a moderate turn.
  const double paper_first = paper[1] - paper[0];
  if (paper_side) {
    EXPECT_EQ(alt.front() > 0.0, paper_first > 0.0);
  }
  EXPECT_GE(std::abs(alt.front()), radToDeg(AcoConfig().min_first_alteration) - 1e-6);
  EXPECT_LE(std::abs(alt.front()), 60.0);
  // Like the paper's, a handful of manoeuvres back to the final waypoint, barely longer than straight.
  EXPECT_LE(alt.size(), 6u);
  EXPECT_LT(plan.cost / straight, 1.03);
}
}  // namespace

TEST(LazarowskaScenarios, Scenario1LikeThePaper) {
  // Paper: 066 -> 077 (11 deg to starboard, astern of target 1) -> 052 (25 deg to port).
  checkScenario(1, lazarowskaScenario1(), lazarowskaScenario1CoursesDeg(), true);
  EXPECT_GT(lazarowskaScenario1CoursesDeg()[1], lazarowskaScenario1CoursesDeg()[0]);  // to starboard
}

TEST(LazarowskaScenarios, Scenario2LikeThePaper) {
  // Paper: 061 -> 050 (11 deg to port) -> 079 (29 deg to starboard) -> 061 (18 deg to port). Sea mode's
  // apparent first alteration (30 deg) makes a port pass the longer one here, so the side is not the
  // paper's (docs/results/aco.md compares both modes with it).
  checkScenario(2, lazarowskaScenario2(), lazarowskaScenario2CoursesDeg(), false);
}

namespace {
// The paper's answers as grid paths: cells (along the base line, to starboard) of side goal / 9, sailed
// on straight legs from t = 0 at the own speed. True when no target's hexagon (paper size) is entered.
bool gridPathClear(const PlanningProblem& p, const std::vector<Eigen::Vector2d>& cells, int* hit) {
  const double cell = p.goal.norm() / 9.0;
  const Eigen::Vector2d along = p.goal.normalized(), stbd(along.y(), -along.x());
  const AcoEnvironment env(p, HexagonDomainConfig{});
  Eigen::Vector2d a = p.own.position;
  double t = 0.0;
  for (size_t i = 1; i < cells.size(); ++i) {
    const Eigen::Vector2d b = p.own.position + along * cells[i].x() * cell + stbd * cells[i].y() * cell;
    const double tb = t + (b - a).norm() / p.own.speed;
    for (size_t j = 0; j < env.targetCount(); ++j)
      if (env.segmentHitsTarget(j, a, t, b, tb)) {
        *hit = static_cast<int>(j) + 1;
        return false;
      }
    a = b;
    t = tb;
  }
  return true;
}

const std::vector<Eigen::Vector2d> kPaperPath1{{0, 0}, {5, 1}, {9, 0}};
const std::vector<Eigen::Vector2d> kPaperPath2{{0, 0}, {5, -1}, {8, 0}, {9, 0}};
}  // namespace

TEST(LazarowskaScenarios, PrintedCoursesAreGridSlopes) {
  // 066 + atan(1/5) = 077.3, then 066 - atan(1/4) = 052.0; 061 - atan(1/5) = 049.7, 061 + atan(1/3) =
  // 079.4, 061: the printed courses to the degree (the paper-mode grid, AcoConfig::long_edges).
  auto course = [](double base, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    return std::lround(base + radToDeg(std::atan2((to - from).y(), (to - from).x())));
  };
  EXPECT_EQ(course(66, kPaperPath1[0], kPaperPath1[1]), 77);
  EXPECT_EQ(course(66, kPaperPath1[1], kPaperPath1[2]), 52);
  EXPECT_EQ(course(61, kPaperPath2[0], kPaperPath2[1]), 50);
  EXPECT_EQ(course(61, kPaperPath2[1], kPaperPath2[2]), 79);
  EXPECT_EQ(course(61, kPaperPath2[2], kPaperPath2[3]), 61);
}

TEST(LazarowskaScenarios, FinalWaypointIsWhereBothPrintedAnswersAreClear) {
  // kLazarowskaGoalRangeNm, calibrated: both answers clear of every hexagon from 6.2 to 7.3 nm, and not
  // beyond (Scenario 2 meets target 5 at 6.1 nm, target 2 at 7.4 nm).
  int hit = 0;
  for (double range : {6.2, kLazarowskaGoalRangeNm, 7.3}) {
    EXPECT_TRUE(gridPathClear(lazarowskaScenario1(range), kPaperPath1, &hit))
        << range << " nm: target " << hit;
    EXPECT_TRUE(gridPathClear(lazarowskaScenario2(range), kPaperPath2, &hit))
        << range << " nm: target " << hit;
  }
  EXPECT_FALSE(gridPathClear(lazarowskaScenario2(6.1), kPaperPath2, &hit));
  EXPECT_EQ(hit, 5);
  EXPECT_FALSE(gridPathClear(lazarowskaScenario2(7.4), kPaperPath2, &hit));
  EXPECT_EQ(hit, 2);
  EXPECT_NEAR(kLazarowskaGoalRangeNm, (6.2 + 7.3) / 2.0, 0.01);
  // Why Scenario 2 is not reproduced (docs/results/aco.md): from the end of the paper's first leg the
  // straight leg to wp_e is clear too, and shorter by 0.75 nm x (sqrt 10 + 1 - sqrt 17) = 54 m.
  EXPECT_TRUE(gridPathClear(lazarowskaScenario2(), {{0, 0}, {5, -1}, {9, 0}}, &hit)) << "target " << hit;
}

TEST(LazarowskaScenarios, PaperModeFindsScenario1AsPrinted) {
  // Over 20 seeds the shortest plan (eq. 9) is the paper's 066 -> 077 -> 052, and it or its mirror
  // (080 -> 055, as long but for the turn model's first leg) is what most seeds give; every plan is a
  // few long legs clear of every hexagon.
  ParamMap pm;
  pm.set("mode", "paper");
  AcoPlanner planner(AcoConfig::fromParams(pm));
  std::map<std::string, int> routes;
  std::string shortest;
  double shortest_len = 1e18;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    PlanningProblem p = lazarowskaScenario1();
    p.seed = seed;
    const Plan plan = planner.plan(p);
    ASSERT_EQ(plan.status, PlanStatus::Ok) << plan.message;
    EXPECT_EQ(violations(plan, p), 0) << plan.message;
    EXPECT_LE(alterationsDeg(plan).size(), 3u) << coursesDeg(plan);
    ++routes[coursesDeg(plan)];
    if (plan.cost < shortest_len - 1e-6) {
      shortest_len = plan.cost;
      shortest = coursesDeg(plan);
    }
  }
  // The plan's waypoints: own ship, the turning point B of the first alteration, the vertex, wp_e.
  EXPECT_EQ(shortest, "066 -> 066 -> 077 -> 052");
  EXPECT_GE(routes["066 -> 066 -> 077 -> 052"], 1);
  EXPECT_GT(routes["066 -> 066 -> 077 -> 052"] + routes["066 -> 066 -> 080 -> 055"], 10);
}

TEST(AcoPlanner, DangerousTargetsAsPrintedAreThoseWhoseCourseCrossesOurs) {
  ParamMap pm;
  pm.set("mode", "paper");
  AcoPlanner paper(AcoConfig::fromParams(pm));
  AcoPlanner sea;
  // A slow ship 3 nm out on the starboard bow heading west: her course crosses ours ahead of both, but
  // at 2 kn she is still 2.4 nm east of our track when we pass (no domain entered).
  PlanningProblem p = openSea(0.0, knotsToMps(10.0), {0.0, nmToMetres(6.0)});
  p.targets.push_back(target("west", {nmToMetres(3.0), nmToMetres(3.0)}, 270.0, knotsToMps(2.0)));
  paper.plan(p);
  EXPECT_EQ(paper.diagnostics().dangerous_targets, 1);
  EXPECT_FALSE(paper.diagnostics().direct_route);
  sea.plan(p);
  EXPECT_EQ(sea.diagnostics().dangerous_targets, 0);
  EXPECT_TRUE(sea.diagnostics().direct_route);
  // A ship stopped 0.2 nm east of our track heading east: her course never crosses ours, so she is not
  // dangerous as printed, but our track passes through her hexagon's stern (0.25 nm): the safety net
  // runs the colony all the same, and the plan keeps out of her hexagon.
  PlanningProblem q = openSea(0.0, knotsToMps(10.0), {0.0, nmToMetres(6.0)});
  q.targets.push_back(target("stopped", {nmToMetres(0.2), nmToMetres(3.0)}, 90.0, 0.0));
  const Plan plan = paper.plan(q);
  EXPECT_EQ(paper.diagnostics().dangerous_targets, 0);
  EXPECT_FALSE(paper.diagnostics().direct_route);
  ASSERT_EQ(plan.status, PlanStatus::Ok) << plan.message;
  EXPECT_EQ(violations(plan, q), 0);
}
