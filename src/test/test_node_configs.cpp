// Each node's Config struct against the YAML file that documents its parameters: every key of the file
// is read by the struct's fromParams() (a key the code does not know would stop the node), the file's
// values pass validate(), and the values a user sees in the file are the code's defaults where the
// file says so. Bad values and wrong types are refused with the parameter's name.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include "asv_core/eval/evaluator_node_config.h"
#include "asv_core/planning/autopilot_bridge.h"
#include "asv_core/planning/planner_node_config.h"
#include "asv_core/risk/risk_node_config.h"
#include "asv_core/sim/sim_node_config.h"
#include "asv_core/tracking/ingestion_config.h"
#include "asv_core/tracking/own_ship.h"
#include "asv_core/tracking/plotter_output.h"
#include "asv_core/tracking/tracker_node_config.h"

using asv::ParamMap;

namespace {

void flatten(const YAML::Node& n, const std::string& key, ParamMap& out) {
  if (n.IsMap()) {
    for (const auto& kv : n)
      flatten(kv.second, key.empty() ? kv.first.as<std::string>() : key + "/" + kv.first.as<std::string>(),
              out);
  } else if (n.IsSequence()) {
    std::vector<std::string> items;
    for (const auto& i : n)
      items.push_back(i.as<std::string>());
    out.setList(key, items);
  } else if (n.IsScalar()) {
    out.set(key, n.as<std::string>());
  }
}

ParamMap loadYaml(const std::string& relative) {
  ParamMap p;
  flatten(YAML::LoadFile(std::string(ASV_SOURCE_DIR) + "/" + relative), "", p);
  p.setLabel("/node/");
  return p;
}

std::string unknown(const ParamMap& p, const std::vector<std::string>& skip = {}) {
  std::string s;
  for (const auto& k : p.unknownKeys(skip))
    s += k + " ";
  return s;
}

}  // namespace

TEST(NodeConfigs, PlannerNodeYamlIsTheCodesKeySetAndDefaults) {
  ParamMap y = loadYaml("asv_planning/config/planner_node.yaml");
  const auto c = asv::PlannerNodeConfig::fromParams(y);
  EXPECT_EQ(unknown(y), "");
  // One definition of the rate of turn: the YAML's 1 deg/s is the core's default for every caller.
  EXPECT_DOUBLE_EQ(c.follower.limits.turn_rate, 0.0175);
  EXPECT_DOUBLE_EQ(asv::OwnShipLimits{}.turn_rate, 0.0175);
  EXPECT_DOUBLE_EQ(asv::PlanFollowerConfig{}.limits.turn_rate, 0.0175);
  EXPECT_DOUBLE_EQ(c.follower.replan_period, asv::PlanFollowerConfig{}.replan_period);
  const asv::PlannerNodeConfig defaults;
  EXPECT_DOUBLE_EQ(c.stale_after, defaults.stale_after);
  EXPECT_FALSE(c.has_goal);  // goal_x/goal_y are commented out
  // The inputs' watch: the file's values are the code's.
  EXPECT_DOUBLE_EQ(c.watch.input_timeout, defaults.watch.input_timeout);
  EXPECT_DOUBLE_EQ(c.watch.wall_floor, defaults.watch.wall_floor);
  EXPECT_EQ(c.upstream_nodes, defaults.upstream_nodes);
  EXPECT_DOUBLE_EQ(c.follower.degraded_plan_hold, asv::PlanFollowerConfig{}.degraded_plan_hold);
}

TEST(NodeConfigs, PlannerNodeGoalNeedsBothCoordinates) {
  ParamMap p(std::map<std::string, std::string>{{"goal_x", "100"}});
  EXPECT_THROW(asv::PlannerNodeConfig::fromParams(p), std::invalid_argument);
  p.set("goal_y", "-50");
  const auto c = asv::PlannerNodeConfig::fromParams(p);
  EXPECT_TRUE(c.has_goal);
  EXPECT_DOUBLE_EQ(c.goal.y(), -50.0);
}

TEST(NodeConfigs, RiskNodeYamlIsTheCodesKeySet) {
  ParamMap y = loadYaml("asv_risk/config/risk_node.yaml");
  const auto c = asv::RiskNodeConfig::fromParams(y);
  EXPECT_EQ(unknown(y), "");
  EXPECT_DOUBLE_EQ(c.stale_after, asv::RiskNodeConfig{}.stale_after);
}

TEST(NodeConfigs, TrackerYamlIsTheCodesKeySet) {
  ParamMap y = loadYaml("asv_risk/config/tracker.yaml");
  const auto c = asv::TrackerNodeConfig::fromParams(y);
  EXPECT_EQ(unknown(y), "");
  EXPECT_DOUBLE_EQ(c.tracker.arpa.drop_after, asv::TrackerConfig{}.arpa.drop_after);
}

TEST(NodeConfigs, IngestionYamlsAreTheCodesKeySets) {
  ParamMap ais = loadYaml("asv_risk/config/ais_node.yaml");
  const auto a = asv::AisNodeConfig::fromParams(ais);
  EXPECT_EQ(unknown(ais, {"input/"}), "");  // input/ is the node's I/O glue
  EXPECT_EQ(a.targets.max_targets, 5000u);  // the AIS table's own defaults, not the radar's
  EXPECT_DOUBLE_EQ(a.targets.forget_after, 900.0);
  ParamMap arpa = loadYaml("asv_risk/config/arpa_node.yaml");
  const auto r = asv::ArpaNodeConfig::fromParams(arpa);
  EXPECT_EQ(unknown(arpa, {"input/"}), "");
  EXPECT_EQ(r.targets.max_targets, 1000u);
  EXPECT_DOUBLE_EQ(r.targets.forget_after, 120.0);
}

// No origin of its own is valid (the node then takes /map_origin); half of one, or one off the globe, is not.
TEST(NodeConfigs, IngestionOriginIsWholeOrAbsent) {
  const auto none = asv::AisNodeConfig::fromParams(ParamMap());
  EXPECT_FALSE(none.has_origin);
  EXPECT_TRUE(none.origin_scenario.empty());
  EXPECT_THROW(asv::AisNodeConfig::fromParams(
                   ParamMap(std::map<std::string, std::string>{{"origin_lat_deg", "54.6"}})),
               std::invalid_argument);
  EXPECT_NO_THROW(asv::ArpaNodeConfig::fromParams(
      ParamMap(std::map<std::string, std::string>{{"origin_scenario", "head_on.yaml"}})));
  EXPECT_THROW(asv::ArpaNodeConfig::fromParams(ParamMap({{"origin_lat_deg", "91"}, {"origin_lon_deg", "0"}})),
               std::invalid_argument);
}

TEST(NodeConfigs, SimNodeYamlIsTheCodesKeySet) {
  ParamMap y = loadYaml("asv_sim/config/sim_node.yaml");
  y.set("scenario", "head_on.yaml");  // required, and not in the file
  const auto c = asv::SimNodeConfig::fromParams(y);
  EXPECT_EQ(unknown(y), "");
  EXPECT_TRUE(c.lockstep_participants.empty());
  EXPECT_THROW(asv::SimNodeConfig::fromParams(ParamMap()), std::invalid_argument);  // no scenario
}

TEST(NodeConfigs, EvaluatorNodeYamlIsTheCodesKeySet) {
  ParamMap y = loadYaml("asv_sim/config/evaluator_node.yaml");
  const auto c = asv::EvaluatorNodeConfig::fromParams(y);
  EXPECT_EQ(unknown(y, {"evaluation/"}), "");  // the subtree is checked by EvaluationConfig
  EXPECT_DOUBLE_EQ(c.time_origin, 1.0e9);      // sim_node's epoch (a YAML 1.1 "1.0e9" would be text)
}

TEST(NodeConfigs, TypedValuesAreRefusedWithTheParameterName) {
  ParamMap p;
  p.setLabel("/sim/");
  p.set("scenario", "head_on.yaml", asv::ParamType::String);
  p.set("rate", "fast", asv::ParamType::String);
  try {
    asv::SimNodeConfig::fromParams(p);
    FAIL() << "a string as rate was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'/sim/rate' has the wrong type"), std::string::npos) << e.what();
  }
}

TEST(NodeConfigs, OwnShipAndAutopilotBridgeYamlAreTheCodesKeySets) {
  ParamMap own = loadYaml("asv_risk/config/own_ship_node.yaml");
  const asv::OwnShipConfig o = asv::OwnShipConfig::fromParams(own);
  EXPECT_EQ(unknown(own, {"input/"}), "");  // input/ is the node's I/O glue
  const asv::OwnShipConfig od;
  EXPECT_DOUBLE_EQ(o.cog_heading_sigma, od.cog_heading_sigma);
  EXPECT_DOUBLE_EQ(o.watch.input_timeout, od.watch.input_timeout);
  EXPECT_FALSE(o.variation);  // variation_deg is commented out
  ParamMap bridge = loadYaml("asv_planning/config/autopilot_bridge.yaml");
  const asv::AutopilotBridgeConfig b = asv::AutopilotBridgeConfig::fromParams(bridge);
  EXPECT_EQ(unknown(bridge, {"output/", "publish_twist"}), "");  // the node's I/O glue
  EXPECT_FALSE(b.armed_at_start);
  EXPECT_EQ(b.safe_action, "hold_course");
  EXPECT_DOUBLE_EQ(b.watch.input_timeout, asv::AutopilotBridgeConfig().watch.input_timeout);
  EXPECT_FALSE(o.has_origin);  // the origin lines are commented out: the run's /map_origin
  EXPECT_FALSE(o.navsat);
}

TEST(NodeConfigs, PlotterYamlIsTheCodesKeySet) {
  ParamMap plotter = loadYaml("asv_risk/config/plotter_node.yaml");
  const asv::PlotterConfig p = asv::PlotterConfig::fromParams(plotter);
  EXPECT_EQ(unknown(plotter, {"output/"}), "");  // output/ is the node's I/O glue (asv_ros::NmeaOutputConfig)
  const asv::PlotterConfig d;
  EXPECT_DOUBLE_EQ(p.rate, d.rate);
  EXPECT_EQ(p.sentences, d.sentences);
  EXPECT_EQ(p.max_targets, d.max_targets);
  EXPECT_DOUBLE_EQ(p.stale_after, d.stale_after);
}
