// The domain each planner plans with round a target (planning.h, aco_planner.h), as planner_node shows
// it in rviz. Expected vertices worked by hand from the configuration in each comment.
#include <gtest/gtest.h>

#include <cmath>

#include "asv_core/common/units.h"
#include "asv_core/planning/aco/aco_planner.h"
#include "asv_core/planning/dssa/dssa.h"
#include "asv_core/planning/ga/ga_planner.h"
#include "asv_core/planning/mopso/mopso_planner.h"

namespace {

asv::PlanningProblem problemWith(asv::Encounter encounter, double min_separation) {
  asv::PlanningProblem pr;
  pr.min_separation = min_separation;
  asv::PlannerTarget t;
  t.state.id = "T1";
  t.state.position = {0.0, 10000.0};
  t.state.course = asv::kPi;  // south
  t.encounter = encounter;
  pr.targets.push_back(t);
  return pr;
}

bool hasVertex(const asv::Polygon& poly, const Eigen::Vector2d& v) {
  for (const auto& p : poly)
    if ((p - v).norm() < 1e-6)
      return true;
  return false;
}

}  // namespace

// ACO's hexagon (Lazarowska 2015, Sec. 3: a 1 nm, b 0.6, c 0.6, d 0.25, e 0.25 nm) with min_separation
// 926 m: no side under 1.3 x 926 = 1203.8 m, so every extent grows by 1203.8 - 463 = 740.8 m: a 2592.8,
// b 1852, c 1852, d 1203.8, e 1203.8. Head-on, colregs_factor 2 doubles a and c: a 5185.6, c 3704. The
// target at (0, 10000) heads south, so her starboard is west: bow (0, 4814.4), starboard beam
// (-3704, 10000), stern (0, 11203.8), port beam (1203.8, 10000).
TEST(PlannerDomains, AcoHexagonAsItPlans) {
  const asv::AcoPlanner aco;
  const auto head_on = aco.domains(problemWith(asv::Encounter::HeadOn, 926.0));
  ASSERT_EQ(head_on.size(), 1u);
  EXPECT_EQ(head_on[0].target_id, "T1");
  ASSERT_EQ(head_on[0].polygon.size(), 6u);
  for (const Eigen::Vector2d& v : {Eigen::Vector2d(0.0, 4814.4), Eigen::Vector2d(-3704.0, 10000.0),
                                   Eigen::Vector2d(0.0, 11203.8), Eigen::Vector2d(1203.8, 10000.0)})
    EXPECT_TRUE(hasVertex(head_on[0].polygon, v)) << v.transpose();
  // A stand-on crossing keeps the inflated hexagon: bow (0, 10000 - 2592.8), starboard beam (-1852, 10000).
  const auto stand_on = aco.domains(problemWith(asv::Encounter::CrossingStandOn, 926.0));
  EXPECT_TRUE(hasVertex(stand_on[0].polygon, {0.0, 7407.2}));
  EXPECT_TRUE(hasVertex(stand_on[0].polygon, {-1852.0, 10000.0}));
}

// In restricted waters (passing_cap 292.8 m, a 94 m ferry at 10 kn: Kijima and Nakiri's starboard
// extent) the paper's hexagon is scaled by 292.8 / 1111.2 = 0.26350 before the floor: a 488.0, b 292.8,
// c 292.8, d 122.0, e 122.0 m; min_separation 185.2: floor 1.3 x 185.2 = 240.76, so every extent grows by
// 240.76 - 122.0 = 118.76: a 606.8, c 411.6, d 240.8, e 240.8. A stand-on crossing (no doubling), target
// at (0, 10000) heading south: bow (0, 9393.2), starboard beam (-411.6, 10000), stern (0, 10240.8).
TEST(PlannerDomains, AcoHexagonScaledInRestrictedWaters) {
  const asv::AcoPlanner aco;
  asv::PlanningProblem pr = problemWith(asv::Encounter::CrossingStandOn, 185.2);
  pr.passing_cap = 292.8;
  const auto d = aco.domains(pr);
  ASSERT_EQ(d.size(), 1u);
  const double k = 292.8 / 1111.2, grow = 1.3 * 185.2 - 463.0 * k;
  for (const Eigen::Vector2d& v :
       {Eigen::Vector2d(0.0, 10000.0 - 1852.0 * k - grow), Eigen::Vector2d(-(292.8 + grow), 10000.0),
        Eigen::Vector2d(0.0, 10000.0 + 240.76)})
    EXPECT_TRUE(hasVertex(d[0].polygon, v)) << v.transpose();
  EXPECT_NEAR(10000.0 - 1852.0 * k - grow, 9393.2, 0.1);  // the figures of the comment
  EXPECT_NEAR(292.8 + grow, 411.6, 0.1);
}

// A planner without a domain of its own shows the separation rule: 1.1 x 926 = 1018.6 m round the
// target, 36 vertices; none without a minimum separation.
TEST(PlannerDomains, OthersShowTheSeparationRule) {
  const asv::MopsoPlanner mopso;
  const auto d = mopso.domains(problemWith(asv::Encounter::HeadOn, 926.0));
  ASSERT_EQ(d.size(), 1u);
  ASSERT_EQ(d[0].polygon.size(), 36u);
  for (const auto& v : d[0].polygon)
    EXPECT_NEAR((v - Eigen::Vector2d(0.0, 10000.0)).norm(), 1018.6, 1e-6);
  EXPECT_TRUE(hasVertex(d[0].polygon, {0.0, 11018.6}));  // due north first
  EXPECT_TRUE(mopso.domains(problemWith(asv::Encounter::HeadOn, 0.0)).empty());
}

// mode paper (planning.h): ACO as Lazarowska (2015) published it plans round the paper's hexagon itself,
// with no inflation and no COLREGs doubling: head-on, bow (0, 10000 - 1852), starboard beam
// (-1111.2, 10000), port beam (463, 10000). Any other mode is refused. MOPSO and DSSA+ switch their
// own extensions.
TEST(PlannerModes, PaperModeIsThePublishedMethod) {
  asv::AcoPlanner aco;
  asv::ParamMap paper;
  paper.set("mode", "paper");
  aco.configure(paper);
  EXPECT_DOUBLE_EQ(aco.config().min_first_alteration, 0.0);
  EXPECT_FALSE(aco.config().smooth);
  const auto d = aco.domains(problemWith(asv::Encounter::HeadOn, 926.0));
  ASSERT_EQ(d.size(), 1u);
  for (const Eigen::Vector2d& v :
       {Eigen::Vector2d(0.0, 8148.0), Eigen::Vector2d(-1111.2, 10000.0), Eigen::Vector2d(463.0, 10000.0)})
    EXPECT_TRUE(hasVertex(d[0].polygon, v)) << v.transpose();

  // Lazarowska (2015) plans once; the other three papers replan.
  EXPECT_TRUE(aco.plansOnce());
  EXPECT_FALSE(asv::GaPlanner().plansOnce());
  EXPECT_FALSE(asv::GaPlanner().ownTrigger()) << "sea mode: the follower's triggers";
  EXPECT_TRUE(asv::GaPlanner(asv::GaConfig::paper()).ownTrigger()) << "Wu et al. 2022: the CRI, every cycle";
  EXPECT_FALSE(aco.ownTrigger());
  EXPECT_FALSE(asv::MopsoPlanner().plansOnce());
  EXPECT_FALSE(asv::DssaPlanner("dssa_plus").plansOnce());

  const asv::GaConfig ga = asv::GaConfig::fromParams(paper);  // Wu et al. (2022): the CRI alone
  EXPECT_EQ(ga.elite_count, 0);
  EXPECT_EQ(ga.safety_penalty + ga.colregs_penalty + ga.new_risk_penalty + ga.turn_penalty, 0.0);
  EXPECT_EQ(asv::GaConfig::fromParams({}).elite_count, 1);  // sea, the default
  EXPECT_TRUE(ga.cri.as_printed);                           // eq. (3) and (4) as printed
  EXPECT_FALSE(asv::GaConfig::fromParams({}).cri.as_printed);

  asv::ParamMap other;
  other.set("mode", "harbour");
  EXPECT_THROW(aco.configure(other), std::invalid_argument);
  // Hu et al. (2017): d_min of eq. (8) as set, not raised to 1.1 x the situation's minimum separation.
  EXPECT_FALSE(asv::MopsoConfig::fromParams(paper).inflate);
  EXPECT_TRUE(asv::MopsoConfig::fromParams({}).inflate);
  // Hirayama et al. (2019): s>c read with the smaller weight 1 (alpha 10, beta 1); sea keeps alpha 1.
  asv::ParamMap sc = paper;
  sc.set("preset", "dssa_plus_sc");
  EXPECT_EQ(asv::DssaConfig::fromParams(sc).alpha, 10.0);
  EXPECT_EQ(asv::DssaConfig::fromParams(sc).beta, 1.0);
  sc.set("mode", "sea");
  EXPECT_EQ(asv::DssaConfig::fromParams(sc).alpha, 1.0);
  EXPECT_EQ(asv::DssaConfig::fromParams(sc).beta, 0.1);
}
