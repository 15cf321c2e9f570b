// RunRecorder and the COLREGs score on scripted two-ship encounters whose geometry is worked out by
// hand in the comments (own ship at the origin heading north at 5 m/s unless said otherwise).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include <yaml-cpp/yaml.h>

#include "asv_core/eval/evaluation.h"

using namespace asv;

namespace {

struct Script {
  Eigen::Vector2d own0{0.0, 0.0};
  double own_speed = 5.0;
  std::map<double, double> own_course_deg{{0.0, 0.0}};  // from time t: course
  Eigen::Vector2d tgt0{5000.0, 5000.0};
  double tgt_course_deg = 270.0, tgt_speed = 5.0;
  std::map<double, double> tgt_turns;  // from time t: ts1's new course (none: tgt_course_deg throughout)
  double duration = 2000.0;
  struct Other {  // a further target (ts2, ts3, ...), holding course and speed
    Eigen::Vector2d p0;
    double course_deg, speed;
  };
  std::vector<Other> others;
  std::vector<StaticObstacle> land;
};

double courseAt(const std::map<double, double>& sched, double t) {
  auto it = sched.upper_bound(t + 1e-9);
  --it;
  return degToRad(it->second);
}

// Kinematic ships sampled every second: the course of sample t is the one sailed from t to t + 1.
RunRecorder record(const Script& s, const EvaluationConfig& cfg = {},
                   const std::vector<SimEvent>& events = {}) {
  RunInfo info;
  info.scenario = "scripted";
  info.planner = "test";
  info.seed = 7;
  info.ships = {{"own", std::nullopt, "test"}, {"ts1", std::nullopt, ""}};
  std::vector<Script::Other> tgts{{s.tgt0, s.tgt_course_deg, s.tgt_speed}};
  for (const auto& o : s.others) {
    info.ships.push_back({"ts" + std::to_string(tgts.size() + 1), std::nullopt, ""});
    tgts.push_back(o);
  }
  info.origin = {54.0, 3.0};  // the open North Sea
  info.obstacles = s.land;
  RunRecorder rec(cfg, info);
  Eigen::Vector2d po = s.own0;
  std::vector<Eigen::Vector2d> pt;
  pt.reserve(tgts.size());
  for (const auto& o : tgts)
    pt.push_back(o.p0);
  for (int k = 0; k <= static_cast<int>(s.duration); ++k) {
    const double t = k;
    const double co = courseAt(s.own_course_deg, t);
    if (!s.tgt_turns.empty() && t + 1e-9 >= s.tgt_turns.begin()->first)
      tgts[0].course_deg = radToDeg(courseAt(s.tgt_turns, t));
    std::vector<ShipSample> ships(1 + tgts.size());
    ships[0].name = "own";
    ships[0].state.position = po;
    ships[0].state.course = ships[0].state.heading = co;
    ships[0].state.speed = s.own_speed;
    ships[0].course_setpoint = co;
    for (size_t n = 0; n < tgts.size(); ++n) {
      ShipSample& tgt = ships[n + 1];
      tgt.name = info.ships[n + 1].name;
      tgt.state.position = pt[n];
      tgt.state.course = tgt.state.heading = degToRad(tgts[n].course_deg);
      tgt.state.speed = tgts[n].speed;
    }
    rec.addSample(t, ships);
    for (const auto& e : events)
      if (std::fabs(e.time - t) < 0.5)
        rec.addEvent(e);
    po += courseSpeedToVelocity(co, s.own_speed);
    for (size_t n = 0; n < tgts.size(); ++n)
      pt[n] += courseSpeedToVelocity(degToRad(tgts[n].course_deg), tgts[n].speed);
  }
  return rec;
}

bool hasNote(const TargetResult& t, const std::string& prefix) {
  for (const auto& n : t.notes)
    if (n.compare(0, prefix.size(), prefix) == 0)
      return true;
  return false;
}

}  // namespace

TEST(Evaluation, SafetyScoreIsPiecewiseLinearBetweenTheRanges) {
  // 1 nm preferred, 0.5 nm minimum (score 0.5), 0.1 nm near miss (score 0).
  EXPECT_DOUBLE_EQ(safetyScore(5000.0, 1852.0, 926.0, 185.2, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(safetyScore(1852.0, 1852.0, 926.0, 185.2, 0.5), 1.0);
  EXPECT_NEAR(safetyScore(1389.0, 1852.0, 926.0, 185.2, 0.5), 0.75, 1e-12);
  EXPECT_NEAR(safetyScore(926.0, 1852.0, 926.0, 185.2, 0.5), 0.5, 1e-12);
  EXPECT_NEAR(safetyScore(555.6, 1852.0, 926.0, 185.2, 0.5), 0.25, 1e-12);
  EXPECT_DOUBLE_EQ(safetyScore(185.2, 1852.0, 926.0, 185.2, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(safetyScore(10.0, 1852.0, 926.0, 185.2, 0.5), 0.0);
}

TEST(Evaluation, CleanEarlyStarboardGiveWayScoresFull) {
  // Target from starboard: (5000, 5000) heading west at 5 m/s, collision at (0, 5000) at t = 1000 s
  // (TCPA 1000 s, DCPA 0: risk at t = 0). Own turns 60 deg to starboard at t = 10 s, 7 km away.
  // Afterwards: relative position (4950, 4950), relative velocity (-9.330, -2.5): DCPA =
  // |4950 * -2.5 - 4950 * -9.330| / 9.659 = 3500 m > 1852 m, so safety 1; the own ship reaches the
  // target's track at x = 8574 m when the target is at x = -4950 m: astern. No penalty.
  Script s;
  s.own_course_deg = {{0.0, 0.0}, {10.0, 60.0}};
  const RunResult r = record(s).finish();
  ASSERT_EQ(r.own.targets.size(), 1u);
  const TargetResult& t = r.own.targets[0];
  EXPECT_EQ(t.encounter, Encounter::CrossingGiveWay);
  EXPECT_STREQ(toString(t.role), "give_way");
  EXPECT_TRUE(t.evaluated);
  EXPECT_NEAR(t.tcpa_at_start, 1000.0, 1e-9);
  EXPECT_NEAR(t.dcpa_at_start, 0.0, 1e-6);
  EXPECT_GT(t.min_distance, 3499.0);
  EXPECT_TRUE(t.colregs_ok);
  EXPECT_DOUBLE_EQ(t.score, 1.0);
  EXPECT_DOUBLE_EQ(r.own.colregs_score, 1.0);
  EXPECT_FALSE(r.collision);
  EXPECT_FALSE(r.safety_violation);
  ASSERT_EQ(r.own.manoeuvres.size(), 1u);
  EXPECT_DOUBLE_EQ(r.own.manoeuvres[0].time, 10.0);
  EXPECT_NEAR(radToDeg(r.own.manoeuvres[0].course_change), 60.0, 1e-9);
}

TEST(Evaluation, PortTurnInHeadOnGetsTheRule14Penalty) {
  // Head-on 10 km apart closing at 10 m/s. Own turns 40 deg to port at t = 100 s (9 km: early,
  // apparent). Then relative position (3214, 9000), relative velocity (3.214, -8.830): DCPA 3081 m,
  // safety 1. Only the port turn is penalised: score 1 x (1 - 0.5) = 0.5.
  Script s;
  s.tgt0 = {0.0, 10000.0};
  s.tgt_course_deg = 180.0;
  s.own_course_deg = {{0.0, 0.0}, {100.0, -40.0}};
  const RunResult r = record(s).finish();
  const TargetResult& t = r.own.targets.at(0);
  EXPECT_EQ(t.encounter, Encounter::HeadOn);
  EXPECT_STREQ(toString(t.encounter), "head_on");
  EXPECT_FALSE(t.colregs_ok);
  EXPECT_TRUE(hasNote(t, "rule 14"));
  EXPECT_FALSE(hasNote(t, "rule 8"));
  EXPECT_FALSE(hasNote(t, "rule 16"));
  EXPECT_NEAR(t.score, 0.5, 1e-12);
  EXPECT_NEAR(r.own.colregs_score, 0.5, 1e-12);
}

// The Rule 14 note says whether an alternative was open at the port turn (t = 100 s; the own ship at
// (0, 495) on 000 at 5 m/s, ts1 at (0, 9505) on 180): each alteration of 10-90 deg to starboard held
// until ts1 is past, then back on 000, and half speed on 000. By hand: 10 deg (0.868, 4.924) m/s passes
// ts1 at 9010 x 0.868 / 9.962 = 785 m < 926 m; 20 deg (1.710, 4.698): 9010 x 1.710 / 9.848 = 1565 m at
// 901 s, then back on 000 from (1541, 4728) with ts1 at (0, 5000) abeam, 1541 m: open. A ship lying
// still at (1500, 3098) (on the old single 30 deg test line) closes 20 deg to 520 m and 40 deg to 525 m
// (perpendicular distances from the line through (0, 495)) and 30 deg to 0 m, but 50 deg passes it
// 1030 m off and ts1 3807 m off: open, so that ship no longer makes the turn "forced". A coast 200 m
// to starboard (x >= 200 m) closes every starboard alteration (10 deg reaches x = 782 m), and half speed
// on 000 meets ts1 head-on (DCPA 0): forced. The finding and its penalty stand either way.
TEST(Evaluation, Rule14NoteSaysWhetherAPortTurnWasForced) {
  Script s;
  s.tgt0 = {0.0, 10000.0};
  s.tgt_course_deg = 180.0;
  s.own_course_deg = {{0.0, 0.0}, {100.0, -40.0}};
  auto rule14 = [](const Script& sc) {
    const RunResult r = record(sc).finish();
    const TargetResult& t = r.own.targets.at(0);
    EXPECT_NEAR(t.score, 0.5, 1e-12);
    for (const auto& n : t.notes)
      if (n.rfind("rule 14: turned", 0) == 0)
        return n;
    return std::string("no rule 14 note");
  };
  EXPECT_NE(rule14(s).find("; not forced: 20 deg to starboard was open"), std::string::npos) << rule14(s);
  Script ship = s;
  ship.others = {{{1500.0, 3098.08}, 0.0, 0.0}};
  EXPECT_NE(rule14(ship).find("; not forced: 50 deg to starboard was open"), std::string::npos)
      << rule14(ship);
  Script coast = s;
  coast.land = {
      {"coast", {{200.0, -1000.0}, {9000.0, -1000.0}, {9000.0, 20000.0}, {200.0, 20000.0}}, nullptr}};
  EXPECT_NE(rule14(coast).find("; forced: no turn of 10-90 deg to starboard nor half speed kept clear"),
            std::string::npos)
      << rule14(coast);
}

// Rule 14 governs while the risk of collision lasts. Own ship north at 5 m/s from the origin, ts1 met
// head-on from (0, 10000) southbound at 5 m/s (entry at t = 0: CPA 0 m in 1000 s). At t = 50 s ts1 turns
// 60 deg to starboard (240): from (0, 9500) relative to the own ship held on 000 at 5 m/s, the relative
// velocity is (-4.330, -7.500), 8.660 m/s, so the CPA is 950 s ahead at 9500 sin 30 = 4750 m >= 1852 m:
// ts1 alone has removed the risk. The own ship turns 40 deg to port (320) at t = 400 s, before the
// closest approach: by hand from (0, 2000) and ts1 at (-1515.5, 8875), relative (-1515.5, 6875) and
// (-1.116, -6.330), the CPA is 2686 m at t = 1412 s. That turn is for no risk with ts1: no Rule 14
// finding, range >= 2 x 926 m (safety 1), first action at 7 km (early): score 1. When ts1 turns only
// 10 deg (190), relative velocity (-0.868, -9.924): the CPA stays 9500 x 0.868 / 9.962 = 828 m, the
// risk lasts, and the same port turn is a Rule 14 finding.
TEST(Evaluation, Rule14JudgesPortTurnsWhileTheRiskLasts) {
  Script s;
  s.tgt0 = {0.0, 10000.0};
  s.tgt_course_deg = 180.0;
  s.tgt_turns = {{50.0, 240.0}};
  s.own_course_deg = {{0.0, 0.0}, {400.0, -40.0}};
  const TargetResult removed = record(s).finish().own.targets.at(0);
  EXPECT_EQ(removed.encounter, Encounter::HeadOn);
  EXPECT_FALSE(hasNote(removed, "rule 14")) << removed.notes.front();
  EXPECT_NEAR(removed.min_distance, 2686.0, 5.0);
  EXPECT_NEAR(removed.score, 1.0, 1e-12);
  // The port turn was for no risk with ts1: it earns no Rule 8 or 16 credit either; the risk went at
  // t = 50 s, 9500 m off, before an action was due.
  EXPECT_TRUE(hasNote(removed, "the target's own motion removed the risk at t=50 s"))
      << removed.notes.front();
  EXPECT_EQ(removed.first_side, 0);
  s.tgt_turns = {{50.0, 190.0}};
  const TargetResult lasting = record(s).finish().own.targets.at(0);
  EXPECT_TRUE(hasNote(lasting, "rule 14: turned 40 deg to port"));
}

// A port turn that brings the actual CPA below entry_dcpa_m again is judged whatever the held-course
// copy says. ts1 met head-on from (0, 10000) turns 25 deg to starboard (205) at t = 50 s: from (0, 9750),
// relative to the own ship held on 000 at (0, 250), r = (0, 9500), v = (-2.113, -9.532): CPA 9500 x
// 2.113 / 9.763 = 2056 m >= 1852 m, so ts1 alone removed the risk. The own ship turns 20 deg to port
// (340) at t = 300 s from (0, 1500), ts1 at (-528.3, 8617): r = (-528.3, 7117), v = (-0.403, -9.230),
// CPA (528.3 x 9.230 + 7117 x 0.403) / 9.239 = 838 m < 1852 m: she made the risk again, a Rule 14
// finding (the held-course copy alone would have seen none).
TEST(Evaluation, PortTurnThatRecreatesTheRiskIsARule14Finding) {
  Script s;
  s.tgt0 = {0.0, 10000.0};
  s.tgt_course_deg = 180.0;
  s.tgt_turns = {{50.0, 205.0}};
  s.own_course_deg = {{0.0, 0.0}, {300.0, -20.0}};
  const TargetResult t = record(s).finish().own.targets.at(0);
  EXPECT_EQ(t.encounter, Encounter::HeadOn);
  EXPECT_TRUE(hasNote(t, "rule 14: turned 20 deg to port in a head-on encounter")) << t.notes.front();
  EXPECT_EQ(t.first_side, -1);
  EXPECT_NEAR(t.min_distance, 838.0, 10.0);
}

// The same port turn made while overtaking ts2, a slow ship ahead ((0, 1700) north at 1 m/s: TCPA
// 1700 / 4 = 425 s, DCPA 0 at t = 0, so the own ship keeps out of its way from the start until she
// passes it, at t = 300 + 111 s: relative (0, 500) and (1.710, -3.698) after the turn), is excused
// for ts1: the note names ts2 and there is no Rule 14 finding.
TEST(Evaluation, PortTurnThatRecreatesTheRiskIsExcusedByADutyToAnotherShip) {
  Script s;
  s.tgt0 = {0.0, 10000.0};
  s.tgt_course_deg = 180.0;
  s.tgt_turns = {{50.0, 205.0}};
  s.own_course_deg = {{0.0, 0.0}, {300.0, -20.0}};
  s.others = {{{0.0, 1700.0}, 0.0, 1.0}};
  const RunResult r = record(s).finish();
  const TargetResult& t1 = r.own.targets.at(0);
  EXPECT_EQ(r.own.targets.at(1).encounter, Encounter::Overtaking);
  EXPECT_TRUE(
      hasNote(t1, "rule 14: the turn to port at t=300 s was made keeping out of the way of ts2: excused"))
      << t1.notes.front();
  EXPECT_FALSE(hasNote(t1, "rule 14: turned"));
}

// The side of the first alteration counts, not the larger one. Head-on as above with ts1 holding 180:
// 35 deg to starboard at t = 100 s (early, apparent), then at t = 300 s from (573.6, 1319) to 330 with
// ts1 at (0, 8500): r = (-573.6, 7181), v = (2.5, -9.330), CPA |(-573.6)(-9.330) - 7181 x 2.5| / 9.659 =
// 1304 m < 1852 m: a swing across the entry course to port while the risk lasts.
TEST(Evaluation, SwingAcrossTheEntryCourseToPortIsARule14Finding) {
  Script s;
  s.tgt0 = {0.0, 10000.0};
  s.tgt_course_deg = 180.0;
  s.own_course_deg = {{0.0, 0.0}, {100.0, 35.0}, {300.0, -30.0}};
  const RunResult r = record(s).finish();
  const TargetResult& t = r.own.targets.at(0);
  EXPECT_EQ(t.first_side, 1);
  EXPECT_TRUE(hasNote(t,
                      "rule 14: swung across the entry course to 30 deg to port at t=300 s (after 35 deg "
                      "to starboard) while the risk lasted"))
      << t.notes.front();
  EXPECT_FALSE(hasNote(t, "rule 8"));
  EXPECT_FALSE(hasNote(t, "rule 16"));
  EXPECT_NEAR(t.min_distance, 1304.0, 10.0);
  EXPECT_NE(toJson(r).find("\"first_alteration\": \"starboard\""), std::string::npos);
}

// Rule 16 is judged at the first readily apparent action: a 6 deg nudge at t = 100 s, then 40 deg to
// starboard at t = 800 s. Just before it (t = 799 s) the own ship is at (365.3, 3975.9) on 006 and ts1 at
// (0, 6005): range 2062 m, TCPA (365.3 x 0.523 + 2029.1 x 9.973) / 99.73 = 201 s, both below 2 nm and
// 8 min: late, p = 0.3 x (1 - 2062 / 3704).
TEST(Evaluation, Rule16IsJudgedAtTheFirstApparentAction) {
  Script s;
  s.tgt0 = {0.0, 10000.0};
  s.tgt_course_deg = 180.0;
  s.own_course_deg = {{0.0, 0.0}, {100.0, 6.0}, {800.0, 40.0}};
  const TargetResult t = record(s).finish().own.targets.at(0);
  EXPECT_TRUE(hasNote(t, "rule 16: first apparent action at t=800 s, 2062 m and 201 s from CPA: late"))
      << t.notes.front();
}

// Rule 16 "so far as possible": ts1 from starboard at (1500, 1500) heading west, collision at (0, 1500)
// at t = 300 s, so the rules apply from t = 0 at 2121 m and TCPA 300 s, already inside 2 nm and 8 min.
// A 60 deg turn at t = 30 s is within reaction_s (60 s) of the entry: early. At t = 90 s it is late:
// at t = 89 s own (0, 445), ts1 (1055, 1500): range 1055 sqrt 2 = 1492 m, TCPA 1055 / 5 = 211 s.
// With reaction_s = 0 the turn at t = 30 s is judged on t = 29 s: own (0, 145), ts1 (1355, 1500):
// 1916 m and 271 s.
TEST(Evaluation, Rule16CountsAnActionWithinTheReactionTimeOfACloseEntryAsEarly) {
  Script s;
  s.tgt0 = {1500.0, 1500.0};
  s.duration = 600.0;
  s.own_course_deg = {{0.0, 0.0}, {30.0, 60.0}};
  const TargetResult prompt = record(s).finish().own.targets.at(0);
  EXPECT_EQ(prompt.encounter, Encounter::CrossingGiveWay);
  EXPECT_FALSE(hasNote(prompt, "rule 16")) << prompt.notes.front();
  EvaluationConfig none;
  none.reaction_s = 0.0;
  const TargetResult strict = record(s, none).finish().own.targets.at(0);
  EXPECT_TRUE(hasNote(strict, "rule 16: first apparent action at t=30 s, 1916 m and 271 s from CPA: late"));
  s.own_course_deg = {{0.0, 0.0}, {90.0, 60.0}};
  const TargetResult slow = record(s).finish().own.targets.at(0);
  EXPECT_TRUE(hasNote(slow, "rule 16: first apparent action at t=90 s, 1492 m and 211 s from CPA: late"));
}

// Rule 8 judges the whole turn the own ship made while the risk lasted. The crossing of the clean case;
// the own ship turns to starboard at 1 deg/s from t = 10 s to 40 deg (t = 50 s) and ts1 turns north at
// t = 20 s, which removes the risk: on the entry course the own ship would then keep 6.9 km from her
// (no relative motion), so the risk lasted to t = 19 s, when the own ship had turned 9 deg. Judged as
// 9 deg, Rule 8 would cost 0.3 x (1 - 9/30) = 0.21; the turn under way runs on to 40 deg: no finding.
TEST(Evaluation, Rule8MeasuresATurnUnderWayWhenTheTargetRemovedTheRiskToItsEnd) {
  Script s;
  s.duration = 600.0;
  for (int i = 0; i <= 40; ++i)
    s.own_course_deg[10.0 + i] = i;
  s.tgt_turns = {{20.0, 0.0}};
  const TargetResult t = record(s).finish().own.targets.at(0);
  EXPECT_EQ(t.encounter, Encounter::CrossingGiveWay);
  EXPECT_FALSE(hasNote(t, "rule 8")) << t.notes.front();
  EXPECT_DOUBLE_EQ(t.score, 1.0);
  // Stopped at 9 deg, the turn is judged as made: 9 deg.
  Script half = s;
  half.own_course_deg.clear();
  for (int i = 0; i <= 9; ++i)
    half.own_course_deg[10.0 + i] = i;
  const TargetResult h = record(half).finish().own.targets.at(0);
  EXPECT_TRUE(hasNote(h, "rule 8: starboard turn 9 deg (speed -0 %) < 30 deg apparent"));
}

// Rule 8(b): three 8 deg steps to starboard (t = 100, 200, 300 s: three manoeuvres, 30 s window) are a
// succession of small alterations; two are not.
TEST(Evaluation, ASuccessionOfSmallAlterationsIsARule8bFinding) {
  Script s;
  s.tgt0 = {0.0, 10000.0};
  s.tgt_course_deg = 180.0;
  s.own_course_deg = {{0.0, 0.0}, {100.0, 8.0}, {200.0, 16.0}, {300.0, 24.0}};
  const TargetResult three = record(s).finish().own.targets.at(0);
  EXPECT_TRUE(hasNote(three, "rule 8(b): a succession of small alterations to starboard (8, 8, 8 deg"))
      << three.notes.front();
  s.own_course_deg = {{0.0, 0.0}, {100.0, 8.0}, {200.0, 16.0}};
  const TargetResult two = record(s).finish().own.targets.at(0);
  EXPECT_FALSE(hasNote(two, "rule 8(b)"));
}

TEST(Evaluation, StandOnShipThatTurnsEarlyGetsTheRule17Penalty) {
  // Target from port: (-5000, 5000) heading east; own is stand-on. Own turns 40 deg to starboard at
  // t = 10 s while the target is far from urgent (TCPA 990 s > 600 s). Afterwards the DCPA is
  // |(-4950)(-3.830) - 4950 * 1.786| / 4.226 = 2394 m (safety 1, never urgent): score 0.5.
  Script s;
  s.tgt0 = {-5000.0, 5000.0};
  s.tgt_course_deg = 90.0;
  s.own_course_deg = {{0.0, 0.0}, {10.0, 40.0}};
  const RunResult r = record(s).finish();
  const TargetResult& t = r.own.targets.at(0);
  EXPECT_EQ(t.encounter, Encounter::CrossingStandOn);
  EXPECT_STREQ(toString(t.role), "stand_on");
  EXPECT_TRUE(hasNote(t, "rule 17"));
  EXPECT_NEAR(t.score, 0.5, 1e-12);
}

namespace {

// ts1 from port, (-5000, 5000) heading east, for which the own ship stands on; she turns 40 deg to
// starboard at t = 10 s. ts2 starts ts2_range ahead at 5 m/s on the given course.
Script standOnTurnWith(double ts2_course_deg, double ts2_range = 8000.0) {
  Script s;
  s.tgt0 = {-5000.0, 5000.0};
  s.tgt_course_deg = 90.0;
  s.others = {{{0.0, ts2_range}, ts2_course_deg, 5.0}};
  s.own_course_deg = {{0.0, 0.0}, {10.0, 40.0}};
  return s;
}

}  // namespace

TEST(Evaluation, StandOnAlterationWhileGivingWayToAnotherShipIsNoRule17Finding) {
  // ts1 as in the test above: from port, (-5000, 5000) heading east, the own ship stands on; her
  // 40 deg starboard turn at t = 10 s leaves it at DCPA 2394 m (safety 1). ts2 meets her head-on:
  // (0, 8000) heading south at 5 m/s, TCPA 800 s <= 1800 s, DCPA 0: both give way from t = 0. The duty
  // is real: just before the turn (t = 9 s) ts2's TCPA is 7910 / 10 = 791 s <= 900 s; 60 s after it
  // (t = 70 s, own at (192.8, 279.8) on 040, ts2 at (0, 7650)) ts2's CPA has widened from 0 to
  // |192.8 x 8.830 + 7370.2 x 3.214| / 9.397 = 2702 m and ts1's from 0 to 2394 m. ts2 scores 1 (40 deg
  // >= 30, Rule 8; at 7.9 km, Rule 16), and the turn taken while keeping out of ts2's way is no Rule 17
  // finding for ts1: 1, not 0.5.
  const RunResult r = record(standOnTurnWith(180.0)).finish();
  ASSERT_EQ(r.own.targets.size(), 2u);
  const TargetResult& t1 = r.own.targets[0];
  const TargetResult& t2 = r.own.targets[1];
  EXPECT_EQ(t1.encounter, Encounter::CrossingStandOn);
  EXPECT_EQ(t2.encounter, Encounter::HeadOn);
  EXPECT_FALSE(hasNote(t1, "rule 17:"));
  EXPECT_TRUE(hasNote(
      t1, "rule 17 not applied: the stand-on ship altered at t=10 s while keeping out of the way of ts2"));
  EXPECT_TRUE(t1.colregs_ok);
  EXPECT_DOUBLE_EQ(t1.score, 1.0);
  EXPECT_TRUE(t2.colregs_ok);
  EXPECT_DOUBLE_EQ(t2.score, 1.0);
  EXPECT_DOUBLE_EQ(r.own.colregs_score, 1.0);
}

TEST(Evaluation, ADutyOutsideItsActionWindowDoesNotExcuseAnEarlyStandOnAlteration) {
  // ts2 head-on from 12 km: a duty (TCPA 1200 s <= 1800 s at entry), but at the turn its TCPA is
  // 11910 / 10 = 1191 s > 900 s: not yet in its own action window, so it does not excuse the early
  // stand-on alteration for ts1: 0.5, and the note says why.
  const RunResult r = record(standOnTurnWith(180.0, 12000.0)).finish();
  const TargetResult& t1 = r.own.targets.at(0);
  EXPECT_TRUE(hasNote(t1, "rule 17: the stand-on ship altered"));
  EXPECT_NE(t1.notes.front().find("; not excused by ts2: its TCPA 1191 s is outside 900 s"),
            std::string::npos)
      << t1.notes.front();
  EXPECT_NEAR(t1.score, 0.5, 1e-12);
}

TEST(Evaluation, AnotherShipWithoutRiskDoesNotExcuseAnEarlyStandOnAlteration) {
  // The same turn, but ts2 sails north 12 km ahead at the own ship's speed: no relative motion, no risk,
  // no duty. ts1's finding stands: 0.5, as with ts1 alone.
  const RunResult r = record(standOnTurnWith(0.0)).finish();
  const TargetResult& t1 = r.own.targets.at(0);
  EXPECT_TRUE(hasNote(t1, "rule 17: the stand-on ship altered"));
  EXPECT_NEAR(t1.score, 0.5, 1e-12);
}

TEST(Evaluation, StandOnShipThatHoldsCourseAndSpeedPastRMinIsNotPenalised) {
  // Target from port at (-5000, 3000) heading east: relative position (-5000, 3000), relative velocity
  // (5, -5): TCPA 800 s, DCPA |(-5000)(-5) - 3000 * 5| / 7.071 = 1414.2 m (< 1852 m: risk). Holding on,
  // the give-way ship passes at 1414 m > r_min without doing anything, so Rule 17(b) never comes: no
  // rule penalty. Safety: 0.5 + 0.5 (1414.2 - 926) / 926 = 0.7636.
  Script s;
  s.tgt0 = {-5000.0, 3000.0};
  s.tgt_course_deg = 90.0;
  const RunResult r = record(s).finish();
  const TargetResult& t = r.own.targets.at(0);
  EXPECT_EQ(t.encounter, Encounter::CrossingStandOn);
  EXPECT_TRUE(t.colregs_ok);
  EXPECT_NEAR(t.min_distance, 10000.0 / std::sqrt(50.0), 0.5);
  EXPECT_NEAR(t.score, 0.5 + 0.5 * (t.min_distance - 926.0) / 926.0, 1e-9);
}

namespace {

// Rule 17(b) on ts1 from port at (-5000, 4000) heading east at 5 m/s, which never gives way: relative
// position (-5000 + 5t, 4000 - 5t) at time t, DCPA |(-5000)(-5) - 4000 * 5| / 7.071 = 707.1 m after
// 900 s. The give-way ship's best own action is 90 deg to port (north, the own ship's velocity), which
// freezes the range once taken: taken 60 s later (extremis_delay_s) it keeps 926 m while
// (5(t+60) - 5000)^2 + (4000 - 5(t+60))^2 >= 926^2, i.e. 5(t+60) <= 4077.2, t <= 755.4 s. From the
// sample at t = 756 s (range |(-1220, 220)| = 1239.7 m) she alone cannot keep r_min; the range falls
// below 926 m at t = 815.4 s.
Script extremis(std::map<double, double> own_course_deg) {
  Script s;
  s.tgt0 = {-5000.0, 4000.0};
  s.tgt_course_deg = 90.0;
  s.own_course_deg = std::move(own_course_deg);
  return s;
}

}  // namespace

TEST(Evaluation, StandOnShipThatHoldsIntoRMinGetsTheRule17bFinding) {
  // The own ship holds on to the CPA at 707.1 m. At t = 756 s (own at (0, 3780)) 40 deg to starboard
  // was open: relative velocity (1.786, -3.830), CPA after 169.2 s at |(-1220)(-3.830) - 220 * 1.786| /
  // 4.226 = 1012.7 m, then back on 000 from (543.8, 4428.1) with ts1 at (-374, 4000): CPA
  // |(-917.8)(-5) - (-428.1)(5)| / 7.071 = 951.7 m >= 926 m (30 deg gives 914 m on that leg). Score:
  // safety 0.5 (707.1 - 185.2) / (926 - 185.2) = 0.352, x (1 - penalty_extremis 0.5).
  const RunResult r = record(extremis({{0.0, 0.0}})).finish();
  const TargetResult& t = r.own.targets.at(0);
  EXPECT_EQ(t.encounter, Encounter::CrossingStandOn);
  EXPECT_FALSE(t.colregs_ok);
  ASSERT_EQ(t.notes.size(), 2u);  // the finding and the closest approach
  EXPECT_EQ(t.notes[0],
            "rule 17(b): the stand-on ship held her course and speed into 707 m (< 926 m) from t=756 s, when "
            "the give-way ship alone could no longer keep 926 m; 40 deg to starboard was open");
  const double dcpa = 5000.0 / std::sqrt(50.0);
  EXPECT_NEAR(t.min_distance, dcpa, 0.5);
  EXPECT_NEAR(t.score, 0.5 * 0.5 * (t.min_distance - 185.2) / (926.0 - 185.2), 1e-9);
  EXPECT_TRUE(r.safety_violation);

  // With a 30 s delay the give-way ship's point comes later: 5(t + 30) <= 4077.2, t <= 785.4 s. At
  // t = 786 s (own at (0, 3930), ts1 at (-1070, 4000)) nothing was open to the own ship either (the
  // best, 50 deg to starboard, passes at 890 m; half speed at 416 m): no Rule 17(b) finding.
  EvaluationConfig quick;
  quick.extremis_delay_s = 30.0;
  const RunResult rq = record(extremis({{0.0, 0.0}}), quick).finish();
  const TargetResult& q = rq.own.targets.at(0);
  EXPECT_FALSE(hasNote(q, "rule 17(b)"));
  EXPECT_TRUE(q.colregs_ok);
}

TEST(Evaluation, StandOnShipThatActsAtTheExtremisPointHasNoRule17bFinding) {
  // The same ships; the own ship turns 40 deg to starboard at t = 760 s, after the give-way ship alone
  // could no longer keep r_min (756 s) but before the range falls below it (815 s). TCPA 140 s and DCPA
  // 707 m then: urgent (Hu level 2), so Rule 17(a)(ii) allows it too. No Rule 17 finding of any kind.
  const RunResult r = record(extremis({{0.0, 0.0}, {760.0, 40.0}})).finish();
  const TargetResult& t = r.own.targets.at(0);
  EXPECT_FALSE(hasNote(t, "rule 17"));
  EXPECT_TRUE(t.colregs_ok);
}

TEST(Evaluation, TenDegreeAlterationGetsTheRule8Penalty) {
  // The crossing of the clean case, but only 10 deg to starboard at t = 10 s. DCPA afterwards:
  // relative velocity (-5.868, -4.924), |4950 * -4.924 - 4950 * -5.868| / 7.660 = 610 m; with the
  // ranges set to 500/300/100 m the safety is 1, so the score is 1 - 0.3 (1 - 10/30) = 0.8.
  Script s;
  s.own_course_deg = {{0.0, 0.0}, {10.0, 10.0}};
  EvaluationConfig cfg;
  cfg.ranges_from_scenario = false;
  cfg.r_pref_m = 500.0;
  cfg.r_min_m = 300.0;
  cfg.r_nm_m = 100.0;
  const RunResult r = record(s, cfg).finish();
  const TargetResult& t = r.own.targets.at(0);
  EXPECT_NEAR(t.min_distance, 610.0, 1.0);
  EXPECT_TRUE(hasNote(t, "rule 8"));
  EXPECT_FALSE(hasNote(t, "rule 16"));
  EXPECT_FALSE(hasNote(t, "rule 15"));
  EXPECT_NEAR(t.score, 0.8, 1e-9);
}

TEST(Evaluation, LateGiveWayGetsAProportionalRule16Penalty) {
  // The crossing with a 60 deg starboard turn only at t = 800 s. Just before (t = 799 s): own at
  // (0, 3995), target at (1005, 5000): range 1421.3 m, TCPA 2010 * 5 / 50 = 201 s. Earliness
  // max(1421.3 / 3704, 201 / 480) = 0.41875: penalty 0.3 (1 - 0.41875) = 0.174375. With ranges
  // 600/400/100 m the pass (DCPA 707 m) is safe: score 0.825625.
  Script s;
  s.own_course_deg = {{0.0, 0.0}, {800.0, 60.0}};
  EvaluationConfig cfg;
  cfg.ranges_from_scenario = false;
  cfg.r_pref_m = 600.0;
  cfg.r_min_m = 400.0;
  cfg.r_nm_m = 100.0;
  const RunResult r = record(s, cfg).finish();
  const TargetResult& t = r.own.targets.at(0);
  EXPECT_TRUE(hasNote(t, "rule 16"));
  EXPECT_FALSE(hasNote(t, "rule 8"));
  EXPECT_NEAR(t.score, 1.0 - 0.3 * (1.0 - 201.0 / 480.0), 1e-9);
}

TEST(Evaluation, CrossingAheadOfTheStandOnShipGetsTheRule15Penalty) {
  // Target from starboard at (3000, 3000) heading west at 2 m/s: relative velocity (-2, -5), TCPA
  // (6000 + 15000) / 29 = 724 s, DCPA |3000 * -5 - 3000 * -2| / 5.385 = 1671 m: risk. Own holds north at
  // 5 m/s and is on the target's track line (y = 3000) at t = 600 s; the first sample past it, t = 601 s,
  // (or t = 600 s itself, by rounding) has the target 1798-1800 m away, ahead of it (< 3704 m).
  Script s;
  s.tgt0 = {3000.0, 3000.0};
  s.tgt_speed = 2.0;
  const RunResult r = record(s).finish();
  const TargetResult& t = r.own.targets.at(0);
  EXPECT_EQ(t.encounter, Encounter::CrossingGiveWay);
  double ahead = 0.0;
  for (const auto& n : t.notes)
    std::sscanf(n.c_str(), "rule 15: crossed %lf m ahead", &ahead);
  EXPECT_GE(ahead, 1798.0);
  EXPECT_LE(ahead, 1800.0);
  EXPECT_TRUE(hasNote(t, "rule 16"));  // and it never acted
  EXPECT_TRUE(hasNote(t, "rule 8"));
}

TEST(Evaluation, CollisionScoresZero) {
  Script s;  // the crossing with no action: the ships meet at (0, 5000) at t = 1000 s
  const RunResult r = record(s, {}, {{SimEvent::Collision, 1000.0, "own", "ts1", 0.0}}).finish();
  EXPECT_TRUE(r.collision);
  EXPECT_TRUE(r.own.collision);
  EXPECT_DOUBLE_EQ(r.own.targets.at(0).score, 0.0);
  EXPECT_DOUBLE_EQ(r.own.colregs_score, 0.0);
  EXPECT_FALSE(r.own.targets.at(0).colregs_ok);
  EXPECT_NEAR(r.own.min_separation, 0.0, 1e-6);
  EXPECT_TRUE(r.safety_violation);
}

// The own ship (100 x 20 m) sails north from the origin at 5 m/s past an island whose west shore is
// at x = 300 for y in [500, 1500]: its starboard side passes 290 m off.
TEST(Evaluation, DistanceToLandIsMeasuredFromTheHull) {
  RunInfo info;
  info.scenario = "land";
  info.ships = {{"own", std::nullopt, ""}};
  info.obstacles = {{"island", {{300, 500}, {1300, 500}, {1300, 1500}, {300, 1500}}, nullptr}};
  RunRecorder rec({}, info);
  for (int k = 0; k <= 600; ++k) {
    ShipSample own;
    own.name = "own";
    own.state.position = {0.0, 5.0 * k};
    own.state.speed = 5.0;
    own.state.length = 100.0;
    own.beam = 20.0;
    rec.addSample(k, {own});
  }
  const RunResult r = rec.finish();
  EXPECT_FALSE(r.own.grounding);
  EXPECT_NEAR(r.own.min_obstacle_distance, 290.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.own.colregs_score, 1.0);
  EXPECT_NE(toJson(r).find("\"grounding\": false, \"min_obstacle_distance_m\": 290.0"), std::string::npos);
}

TEST(Evaluation, GroundingScoresZeroLikeACollision) {
  RunInfo info;
  info.scenario = "land";
  info.ships = {{"own", std::nullopt, ""}};
  info.obstacles = {{"island", {{-500, 500}, {500, 500}, {500, 1500}, {-500, 1500}}, nullptr}};
  RunRecorder rec({}, info);
  ShipSample own;
  own.name = "own";
  own.state.position = {0.0, 1000.0};  // in the middle of the island
  own.state.length = 100.0;
  rec.addSample(0.0, {own});
  const RunResult r = rec.finish();
  EXPECT_TRUE(r.own.grounding);
  EXPECT_DOUBLE_EQ(r.own.min_obstacle_distance, 0.0);
  EXPECT_DOUBLE_EQ(r.own.colregs_score, 0.0);
  EXPECT_FALSE(r.collision);
  // The simulator's event alone (a contact between two samples) is a grounding too.
  RunInfo open = info;
  open.obstacles.clear();
  RunRecorder ev({}, open);
  own.state.position = {0.0, 0.0};
  ev.addSample(0.0, {own});
  ev.addEvent({SimEvent::Grounding, 0.5, "own", "island", 0.0});
  EXPECT_TRUE(ev.finish().own.grounding);
}

TEST(Evaluation, CollisionIsTheOwnShipsAndTargetsCollisionsAreCounted) {
  RunInfo info;
  info.scenario = "c";
  info.ships = {{"own", std::nullopt, ""}, {"a", std::nullopt, ""}, {"b", std::nullopt, ""}};
  RunRecorder rec({}, info);
  ShipSample own, a, b;
  own.name = "own";
  a.name = "a";
  a.state.position = {5000.0, 0.0};
  b.name = "b";
  b.state.position = {5000.0, 10.0};
  rec.addSample(0.0, {own, a, b});
  rec.addEvent({SimEvent::Collision, 0.0, "a", "b", 10.0});
  const RunResult r = rec.finish();
  EXPECT_FALSE(r.collision);  // two other ships touched: not the own ship's collision
  EXPECT_EQ(r.collisions_between_targets, 1);
  EXPECT_NE(toJson(r).find("\"collision\": false, \"collisions_between_targets\": 1"), std::string::npos);
}

TEST(Evaluation, ManoeuvresAreConsolidatedOverTheWindow) {
  RunInfo info;
  info.scenario = "m";
  info.ships = {{"own", std::nullopt, ""}};
  RunRecorder rec({}, info);
  ShipSample own;
  own.name = "own";
  own.state.course = 0.0;
  own.state.speed = 5.0;
  rec.addSample(0.0, {own});
  rec.addSetpoint(0.0, "own", degToRad(2.0));      // below 5 deg: no manoeuvre
  rec.addSetpoint(100.0, "own", degToRad(20.0));   // starts one ...
  rec.addSetpoint(105.0, "own", degToRad(30.0));   // ... consolidated with this (within 30 s)
  rec.addSetpoint(300.0, "own", degToRad(33.0));   // 3 deg: none
  rec.addSetpoint(400.0, "own", degToRad(350.0));  // back 43 deg to port from 33
  const RunResult r = rec.finish();
  ASSERT_EQ(r.own.manoeuvres.size(), 2u);
  EXPECT_DOUBLE_EQ(r.own.manoeuvres[0].time, 100.0);
  EXPECT_NEAR(radToDeg(r.own.manoeuvres[0].course_change), 30.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.own.manoeuvres[1].time, 400.0);
  EXPECT_NEAR(radToDeg(r.own.manoeuvres[1].course_change), -40.0, 1e-9);
}

TEST(Evaluation, JsonIsDeterministicWithFixedKeysAndNullForUnknowns) {
  Script s;
  s.own_course_deg = {{0.0, 0.0}, {10.0, 60.0}};
  RunRecorder a = record(s), b = record(s);
  a.addPlanTime(0.002);
  b.addPlanTime(0.002);
  const std::string ja = toJson(a.finish()), jb = toJson(b.finish());
  EXPECT_EQ(ja, jb);
  EXPECT_EQ(toJson(a.finish(), true), toJson(b.finish(), true));
  EXPECT_EQ(ja.find('\n'), std::string::npos);  // one line: JSON Lines
  EXPECT_EQ(
      ja.rfind("{\"scenario\": \"scripted\", \"planner\": \"test\", \"seed\": 7, \"collision\": false, ", 0),
      0u);
  // No obstacles: no grounding, and no distance to land.
  EXPECT_NE(ja.find("\"grounding\": false, \"min_obstacle_distance_m\": null"), std::string::npos);
  // No goal, not arrived: time_to_goal_s and path_ratio are null, never NaN.
  EXPECT_NE(ja.find("\"arrived\": false, \"time_to_goal_s\": null"), std::string::npos);
  EXPECT_NE(ja.find("\"path_ratio\": null"), std::string::npos);
  EXPECT_EQ(ja.find("nan"), std::string::npos);
  EXPECT_EQ(ja.find("inf"), std::string::npos);
  EXPECT_NE(ja.find("\"manoeuvres\": [{\"t_s\": 10.0, \"course_change_deg\": 60.0}]"), std::string::npos);
  EXPECT_NE(ja.find("\"plan_time_ms\": {\"median\": 2.000, \"max\": 2.000, \"count\": 1}"),
            std::string::npos);
  // Key order of the whole object (docs/evaluation.md).
  size_t pos = 0;
  for (const char* key : {"scenario", "planner", "seed", "collision", "collisions_between_targets",
                          "grounding", "min_obstacle_distance_m", "min_separation_m", "safety_violation",
                          "arrived", "time_to_goal_s", "path_length_m", "path_ratio", "manoeuvres", "targets",
                          "colregs_score", "plan_time_ms", "wall_time_s"}) {
    const size_t at = ja.find(std::string("\"") + key + "\":", pos);
    ASSERT_NE(at, std::string::npos) << key;
    pos = at;
  }
  for (const char* key : {"\"name\": \"ts1\"", "\"encounter\": \"crossing\"", "\"own_role\": \"give_way\"",
                          "\"min_distance_m\"", "\"tcpa_at_start_s\": 1000.0", "\"dcpa_at_start_m\": 0.0",
                          "\"colregs_ok\": true", "\"colregs_notes\": []"})
    EXPECT_NE(ja.find(key), std::string::npos) << key;
  RunResult z = a.finish();
  z.wall_time = 1.234;
  zeroWallClock(z);
  EXPECT_NE(toJson(z).find("\"wall_time_s\": 0.000"), std::string::npos);
}

TEST(Evaluation, ArrivalGivesTimeToGoalAndPathRatio) {
  RunInfo info;
  info.scenario = "a";
  info.ships = {{"own", Eigen::Vector2d(0.0, 1000.0), ""}};
  RunRecorder rec({}, info);
  for (int k = 0; k <= 200; ++k) {
    ShipSample own;
    own.name = "own";
    own.state.position = {0.0, 5.0 * k};
    own.state.speed = 5.0;
    rec.addSample(k, {own});
  }
  rec.addEvent({SimEvent::Arrival, 200.0, "own", "", 0.0});
  const RunResult r = rec.finish();
  EXPECT_TRUE(r.own.arrived);
  EXPECT_DOUBLE_EQ(r.own.time_to_goal, 200.0);
  EXPECT_NEAR(r.own.path_length, 1000.0, 1e-9);
  EXPECT_NEAR(r.own.path_ratio, 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(r.own.min_separation));
  EXPECT_DOUBLE_EQ(r.own.colregs_score, 1.0);
}

TEST(Evaluation, ConfigValidatesAndReadsParams) {
  EvaluationConfig bad;
  bad.r_min_m = 5000.0;
  bad.ranges_from_scenario = false;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
  ParamMap p;
  p.set("apparent_course_deg", 20.0);
  p.set("hu/t_safe_s", 300.0);
  const EvaluationConfig c = EvaluationConfig::fromParams(p);
  EXPECT_DOUBLE_EQ(c.apparent_course_deg, 20.0);
  EXPECT_DOUBLE_EQ(c.hu.t_safe_s, 300.0);
  ParamMap extremis;
  extremis.set("extremis_delay_s", -1.0);
  EXPECT_THROW(EvaluationConfig::fromParams(extremis), std::invalid_argument);
  ParamMap reaction;
  reaction.set("reaction_s", -1.0);
  EXPECT_THROW(EvaluationConfig::fromParams(reaction), std::invalid_argument);
  reaction.set("reaction_s", 30.0);
  EXPECT_DOUBLE_EQ(EvaluationConfig::fromParams(reaction).reaction_s, 30.0);
  ParamMap typo;
  typo.set("apparent_course", 20.0);
  EXPECT_THROW(EvaluationConfig::fromParams(typo), std::invalid_argument);
}

// The closest approach of a crossing, by hand: own north from (0, 0), target west from (5000, 5300),
// both 5 m/s; relative position (5000 - 5t, 5300 - 5t) is shortest at t = 1030 s, 212.1 m, with the own
// ship at (0, 5150) and the target at (-150, 5300). In latitude/longitude from 54 N 3 E (one degree of
// latitude 111,305 m there, from the meridian arc series; one of longitude 65,576 m at 54 N, x cos
// ratio to the target's 54.0476 N = 65,501 m): own 54.046270 N 3.000000 E, target 54.047618 N
// 2.997710 E.
TEST(Evaluation, ClosestApproachAndGeoJsonAreInLatitudeLongitude) {
  Script s;
  s.tgt0 = {5000.0, 5300.0};
  RunRecorder rec = record(s);
  const RunResult r = rec.finish();
  ASSERT_EQ(r.own.targets.size(), 1u);
  const TargetResult& t = r.own.targets[0];
  EXPECT_DOUBLE_EQ(t.closest_time, 1030.0);
  EXPECT_NEAR(t.min_distance, 212.13, 0.01);
  EXPECT_NEAR((t.own_at_closest - Eigen::Vector2d(0.0, 5150.0)).norm(), 0.0, 1e-6);
  EXPECT_NEAR((t.target_at_closest - Eigen::Vector2d(-150.0, 5300.0)).norm(), 0.0, 1e-6);
  const YAML::Node j = YAML::Load(toJson(r));
  const YAML::Node ca = j["targets"][0]["closest_approach"];
  EXPECT_DOUBLE_EQ(ca["t_s"].as<double>(), 1030.0);
  EXPECT_NEAR(ca["own"]["lat_deg"].as<double>(), 54.0 + 5150.0 / 111305.0, 2e-6);
  EXPECT_NEAR(ca["own"]["lon_deg"].as<double>(), 3.0, 1e-7);
  EXPECT_NEAR(ca["target"]["lat_deg"].as<double>(), 54.0 + 5300.0 / 111305.0, 2e-6);
  EXPECT_NEAR(ca["target"]["lon_deg"].as<double>(), 3.0 - 150.0 / 65501.0, 2e-6);
  // GeoJSON: two tracks, the closest approach as a point and a line, longitude first.
  const YAML::Node g = YAML::Load(rec.geoJson(r));
  EXPECT_EQ(g["type"].as<std::string>(), "FeatureCollection");
  std::map<std::string, int> kinds;
  for (const auto& f : g["features"]) {
    const std::string k = f["properties"]["kind"].as<std::string>();
    ++kinds[k];
    if (k == "closest_approach") {
      EXPECT_EQ(f["geometry"]["type"].as<std::string>(), "Point");
      EXPECT_NEAR(f["geometry"]["coordinates"][0].as<double>(), 3.0, 1e-7);
      EXPECT_NEAR(f["geometry"]["coordinates"][1].as<double>(), 54.0 + 5150.0 / 111305.0, 2e-6);
      EXPECT_NEAR(f["properties"]["distance_m"].as<double>(), 212.1, 0.05);
    }
    if (k == "track") {
      EXPECT_GE(f["geometry"]["coordinates"].size(), 2u);
    }
  }
  EXPECT_EQ(kinds["track"], 2);
  EXPECT_EQ(kinds["closest_approach"], 1);
  EXPECT_EQ(kinds["closest_approach_line"], 1);
  EXPECT_EQ(kinds["manoeuvre"], 0);  // she held her course
}
