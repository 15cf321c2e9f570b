// The five planners load by short name through pluginlib (no master), plan a head-on encounter, and
// a bad name or key fails loudly.
#include <gtest/gtest.h>

#include <algorithm>

#include <asv_core/common/units.h>
#include <asv_core/planning/dssa/dssa.h>

#include "asv_planning/plugin_loader.h"

using namespace asv_planning;

namespace {
asv::PlanningProblem headOn() {
  asv::PlanningProblem p;
  p.own.id = "own";
  p.own.speed = asv::knotsToMps(10.0);
  p.goal = {0.0, 12 * 1852.0};
  p.limits.max_speed = 8.0;
  asv::PlannerTarget t;
  t.state.id = "ts1";
  t.state.position = {0.0, 3 * 1852.0};
  t.state.course = t.state.heading = asv::kPi;
  t.state.speed = asv::knotsToMps(10.0);
  t.risk = asv::RiskLevel::Collision;
  t.encounter = asv::Encounter::HeadOn;
  t.role = asv::OwnRole::BothGiveWay;
  t.tcpa = 3 * 1852.0 / (2 * t.state.speed);
  t.cri = 0.9;
  p.targets.push_back(t);
  return p;
}
}  // namespace

TEST(PluginLoader, DeclaresTheFivePlanners) {
  PluginLoader loader;
  auto d = loader.declared();
  for (const char* n : {"asv_planning/aco", "asv_planning/dssa", "asv_planning/dssa_plus",
                        "asv_planning/mopso", "asv_planning/ga"})
    EXPECT_NE(std::find(d.begin(), d.end(), n), d.end()) << n;
}

TEST(PluginLoader, EachPlannerLoadsByShortNameAndAltersToStarboardHeadOn) {
  PluginLoader loader;
  for (const char* n : {"aco", "dssa", "dssa_plus", "mopso", "ga"}) {
    auto plugin = loader.load(n, asv::ParamMap());
    ASSERT_TRUE(plugin) << n;
    EXPECT_EQ(plugin->name(), n);
    const asv::Plan plan = plugin->plan(headOn());
    EXPECT_EQ(plan.status, asv::PlanStatus::Ok) << n << ": " << plan.message;
    // Northbound own ship: a starboard alteration takes the planned track east of the meeting line (the
    // set-point course is then between 000 and 180).
    double east = 0.0, west = 0.0;
    for (const auto& w : plan.waypoints) {
      if (w.position.y() > 1.5 * 1852.0)
        break;  // beyond the meeting point
      east = std::max(east, w.position.x());
      west = std::min(west, w.position.x());
    }
    const double sp = asv::radToDeg(asv::wrapPi(plan.course_setpoint));
    // DSSA has no COLREGs rule (it minimises collision risk and inefficiency only): it must alter,
    // to either side.
    const bool colregs = std::string(n).rfind("dssa", 0) != 0;
    if (colregs) {
      EXPECT_TRUE(east > -west || (sp > 0.0 && sp < 180.0))
          << n << " east " << east << " west " << west << " set-point " << sp;
    }
    EXPECT_GT(std::max(east, -west) + std::fabs(sp), 1.0) << n << " did not alter at all";
  }
}

TEST(PluginLoader, UnknownPlannerListsTheDeclaredOnes) {
  PluginLoader loader;
  try {
    loader.load("astar", asv::ParamMap());
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("astar"), std::string::npos);
    EXPECT_NE(what.find("asv_planning/mopso"), std::string::npos) << what;
  }
}

TEST(PluginLoader, UnknownParameterIsRejected) {
  PluginLoader loader;
  asv::ParamMap p;
  p.set("antz", "10");
  EXPECT_THROW(loader.load("aco", p), std::invalid_argument);
}

// The parameters in force are the plugin's defaults with the given keys over them: the distributed
// DSSA agent builds its algorithm from them, through the interface rather than a cast.
TEST(PluginLoader, ParametersInForceAreTheDefaultsWithTheGivenKeysOver) {
  PluginLoader loader;
  asv::ParamMap given;
  given.set("time_step", "5");
  auto plugin = loader.load("dssa_plus", given);
  const asv::ParamMap p = plugin->parameters();
  EXPECT_EQ(p.getDouble("time_step", 0.0), 5.0);      // given
  EXPECT_EQ(p.getDouble("time_window", 0.0), 600.0);  // the sea-scale default (10 minutes)
  EXPECT_FALSE(p.has("preset"));                      // the plugin's name stands for it
  const asv::DssaConfig c = asv::DssaConfig::fromParams(p, plugin->name());
  EXPECT_EQ(c.time_step, 5.0);
  EXPECT_TRUE(c.speed_changes);  // DSSA+ changes speed as well as course (Hirayama et al. 2019, Sec. 4)
  EXPECT_EQ(c.alpha, c.beta);    // the plugin's dssa_plus is the s=c variant, alpha = beta
  EXPECT_TRUE(loader.load("aco", asv::ParamMap())->parameters().values().empty());  // no defaults of its own
}

// planner_node shows each plugin's domains: through the plugin, ACO gives its hexagon (6 vertices,
// test_planner_domains.cpp) and the others the separation circle (36).
TEST(PluginLoader, DomainsComeFromTheAlgorithm) {
  PluginLoader loader;
  asv::PlanningProblem pr;
  pr.min_separation = 926.0;
  asv::PlannerTarget t;
  t.state.id = "T1";
  t.state.position = {0.0, 10000.0};
  pr.targets.push_back(t);
  for (const std::string& n : {std::string("aco"), std::string("ga")}) {
    const auto d = loader.load(n, asv::ParamMap())->domains(pr);
    ASSERT_EQ(d.size(), 1u) << n;
    EXPECT_EQ(d[0].target_id, "T1");
    EXPECT_EQ(d[0].polygon.size(), n == "aco" ? 6u : 36u) << n;
  }
}

// asv_batch and planner_node set paper mode's follower from the plugin: only ACO (Lazarowska 2015)
// plans once.
TEST(PluginLoader, PlansOnceComesFromTheAlgorithm) {
  PluginLoader loader;
  for (const char* n : {"aco", "dssa", "dssa_plus", "mopso", "ga"})
    EXPECT_EQ(loader.load(n, asv::ParamMap())->plansOnce(), std::string(n) == "aco") << n;
}
