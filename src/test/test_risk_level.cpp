#include <gtest/gtest.h>

#include <string>

#include "asv_core/risk/risk_assessment.h"

using namespace asv;

namespace {

// A ship with this id at p [m, east/north], on course_deg (nautical) at speed [m/s].
ShipState ship(const std::string& id, Eigen::Vector2d p, double course_deg, double speed) {
  ShipState s;
  s.id = id;
  s.position = p;
  s.course = s.heading = degToRad(course_deg);
  s.speed = speed;
  return s;
}

// The own ship of the assessor tests: at the origin, north at 6 m/s.
ShipState northbound() {
  return ship("own", {0.0, 0.0}, 0.0, 6.0);
}

}  // namespace

TEST(RiskLevel, Equations1And2) {
  const HuRiskConfig cfg;  // t_max 1200 s, d_min 1852 m, t_safe 600 s, d_safe 926 m
  EXPECT_EQ(riskLevel(1000, 1000, cfg), RiskLevel::Collision);
  EXPECT_EQ(riskLevel(500, 500, cfg), RiskLevel::Urgent);
  EXPECT_EQ(riskLevel(500, 1500, cfg), RiskLevel::Collision);  // (1) holds, (2) does not
  EXPECT_EQ(riskLevel(0, 0, cfg), RiskLevel::Urgent);
  EXPECT_EQ(riskLevel(-10, 0, cfg), RiskLevel::None);     // CPA passed
  EXPECT_EQ(riskLevel(1300, 0, cfg), RiskLevel::None);    // too far in the future
  EXPECT_EQ(riskLevel(100, 2000, cfg), RiskLevel::None);  // passes clear
}

TEST(RiskLevel, ConfigMustOrderThresholds) {
  HuRiskConfig cfg;
  cfg.t_safe_s = cfg.t_max_s;
  EXPECT_THROW(cfg.validate(), std::invalid_argument);
  cfg = {};
  cfg.d_safe_m = 2000;
  EXPECT_THROW(cfg.validate(), std::invalid_argument);
}

TEST(ComplianceMonitor, Algorithm1) {
  ComplianceMonitor m;
  // Risk 1 then 2: the give-way target did not act -> non-compliant, Rule 2 (Table 1, x).
  ComplianceResult r = m.update("a", 1000, 800, true);
  EXPECT_EQ(r.risk, RiskLevel::Collision);
  EXPECT_TRUE(r.compliant);
  EXPECT_EQ(r.decision, RuleDecision::RuleApplies);
  r = m.update("a", 500, 300, true);
  EXPECT_EQ(r.risk, RiskLevel::Urgent);
  EXPECT_FALSE(r.compliant);
  EXPECT_EQ(r.decision, RuleDecision::Rule2);
  r = m.update("a", 400, 300, true);  // still urgent: the flag stays
  EXPECT_FALSE(r.compliant);
  r = m.update("a", -5, 300, true);  // passed: no risk, compliant again
  EXPECT_EQ(r.risk, RiskLevel::None);
  EXPECT_TRUE(r.compliant);
  EXPECT_EQ(r.decision, RuleDecision::NoRule);
  // Risk 2 straight from 0 (a target appearing close) stays compliant, also on the next update.
  r = m.update("b", 300, 100, true);
  EXPECT_EQ(r.risk, RiskLevel::Urgent);
  EXPECT_TRUE(r.compliant);
  EXPECT_TRUE(m.update("b", 290, 100, true).compliant);
  // Histories are per target.
  m.update("c", 1000, 800, true);
  EXPECT_TRUE(m.update("d", 300, 100, true).compliant);
  EXPECT_FALSE(m.update("c", 300, 100, true).compliant);
  m.retainOnly({"c"});
  EXPECT_EQ(m.size(), 1u);
}

// Hu et al. (2017) Sec. 2.1: only a target "required to manoeuvre ... as a give-way vessel" is flagged.
// The same risk 1 -> 2 history for a target the own ship gives way to (a crossing from starboard)
// leaves it compliant: Rule 2(b) is not invoked against a ship that was right to stand on.
TEST(ComplianceMonitor, OnlyAGiveWayTargetIsFlagged) {
  ComplianceMonitor m;
  EXPECT_TRUE(m.update("so", 1000, 800, false).compliant);
  const ComplianceResult r = m.update("so", 500, 300, false);
  EXPECT_EQ(r.risk, RiskLevel::Urgent);
  EXPECT_TRUE(r.compliant);
  EXPECT_EQ(r.decision, RuleDecision::RuleApplies);
}

// Through the assessor: own ship north-bound, a target crossing from starboard (own ship gives way,
// Rule 15) that closes from risk 1 to risk 2 is not flagged; the mirror image from port is.
TEST(ComplianceMonitor, AssessorPassesTheRole) {
  for (double side : {1.0, -1.0}) {
    RiskAssessor assessor;
    ShipState own = northbound();
    ShipState t;
    t.id = "t";
    // Westbound from starboard, eastbound from port.
    const double heading = degToRad(side > 0 ? 270.0 : 90.0);
    t.heading = t.course = heading;
    t.speed = 6.0;
    // Both reach (0, 6000) at TCPA: risk 1 at 1000 s, risk 2 at 500 s (t_safe 600 s, d_safe 926 m).
    for (double tcpa : {1000.0, 500.0}) {
      own.position = {0.0, 6000.0 - 6.0 * tcpa};
      t.position = {side * 6.0 * tcpa, 6000.0};
      const TargetRisk r = assessor.assess(own, t);
      EXPECT_NEAR(r.cpa.tcpa, tcpa, 1e-6);
      if (tcpa < 600.0) {
        EXPECT_EQ(r.geometry.role, side > 0 ? OwnRole::GiveWay : OwnRole::StandOn);
        EXPECT_EQ(r.compliance.compliant, side > 0) << "side " << side;
      }
    }
  }
}

TEST(RiskAssessor, CombinesCpaCriEncounterAndFlag) {
  RiskAssessor assessor;
  ShipState own = northbound();
  // A target crossing from port (own ship stand-on) that keeps coming.
  auto target = [](double west, double north) { return ship("ts1", {-west, north}, 90.0, 6.0); };
  // Collision course: both reach (0, N) together when offset == N.
  TargetRisk r = assessor.assess(own, target(6000, 6000));
  EXPECT_EQ(r.geometry.encounter, Encounter::CrossingStandOn);
  EXPECT_EQ(r.compliance.risk, RiskLevel::Collision);  // TCPA 1000 s
  EXPECT_EQ(r.rule, 17);
  own.position = {0, 3000};
  r = assessor.assess(own, target(3000, 6000));  // 500 s to go
  EXPECT_EQ(r.compliance.risk, RiskLevel::Urgent);
  EXPECT_FALSE(r.compliance.compliant);
  EXPECT_EQ(r.rule, 2);
  EXPECT_NEAR(r.cpa.tcpa, 500.0, 1e-9);
  EXPECT_NEAR(r.cpa.dcpa, 0.0, 1e-9);
  EXPECT_GT(r.cri.cri, 0.6);
}

// The encounter stands as it was when the risk arose. Own ship at the origin, north at 6 m/s. First a
// ship crossing from starboard, westbound from (6000, 6000) at 6 m/s: CPA 0 m in 1000 s, risk 1, the own
// ship gives way (Rule 15). Then the same ship 1000 m dead ahead, northbound at 3 m/s: alone that reads
// as overtaking (she is in the target's stern sector; CPA 0 m in 333 s), but the crossing stands. Once
// she is past (100 m astern, northbound at 3 m/s: opening, TCPA < 0) the situation is over, and the same
// overtaking geometry then reads as overtaking.
TEST(RiskAssessor, TheEncounterStandsAsItWasWhenTheRiskArose) {
  RiskAssessor assessor;
  const ShipState own = northbound();
  auto ts1 = [](Eigen::Vector2d p, double course_deg, double speed) {
    return ship("ts1", p, course_deg, speed);
  };
  TargetRisk r = assessor.assess(own, ts1({6000.0, 6000.0}, 270.0, 6.0));
  EXPECT_EQ(r.geometry.encounter, Encounter::CrossingGiveWay);
  EXPECT_EQ(r.compliance.risk, RiskLevel::Collision);
  EXPECT_EQ(classifyEncounter(own, ts1({0.0, 1000.0}, 0.0, 3.0),
                              computeCpa(own, ts1({0.0, 1000.0}, 0.0, 3.0)), ColregsConfig{})
                .encounter,
            Encounter::Overtaking);
  r = assessor.assess(own, ts1({0.0, 1000.0}, 0.0, 3.0));
  EXPECT_NEAR(r.cpa.tcpa, 1000.0 / 3.0, 1e-9);
  EXPECT_EQ(r.geometry.encounter, Encounter::CrossingGiveWay);
  EXPECT_EQ(r.geometry.role, OwnRole::GiveWay);
  EXPECT_EQ(r.rule, 15);
  r = assessor.assess(own, ts1({0.0, -100.0}, 0.0, 3.0));
  EXPECT_EQ(r.geometry.encounter, Encounter::None);
  r = assessor.assess(own, ts1({0.0, 1000.0}, 0.0, 3.0));
  EXPECT_EQ(r.geometry.encounter, Encounter::Overtaking);
  EXPECT_EQ(r.rule, 13);
}
