#include <gtest/gtest.h>

#include "asv_core/risk/risk_assessment.h"

using namespace asv;

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
  ComplianceResult r = m.update("a", 1000, 800);
  EXPECT_EQ(r.risk, RiskLevel::Collision);
  EXPECT_TRUE(r.compliant);
  EXPECT_EQ(r.decision, RuleDecision::RuleApplies);
  r = m.update("a", 500, 300);
  EXPECT_EQ(r.risk, RiskLevel::Urgent);
  EXPECT_FALSE(r.compliant);
  EXPECT_EQ(r.decision, RuleDecision::Rule2);
  r = m.update("a", 400, 300);  // still urgent: the flag stays
  EXPECT_FALSE(r.compliant);
  r = m.update("a", -5, 300);  // passed: no risk, compliant again
  EXPECT_EQ(r.risk, RiskLevel::None);
  EXPECT_TRUE(r.compliant);
  EXPECT_EQ(r.decision, RuleDecision::NoRule);
  // Risk 2 straight from 0 (a target appearing close) stays compliant, also on the next update.
  r = m.update("b", 300, 100);
  EXPECT_EQ(r.risk, RiskLevel::Urgent);
  EXPECT_TRUE(r.compliant);
  EXPECT_TRUE(m.update("b", 290, 100).compliant);
  // Histories are per target.
  m.update("c", 1000, 800);
  EXPECT_TRUE(m.update("d", 300, 100).compliant);
  EXPECT_FALSE(m.update("c", 300, 100).compliant);
  m.retainOnly({"c"});
  EXPECT_EQ(m.size(), 1u);
}

TEST(RiskAssessor, CombinesCpaCriEncounterAndFlag) {
  RiskAssessor assessor;
  ShipState own;
  own.id = "own";
  own.course = own.heading = 0.0;
  own.speed = 6.0;
  // A target crossing from port (own ship stand-on) that keeps coming: 20 km out first.
  auto target = [](double y_east_offset, double north) {
    ShipState t;
    t.id = "ts1";
    t.position = {-y_east_offset, north};
    t.course = t.heading = degToRad(90.0);
    t.speed = 6.0;
    return t;
  };
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
