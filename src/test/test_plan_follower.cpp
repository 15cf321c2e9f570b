// PlanFollower's COLREGs and replanning policy (plan_follower.h), the situation's minimum separation
// passed to the planners (planning.h), and DSSA's COLREGs restriction of its search (dssa.h).
#include <gtest/gtest.h>

#include <cmath>

#include "asv_core/common/units.h"
#include "asv_core/planning/dssa/dssa.h"
#include "asv_core/planning/land_route.h"
#include "asv_core/planning/plan_follower.h"
#include "asv_core/planning/safety_net.h"

namespace {

asv::ShipState own() {
  asv::ShipState s;
  s.id = "own";
  s.position = {0.0, 0.0};
  s.course = s.heading = 0.0;  // north
  s.speed = 6.0;
  s.length = 100.0;
  return s;
}

// A crossing target on the own port side: the own ship is the stand-on vessel.
asv::PlannerTarget standOnTarget(bool compliant, asv::RiskLevel risk) {
  asv::PlannerTarget t;
  t.state.id = "ts1";
  t.state.position = {-5000.0, 5000.0};
  t.state.course = t.state.heading = asv::kPi / 2;  // east
  t.state.speed = 6.0;
  t.encounter = asv::Encounter::CrossingStandOn;
  t.role = asv::OwnRole::StandOn;
  t.compliant = compliant;
  t.risk = risk;
  return t;
}

// A ship met head-on: southbound at 6 m/s from (x, 6000), x metres east of the own track.
asv::PlannerTarget headOnTarget(double x) {
  asv::PlannerTarget t;
  t.state.id = "ts1";
  t.state.position = {x, 6000.0};
  t.state.course = t.state.heading = asv::kPi;
  t.state.speed = 6.0;
  t.encounter = asv::Encounter::HeadOn;
  return t;
}

// A follower of config c for own(), bound 20 km north.
asv::PlanFollower northbound(const asv::PlanFollowerConfig& c) {
  asv::PlanFollower f(c);
  f.setGoal({0.0, 20000.0});
  f.updateOwn(own());
  return f;
}

asv::PlanFollower follower(bool stand_on_policy = true, bool replan_on_risk = true) {
  asv::PlanFollowerConfig c;
  c.min_separation = 926.0;
  c.stand_on_policy = stand_on_policy;
  c.replan_on_risk = replan_on_risk;
  return northbound(c);
}

// An Ok plan straight to the goal, 20 km north at 6 m/s.
asv::Plan straightNorth() {
  asv::Plan p;
  p.status = asv::PlanStatus::Ok;
  p.waypoints = {{{0.0, 0.0}, 0.0, 0.0, 6.0}, {{0.0, 20000.0}, 3333.0, 0.0, 6.0}};
  return p;
}

}  // namespace

TEST(PlanFollower, StandOnKeepsOutCompliantGiveWayTargetsOnly) {
  const asv::PlanFollower f = follower();
  // Rule 17(a)(i): the give-way ship is expected to act; the planner does not see it.
  EXPECT_TRUE(f.buildProblem(0.0, {standOnTarget(true, asv::RiskLevel::Collision)}).targets.empty());
  // Rule 17(a)(ii): the give-way ship does not act (Hu's non-compliance flag): the own ship acts.
  EXPECT_EQ(f.buildProblem(0.0, {standOnTarget(false, asv::RiskLevel::Collision)}).targets.size(), 1u);
  // Rule 17(b): close quarters (Hu's urgent level): the own ship acts whatever the other does.
  EXPECT_EQ(f.buildProblem(0.0, {standOnTarget(true, asv::RiskLevel::Urgent)}).targets.size(), 1u);
  // The policy off: every target is planned against.
  EXPECT_EQ(
      follower(false).buildProblem(0.0, {standOnTarget(true, asv::RiskLevel::Collision)}).targets.size(), 1u);
}

// The plan-clearance trigger leaves out a ship she stands on for, as the plan did. By hand: the target
// from (-5000, 5000) east at 6 m/s and the own ship north at 6 m/s from the origin both reach (0, 5000)
// at 833 s, so the straight plan passes her at 0 m, under 926 m. While the give-way ship is compliant and
// not urgent the own ship stands on: no replan. Not compliant (17(a)(ii)) the 0 m pass replans; urgent
// (17(b)) the rise replans; with the stand-on policy off the 0 m pass replans.
TEST(PlanFollower, StandingOnDoesNotReplanForTheShipStoodOnFor) {
  asv::Plan p;
  p.status = asv::PlanStatus::Ok;
  p.waypoints = {{{0.0, 0.0}, 0.0, 0.0, 6.0}, {{0.0, 20000.0}, 3333.0, 0.0, 6.0}};
  // The clearance in the reason, sampled along the route (0 m by hand, a few metres off at the samples).
  auto passesWithin = [](const std::string& why) {
    const std::string lead = "plan predicted to pass within ";
    return why.rfind(lead, 0) == 0 ? std::stod(why.substr(lead.size())) : -1.0;
  };
  auto after = [&](asv::PlanFollower f, const asv::PlannerTarget& now, std::string& why) {
    f.acceptPlan(p, 0.0, {standOnTarget(true, asv::RiskLevel::Collision)}, "test");
    return f.replanNeeded(10.0, {now}, why);
  };
  std::string why;
  EXPECT_FALSE(after(follower(), standOnTarget(true, asv::RiskLevel::Collision), why)) << why;
  EXPECT_TRUE(after(follower(), standOnTarget(false, asv::RiskLevel::Collision), why));
  EXPECT_NEAR(passesWithin(why), 0.0, 50.0) << why;
  EXPECT_TRUE(after(follower(), standOnTarget(true, asv::RiskLevel::Urgent), why));
  EXPECT_EQ(why, "risk of ts1 1 -> 2");
  EXPECT_TRUE(after(follower(false), standOnTarget(true, asv::RiskLevel::Collision), why));
  EXPECT_NEAR(passesWithin(why), 0.0, 50.0) << why;
}

// Rule 17(a)(i) lasts until the ship is past. ts1 (from port, compliant) at risk 1 when a plan is made;
// at the next plan she still stands on for it (PlanningProblem::standing_on), at risk 1 still or after
// its own action removed the risk (level 0) with its CPA still ahead, until the CPA is past, the ship
// turns non-compliant or urgent, a risk gives her another role, or with the stand-on policy off; with
// no risk, not when its CPA is beyond the prediction horizon (1200 s) or the geometry makes her the
// ship to keep out of the way. A stand-on situation no earlier plan saw (a fresh follower: a risk her
// own turn may have made) does not count; the planner's plan is judged as before (closesStandOn). A
// plan made while the ship is missing from the picture (degraded operation) keeps her place.
TEST(PlanFollower, SheStandsOnUntilTheShipIsPastThoughItsActionRemovedTheRisk) {
  asv::PlannerTarget seen = standOnTarget(true, asv::RiskLevel::Collision);
  seen.tcpa = 833.3;
  asv::PlannerTarget removed = seen;
  removed.risk = asv::RiskLevel::None;
  removed.tcpa = 600.0;
  auto standingOn = [&](asv::PlanFollower f, const asv::PlannerTarget& now) {
    f.acceptPlan(straightNorth(), 0.0, {seen}, "test");
    return f.buildProblem(10.0, {now}).standing_on.size();
  };
  EXPECT_EQ(standingOn(follower(), removed), 1u);
  EXPECT_TRUE(follower().buildProblem(10.0, {removed}).standing_on.empty());
  asv::PlannerTarget past = removed;
  past.tcpa = -5.0;
  EXPECT_EQ(standingOn(follower(), past), 0u);
  asv::PlannerTarget lacking = removed;
  lacking.compliant = false;
  EXPECT_EQ(standingOn(follower(), lacking), 0u);
  EXPECT_EQ(standingOn(follower(false), removed), 0u);
  EXPECT_EQ(standingOn(follower(), seen), 1u);
  EXPECT_TRUE(follower().buildProblem(10.0, {seen}).standing_on.empty());
  asv::PlannerTarget other_role = seen;
  other_role.encounter = asv::Encounter::CrossingGiveWay;
  other_role.role = asv::OwnRole::GiveWay;
  EXPECT_EQ(standingOn(follower(), other_role), 0u);
  asv::PlannerTarget urgent = seen;
  urgent.risk = asv::RiskLevel::Urgent;
  EXPECT_EQ(standingOn(follower(), urgent), 0u);
  asv::PlannerTarget far = removed;
  far.tcpa = 1300.0;
  EXPECT_EQ(standingOn(follower(), far), 0u);
  asv::PlannerTarget overtaking = removed;
  overtaking.encounter = asv::Encounter::Overtaking;
  overtaking.role = asv::OwnRole::GiveWay;
  EXPECT_EQ(standingOn(follower(), overtaking), 0u);
  asv::PlanFollower lost = follower();
  lost.acceptPlan(straightNorth(), 0.0, {seen}, "test");
  lost.acceptPlan(straightNorth(), 5.0, {}, "degraded");
  EXPECT_EQ(lost.buildProblem(10.0, {removed}).standing_on.size(), 1u);
  // Missing for longer than a prediction horizon (1200 s) since last seen, it is forgotten.
  lost.acceptPlan(straightNorth(), 1201.0, {}, "degraded");
  EXPECT_TRUE(lost.buildProblem(1210.0, {removed}).standing_on.empty());
  // Left out of the plan-clearance trigger as of the problem, whatever the geometry now calls it: the
  // plan north passes it at 0 m (both reach (0, 5000) at 833 s), and no replan follows.
  asv::PlannerTarget unnamed = removed;
  unnamed.encounter = asv::Encounter::None;
  unnamed.role = asv::OwnRole::None;
  asv::PlanFollower held = follower();
  held.acceptPlan(straightNorth(), 0.0, {seen}, "test");
  std::string why;
  EXPECT_FALSE(held.replanNeeded(10.0, {unnamed}, why)) << why;
  asv::PlanFollower unlatched = follower();
  unlatched.acceptPlan(straightNorth(), 0.0, {}, "test");
  EXPECT_TRUE(unlatched.replanNeeded(10.0, {unnamed}, why));
  EXPECT_EQ(why.rfind("plan predicted to pass within", 0), 0u) << why;
  // A plan made meanwhile (the ship past) ends it: a later risk-free picture does not bring it back.
  asv::PlanFollower f = follower();
  f.acceptPlan(straightNorth(), 0.0, {seen}, "test");
  f.acceptPlan(straightNorth(), 20.0, {past}, "test");
  EXPECT_TRUE(f.buildProblem(30.0, {removed}).standing_on.empty());
}

namespace {

// A slow ship the own ship overtakes: 1000 m east of her track, `ahead` metres ahead, north at 2 m/s;
// the own ship (north at 6 m/s) closes on it at 4 m/s, so its TCPA is ahead / 4 s.
asv::PlannerTarget overtaken(double ahead) {
  asv::PlannerTarget t;
  t.state.id = "ts2";
  t.state.position = {1000.0, ahead};
  t.state.course = t.state.heading = 0.0;
  t.state.speed = 2.0;
  t.encounter = asv::Encounter::Overtaking;
  t.role = asv::OwnRole::GiveWay;
  t.risk = asv::RiskLevel::Collision;
  t.tcpa = ahead / 4.0;
  t.dcpa = 1000.0;
  return t;
}

}  // namespace

// Rule 17 with several ships: she stands on for ts1 (from port, compliant; both reach (0, 5000) at
// 833 s); her duty to keep out of the way of ts2, which she overtakes, waits while its CPA is more than
// duty_window_s (900 s) away: 4000 m ahead, 1000 s. ts2 is then watched as a ship she stands on for, not
// planned against, and the plan may hold her course. At 3200 m (800 s) the duty is due: ts2 is planned
// against, and a plan made while it waited is replaced at once. Without a ship she stands on for, or
// with ts1 past, the duty never waits. With ts1's CPA 300 s away, ts2's at 3400 m (850 s) comes more
// than kDutyLead (480 s) after it and waits too: she can stand on and still act early; urgent, never.
TEST(PlanFollower, ARemoteGiveWayDutyWaitsWhileSheStandsOn) {
  const asv::PlanFollower f = follower();
  asv::PlannerTarget ts1 = standOnTarget(true, asv::RiskLevel::Collision);
  ts1.tcpa = 5000.0 / 6.0;
  const asv::PlanningProblem waiting = f.buildProblem(0.0, {ts1, overtaken(4000.0)});
  EXPECT_TRUE(waiting.targets.empty());
  ASSERT_EQ(waiting.stand_on_for.size(), 2u);
  EXPECT_EQ(waiting.stand_on_for[1].state.id, "ts2");
  const asv::PlanningProblem due = f.buildProblem(0.0, {ts1, overtaken(3200.0)});
  ASSERT_EQ(due.targets.size(), 1u);
  EXPECT_EQ(due.targets[0].state.id, "ts2");
  EXPECT_EQ(f.buildProblem(0.0, {overtaken(4000.0)}).targets.size(), 1u);
  EXPECT_EQ(follower(false).buildProblem(0.0, {ts1, overtaken(4000.0)}).targets.size(), 2u);
  asv::PlannerTarget past = ts1;
  past.tcpa = -10.0;
  EXPECT_EQ(f.buildProblem(0.0, {past, overtaken(4000.0)}).targets.size(), 1u);
  asv::PlannerTarget soon = ts1;
  soon.tcpa = 300.0;
  EXPECT_TRUE(f.buildProblem(0.0, {soon, overtaken(3400.0)}).targets.empty());
  EXPECT_EQ(f.buildProblem(0.0, {ts1, overtaken(3400.0)}).targets.size(), 1u);  // 850 < 833 + 480
  asv::PlannerTarget urgent = overtaken(4000.0);
  urgent.risk = asv::RiskLevel::Urgent;
  EXPECT_EQ(f.buildProblem(0.0, {ts1, urgent}).targets.size(), 1u);

  asv::PlanFollower g = follower();
  asv::Plan hold;
  hold.status = asv::PlanStatus::Ok;
  hold.waypoints = {{{0.0, 0.0}, 0.0, 0.0, 6.0}, {{0.0, 20000.0}, 3333.0, 0.0, 6.0}};
  g.acceptPlan(hold, 0.0, {ts1, overtaken(4000.0)}, "test");
  std::string why;
  EXPECT_FALSE(g.replanNeeded(10.0, {ts1, overtaken(3960.0)}, why)) << why;
  EXPECT_TRUE(g.replanNeeded(30.0, {ts1, overtaken(3560.0)}, why));
  EXPECT_EQ(why, "the duty to keep out of the way of ts2 is due");
}

TEST(PlanFollower, PassesTheMinimumSeparationToThePlanners) {
  EXPECT_DOUBLE_EQ(follower().buildProblem(0.0, {}).min_separation, 926.0);
}

// The cruise speed (here the own speed at the first update, 6 m/s) goes to the planners; a ship that
// is faster after a turn keeps her speed as own.speed, but a plan that keeps her speed asks for 6 m/s.
TEST(PlanFollower, PassesTheCruiseSpeedToThePlanners) {
  asv::PlanFollower f = follower();
  asv::ShipState faster = own();
  faster.speed = 6.4;
  f.updateOwn(faster);
  const asv::PlanningProblem pr = f.buildProblem(0.0, {});
  EXPECT_DOUBLE_EQ(pr.cruise_speed, 6.0);
  EXPECT_DOUBLE_EQ(pr.own.speed, 6.4);
  EXPECT_DOUBLE_EQ(asv::keptSpeed(pr), 6.0);
  asv::PlanningProblem unknown = pr;
  unknown.cruise_speed = 0.0;
  EXPECT_DOUBLE_EQ(asv::keptSpeed(unknown), 6.4);
}

// replan_on_risk false (plan once, as Lazarowska 2015): a far target's rise from 0 to 2 no longer
// replans a plan that stays safe; a plan predicted to pass inside the minimum separation still does.
TEST(PlanFollower, PlanOnceIgnoresRisingRiskButNotAnUnsafePlan) {
  asv::PlanFollower f = follower(false, false);
  std::string why;
  asv::Plan p;
  p.status = asv::PlanStatus::Ok;
  p.waypoints = {{{0.0, 0.0}, 0.0, 0.0, 6.0}, {{0.0, 20000.0}, 3333.0, 0.0, 6.0}};
  asv::PlannerTarget t = standOnTarget(false, asv::RiskLevel::None);
  t.state.position = {-30000.0, 30000.0};
  f.acceptPlan(p, 0.0, {t}, "test");
  t.risk = asv::RiskLevel::Urgent;
  EXPECT_FALSE(f.replanNeeded(10.0, {t}, why)) << why;
  // A stopped ship 500 m off the planned track: predicted clearance 500 m < 926 m.
  t.state.position = {500.0, 5000.0};
  t.state.speed = 0.0;
  EXPECT_TRUE(f.replanNeeded(20.0, {t}, why));
  EXPECT_NE(why.find("plan predicted to pass within"), std::string::npos) << why;
}

// Paper mode takes the method's plan as it is: a plan passing a stopped ship 300 m off its track (sea
// mode replans below plan_clearance, 370 m) is kept; a failed plan holds course and speed, even with an
// urgent ship 500 m off (sea mode: hard to starboard inside extremis_range, else half speed).
TEST(PlanFollower, PaperModeKeepsAClosePassAndHasNoSeaFallback) {
  for (const asv::PlannerMode mode : {asv::PlannerMode::Sea, asv::PlannerMode::Paper}) {
    SCOPED_TRACE(mode == asv::PlannerMode::Paper ? "paper" : "sea");
    asv::PlanFollowerConfig c;
    asv::applyPlannerMode(c, mode);
    asv::PlanFollower f = northbound(c);
    asv::PlannerTarget t = standOnTarget(false, asv::RiskLevel::None);
    t.state.position = {300.0, 5000.0};
    t.state.speed = 0.0;
    f.acceptPlan(straightNorth(), 0.0, {t}, "test");
    std::string why;
    EXPECT_EQ(f.replanNeeded(20.0, {t}, why), mode == asv::PlannerMode::Sea) << why;

    asv::Plan failed;
    failed.status = asv::PlanStatus::NoSolution;
    failed.message = "nothing found";
    t.risk = asv::RiskLevel::Urgent;
    t.state.position = {0.0, 500.0};
    const asv::Plan& got = f.acceptPlan(failed, 30.0, {t}, "test");
    EXPECT_EQ(got.status, asv::PlanStatus::Fallback);
    if (mode == asv::PlannerMode::Paper) {
      EXPECT_NEAR(got.course_setpoint, own().course, 1e-12);
      EXPECT_NEAR(got.speed_setpoint, 6.0, 1e-12);
    } else {
      EXPECT_NEAR(got.course_setpoint, own().course + asv::kPi / 2, 1e-12) << got.message;
    }
  }
}

// Paper mode: the follower's stand-on policy and minimum separation are sea extensions (off), and the
// planner's plan is taken as it is, without the shared rules' separation net or retries.
TEST(PlanFollower, PaperModeSwitchesTheSeaExtensionsOff) {
  asv::PlanFollowerConfig c;
  c.min_separation = 926.0;
  asv::applyPlannerMode(c, asv::PlannerMode::Sea);
  EXPECT_TRUE(c.stand_on_policy);
  EXPECT_EQ(c.min_separation, 926.0);
  asv::applyPlannerMode(c, asv::PlannerMode::Paper);
  EXPECT_FALSE(c.stand_on_policy);
  EXPECT_EQ(c.min_separation, 0.0);
  EXPECT_TRUE(c.replan_on_risk);  // a method that replans keeps replanning on rising risk
  EXPECT_EQ(c.plan_clearance, 0.0) << "no replan for passing closer than the stack's clearance";
  EXPECT_EQ(c.extremis_range, 0.0) << "no hard starboard in extremis";
  EXPECT_EQ(c.fallback_speed_factor, 1.0) << "a failed plan holds course and speed";
  // A method that plans once (ACO, Lazarowska 2015) sails its plan in paper mode; at sea it replans.
  asv::PlanFollowerConfig once;
  asv::applyPlannerMode(once, asv::PlannerMode::Sea, true);
  EXPECT_TRUE(once.replan_on_risk);
  asv::applyPlannerMode(once, asv::PlannerMode::Paper, true);
  EXPECT_FALSE(once.replan_on_risk);
  EXPECT_FALSE(once.replan_each_cycle);
  // A method with its own trigger (Wu et al. 2022) is asked at every cycle in paper mode only.
  asv::PlanFollowerConfig own_trigger;
  asv::applyPlannerMode(own_trigger, asv::PlannerMode::Sea, false, true);
  EXPECT_FALSE(own_trigger.replan_each_cycle);
  asv::applyPlannerMode(own_trigger, asv::PlannerMode::Paper, false, true);
  EXPECT_TRUE(own_trigger.replan_each_cycle);
  asv::PlanFollower every = northbound(own_trigger);
  every.acceptPlan(straightNorth(), 0.0, {}, "test");
  std::string why;
  EXPECT_FALSE(every.replanNeeded(1.0, {}, why)) << "not before min_replan_interval (2 s)";
  EXPECT_TRUE(every.replanNeeded(2.0, {}, why));
  EXPECT_EQ(why, "the method's own trigger, checked every cycle");

  asv::PlanningProblem pr;
  pr.own = own();
  pr.goal = {0.0, 20000.0};
  pr.min_separation = 926.0;
  asv::PlannerTarget head_on = standOnTarget(false, asv::RiskLevel::Urgent);
  head_on.state.position = {0.0, 3000.0};
  head_on.state.course = head_on.state.heading = asv::degToRad(180.0);
  head_on.state.speed = 6.0;
  head_on.encounter = asv::Encounter::HeadOn;
  head_on.role = asv::OwnRole::BothGiveWay;
  head_on.tcpa = 250.0;
  pr.targets = {head_on};
  int calls = 0;
  auto straight = [&](const asv::PlanningProblem& q) {  // through the target: breaks the separation rule
    ++calls;
    asv::Plan p;
    p.status = asv::PlanStatus::Ok;
    p.course_setpoint = 0.0;
    p.speed_setpoint = 6.0;
    p.waypoints = {{q.own.position, 0.0, 0.0, 6.0}, {{0.0, 20000.0}, 3333.0, 0.0, 6.0}};
    return p;
  };
  const asv::Plan paper = asv::planInMode(straight, pr, asv::PlannerMode::Paper);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(paper.course_setpoint, 0.0);
  calls = 0;
  const asv::Plan sea = asv::planInMode(straight, pr, asv::PlannerMode::Sea);
  EXPECT_EQ(calls, 1);  // refused for the preferred distance, and the net's turn for it taken instead
  EXPECT_NE(sea.course_setpoint, 0.0) << sea.message;
  EXPECT_NE(sea.message.find("separation manoeuvre"), std::string::npos) << sea.message;
}

TEST(PlanFollower, RiskMustStayClearBeforeARiseReplansAgain) {
  asv::PlanFollower f = follower(false);
  std::string why;
  ASSERT_TRUE(f.replanNeeded(0.0, {}, why));  // first plan
  asv::Plan p;
  p.status = asv::PlanStatus::Ok;
  p.waypoints = {{{0.0, 0.0}, 0.0, 0.0, 6.0}, {{0.0, 20000.0}, 3333.0, 0.0, 6.0}};
  auto at = [](asv::RiskLevel r) {
    asv::PlannerTarget t = standOnTarget(true, r);
    t.state.position = {-30000.0, 30000.0};  // far: the plan's predicted clearance never triggers
    return std::vector<asv::PlannerTarget>{t};
  };
  f.acceptPlan(p, 0.0, at(asv::RiskLevel::Collision), "test");
  // Level 1 -> 0 -> 1 within risk_clear_time (60 s): tracking flicker, no replan.
  EXPECT_FALSE(f.replanNeeded(10.0, at(asv::RiskLevel::None), why));
  EXPECT_FALSE(f.replanNeeded(40.0, at(asv::RiskLevel::Collision), why)) << why;
  // Clear for 60 s: a new rise is news again.
  EXPECT_FALSE(f.replanNeeded(50.0, at(asv::RiskLevel::None), why));
  EXPECT_FALSE(f.replanNeeded(111.0, at(asv::RiskLevel::None), why));
  EXPECT_TRUE(f.replanNeeded(120.0, at(asv::RiskLevel::Collision), why));
  EXPECT_NE(why.find("0 -> 1"), std::string::npos) << why;

  // With the CPA still ahead, a risk that falls to none (the plan working) never re-arms: back at
  // level 1 after 200 s, no replan; a rise above what the plan saw (level 2) still replans.
  f.acceptPlan(p, 120.0, at(asv::RiskLevel::Collision), "test");
  auto ahead = [&](asv::RiskLevel r) {
    auto v = at(r);
    v[0].tcpa = 600.0;
    return v;
  };
  EXPECT_FALSE(f.replanNeeded(130.0, ahead(asv::RiskLevel::None), why));
  EXPECT_FALSE(f.replanNeeded(330.0, ahead(asv::RiskLevel::None), why));
  EXPECT_FALSE(f.replanNeeded(340.0, ahead(asv::RiskLevel::Collision), why)) << why;
  EXPECT_TRUE(f.replanNeeded(350.0, ahead(asv::RiskLevel::Urgent), why));
}

// Live parameters (planner_node's dynamic_reconfigure): a new minimum separation reaches the next
// problem, replans at once although min_replan_interval has not passed, keeps the cruise speed fixed at
// the first update (6 m/s, the own ship's) when given 0, and a bad value changes nothing.
TEST(PlanFollower, ReconfigureReplansAtOnceUnderTheNewValues) {
  asv::PlanFollower f = follower();
  std::string why;
  ASSERT_TRUE(f.replanNeeded(0.0, {}, why));
  asv::Plan p;
  p.status = asv::PlanStatus::Ok;
  p.waypoints = {{{0.0, 0.0}, 0.0, 0.0, 6.0}, {{0.0, 20000.0}, 3333.0, 0.0, 6.0}};
  f.acceptPlan(p, 0.0, {}, "test");
  EXPECT_FALSE(f.replanNeeded(1.0, {}, why));  // within min_replan_interval (2 s), nothing new

  asv::PlanFollowerConfig c = f.config();
  c.cruise_speed = 0.0;
  c.min_separation = 1852.0;
  f.reconfigure(c);
  EXPECT_DOUBLE_EQ(f.cruiseSpeed(), 6.0);
  EXPECT_DOUBLE_EQ(f.buildProblem(1.0, {}).min_separation, 1852.0);
  ASSERT_TRUE(f.replanNeeded(1.0, {}, why));
  EXPECT_EQ(why, "parameters changed");
  EXPECT_TRUE(f.havePlan());  // the plan in force is flown meanwhile
  f.acceptPlan(p, 1.0, {}, "test");
  EXPECT_FALSE(f.replanNeeded(1.5, {}, why));  // once

  c.replan_period = -1.0;
  EXPECT_THROW(f.reconfigure(c), std::invalid_argument);
  EXPECT_DOUBLE_EQ(f.config().replan_period, 30.0);
  EXPECT_FALSE(f.replanNeeded(1.5, {}, why));
}

// Head-on: a target dead ahead on the reciprocal course, slightly to starboard of the own track, so
// that the paper's search (shortest deviation) turns to port; with `colregs` DSSA turns to starboard.
TEST(DssaColregs, GiveWayInHeadOnSearchesStarboardOnly) {
  asv::PlanningProblem pr;
  pr.own = own();
  pr.goal = {0.0, 20000.0};
  pr.limits.max_speed = 8.0;
  pr.time_budget = 10.0;
  asv::PlannerTarget t = headOnTarget(150.0);
  t.role = asv::OwnRole::GiveWay;
  t.risk = asv::RiskLevel::Collision;
  pr.targets = {t};
  auto firstCourseChange = [&](bool colregs) {
    asv::DssaPlanner d("dssa");
    asv::ParamMap p = asv::DssaConfig::seaDefaults();
    p.set("colregs", colregs ? "true" : "false");
    d.configure(p);
    const asv::Plan plan = d.plan(pr);
    EXPECT_EQ(plan.status, asv::PlanStatus::Ok) << plan.message;
    return std::remainder(plan.course_setpoint - pr.own.course, 2 * asv::kPi);
  };
  EXPECT_LT(firstCourseChange(false), -1e-6);  // the paper's search: to port, away from the target
  EXPECT_GT(firstCourseChange(true), 1e-6);    // Rule 14: to starboard
}

// Rules 14/15 guard: a fake planner that alters 20 deg to port on its first seed and 20 deg to
// starboard on any other.
// Rule 17(c): a ship crossing from the port side that did not give way is now in the problem (she is no
// longer stood on for); a planner that answers only with a turn to port (20 deg, which keeps 926 m from
// this ship: she passes ahead of the own ship's new track) is refused, retried, and replaced by the
// net's manoeuvre, which turns to starboard and keeps the minimum with its margin.
TEST(PlanUnderSharedRules, NoTurnToPortForAShipOnThePortSide) {
  asv::PlanningProblem pr;
  pr.own = own();
  pr.goal = {0.0, 20000.0};
  pr.min_separation = 926.0;
  pr.targets = {standOnTarget(false, asv::RiskLevel::Collision)};
  int calls = 0;
  auto port = [&](const asv::PlanningProblem& q) {
    ++calls;
    asv::Plan plan;
    plan.status = asv::PlanStatus::Ok;
    plan.course_setpoint = asv::wrapTwoPi(q.own.course - asv::degToRad(20.0));
    plan.speed_setpoint = q.own.speed;
    return plan;
  };
  ASSERT_GE(asv::planSeparation(port(pr), pr), 926.0);  // the port plan is refused for its side alone
  calls = 0;
  const asv::Plan p = asv::planUnderSharedRules(port, pr);
  EXPECT_EQ(calls, 5);  // for the preferred distance (open water), then the plan and 3 retries
  EXPECT_GE(std::remainder(p.course_setpoint - pr.own.course, 2 * asv::kPi), asv::degToRad(30.0) - 1e-9)
      << p.message;
  EXPECT_NE(p.message.find("Rule 17(c)"), std::string::npos) << p.message;
  EXPECT_GE(asv::planSeparation(p, pr), 1.1 * 926.0) << p.message;
}

// A plan alters to port by its legs before the last CPA, not only by its set-point. A ship met head-on
// 6000 m ahead, both at 6 m/s: her CPA is at 500 s. By hand, each plan from the origin (north) for
// 200 s and then 330 deg for 300 s: ahead first (000), 30 deg to port; 030 first, back across the
// course to 330: 30 each way, port within 10 of starboard, to port; 060 first and 330 after: 60 to
// starboard, 30 to port, not; 003 first, 330 second, to port; 030 and 357: 3 deg to port, under the
// 5 deg threshold, not; ahead 3600 m (600 s, past the CPA) and then 330: the later leg is the way on,
// no alteration.
TEST(PlanUnderSharedRules, APlanAltersToPortByItsLegsBeforeTheLastCpa) {
  asv::PlanningProblem pr;
  pr.own = own();
  pr.targets = {headOnTarget(0.0)};
  auto plan = [](std::vector<std::pair<double, double>> legs) {  // (course deg, seconds) at 6 m/s
    asv::Plan p;
    p.status = asv::PlanStatus::Ok;
    p.course_setpoint = asv::degToRad(legs.front().first);
    asv::PlannedWaypoint w;
    p.waypoints = {w};
    for (const auto& [course, seconds] : legs) {
      w.position += asv::courseSpeedToVelocity(asv::degToRad(course), 6.0) * seconds;
      w.time += seconds;
      p.waypoints.push_back(w);
    }
    return p;
  };
  EXPECT_TRUE(asv::altersToPort(plan({{0.0, 200.0}, {330.0, 300.0}}), pr));
  EXPECT_TRUE(asv::altersToPort(plan({{30.0, 200.0}, {330.0, 300.0}}), pr));
  EXPECT_FALSE(asv::altersToPort(plan({{60.0, 200.0}, {330.0, 300.0}}), pr));
  EXPECT_TRUE(asv::altersToPort(plan({{3.0, 200.0}, {330.0, 300.0}}), pr));
  EXPECT_FALSE(asv::altersToPort(plan({{30.0, 200.0}, {357.0, 300.0}}), pr));
  EXPECT_FALSE(asv::altersToPort(plan({{0.0, 600.0}, {330.0, 300.0}}), pr));
}

TEST(PlanUnderSharedRules, RetriesAPortPlanWhenGivingWay) {
  asv::PlanningProblem pr;
  pr.own = own();
  pr.seed = 7;
  int calls = 0;
  auto fake = [&](const asv::PlanningProblem& p) {
    ++calls;
    asv::Plan plan;
    plan.status = asv::PlanStatus::Ok;
    plan.course_setpoint = asv::wrapTwoPi(p.own.course + asv::degToRad(p.seed == 7 ? -20.0 : 20.0));
    return plan;
  };
  // No head-on or crossing give-way target: the plan stands, whatever its side.
  asv::Plan p = asv::planUnderSharedRules(fake, pr);
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(asv::altersToPort(p, pr));
  // Head-on: the port plan is refused and the retry's starboard plan taken.
  asv::PlannerTarget t;
  t.state.id = "ts1";
  t.encounter = asv::Encounter::HeadOn;
  pr.targets = {t};
  calls = 0;
  p = asv::planUnderSharedRules(fake, pr);
  EXPECT_EQ(calls, 2);
  EXPECT_NEAR(std::remainder(p.course_setpoint - pr.own.course, 2 * asv::kPi), asv::degToRad(20.0), 1e-12);
  EXPECT_NE(p.message.find("retry 1"), std::string::npos);
  // A planner that only knows port: after 3 retries the first plan is kept, and says so.
  calls = 0;
  p = asv::planUnderSharedRules(
      [&](const asv::PlanningProblem& q) {
        ++calls;
        asv::Plan plan;
        plan.status = asv::PlanStatus::Ok;
        plan.course_setpoint = asv::wrapTwoPi(q.own.course - 0.5);
        return plan;
      },
      pr);
  EXPECT_EQ(calls, 4);
  EXPECT_NE(p.message.find("port alteration kept"), std::string::npos);
}

namespace {
// A 2 km square island whose south shore lies 1 km ahead of the own ship (at the origin, heading north).
asv::StaticObstacle island() {
  return {"island", {{-1000.0, 1000.0}, {1000.0, 1000.0}, {1000.0, 3000.0}, {-1000.0, 3000.0}}};
}
asv::Plan waypointPlan(const std::vector<Eigen::Vector2d>& points) {
  asv::Plan plan;
  plan.status = asv::PlanStatus::Ok;
  for (const auto& p : points)
    plan.waypoints.push_back({p, 0.0, 0.0, 5.0});
  plan.course_setpoint = 0.0;
  plan.speed_setpoint = 5.0;
  return plan;
}
}  // namespace

// Land is a rule of every plan: a fake planner goes straight through the island on its first seed and
// round its west side (1300 m clear of the west shore's x = -1000, via x = -1500) on any other.
TEST(PlanUnderSharedRules, APlanOverLandIsRefusedAndReplanned) {
  asv::PlanningProblem pr;
  pr.own = own();
  pr.goal = {0.0, 4000.0};  // behind the island: a plan is judged on its way there
  pr.seed = 7;
  pr.obstacles = {island()};
  pr.min_obstacle_clearance = 185.2;
  int calls = 0;
  auto fake = [&](const asv::PlanningProblem& p) {
    ++calls;
    return p.seed == 7 ? waypointPlan({{0, 0}, {0, 4000}})
                       : waypointPlan({{0, 0}, {-1500, 900}, {-1500, 3100}, {0, 4000}});
  };
  asv::Plan p = asv::planUnderSharedRules(fake, pr);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(p.waypoints.size(), 4u);
  EXPECT_NE(p.message.find("of land"), std::string::npos) << p.message;
  // The detour's closest approach, by hand: the leg (0,0)-(-1500,900) passes the corner (-1000,1000) at
  // |cross((-1500,900), (-1000,1000))| / |(-1500,900)| = 600000 / 1749.3 = 343.0 m.
  EXPECT_NEAR(asv::trackObstacleDistance(asv::landTrack(p, pr.own.position, 1e5), pr.obstacles), 343.0, 0.1);
  // A planner that only goes straight: no plan keeps clear, the result is NoSolution (the fallback).
  calls = 0;
  p = asv::planUnderSharedRules(
      [&](const asv::PlanningProblem&) {
        ++calls;
        return waypointPlan({{0, 0}, {0, 4000}});
      },
      pr);
  EXPECT_EQ(calls, 4);
  EXPECT_EQ(p.status, asv::PlanStatus::NoSolution);
  // Without a clearance requirement the straight plan stands.
  pr.min_obstacle_clearance = 0.0;
  calls = 0;
  EXPECT_EQ(asv::planUnderSharedRules(fake, pr).waypoints.size(), 2u);
}

// A planner's least-violation plan (status Fallback: MOPSO's when no particle is feasible) is sailed
// like any other, so land is its rule too: over the island it is refused, and the detour is taken.
// (It was let through unchecked, and MOPSO ran aground in New York's Narrows.)
TEST(PlanUnderSharedRules, APlannersFallbackPlanOverLandIsRefusedToo) {
  asv::PlanningProblem pr;
  pr.own = own();
  pr.goal = {0.0, 4000.0};
  pr.seed = 7;
  pr.obstacles = {island()};
  pr.min_obstacle_clearance = 185.2;
  auto fake = [&](const asv::PlanningProblem& p) {
    asv::Plan plan = p.seed == 7 ? waypointPlan({{0, 0}, {0, 4000}})
                                 : waypointPlan({{0, 0}, {-1500, 900}, {-1500, 3100}, {0, 4000}});
    plan.status = asv::PlanStatus::Fallback;
    return plan;
  };
  const asv::Plan p = asv::planUnderSharedRules(fake, pr);
  EXPECT_EQ(p.waypoints.size(), 4u);
  EXPECT_NE(p.message.find("of land"), std::string::npos) << p.message;
}

TEST(PlanUnderSharedRules, LandRequirementLetsAShipInsideTheClearanceMove) {
  const std::vector<asv::StaticObstacle> land = {island()};
  const Eigen::Vector2d far_goal(0.0, -10000.0);
  EXPECT_DOUBLE_EQ(asv::landRequirement({0.0, 0.0}, far_goal, land, 185.2),
                   185.2);  // 1 km off: the clearance
  EXPECT_DOUBLE_EQ(asv::landRequirement({0.0, 900.0}, far_goal, land, 185.2), 50.0);    // 100 m off: half
  EXPECT_DOUBLE_EQ(asv::landRequirement({0.0, 0.0}, {0.0, 960.0}, land, 185.2), 20.0);  // a berth 40 m off
  EXPECT_DOUBLE_EQ(asv::landRequirement({0.0, 900.0}, far_goal, {}, 185.2), 0.0);       // no land
  // Land beyond the reach is a later plan's: 800 m of a northbound track stop short of the shore.
  EXPECT_DOUBLE_EQ(asv::trackObstacleDistance(asv::truncateTrack({{0, 0}, {0, 4000}}, 800.0), land), 200.0);
  // A course-only plan is judged over its reach (speed x horizon, here 6 km): north, over the island.
  asv::Plan course_only;
  course_only.status = asv::PlanStatus::Ok;
  course_only.course_setpoint = 0.0;
  course_only.speed_setpoint = 5.0;
  EXPECT_DOUBLE_EQ(asv::trackObstacleDistance(asv::landTrack(course_only, {0.0, 0.0}, 6000.0), land), 0.0);
  course_only.course_setpoint = asv::kPi;  // south: away from it
  EXPECT_DOUBLE_EQ(asv::trackObstacleDistance(asv::landTrack(course_only, {0.0, 0.0}, 6000.0), land), 1000.0);
}

TEST(PlanFollower, FallbackStopsRatherThanRunAground) {
  asv::PlanFollower f;
  f.setObstacles({island()});
  f.updateOwn(own());  // heading north at 6 m/s: the island 1 km ahead
  const asv::Plan fb = f.fallback({}, "test");
  EXPECT_EQ(fb.status, asv::PlanStatus::Fallback);
  EXPECT_DOUBLE_EQ(fb.speed_setpoint, 0.0);
  EXPECT_NE(fb.message.find("land ahead"), std::string::npos);
  asv::PlanFollower open_sea;
  open_sea.updateOwn(own());
  EXPECT_DOUBLE_EQ(open_sea.fallback({}, "test").speed_setpoint, 3.0);  // half of 6 m/s: unchanged
}

TEST(PlanFollower, APlanInForceThatNowLeadsOntoLandIsReplanned) {
  asv::PlanFollower f;
  f.updateOwn(own());
  f.acceptPlan(waypointPlan({{0, 0}, {0, 4000}}), 0.0, {}, "first");  // no land known yet
  std::string why;
  EXPECT_FALSE(f.replanNeeded(100.0, {}, why));
  f.setObstacles({island()});  // e.g. a chart loaded: the plan in force crosses it
  EXPECT_TRUE(f.replanNeeded(100.0, {}, why));
  EXPECT_NE(why.find("of land"), std::string::npos);
}

// Issue: at start-up the tracks reached planner_node a moment before their first risk assessment, the
// first plan (t = 1 s) was made risk-blind, and in a being-overtaken encounter (own ship stand-on) ACO
// and GA turned 12-16 deg. The planner must leave unassessed targets out until the risk picture has had
// stale_after (10 s) to arrive; risk-blind planning is only for a picture that has gone silent.
TEST(PlanFollower, NoRiskBlindPlanningBeforeTheFirstAssessmentHadTimeToArrive) {
  const double stale_after = 10.0, start = 1000.0;
  EXPECT_FALSE(asv::riskBlindPlanning(false, start + 1.0, start, stale_after));  // the t = 1 s case
  EXPECT_FALSE(asv::riskBlindPlanning(false, start + 9.99, start, stale_after));
  EXPECT_TRUE(asv::riskBlindPlanning(false, start + 10.0, start, stale_after));   // silent 10 s: degraded
  EXPECT_FALSE(asv::riskBlindPlanning(true, start + 500.0, start, stale_after));  // a fresh picture
  EXPECT_FALSE(asv::riskBlindPlanning(false, start + 500.0, -1.0, stale_after));  // no input at all yet
}

// Which tracks reach the planner: unassessed tracks wait for their assessment while the risk picture
// is alive, and are planned against risk-blind once it is silent; the own track and broken tracks never.
TEST(PlanFollower, PlannerTargetsFollowTheRiskPicture) {
  auto track = [](const std::string& id, double x) {
    asv::ShipState s;
    s.id = id;
    s.position = {x, 1000.0};
    s.course = asv::kPi;
    s.speed = 5.0;
    return s;
  };
  asv::ShipState broken = track("broken", 0.0);
  broken.speed = std::nan("");
  const std::vector<asv::ShipState> tracks = {track("own", 0.0), track("a", 100.0), track("new", 200.0),
                                              broken};
  std::map<std::string, asv::PlannerTarget> assessed;
  assessed["a"].risk = asv::RiskLevel::Urgent;
  assessed["a"].role = asv::OwnRole::GiveWay;
  assessed["broken"].risk = asv::RiskLevel::Urgent;

  const auto alive = asv::selectPlannerTargets("own", tracks, assessed, true);
  ASSERT_EQ(alive.size(), 1u);
  EXPECT_EQ(alive[0].state.id, "a");
  EXPECT_EQ(alive[0].risk, asv::RiskLevel::Urgent);
  EXPECT_EQ(alive[0].role, asv::OwnRole::GiveWay);
  EXPECT_DOUBLE_EQ(alive[0].state.position.x(), 100.0);

  const auto silent = asv::selectPlannerTargets("own", tracks, assessed, false);
  ASSERT_EQ(silent.size(), 2u);
  EXPECT_EQ(silent[1].state.id, "new");
  EXPECT_EQ(silent[1].role, asv::OwnRole::None);  // risk-blind
  EXPECT_EQ(silent[1].risk, asv::RiskLevel::None);
}

// The route round the 2 km island from the origin to (0, 4000): its corners pushed out 1.2 x 185.2 m
// along the diagonals (222.2 m in x and y), e.g. (-1222.2, 777.8) and (-1222.2, 3222.2) on the west
// side; length 2 x hypot(1222.2, 777.8) + 2444.4 = 5341.8 m (the east side is as long).
TEST(LandRoute, ShortestWayRoundAnIslandKeepsTheClearance) {
  const std::vector<asv::StaticObstacle> land = {island()};
  const auto route = asv::landRoute({0.0, 0.0}, {0.0, 4000.0}, land, 185.2, 185.2);
  ASSERT_TRUE(route.has_value());
  ASSERT_EQ(route->size(), 2u);
  EXPECT_NEAR(std::fabs((*route)[0].x()), 1222.2, 0.1);
  EXPECT_NEAR((*route)[0].y(), 777.8, 0.1);
  std::vector<Eigen::Vector2d> track{{0.0, 0.0}};
  track.insert(track.end(), route->begin(), route->end());
  track.push_back({0.0, 4000.0});
  double length = 0.0;
  for (size_t i = 1; i < track.size(); ++i)
    length += (track[i] - track[i - 1]).norm();
  EXPECT_NEAR(length, 5341.8, 0.5);
  EXPECT_GE(asv::trackObstacleDistance(track, land), 185.2);
  // Clear water: no points; a goal on the island: no route.
  EXPECT_TRUE(asv::landRoute({0.0, 0.0}, {3000.0, 0.0}, land, 185.2, 185.2)->empty());
  EXPECT_FALSE(asv::landRoute({0.0, 0.0}, {0.0, 2000.0}, land, 185.2, 185.2).has_value());
}

TEST(LandRoute, TheFollowersProblemCarriesTheRouteRoundLand) {
  asv::PlanFollower f;
  f.setObstacles({island()});
  f.setGoal({0.0, 4000.0});
  f.updateOwn(own());
  const asv::PlanningProblem pr = f.buildProblem(0.0, {});
  EXPECT_EQ(pr.route.size(), 2u);
  EXPECT_DOUBLE_EQ(pr.min_obstacle_clearance, 185.2);
  f.setGoal({3000.0, 0.0});  // clear water: no route
  EXPECT_TRUE(f.buildProblem(0.0, {}).route.empty());
}

// A harbour entrance 400 m wide between two breakwaters (80 m thick, y = 0..80): the berth lies
// inside, and the ship arrives from off the axis. The only way in keeps 200 m from both heads, through
// the gap's middle (0, 40) or (0, 80)-(0, 0): not round the 2.4 km breakwater.
TEST(LandRoute, ThroughAHarbourEntranceNotRoundTheBreakwater) {
  const std::vector<asv::StaticObstacle> port = {{"west", {{-2600, 0}, {-200, 0}, {-200, 80}, {-2600, 80}}},
                                                 {"east", {{200, 0}, {2600, 0}, {2600, 80}, {200, 80}}}};
  const auto route = asv::landRoute({-500.0, 8000.0}, {0.0, -1500.0}, port, 185.2, 185.2);
  ASSERT_TRUE(route.has_value());
  ASSERT_FALSE(route->empty());
  std::vector<Eigen::Vector2d> track{{-500.0, 8000.0}};
  track.insert(track.end(), route->begin(), route->end());
  track.push_back({0.0, -1500.0});
  double length = 0.0;
  for (size_t i = 1; i < track.size(); ++i)
    length += (track[i] - track[i - 1]).norm();
  EXPECT_LT(length, 9600.0);  // the straight 9513 m and a little, not a 5 km detour
  EXPECT_GE(asv::trackObstacleDistance(track, port), 185.2);
}

namespace {

asv::Plan northPlan() {
  asv::Plan p;
  p.status = asv::PlanStatus::Ok;
  p.course_setpoint = 0.0;
  p.speed_setpoint = 6.0;
  p.waypoints = {{{0.0, 0.0}, 0.0, 0.0, 6.0}, {{0.0, 20000.0}, 3333.0, 0.0, 6.0}};
  return p;
}

asv::PlannerTarget westbound(const Eigen::Vector2d& at) {
  asv::PlannerTarget t;
  t.state.id = "ts1";
  t.state.position = at;
  t.state.course = t.state.heading = 1.5 * asv::kPi;  // west
  t.state.speed = 6.0;
  return t;
}

}  // namespace

TEST(PlanFollower, DeadReckonMovesThePictureOnAtEachCourseAndSpeed) {
  asv::PlannerTarget t = westbound({100.0, 50.0});
  const auto moved = asv::PlanFollower::deadReckon({t}, 10.0, 14.0);
  EXPECT_NEAR(moved[0].state.position.x(), 100.0 - 6.0 * 4.0, 1e-9);  // 4 s west at 6 m/s
  EXPECT_NEAR(moved[0].state.position.y(), 50.0, 1e-9);
}

TEST(PlanFollower, DegradedKeepsASafePlanForAMinuteThenHoldsCourseSlowly) {
  asv::PlanFollower f = follower(false);
  f.acceptPlan(northPlan(), 0.0, {}, "test");
  // The last picture: a ship 20 km east, westbound: she crosses x = 0 after 3333 s, beyond the
  // 1200 s horizon: the plan still passes her.
  const std::vector<asv::PlannerTarget> far{westbound({20000.0, 5000.0})};
  EXPECT_EQ(f.degrade(10.0, far, "risk: none for 2.0 s").status, asv::PlanStatus::Ok);
  EXPECT_TRUE(f.degraded());
  EXPECT_EQ(f.degrade(70.0, far, "risk: none for 62.0 s").status, asv::PlanStatus::Ok);  // 60 s held
  const asv::Plan& held = f.degrade(70.5, far, "risk: none for 62.5 s");
  EXPECT_EQ(held.status, asv::PlanStatus::Fallback);
  EXPECT_EQ(held.message.rfind("degraded: ", 0), 0u) << held.message;
  EXPECT_NE(held.message.find("risk: none for 62.5 s"), std::string::npos) << held.message;
  EXPECT_DOUBLE_EQ(held.course_setpoint, 0.0);  // the course she had
  EXPECT_DOUBLE_EQ(held.speed_setpoint, 3.0);   // 0.5 x 6 m/s
  // The course held is the one of the loss, not wherever she drifts afterwards.
  asv::ShipState drifted = own();
  drifted.course = 0.3;
  f.updateOwn(drifted);
  EXPECT_DOUBLE_EQ(f.degrade(80.0, far, "x").course_setpoint, 0.0);
}

TEST(PlanFollower, DegradedDropsAPlanThatNoLongerPassesTheLastPicture) {
  asv::PlanFollower f = follower(false);
  f.acceptPlan(northPlan(), 0.0, {}, "test");
  // By hand: own ship north at 6 m/s from (0, 0), target west at 6 m/s from (5000, 5000): both reach
  // (0, 5000) at t = 833 s, a collision course: the plan is not kept.
  const asv::Plan& p = f.degrade(1.0, {westbound({5000.0, 5000.0})}, "tracks: none for 1.6 s");
  EXPECT_EQ(p.status, asv::PlanStatus::Fallback);
  EXPECT_DOUBLE_EQ(p.speed_setpoint, 3.0);
  // Rechecked at every call: the last known ship (risk unknown) now 600 m off, inside extremis_range
  // (926 m): hard to starboard from the course held (000 -> 090) at full speed.
  const asv::Plan& x = f.degrade(2.0, {westbound({600.0, 0.0})}, "tracks: none for 2.6 s");
  EXPECT_NEAR(x.course_setpoint, asv::kPi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(x.speed_setpoint, 6.0);
  EXPECT_NE(x.message.find("in extremis with ts1"), std::string::npos) << x.message;
  // The picture comes back: a plan at once, whatever min_replan_interval says.
  f.recover();
  EXPECT_FALSE(f.degraded());
  std::string why;
  EXPECT_TRUE(f.replanNeeded(1.5, {}, why));
  EXPECT_EQ(why, "picture back after degraded operation");
  EXPECT_THROW(
      [] {
        asv::PlanFollowerConfig c;
        c.degraded_plan_hold = -1.0;
        c.validate();
      }(),
      std::invalid_argument);
}

namespace {

// The own ship of own() for a goal `ahead` m north, minimum separation 926 m, and one ship ts1 at `at`
// on `course_deg` at `speed` in the encounter `e` (the own ship's role from it).
asv::PlanningProblem oneShip(double ahead, const Eigen::Vector2d& at, double course_deg, double speed,
                             asv::Encounter e) {
  asv::PlanningProblem pr;
  pr.own = own();
  pr.goal = {0.0, ahead};
  pr.min_separation = 926.0;
  asv::PlannerTarget t;
  t.state.id = "ts1";
  t.state.position = at;
  t.state.course = t.state.heading = asv::degToRad(course_deg);
  t.state.speed = speed;
  t.encounter = e;
  t.role = asv::ownRole(e);
  pr.targets = {t};
  return pr;
}

}  // namespace

// The preferred passing distance (kPreferredSeparation x min_separation, planning.h): in open water the
// planner is asked for it first, and its plan is kept when it is Ok and keeps the ship's way. A head-on
// target 10 km ahead; the fake planner's plan turns due east at `speed` (the target, on x = 0, never
// comes within 9 km of that track: every rule kept).
TEST(PlanUnderSharedRules, OpenWaterAsksForThePreferredDistanceFirst) {
  asv::PlanningProblem pr = oneShip(20000.0, {0.0, 10000.0}, 180.0, 6.0, asv::Encounter::HeadOn);
  const asv::PlannerTarget t = pr.targets[0];
  std::vector<double> asked;
  double wide_speed = 6.0;
  auto east = [&](const asv::PlanningProblem& q) {
    asked.push_back(q.min_separation);
    const double v = q.min_separation > 926.0 ? wide_speed : 6.0;
    asv::Plan p;
    p.status = asv::PlanStatus::Ok;
    p.course_setpoint = asv::degToRad(90.0);
    p.speed_setpoint = v;
    p.waypoints = {{{0.0, 0.0}, 0.0, asv::degToRad(90.0), v},
                   {{12000.0, 0.0}, 12000.0 / v, asv::degToRad(90.0), v}};
    return p;
  };
  // Open water: one call, for 2 x 926 m; its plan is the answer.
  asv::Plan p = asv::planUnderSharedRules(east, pr);
  EXPECT_EQ(asked, (std::vector<double>{1852.0}));
  EXPECT_EQ(p.speed_setpoint, 6.0);
  // A wide plan at under half the planned speed (2.9 < 3 m/s) does not keep the ship's way. The own ship
  // keeps out of the way of a head-on ship: the net's turn to starboard at full speed for 1852 m is
  // taken, and the minimum is never asked for.
  asked.clear();
  wide_speed = 2.9;
  p = asv::planUnderSharedRules(east, pr);
  EXPECT_EQ(asked, (std::vector<double>{1852.0}));
  EXPECT_EQ(p.message.rfind("separation manoeuvre (preferred distance: ", 0), 0u) << p.message;
  const double turn = asv::radToDeg(std::remainder(p.course_setpoint, 2.0 * asv::kPi));
  EXPECT_GE(turn, 30.0 - 1e-9);
  EXPECT_LE(turn, 90.0 + 1e-9);
  ASSERT_EQ(p.waypoints.size(), 2u);
  EXPECT_EQ(p.waypoints[1].speed, 6.0);
  EXPECT_GE(asv::planSeparation(p, pr), 1852.0);
  // A second ship, crossing from her port side 8 km west (she stands on for it): she has a duty besides
  // keeping out of the way, and the net is not used for the preferred distance; the minimum is asked for.
  asv::PlannerTarget port = t;
  port.state.id = "ts2";
  port.state.position = {-8000.0, 8000.0};
  port.state.course = port.state.heading = asv::degToRad(90.0);
  port.encounter = asv::Encounter::CrossingStandOn;
  port.role = asv::OwnRole::StandOn;
  pr.targets.push_back(port);
  asked.clear();
  p = asv::planUnderSharedRules(east, pr);
  EXPECT_EQ(asked, (std::vector<double>{1852.0, 926.0}));
  pr.targets.pop_back();
  // The same for a ship she stands on for: no net (she keeps her course and speed for that ship, Rule
  // 17); the plan for the minimum is asked for and taken.
  pr.targets[0].encounter = asv::Encounter::CrossingStandOn;
  pr.targets[0].role = asv::OwnRole::StandOn;
  asked.clear();
  p = asv::planUnderSharedRules(east, pr);
  EXPECT_EQ(asked, (std::vector<double>{1852.0, 926.0}));
  EXPECT_EQ(p.speed_setpoint, 6.0);
  wide_speed = 3.0;  // half the speed exactly still keeps it
  asked.clear();
  EXPECT_EQ(asv::planUnderSharedRules(east, pr).speed_setpoint, 3.0);
  // Land 1 km ahead (within 1 nm): no open water, the minimum only.
  asked.clear();
  pr.obstacles = {island()};
  p = asv::planUnderSharedRules(east, pr);
  EXPECT_EQ(asked, (std::vector<double>{926.0}));
  // The island moved to 1852 m (1 nm) ahead: open water again.
  pr.obstacles = {{"island", {{-1000.0, 1852.0}, {1000.0, 1852.0}, {1000.0, 3000.0}, {-1000.0, 3000.0}}}};
  asked.clear();
  asv::planUnderSharedRules(east, pr);
  EXPECT_EQ(asked, (std::vector<double>{1852.0}));
}

// An overtaking is judged over the whole pass (passingHorizon), not the 1200 s prediction horizon. The own
// ship (north, 6 m/s, goal 30 km ahead) overtakes a ship 3 km ahead at 3 m/s. The fake planner's plan
// swings out to (2400, 300) (403 s) and back for the goal: by hand, at 1200 s the ship is 2015 m abeam
// and 1534 m astern of the target (2532 m apart), but she comes abeam at 1715 s only 1766 m off. The
// whole pass lasts 1000 s to the CPA + 2037 m / 3 m/s to open + 60 s = 1739 s. So the plan keeps the
// preferred 1852 m over the horizon but not over the pass, and the net's turn to starboard, held until
// the ship is clear, is taken instead; the minimum is never asked for.
TEST(PlanUnderSharedRules, AnOvertakingIsJudgedOverTheWholePass) {
  asv::PlanningProblem pr = oneShip(30000.0, {0.0, 3000.0}, 0.0, 3.0, asv::Encounter::Overtaking);
  std::vector<double> asked;
  auto swing = [&](const asv::PlanningProblem& q) {
    asked.push_back(q.min_separation);
    asv::Plan p;
    p.status = asv::PlanStatus::Ok;
    p.course_setpoint = asv::courseOf({2400.0, 300.0});
    p.speed_setpoint = 6.0;
    p.waypoints = {{{0.0, 0.0}, 0.0, p.course_setpoint, 6.0},
                   {{2400.0, 300.0}, std::hypot(2400.0, 300.0) / 6.0, p.course_setpoint, 6.0}};
    p.message = "swing";
    return p;
  };
  asv::PlanningProblem wide = pr;
  wide.min_separation = 1852.0;
  EXPECT_NEAR(asv::passingHorizon(wide), 1000.0 + 1.1 * 1852.0 / 3.0 + 60.0, 1e-6);
  EXPECT_GE(asv::planSeparation(swing(wide), wide), 1852.0);
  wide.prediction_horizon = asv::passingHorizon(wide);
  EXPECT_NEAR(asv::planSeparation(swing(wide), wide), 1766.0, 15.0);
  asked.clear();
  const asv::Plan p = asv::planUnderSharedRules(swing, pr);
  EXPECT_EQ(asked, (std::vector<double>{1852.0}));
  EXPECT_EQ(p.message.rfind("separation manoeuvre (preferred distance: swing)", 0), 0u) << p.message;
  EXPECT_GE(asv::planSeparation(p, wide), 1852.0);
  // Met head-on instead, the same plan is judged over the horizon and kept as it is.
  pr.targets[0].encounter = asv::Encounter::HeadOn;
  EXPECT_EQ(asv::planUnderSharedRules(swing, pr).message, "swing (for the preferred distance, 1852 m)");
}

namespace {

// A still ship at `at` that the own ship stands on for (left out of the problem).
asv::PlannerTarget stillStandOnShip(const Eigen::Vector2d& at) {
  asv::PlannerTarget still;
  still.state.id = "still";
  still.state.position = at;
  still.state.speed = 0.0;
  still.encounter = asv::Encounter::CrossingStandOn;
  still.role = asv::OwnRole::StandOn;
  return still;
}

// ts1 crossing from starboard, westbound from `at`: the own ship keeps out of its way (Rule 15).
asv::PlannerTarget westboundGiveWay(const Eigen::Vector2d& at, double speed) {
  asv::PlannerTarget crossing;
  crossing.state.id = "ts1";
  crossing.state.position = at;
  crossing.state.course = crossing.state.heading = asv::degToRad(270.0);
  crossing.state.speed = speed;
  crossing.encounter = asv::Encounter::CrossingGiveWay;
  crossing.role = asv::OwnRole::GiveWay;
  return crossing;
}

}  // namespace

// Rule 17(a)(i) gives way to a duty to keep out of the way. Own ship north at 6 m/s; a ship she stands
// on for lies still at (2340.0, 2113.1): 3000 m along the 030 line and 970 m to starboard of it, 2340 m
// off her present track. A plan that turns to 030 passes her at 970 m: closer than holding course and
// inside the 1018.6 m margin, so refused alone (the ship stands on). With a ship crossing from
// starboard to keep out of the way of (westbound at 1 m/s from (8000, 8000), over 3 km off the plan
// throughout), the duty comes first and only the 926 m minimum is asked of the stand-on pass: taken.
TEST(PlanUnderSharedRules, TheStandOnRuleYieldsToADutyToKeepOutOfTheWay) {
  asv::PlanningProblem pr;
  pr.own = own();
  pr.goal = {5000.0, 8660.3};
  pr.min_separation = 926.0;
  pr.stand_on_for = {stillStandOnShip({2340.0, 2113.1})};
  auto turn = [](const asv::PlanningProblem& p) {
    asv::Plan plan;
    plan.status = asv::PlanStatus::Ok;
    plan.course_setpoint = asv::degToRad(30.0);
    plan.speed_setpoint = 6.0;
    asv::PlannedWaypoint a, b;
    a.position = p.own.position;
    b.position = asv::courseSpeedToVelocity(asv::degToRad(30.0), 6.0) * 1200.0;
    b.time = 1200.0;
    b.speed = 6.0;
    plan.waypoints = {a, b};
    return plan;
  };
  EXPECT_NEAR(asv::planSeparation(turn(pr),
                                  [&] {
                                    asv::PlanningProblem w = pr;
                                    w.targets = pr.stand_on_for;
                                    return w;
                                  }()),
              970.0, 1.0);
  const asv::Plan alone = asv::planUnderSharedRules(turn, pr);
  EXPECT_NEAR(alone.course_setpoint, 0.0, 1e-9) << alone.message;
  EXPECT_NE(alone.message.find("stand on (Rule 17(a)(i))"), std::string::npos) << alone.message;

  pr.targets = {westboundGiveWay({8000.0, 8000.0}, 1.0)};
  const asv::Plan duty = asv::planUnderSharedRules(turn, pr);
  EXPECT_NEAR(duty.course_setpoint, asv::degToRad(30.0), 1e-9) << duty.message;
}

// While she stands on for a ship in a risk (standing_on) the shared rules keep her course and speed
// instead of a plan that turns her (a route bend 40 deg to starboard, say), without asking the planner.
// ts1 has given way (turned south at (-5000, 5000)): holding north she passes it 5000 m abeam at
// 5000 / 12 = 417 s, so the risk is none;
// with a duty to keep out of the way of another ship (ts2 crossing from starboard), or with land within
// 1 nm (a rock 1500 m to port, clear of the plan), the planner's plan.
TEST(PlanUnderSharedRules, SheKeepsHerCourseThroughARouteBendWhileSheStandsOn) {
  asv::PlanningProblem pr;
  pr.own = own();
  pr.goal = {12855.8, 15320.9};  // 040 deg, 20 km
  pr.min_separation = 926.0;
  asv::PlannerTarget ts1 = standOnTarget(true, asv::RiskLevel::None);
  ts1.state.course = ts1.state.heading = asv::kPi;
  ts1.tcpa = 416.7;
  pr.stand_on_for = pr.standing_on = {ts1};
  int asked = 0;
  auto bend = [&](const asv::PlanningProblem& p) {
    ++asked;
    asv::Plan plan;
    plan.status = asv::PlanStatus::Ok;
    plan.course_setpoint = asv::degToRad(40.0);
    plan.speed_setpoint = 6.0;
    plan.waypoints = {{p.own.position, 0.0, 0.0, 0.0}, {p.goal, 3333.0, asv::degToRad(40.0), 6.0}};
    return plan;
  };
  const asv::Plan held = asv::planUnderSharedRules(bend, pr);
  EXPECT_NEAR(held.course_setpoint, 0.0, 1e-12) << held.message;
  EXPECT_EQ(held.message, "stand on (Rule 17(a)(i)) for ts1 until past");
  EXPECT_EQ(asked, 0);
  asv::PlannerTarget ts2 = westboundGiveWay({8000.0, 8000.0}, 1.0);
  ts2.state.id = "ts2";
  pr.targets = {ts2};
  const asv::Plan duty = asv::planUnderSharedRules(bend, pr);
  EXPECT_NEAR(duty.course_setpoint, asv::degToRad(40.0), 1e-9) << duty.message;
  EXPECT_GE(asked, 1);
  pr.targets.clear();
  pr.obstacles = {{"rock", {{-1600.0, -100.0}, {-1500.0, -100.0}, {-1500.0, 100.0}, {-1600.0, 100.0}}}};
  asked = 0;
  const asv::Plan coastal = asv::planUnderSharedRules(bend, pr);
  EXPECT_NEAR(coastal.course_setpoint, asv::degToRad(40.0), 1e-9) << coastal.message;
  EXPECT_EQ(asked, 1);
}

// The net taken instead of a port plan keeps its margin from a ship she stands on for while she gives
// way to another (RuleCheck::closesStandOn asks the minimum of it). Own ship north at 6 m/s for a goal
// 20 km north; ts1 crosses from starboard, westbound from (5000, 5000) at 6 m/s (CPA 0 m at 833 s); a
// still ship she stands on for lies 3000 m out on the 030 line, (1500, 2598.1). The planner only turns
// 20 deg to port (refused, Rule 15). By hand, the net's turns to starboard from 000: 030 passes the
// still ship at 0 m, 040 at 3000 sin 10 = 521 m, 050 at 3000 sin 20 = 1026 m >= 1.1 x 926 m; ts1 is
// passed at 2988 m on 050 (relative velocity (-10.596, -3.857): 5000 x 6.739 / 11.276). So 050. Were
// the still ship left out of the net, its first turn, 030 (ts1 at 1830 m), would run into the still
// ship, be refused, and the port plan would stay.
TEST(PlanUnderSharedRules, TheNetForAPortPlanKeepsClearOfAShipSheStandsOnFor) {
  asv::PlanningProblem pr;
  pr.own = own();
  pr.goal = {0.0, 20000.0};
  pr.min_separation = 926.0;
  pr.targets = {westboundGiveWay({5000.0, 5000.0}, 6.0)};
  pr.targets[0].risk = asv::RiskLevel::Collision;
  pr.stand_on_for = {stillStandOnShip({1500.0, 2598.1})};
  auto port = [](const asv::PlanningProblem& q) {
    asv::Plan plan;
    plan.status = asv::PlanStatus::Ok;
    plan.course_setpoint = asv::wrapTwoPi(q.own.course - asv::degToRad(20.0));
    plan.speed_setpoint = q.own.speed;
    return plan;
  };
  const asv::Plan p = asv::planUnderSharedRules(port, pr);
  EXPECT_NEAR(p.course_setpoint, asv::degToRad(50.0), 1e-9) << p.message;
  EXPECT_NE(p.message.find("separation manoeuvre (the plan altered to port, Rules 14/15)"), std::string::npos)
      << p.message;
  asv::PlanningProblem watched = pr;
  watched.targets = pr.stand_on_for;
  EXPECT_GE(asv::planSeparation(p, watched), 926.0) << p.message;
}
