// A planner of another package loads as asv_planning's own do: by its pluginlib name, through the
// loader planner_node and asv_batch use, and runs a whole scenario in asv_batch.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

#include <asv_core/common/units.h>
#include <asv_planning/plugin_loader.h>

namespace {

const std::string kName = "asv_planner_example/straight";

asv::PlanningProblem towards(const Eigen::Vector2d& goal) {
  asv::PlanningProblem p;
  p.own.id = "own";
  p.own.speed = 6.0;
  p.cruise_speed = 8.0;
  p.limits.max_speed = 10.0;
  p.goal = goal;
  return p;
}

}  // namespace

TEST(ExamplePlugin, IsDeclaredUnderItsPackagesName) {
  asv_planning::PluginLoader loader;
  const auto d = loader.declared();
  EXPECT_NE(std::find(d.begin(), d.end(), kName), d.end());
  EXPECT_NE(std::find(d.begin(), d.end(), "asv_planning/aco"), d.end());
  // Its parameters go under its full name (~asv_planner_example/straight/, planner_params), ours under
  // the short one.
  const auto names = loader.parameterNames();
  EXPECT_NE(std::find(names.begin(), names.end(), kName), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "aco"), names.end());
}

// Goal 3000 m east and 4000 m north: course atan2(3000, 4000) = 36.87 deg; speed half the cruise
// speed of 8 m/s.
TEST(ExamplePlugin, LoadsByItsPluginlibNameAndPlans) {
  asv_planning::PluginLoader loader;
  asv::ParamMap config;
  config.set("speed_fraction", "0.5");
  auto planner = loader.load(kName, config);
  ASSERT_TRUE(planner);
  EXPECT_EQ(planner->name(), "straight");
  EXPECT_EQ(planner->parameters().getDouble("speed_fraction", 0.0), 0.5);
  const asv::Plan plan = planner->plan(towards({3000.0, 4000.0}));
  EXPECT_EQ(plan.status, asv::PlanStatus::Ok);
  EXPECT_NEAR(asv::radToDeg(plan.course_setpoint), 36.87, 0.01);
  EXPECT_DOUBLE_EQ(plan.speed_setpoint, 4.0);
  ASSERT_EQ(plan.waypoints.size(), 2u);
  EXPECT_NEAR(plan.waypoints[1].time, 5000.0 / 4.0, 1e-9);
}

TEST(ExamplePlugin, BadParametersFailLoudly) {
  asv_planning::PluginLoader loader;
  asv::ParamMap typo;
  typo.set("speed_fracton", "0.5");
  EXPECT_THROW(loader.load(kName, typo), std::invalid_argument);
  asv::ParamMap out_of_range;
  out_of_range.set("speed_fraction", "1.5");
  EXPECT_THROW(loader.load(kName, out_of_range), std::invalid_argument);
}

// asv_batch takes any declared planner by its pluginlib name: a head-on meeting at 4 nm, both ships at
// 10 kn, the goal 12 km ahead (1 h allowed; 2333 s straight). The example steers straight at the other
// ship; the follower's shared rules must still keep the own ship half a mile clear, the default
// minimum (the result names the planner as given).
TEST(ExamplePlugin, RunsAScenarioInAsvBatch) {
  const std::string scenario = ::testing::TempDir() + "example_head_on.yaml";
  std::ofstream(scenario)
      << "format: 1\nname: example_head_on\nduration_s: 3600\n"
         "own_ship:\n  name: own\n  position: {x_m: 0, y_m: 0}\n  course_deg: 0\n"
         "  speed_kn: 10\n  goal: {x_m: 0, y_m: 12000}\n"
         "targets:\n  - name: ts1\n    position: {x_m: 0, y_m: 7408}\n    course_deg: 180\n"
         "    speed_kn: 10\n";
  const std::string cmd = std::string(ASV_BATCH_BIN) + " --scenario " + scenario + " --planner " + kName +
                          " --deterministic --quiet";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  ASSERT_TRUE(pipe);
  std::string out;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), buf.size(), pipe.get()))
    out += buf.data();
  EXPECT_NE(out.find("\"planner\": \"" + kName + "\""), std::string::npos) << out;
  EXPECT_NE(out.find("\"collision\": false"), std::string::npos) << out;
  EXPECT_NE(out.find("\"safety_violation\": false"), std::string::npos) << out;
  EXPECT_NE(out.find("\"arrived\": true"), std::string::npos) << out;
}
