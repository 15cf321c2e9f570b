#include <gtest/gtest.h>

#include "asv_core/common/units.h"
#include "asv_core/world/scenario.h"

using namespace asv;

namespace {
const char* kGood = R"(format: 1
name: lazarowska_like
description: own ship and two targets
duration_s: 3600
origin: {lat_deg: 54.60, lon_deg: 18.80}
safety: {min_separation_m: 926}
own_ship:
  name: own
  mmsi: 261000000
  model: kinematic
  position: {x_m: 0, y_m: 0}
  course_deg: 66
  speed_kn: 10.4
  goal: {bearing_deg: 66, range_nm: 12}
  planner: aco
targets:
  - name: ts1
    position: {bearing_deg: 90, range_nm: 7.9}
    course_deg: 294
    speed_kn: 10.4
    behaviour: constant
  - name: ts2
    position: {lat_deg: 54.65, lon_deg: 18.80}
    course_deg: 180
    speed_mps: 5
    behaviour: waypoints
    waypoints: [{x_m: 0, y_m: 0}, {x_m: 100, y_m: -5000}]
  - name: ts3
    position: {x_m: 3000, y_m: 3000}
    course_deg: 0
    speed_kn: 8
    behaviour: planner
    planner: dssa_plus
    goal: {x_m: 3000, y_m: 9000}
static_obstacles:
  - name: islet
    polygon: [{x_m: 5000, y_m: 0}, {x_m: 5100, y_m: 0}, {x_m: 5050, y_m: 80}]
planner_params: {aco: {ants: 10, rho: 0.1}, seed_note: x}
)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const size_t p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  return s.replace(p, from.size(), to);
}

void expectError(const std::string& yaml, const std::string& needle) {
  try {
    parseScenario(yaml, "test.yaml");
    FAIL() << "no error for " << needle;
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(Scenario, ParsesEveryPositionFormInSi) {
  const Scenario s = parseScenario(kGood, "good.yaml");
  EXPECT_EQ(s.name, "lazarowska_like");
  EXPECT_DOUBLE_EQ(s.duration, 3600.0);
  EXPECT_TRUE(s.has_origin);
  EXPECT_NEAR(s.own.speed, 10.4 * 1852.0 / 3600.0, 1e-12);
  EXPECT_NEAR(radToDeg(s.own.course), 66.0, 1e-12);
  ASSERT_TRUE(s.own.goal.has_value());
  EXPECT_NEAR(s.own.goal->x(), 12 * 1852.0 * std::sin(degToRad(66.0)), 1e-6);
  EXPECT_NEAR(s.own.goal->y(), 12 * 1852.0 * std::cos(degToRad(66.0)), 1e-6);
  ASSERT_EQ(s.targets.size(), 3u);
  EXPECT_NEAR(s.targets[0].position.x(), 7.9 * 1852.0, 1e-6);  // bearing 090 from the own ship
  EXPECT_NEAR(s.targets[0].position.y(), 0.0, 1e-6);
  // 0.05 deg of latitude north of the origin: about 5.57 km (1 deg ~ 111.4 km at 54.6 N).
  EXPECT_NEAR(s.targets[1].position.y(), 5566.0, 15.0);
  EXPECT_NEAR(s.targets[1].position.x(), 0.0, 1.0);
  EXPECT_EQ(s.targets[1].behaviour, Behaviour::Waypoints);
  EXPECT_EQ(s.targets[1].waypoints.size(), 2u);
  EXPECT_DOUBLE_EQ(s.targets[1].speed, 5.0);
  EXPECT_EQ(s.targets[2].behaviour, Behaviour::Planner);
  EXPECT_EQ(s.planningShips().size(), 2u);
  EXPECT_EQ(s.obstacles.size(), 1u);
  EXPECT_EQ(s.planner_params.getInt("aco/ants", 0), 10);
}

TEST(Scenario, UnknownKeyNamesFileLineAndKey) {
  expectError(replace(kGood, "    course_deg: 294", "    course_deg: 294\n    speed_knots: 3"),
              "test.yaml:20: 'targets[0].speed_knots': unknown key");
  expectError(replace(kGood, "duration_s: 3600", "duration: 3600"), "'duration': unknown key");
}

TEST(Scenario, MissingFieldsAndAmbiguousForms) {
  expectError(replace(kGood, "  course_deg: 66\n", ""), "'own_ship.course_deg': missing");
  expectError(replace(kGood, "  speed_kn: 10.4\n  goal", "  speed_kn: 10.4\n  speed_mps: 5\n  goal"),
              "exactly one of speed_kn or speed_mps");
  expectError(
      replace(kGood, "position: {x_m: 0, y_m: 0}", "position: {x_m: 0, y_m: 0, lat_deg: 1, lon_deg: 2}"),
      "exactly one position form");
  expectError(replace(kGood, "behaviour: planner\n    planner: dssa_plus", "behaviour: planner"),
              "behaviour planner needs a planner");
  expectError(replace(kGood, "format: 1", "format: 2"), "unsupported format");
}

TEST(Scenario, UnitMistakesAreCaught) {
  expectError(replace(kGood, "speed_kn: 10.4\n  goal", "speed_kn: 104\n  goal"), "must be in [0, 60] kn");
  expectError(replace(kGood, "range_nm: 7.9", "range_nm: 14630"), "metres given as miles?");
  expectError(replace(kGood, "course_deg: 66", "course_deg: 400"), "[0, 360) deg");
  // Any plugin may be named (pluginlib says at load time which exist); a malformed name is refused.
  EXPECT_EQ(parseScenario(replace(kGood, "planner: aco", "planner: my_pkg/astar")).own.planner,
            "my_pkg/astar");
  expectError(replace(kGood, "planner: aco", "planner: A*"), "not a planner name");
  expectError(replace(kGood, "planner: aco", "planner: my_pkg/"), "not a planner name");
  expectError(replace(kGood, "planner: aco", "planner: a/b/c"), "not a planner name");
}

TEST(Scenario, GoalRadiusNeedsAGoalAndAPositiveValue) {
  const Scenario sc =
      parseScenario(replace(kGood, "  planner: aco\n", "  planner: aco\n  goal_radius_m: 5\n"));
  EXPECT_DOUBLE_EQ(sc.own.goal_radius, 5.0);
  EXPECT_DOUBLE_EQ(sc.targets[2].goal_radius, 0.0);  // not given: the simulator's default
  expectError(replace(kGood, "  planner: aco\n", "  planner: aco\n  goal_radius_m: -1\n"), "goal_radius_m");
  expectError(replace(kGood, "    behaviour: constant\n", "    behaviour: constant\n    goal_radius_m: 5\n"),
              "needs a goal");
}

TEST(Scenario, StaysAtGoalIsABooleanThatNeedsAGoal) {
  const Scenario sc =
      parseScenario(replace(kGood, "  planner: aco\n", "  planner: aco\n  stays_at_goal: true\n"));
  EXPECT_TRUE(sc.own.stays_at_goal);
  EXPECT_FALSE(sc.targets[2].stays_at_goal);  // not given: an arrived ship leaves the scenario
  EXPECT_FALSE(parseScenario(replace(kGood, "  planner: aco\n", "  planner: aco\n  stays_at_goal: false\n"))
                   .own.stays_at_goal);
  expectError(replace(kGood, "  planner: aco\n", "  planner: aco\n  stays_at_goal: yes\n"),
              "must be true or false");
  expectError(
      replace(kGood, "    behaviour: constant\n", "    behaviour: constant\n    stays_at_goal: true\n"),
      "needs a goal");
}

TEST(Scenario, OverlappingShipsAreAnError) {
  expectError(replace(kGood, "position: {x_m: 3000, y_m: 3000}", "position: {x_m: 3, y_m: 3}"),
              "starts overlapping 'own'");
}

TEST(Scenario, YamlSyntaxErrorNamesTheLine) {
  expectError("format: 1\nname: [unclosed\n", "test.yaml:");
  EXPECT_THROW(loadScenario("/nonexistent/scenario.yaml"), ScenarioError);
}

// Found by fuzzing (src/fuzz/fuzz_scenario.cpp): each was a crash, a NaN in an accepted scenario, a
// non-ScenarioError exception or a hang.
TEST(ScenarioFuzzRegression, HostileValuesAreScenarioErrors) {
  // Cast to int before the check: undefined behaviour (UBSan: float-cast-overflow).
  expectError(replace(kGood, "format: 1", "format: 1e300"), "unsupported format");
  expectError(replace(kGood, "format: 1", "format: 1.5"), "unsupported format");
  // Unbounded bearing: degToRad(1e308) is inf, the position NaN, and the scenario was accepted.
  expectError(replace(kGood, "bearing_deg: 90", "bearing_deg: 1e308"), "must be in [0, 360] deg");
  // A sequence as a key: yaml-cpp's BadConversion escaped instead of a ScenarioError.
  expectError(replace(kGood, "seed_note: x", "[a]: x"), "test.yaml:");
  // "Billion laughs": 5 levels of 12 aliases each, in 1 KB, expand to 2 x 12^5 planner parameters.
  std::string laughs = "planner_params:\n  a0: &a0 {x: 1, y: 2}\n";
  for (int i = 1; i <= 5; ++i) {
    laughs += "  a" + std::to_string(i) + ": &a" + std::to_string(i) + " {";
    for (int k = 0; k < 12; ++k)
      laughs += (k ? ", p" : "p") + std::to_string(k) + ": *a" + std::to_string(i - 1);
    laughs += "}\n";
  }
  expectError(replace(kGood, "planner_params: {aco: {ants: 10, rho: 0.1}, seed_note: x}\n", laughs),
              "more than 10000 entries");
  // A mapping holding an alias of itself (found by fuzz_scenario): each level lengthened every key, and
  // 10000 levels of keys took 120 MB and half a second before the entry cap stopped them.
  expectError(replace(kGood, "planner_params: {aco: {ants: 10, rho: 0.1}, seed_note: x}\n",
                      "planner_params:\n  aco: &p\n    ants: 10\n    again: *p\n"),
              "nested deeper than 8 levels");
  // Eight levels are accepted: the limit is on nesting, not on a plugin's ordinary keys.
  const Scenario deep =
      parseScenario(replace(kGood, "planner_params: {aco: {ants: 10, rho: 0.1}, seed_note: x}\n",
                            "planner_params: {a: {b: {c: {d: {e: {f: {g: {h: 1}}}}}}}}\n"),
                    "test.yaml");
  EXPECT_EQ(deep.planner_params.getDouble("a/b/c/d/e/f/g/h", 0.0), 1.0);
}

TEST(Scenario, ObstacleClearanceOfTheWaters) {
  EXPECT_DOUBLE_EQ(parseScenario(kGood).min_obstacle_clearance, 0.0);  // not given: the node's own
  const Scenario s = parseScenario(replace(kGood, "safety: {min_separation_m: 926}",
                                           "safety: {min_separation_m: 926, min_obstacle_clearance_m: 100}"));
  EXPECT_DOUBLE_EQ(s.min_obstacle_clearance, 100.0);
  EXPECT_DOUBLE_EQ(s.min_separation, 926.0);
  expectError(replace(kGood, "safety: {min_separation_m: 926}", "safety: {min_obstacle_clearance_m: -5}"),
              "must be > 0 m");
}
