// The separation rule of the shared layer (safety_net.h, planUnderSharedRules): predictions checked
// against hand geometry, the separation manoeuvre checked by flying its route in the test's own loop.
#include <gtest/gtest.h>

#include <cmath>

#include "asv_core/common/units.h"
#include "asv_core/planning/plan_follower.h"
#include "asv_core/planning/safety_net.h"
#include "planner_target.h"

using namespace asv;

namespace {

PlannerTarget target(const std::string& id, const Eigen::Vector2d& pos, double course_deg, double speed) {
  return plannerTarget(id, pos, course_deg, speed);
}

// Own ship at the origin heading north at 6 m/s, goal 20 km ahead, minimum separation 926 m, and a
// ship met head-on 8 km ahead at 6 m/s (she gives way too, but nobody counts on it).
PlanningProblem headOn() {
  PlanningProblem pr;
  pr.own.id = "own";
  pr.own.speed = 6.0;
  pr.goal = {0.0, 20000.0};
  pr.min_separation = 926.0;
  PlannerTarget t = target("ts1", {0.0, 8000.0}, 180.0, 6.0);
  t.encounter = Encounter::HeadOn;
  t.role = OwnRole::BothGiveWay;
  pr.targets = {t};
  return pr;
}

Plan straightOn(const PlanningProblem& pr) {
  Plan p;
  p.status = PlanStatus::Ok;
  p.course_setpoint = pr.own.course;
  p.speed_setpoint = pr.own.speed;
  p.waypoints = {{pr.own.position, 0.0, 0.0, 0.0}, {pr.goal, 0.0, 0.0, pr.own.speed}};
  p.message = "straight on";
  return p;
}

// The test's own flight of a plan: waypoints at their speeds, then the goal at the plan's speed, 1 s
// steps, against the target holding course and speed; the smallest distance until arrival.
double flownSeparation(const Plan& p, const PlanningProblem& pr) {
  std::vector<Eigen::Vector2d> pts{pr.own.position};
  std::vector<double> speeds;
  for (size_t i = 1; i < p.waypoints.size(); ++i) {
    pts.push_back(p.waypoints[i].position);
    speeds.push_back(p.waypoints[i].speed);
  }
  pts.push_back(pr.goal);
  speeds.push_back(p.speed_setpoint);
  Eigen::Vector2d own = pts[0];
  size_t leg = 0;
  double best = 1e12;
  const auto& t = pr.targets[0].state;
  for (int s = 0; s < 4000 && leg < speeds.size(); ++s) {
    best = std::min(best, (t.position + t.velocity() * s - own).norm());
    const Eigen::Vector2d d = pts[leg + 1] - own;
    if (d.norm() <= speeds[leg])
      own = pts[++leg];
    else
      own += d.normalized() * speeds[leg];
  }
  return best;
}

}  // namespace

TEST(SafetyNet, RouteClearanceMatchesHandGeometry) {
  // A ship stopped at the origin; a target 1000 m east of the track x = 1000, northbound at 10 m/s,
  // abeam at t = 500 s: 1000 m.
  const std::vector<PlannerTarget> passing{target("a", {1000.0, -5000.0}, 0.0, 10.0)};
  EXPECT_NEAR(routeClearance({{{0.0, 0.0}}, {}}, passing, 1200.0), 1000.0, 1e-6);
  // Own ship 0 -> (0, 1000) at 10 m/s; a target from (0, 3000) southbound at 10 m/s. They are 1000 m
  // apart when the own ship reaches the end of her route (t = 100 s); if that end is the goal she has
  // arrived and left; if not she waits there and is run down at t = 200 s.
  const std::vector<PlannerTarget> meeting{target("b", {0.0, 3000.0}, 180.0, 10.0)};
  PredictedRoute r{{{0.0, 0.0}, {0.0, 1000.0}}, {10.0}, true};
  EXPECT_NEAR(routeClearance(r, meeting, 1200.0), 1000.0, 1e-6);
  r.ends_at_goal = false;
  EXPECT_NEAR(routeClearance(r, meeting, 1200.0), 0.0, 1e-6);
  EXPECT_TRUE(std::isinf(routeClearance(r, {}, 1200.0)));
}

TEST(SafetyNet, AStraightOnPlanIntoAHeadOnShipIsReplacedByAStarboardManoeuvre) {
  PlanningProblem pr = headOn();
  EXPECT_NEAR(planSeparation(straightOn(pr), pr), 0.0, 60.0);  // they meet at 4 km: 0 m, by 5 s samples
  int calls = 0;
  auto straight = [&](const PlanningProblem& q) { return ++calls, straightOn(q); };
  // In open water the planner is asked for the preferred 2 x 926 m; its straight plan is refused and the
  // net's turn to starboard at full speed for that distance is taken.
  Plan p = planUnderSharedRules(straight, pr);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(p.message.rfind("separation manoeuvre (preferred distance: straight on)", 0), 0u) << p.message;
  const double turn = std::remainder(p.course_setpoint - pr.own.course, kTwoPi);
  EXPECT_GE(turn, degToRad(30.0) - 1e-9);
  ASSERT_EQ(p.waypoints.size(), 2u);
  EXPECT_DOUBLE_EQ(p.waypoints[1].speed, 6.0);
  EXPECT_GE(flownSeparation(p, pr), 1852.0);
  // A ship the risk layer gives no encounter (so no give-way duty): the minimum, asked for again.
  pr.targets[0].encounter = Encounter::None;
  calls = 0;
  p = planUnderSharedRules(straight, pr);
  EXPECT_EQ(calls,
            5);  // the preferred distance (open water), the first plan and three retries, all straight on
  EXPECT_EQ(p.status, PlanStatus::Ok);
  EXPECT_NE(p.message.find("separation manoeuvre (every plan in 4 tries"), std::string::npos) << p.message;
  // The first preference: 30 deg to starboard (Rule 14, readily apparent by Rule 8), at full speed.
  EXPECT_NEAR(std::remainder(p.course_setpoint - pr.own.course, kTwoPi), degToRad(30.0), 1e-9);
  ASSERT_EQ(p.waypoints.size(), 2u);
  EXPECT_DOUBLE_EQ(p.waypoints[1].speed, 6.0);
  // Flown by the test's own loop, the manoeuvre and the way back to the goal keep the minimum.
  EXPECT_GE(flownSeparation(p, pr), 926.0);
}

// A manoeuvre renewed while the ship is already turned away (heading 040 after an earlier one) is
// measured from the way to the goal (000), not from her heading: 030 again, not 070. From her heading,
// each renewal added 30 deg more and the ship turned full circles in crowded waters.
TEST(SafetyNet, ARenewedManoeuvreIsMeasuredFromTheWayNotTheHeading) {
  PlanningProblem pr = headOn();
  pr.own.course = pr.own.heading = degToRad(40.0);
  const Plan p = separationManoeuvre(pr, 0.0, "renewed");
  EXPECT_NEAR(p.course_setpoint, degToRad(30.0), 1e-9) << p.message;
  EXPECT_GE(flownSeparation(p, pr), 926.0);
  // With a land route the way is its next point: due east of the ship, so 090 + 30 = 120.
  pr.route = {{3000.0, 0.0}};
  EXPECT_NEAR(separationManoeuvre(pr, 0.0, "route").course_setpoint, degToRad(120.0), 1e-9);
}

TEST(SafetyNet, NoSolutionBecomesTheManoeuvreAndWithoutAMinimumNothingChanges) {
  PlanningProblem pr = headOn();
  auto none = [](const PlanningProblem&) {
    Plan p;
    p.status = PlanStatus::NoSolution;
    p.message = "stuck";
    return p;
  };
  Plan net = planUnderSharedRules(none, pr);  // open water: the net for the preferred distance
  EXPECT_EQ(net.status, PlanStatus::Ok);
  EXPECT_NE(net.message.find("preferred distance: stuck"), std::string::npos) << net.message;
  pr.targets[0].encounter = Encounter::None;  // no give-way duty: the net for the minimum
  net = planUnderSharedRules(none, pr);
  EXPECT_EQ(net.status, PlanStatus::Ok);
  EXPECT_NE(net.message.find("no solution: stuck"), std::string::npos) << net.message;
  pr.min_separation = 0.0;  // the planners' own distances: the shared layer does not judge
  EXPECT_EQ(planUnderSharedRules(none, pr).status, PlanStatus::NoSolution);
  EXPECT_EQ(planUnderSharedRules(straightOn, pr).message, "straight on");
}

TEST(SafetyNet, TheStandOnShipHoldsCourseWhenThePlanWouldCloseHerGiveWayShip) {
  // A give-way ship from port, expected to act, so the follower leaves her to stand_on_for. Holding
  // course the own ship passes 1202 m astern of her (relative motion by hand: r0 = (-3000, 4700),
  // v = (6, -6), TCPA 641.7 s, DCPA |(850, 850)| = 1202 m); steering 020 for a goal there, 238 m
  // (same formula, v = (6 - 2.05, -5.64)). The shared layer holds course and speed instead.
  PlanningProblem pr;
  pr.own.id = "own";
  pr.own.speed = 6.0;
  pr.goal = {6840.4, 18793.9};  // 020 deg, 20 km
  pr.min_separation = 926.0;
  PlannerTarget gw = target("gw", {-3000.0, 4700.0}, 90.0, 6.0);
  gw.encounter = Encounter::CrossingStandOn;
  gw.role = OwnRole::StandOn;
  gw.compliant = true;
  pr.stand_on_for = {gw};
  auto toGoal = [](const PlanningProblem& q) {
    Plan p = straightOn(q);
    p.course_setpoint = courseOf(q.goal - q.own.position);
    return p;
  };
  const Plan p = planUnderSharedRules(toGoal, pr);
  EXPECT_NE(p.message.find("stand on (Rule 17(a)(i))"), std::string::npos) << p.message;
  EXPECT_NEAR(p.course_setpoint, 0.0, 1e-12);
  ASSERT_EQ(p.waypoints.size(), 2u);
  EXPECT_DOUBLE_EQ(p.waypoints[1].speed, 6.0);
}

// The stand-on hold lasts until the way back is clear. Own ship north at 6 m/s, her goal at (3000, 0);
// a give-way ship from port, eastbound at 6 m/s from (-4000, 2000). Holding course, by hand: relative
// position (-4000, 2000), velocity (6, -6), TCPA 36000 / 72 = 500 s, DCPA |(-1000, -1000)| = 1414 m,
// wider than 1.1 x 926 m: past at 500 + 60 = 560 s. Steering for the goal from (0, 3360) then (velocity
// 6 x (3000, -3360) / 4504.4 = (4.00, -4.48)), with the ship at (-640, 2000): relative (-640, -1360),
// (2.00, 4.48), TCPA 306 s, DCPA 30 m, a collision course of her own making. The hold is lengthened
// until the way back passes her at min(1.1 x 1852, 1414) - 1 = 1413 m, checked here with the CPA in
// closed form (the shared layer samples the plan); half a minute less would not.
TEST(SafetyNet, TheStandOnHoldLastsUntilTheWayBackIsClear) {
  PlanningProblem pr;
  pr.own.id = "own";
  pr.own.speed = 6.0;
  pr.goal = {3000.0, 0.0};
  pr.min_separation = 926.0;
  PlannerTarget gw = target("gw", {-4000.0, 2000.0}, 90.0, 6.0);
  gw.encounter = Encounter::CrossingStandOn;
  gw.role = OwnRole::StandOn;
  const Cpa held = computeCpa(pr.own.position, pr.own.velocity(), gw.state.position, gw.state.velocity());
  EXPECT_NEAR(held.tcpa, 500.0, 1e-9);
  EXPECT_NEAR(held.dcpa, 1414.2, 0.1);
  auto wayBack = [&](double hold) {  // the CPA of the straight way from the hold's end to the goal
    const Eigen::Vector2d at = pr.own.position + pr.own.velocity() * hold;
    const Eigen::Vector2d v = courseSpeedToVelocity(courseOf(pr.goal - at), 6.0);
    return computeCpa(at, v, gw.state.position + gw.state.velocity() * hold, gw.state.velocity()).dcpa;
  };
  EXPECT_NEAR(wayBack(560.0), 30.0, 5.0);
  const Plan p = holdCoursePlan(pr, {gw});
  ASSERT_EQ(p.waypoints.size(), 2u);
  EXPECT_NEAR(p.course_setpoint, 0.0, 1e-12);
  const double hold = p.waypoints[1].time;
  EXPECT_GT(hold, 560.0);
  EXPECT_GE(wayBack(hold), 1413.0 - 5.0) << "hold " << hold << " s";
  EXPECT_LT(wayBack(hold - 30.0), 1413.0) << "hold " << hold << " s";
}

// How planUnderSharedRules seeks the preferred distance: the net's turns to starboard at full speed only.
// A ship crossing from starboard at 4 m/s, westbound 1 km ahead: where no turn to starboard at full speed
// keeps the margin, the net by its order of preference slows down on the way (target 2.5 km east) or
// turns 30 deg to port (1.5 km east); restricted, it keeps to starboard at full speed.
TEST(SafetyNet, ThePreferredDistanceIsSoughtOnlyToStarboardAtFullSpeed) {
  for (double east : {2500.0, 1500.0}) {
    PlanningProblem pr = headOn();
    PlannerTarget t = target("ts1", {east, 1000.0}, 270.0, 4.0);
    t.encounter = Encounter::CrossingGiveWay;
    t.role = OwnRole::GiveWay;
    pr.targets = {t};
    const Plan any = separationManoeuvre(pr, 0.0, "any");
    ASSERT_EQ(any.waypoints.size(), 2u);
    const double any_turn = std::remainder(any.course_setpoint - pr.own.course, kTwoPi);
    EXPECT_TRUE(any.waypoints[1].speed < 6.0 || any_turn < 0.0) << any.message;
    const Plan starboard = separationManoeuvre(pr, 0.0, "starboard", NetOptions::preferredDistance());
    ASSERT_EQ(starboard.waypoints.size(), 2u);
    EXPECT_DOUBLE_EQ(starboard.waypoints[1].speed, 6.0) << starboard.message;
    EXPECT_GE(std::remainder(starboard.course_setpoint - pr.own.course, kTwoPi), degToRad(30.0) - 1e-9);
  }
}

namespace {

// Own ship at the origin heading north at 6 m/s for a goal 30 km ahead; a ship `ahead` m ahead on the
// same course at `speed`, which she overtakes (Rule 13).
PlanningProblem slowOvertaking(double ahead, double speed) {
  PlanningProblem pr = headOn();
  pr.goal = {0.0, 30000.0};
  PlannerTarget t = target("ts1", {0.0, ahead}, 0.0, speed);
  t.encounter = Encounter::Overtaking;
  t.role = OwnRole::GiveWay;
  pr.targets = {t};
  return pr;
}

// The same, sought for the preferred distance as planUnderSharedRules seeks it: 1852 m, judged over the
// whole pass.
PlanningProblem preferredOvertaking(double ahead, double speed) {
  PlanningProblem pr = slowOvertaking(ahead, speed);
  pr.min_separation = 1852.0;
  pr.prediction_horizon = passingHorizon(pr);
  return pr;
}

}  // namespace

// passingHorizon: sailing for the goal, the own ship closes a ship 2000 m ahead at 6 - 4 = 2 m/s: CPA
// (DCPA 0) at 1000 s, and the range opens to 1.1 x 926 = 1018.6 m another 509.3 s later; plus a minute:
// 1569.3 s, beyond the 1200 s prediction horizon.
TEST(SafetyNet, PassingHorizonLastsUntilAnOvertakenShipIsPast) {
  PlanningProblem pr = slowOvertaking(2000.0, 4.0);
  EXPECT_NEAR(passingHorizon(pr), 1000.0 + 1.1 * 926.0 / 2.0 + 60.0, 1e-6);
  // 10 km ahead at 5 m/s: 10000 s to the CPA, held to kLongestPass.
  EXPECT_DOUBLE_EQ(passingHorizon(slowOvertaking(10000.0, 5.0)), kLongestPass);
  // No overtaking: the prediction horizon, whatever the pass takes.
  pr.targets[0].encounter = Encounter::HeadOn;
  EXPECT_DOUBLE_EQ(passingHorizon(pr), pr.prediction_horizon);
}

// Rule 13(d): sought for the preferred distance (min_separation 1852 m, judged over the whole pass), the
// net's turn is held until the overtaken ship is clear on the way back to the goal, not only until she is
// past on the new course, though never longer than kLongestHold. Checked by the test's own flight; the
// same turn held only until past on it (hold by hand: TCPA + the time to open to 1.1 x 1852 m + 60 s)
// comes back closer than 1852 m.
TEST(SafetyNet, ThePreferredTurnIsHeldUntilAnOvertakenShipIsClear) {
  PlanningProblem pr = preferredOvertaking(3000.0, 3.0);
  double predicted = 0.0;
  const Plan p = separationManoeuvre(pr, 0.0, "preferred", NetOptions::preferredDistance(), &predicted);
  ASSERT_EQ(p.waypoints.size(), 2u) << p.message;
  EXPECT_GE(flownSeparation(p, pr), 1852.0) << p.message;
  EXPECT_NEAR(predicted, flownSeparation(p, pr), 1.0) << p.message;  // what the net reports is what it flies

  const Eigen::Vector2d rel_p = pr.targets[0].state.position - pr.own.position;
  const Eigen::Vector2d rel_v =
      pr.targets[0].state.velocity() - courseSpeedToVelocity(p.course_setpoint, 6.0);
  const double tcpa = -rel_p.dot(rel_v) / rel_v.squaredNorm();
  const double dcpa = std::abs(rel_p.x() * rel_v.y() - rel_p.y() * rel_v.x()) / rel_v.norm();
  const double open = 1.1 * 1852.0;
  const double past = tcpa + std::sqrt(std::max(0.0, open * open - dcpa * dcpa)) / rel_v.norm() + 60.0;
  EXPECT_GT(p.waypoints[1].time, past + 1.0) << p.message;
  EXPECT_LE(p.waypoints[1].time, kLongestHold) << p.message;
  Plan until_past = p;
  until_past.waypoints[1].time = past;
  until_past.waypoints[1].position = pr.own.position + courseSpeedToVelocity(p.course_setpoint, 6.0) * past;
  EXPECT_LT(flownSeparation(until_past, pr), 1852.0);
}

// Rule 13(d) as a seaman overtakes: when no turn held at most kLongestHold and then undone towards the
// goal keeps the preferred distance over the whole of a slow pass (6 m/s past a ship 3000 m ahead at
// 4.5 m/s: the CPA is 2000 s away), the net offsets to one side and runs parallel to the way until the
// overtaken ship is clear. By hand: 30 deg to starboard until 1.1 x 1.1 x 1852 = 2240.9 m off the way
// (2240.9 / (6 sin 30 deg) = 747.0 s), then north; the overtaken ship stays on x = 0, so the pass is
// the offset, 2240.9 m. With the ship 300 m to starboard of the way, the offset is to port, away from her.
TEST(SafetyNet, ASlowOvertakingIsPassedOnAnOffsetParallelToTheWay) {
  PlanningProblem pr = preferredOvertaking(3000.0, 4.5);
  double predicted = 0.0;
  const Plan p = separationManoeuvre(pr, 0.0, "preferred", NetOptions::preferredDistance(), &predicted);
  ASSERT_EQ(p.waypoints.size(), 3u) << p.message;
  EXPECT_NEAR(radToDeg(std::remainder(p.course_setpoint, kTwoPi)), 30.0, 1e-9) << p.message;
  EXPECT_NEAR(p.waypoints[1].position.x(), 2240.92, 1e-6);
  EXPECT_NEAR(p.waypoints[1].time, 2240.92 / 3.0, 1e-6);
  EXPECT_NEAR(p.waypoints[2].position.x(), 2240.92, 1e-6);  // parallel to the way (north)
  EXPECT_GT(p.waypoints[2].position.y(), pr.targets[0].state.position.y() + 4.5 * p.waypoints[2].time);
  EXPECT_NEAR(predicted, 2240.92, 1.0) << p.message;
  EXPECT_GE(flownSeparation(p, pr), 1852.0) << p.message;

  pr.targets[0].state.position.x() = 300.0;
  const Plan port = separationManoeuvre(pr, 0.0, "preferred", NetOptions::preferredDistance());
  ASSERT_EQ(port.waypoints.size(), 3u) << port.message;
  EXPECT_LT(std::remainder(port.course_setpoint, kTwoPi), 0.0) << port.message;
  EXPECT_GE(flownSeparation(port, pr), 1852.0) << port.message;
}
