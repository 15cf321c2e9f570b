// asv_batch end to end: runs the built binary on a small crossing scenario and checks the JSON it
// writes (docs/evaluation.md), the exit codes of bad input, and determinism across two runs.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Output {
  std::string out;
  int status = -1;
};

Output run(const std::string& args) {
  Output o;
  const std::string cmd = std::string(ASV_BATCH_BIN) + " " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  if (!p)
    return o;
  char buf[4096];
  size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0)
    o.out.append(buf, n);
  const int st = pclose(p);
  o.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return o;
}

const std::string kScenario = std::string(ASV_SIM_TEST_DIR) + "/batch_crossing.yaml";

double number(const std::string& json, const std::string& key) {
  const std::regex re("\"" + key + "\": (-?[0-9.]+)");
  std::smatch m;
  if (!std::regex_search(json, m, re))
    return NAN;
  return std::stod(m[1]);
}
bool flag(const std::string& json, const std::string& key) {
  return json.find("\"" + key + "\": true") != std::string::npos;
}
// The run result without its wall-clock values.
std::string stripWallClock(std::string json) {
  json = std::regex_replace(json, std::regex("\"wall_time_s\": [-0-9.enull]+"), "\"wall_time_s\": X");
  json = std::regex_replace(json, std::regex("\"median\": [-0-9.enull]+, \"max\": [-0-9.enull]+"),
                            "\"median\": X, \"max\": X");
  return json;
}

}  // namespace

TEST(AsvBatch, HelpAndBadInputExitCodes) {
  const Output help = run("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--scenario"), std::string::npos);
  EXPECT_EQ(run("").status, 2);                                               // no scenario
  EXPECT_EQ(run("--scenario /nonexistent/scenario.yaml").status, 2);          // bad file
  EXPECT_EQ(run("--scenario " + kScenario + " --planner nosuch").status, 2);  // unknown planner
  EXPECT_EQ(run("--scenario " + kScenario + " --bogus").status, 2);
}

TEST(AsvBatch, NoPlannerSteersIntoTheCollisionAndSaysSo) {
  // The target (3000, 3000) heading west at 5 m/s meets the own ship (north at 5 m/s) at (0, 3000) at
  // t = 600 s: without a planner the run must report the collision.
  const Output o = run("--scenario " + kScenario + " --planner none --seed 3 --quiet");
  ASSERT_EQ(o.status, 0);
  EXPECT_TRUE(flag(o.out, "collision"));
  EXPECT_LT(number(o.out, "min_separation_m"), 100.0);
  EXPECT_TRUE(flag(o.out, "safety_violation"));
  EXPECT_NE(o.out.find("\"planner\": \"none\""), std::string::npos);
  EXPECT_NE(o.out.find("\"seed\": 3"), std::string::npos);
  EXPECT_NEAR(number(o.out, "colregs_score"), 0.0, 1e-9);
}

TEST(AsvBatch, PlannerAvoidsArrivesAndWritesEveryKey) {
  const Output o = run("--scenario " + kScenario + " --seed 1 --quiet --deterministic");
  ASSERT_EQ(o.status, 0) << o.out;
  ASSERT_EQ(std::count(o.out.begin(), o.out.end(), '\n'), 1);  // one JSON line per run
  for (const char* key : {"scenario",
                          "planner",
                          "seed",
                          "collision",
                          "min_separation_m",
                          "safety_violation",
                          "arrived",
                          "time_to_goal_s",
                          "path_length_m",
                          "path_ratio",
                          "manoeuvres",
                          "targets",
                          "colregs_score",
                          "plan_time_ms",
                          "wall_time_s",
                          "encounter",
                          "own_role",
                          "min_distance_m",
                          "tcpa_at_start_s",
                          "dcpa_at_start_m",
                          "colregs_ok",
                          "colregs_notes",
                          "collisions_between_targets",
                          "grounding",
                          "min_obstacle_distance_m"})
    EXPECT_NE(o.out.find(std::string("\"") + key + "\": "), std::string::npos) << key;
  EXPECT_NE(o.out.find("\"scenario\": \"batch_crossing\", \"planner\": \"ga\""), std::string::npos);
  EXPECT_FALSE(flag(o.out, "collision"));
  EXPECT_TRUE(flag(o.out, "arrived"));
  EXPECT_GT(number(o.out, "min_separation_m"), 200.0);
  // Start geometry of ts1, by hand: relative position (3000, 3000), relative velocity (-5, -5).
  EXPECT_NEAR(number(o.out, "tcpa_at_start_s"), 600.0, 0.05);
  EXPECT_NEAR(number(o.out, "dcpa_at_start_m"), 0.0, 0.05);
  EXPECT_NE(o.out.find("\"encounter\": \"crossing\", \"own_role\": \"give_way\""), std::string::npos);
  // Arrived within the 200 m acceptance radius of the 6000 m straight line: ratio >= 5800 / 6000.
  EXPECT_GE(number(o.out, "path_ratio"), 5800.0 / 6000.0);
  EXPECT_GE(number(o.out, "path_length_m"), 6000.0 - 200.0);
  EXPECT_GT(number(o.out, "count"), 0.0);
}

TEST(AsvBatch, SameSeedGivesByteIdenticalJson) {
  const Output a = run("--scenario " + kScenario + " --seed 5 --runs 2 --quiet");
  const Output b = run("--scenario " + kScenario + " --seed 5 --runs 2 --quiet");
  ASSERT_EQ(a.status, 0);
  ASSERT_EQ(b.status, 0);
  EXPECT_EQ(std::count(a.out.begin(), a.out.end(), '\n'), 2);
  EXPECT_NE(a.out.find("\"seed\": 6"), std::string::npos);
  EXPECT_EQ(stripWallClock(a.out), stripWallClock(b.out));
  const Output d1 = run("--scenario " + kScenario + " --seed 5 --quiet --deterministic");
  const Output d2 = run("--scenario " + kScenario + " --seed 5 --quiet --deterministic");
  EXPECT_EQ(d1.out, d2.out);
}

TEST(AsvBatch, DssaPaperSixteenShipsAllArriveWithoutCollision) {
  // Hirayama et al. (2019) Table 2: DSSA+ s>c succeeds in 50 of 50 trials of the 16-ship crossing. In sea
  // mode (alpha 1: a predicted collision outweighs any turn) ten of them here (seeds 1-10): every ship
  // arrives and no two come closer than the collision distance 40. The paper mode's figures are in
  // docs/results/dssa.md (make papers).
  const std::string sc = std::string(ASV_SIM_TEST_DIR) + "/../../asv_bringup/scenarios/dssa_16_ships.yaml";
  const Output o = run("--scenario " + sc +
                       " --planner dssa_plus --agents dssa_plus --set dssa_plus.preset=dssa_plus_sc"
                       " --set dssa_plus.mode=sea --runs 10 --deterministic --quiet");
  ASSERT_EQ(o.status, 0);
  int lines = 0;
  size_t start = 0;
  for (size_t end; (end = o.out.find('\n', start)) != std::string::npos; start = end + 1) {
    const std::string line = o.out.substr(start, end - start);
    ++lines;
    EXPECT_EQ(line.find("\"arrived\": false"), std::string::npos) << "seed " << lines;
    EXPECT_FALSE(flag(line, "collision")) << "seed " << lines;
    EXPECT_NE(line.find("\"collisions_between_targets\": 0,"), std::string::npos) << "seed " << lines;
    const std::regex sep("\"min_separation_m\": ([0-9.]+)");
    int ships = 0;
    for (std::sregex_iterator it(line.begin(), line.end(), sep), e; it != e; ++it, ++ships)
      EXPECT_GE(std::stod((*it)[1]), 40.0) << "seed " << lines;
    EXPECT_EQ(ships, 17);  // the own ship at the top level, then all 16 under "ships"
  }
  EXPECT_EQ(lines, 10);
  // --agents gives every planning target that planner: plain DSSA, the own ship and 16 under "ships".
  const Output d = run("--scenario " + sc + " --planner dssa --agents dssa --deterministic --quiet");
  ASSERT_EQ(d.status, 0);
  const std::regex dssa("\"planner\": \"dssa\"");
  EXPECT_EQ(std::distance(std::sregex_iterator(d.out.begin(), d.out.end(), dssa), std::sregex_iterator()),
            17);
  // --set is checked: a malformed one and an unknown key are usage errors.
  EXPECT_EQ(run("--scenario " + sc + " --set dssa_plus").status, 2);
  EXPECT_EQ(run("--scenario " + sc + " --set dssa_plus.no_such_key=1 --quiet").status, 2);
}

// Land is a hazard for every planner: with no traffic at all, the straight way to the goal crosses an
// island. Without a planner the ship runs aground (and the result says so); every planner goes round.
TEST(AsvBatch, EveryPlannerGoesRoundAnIslandAndNoneRunsAground) {
  const std::string island = std::string(ASV_SIM_TEST_DIR) + "/../../asv_bringup/scenarios/island.yaml";
  const Output none = run("--scenario " + island + " --planner none --seed 1");
  ASSERT_EQ(none.status, 0) << none.out;
  EXPECT_TRUE(flag(none.out, "grounding")) << none.out;
  EXPECT_DOUBLE_EQ(number(none.out, "min_obstacle_distance_m"), 0.0);
  EXPECT_DOUBLE_EQ(number(none.out, "colregs_score"), 0.0);
  for (const char* planner : {"aco", "mopso", "ga", "dssa", "dssa_plus"}) {
    const Output o = run("--scenario " + island + " --planner " + planner + " --seed 1");
    ASSERT_EQ(o.status, 0) << planner << ": " << o.out;
    EXPECT_FALSE(flag(o.out, "grounding")) << planner << ": " << o.out;
    EXPECT_TRUE(flag(o.out, "arrived")) << planner << ": " << o.out;
    EXPECT_GT(number(o.out, "min_obstacle_distance_m"), 90.0) << planner << ": " << o.out;
  }
}

// Rule 9: in narrow_channel.yaml a coaster comes down the middle line of a 400 m channel, which the own
// ship's route follows too, and never gives way. Keeping to the starboard side of the channel, every
// planner passes her port to port, clear of the 50 m separation, and arrives; with the rule off
// (narrow_fairway_width_m 0) ACO holds the middle line into a collision.
TEST(AsvBatch, EveryPlannerKeepsToTheStarboardSideOfANarrowChannel) {
  const std::string channel =
      std::string(ASV_SIM_TEST_DIR) + "/../../asv_bringup/scenarios/narrow_channel.yaml";
  for (const char* planner : {"aco", "mopso", "ga", "dssa", "dssa_plus"}) {
    const Output o = run("--scenario " + channel + " --planner " + planner + " --seed 1 --deterministic");
    ASSERT_EQ(o.status, 0) << planner << ": " << o.out;
    EXPECT_FALSE(flag(o.out, "collision")) << planner << ": " << o.out;
    EXPECT_FALSE(flag(o.out, "grounding")) << planner << ": " << o.out;
    EXPECT_TRUE(flag(o.out, "arrived")) << planner << ": " << o.out;
    EXPECT_GT(number(o.out, "min_separation_m"), 50.0) << planner << ": " << o.out;
  }
  const Output off = run("--scenario " + channel +
                         " --planner aco --seed 1 --deterministic --follower narrow_fairway_width_m=0");
  ASSERT_EQ(off.status, 0) << off.out;
  EXPECT_TRUE(flag(off.out, "collision")) << off.out;
}

// Real land from a chart: the New York scenario's straight way cuts the Brooklyn shore (GSHHG full
// through GMT, installed by scripts/setup). Without a planner the run is a grounding, and --charts
// replaces the scenario's chart: with an island of a GeoJSON file 8,000 km away, nothing is land here.
TEST(AsvBatch, ChartLandGroundsAShipWithoutAPlannerAndChartsOverridesTheSource) {
  const std::string root = std::string(ASV_SIM_TEST_DIR) + "/../..";
  const std::string ny = root + "/asv_bringup/scenarios/ny_upper_bay.yaml";
  const Output none = run("--scenario " + ny + " --planner none --seed 1 --chart-cache none");
  ASSERT_EQ(none.status, 0) << none.out;
  EXPECT_TRUE(flag(none.out, "grounding")) << none.out;
  const Output other = run("--scenario " + ny + " --planner none --seed 1 --chart-cache none --charts " +
                           root + "/src/test/data/island.geojson");
  ASSERT_EQ(other.status, 0) << other.out;
  EXPECT_FALSE(flag(other.out, "grounding")) << other.out;
  const Output bad = run("--scenario " + ny + " --planner none --charts /nonexistent.geojson");
  EXPECT_EQ(bad.status, 2);
}

// --risk writes the own ship's picture; Hu et al. (2017) Fig. 6 (hu_non_compliant): A, the give-way ship
// from port, heads for the point the own ship reaches at 900 s (TCPA 900 s, DCPA 0 at the start), so it is
// at risk 1 until its TCPA falls to t_safe = 600 s, and Algorithm 1 flags it at t = 300 s, by hand. With
// the picture every 5 s the first non-compliant row is at 300 s. --follower keys are checked.
TEST(AsvBatch, RiskPictureShowsTheFlagOfFigure6) {
  const std::string sc = std::string(ASV_SIM_TEST_DIR) + "/../../asv_bringup/scenarios/hu_non_compliant.yaml";
  const std::string csv = ::testing::TempDir() + "asv_batch_risk.csv";
  const Output o =
      run("--scenario " + sc + " --deterministic --quiet --risk " + csv + " --follower replan_on_risk=true");
  ASSERT_EQ(o.status, 0) << o.out;
  std::ifstream f(csv);
  std::string line;
  ASSERT_TRUE(std::getline(f, line));
  EXPECT_EQ(line, "t_s,target,range_m,tcpa_s,dcpa_m,cri,risk_level,compliant,role,cri_eq1");
  double first_flag = -1.0;
  int rows = 0, passed = 0;
  while (std::getline(f, line)) {
    ++rows;
    std::stringstream ss(line);
    std::vector<std::string> c;
    for (std::string cell; std::getline(ss, cell, ',');)
      c.push_back(cell);
    ASSERT_EQ(c.size(), 10u) << line;
    // cri_eq1 is Wu et al. eq. (1) without Fig. 3's rule: the same while the CPA is ahead; once the
    // ship is past, cri is 0 and eq. (1) is not.
    if (std::stod(c[3]) > 0.0) {
      EXPECT_EQ(c[5], c[9]) << line;
    } else if (std::stod(c[9]) > 0.0) {
      EXPECT_EQ(std::stod(c[5]), 0.0) << line;
      ++passed;
    }
    if (rows == 1) {
      EXPECT_EQ(c[0], "0.0");
      EXPECT_NEAR(std::stod(c[3]), 900.0, 1.0);  // TCPA
      EXPECT_EQ(c[6], "1");                      // risk 1
      EXPECT_EQ(c[8], "stand_on");
    }
    if (c[7] == "0" && first_flag < 0.0)
      first_flag = std::stod(c[0]);
  }
  EXPECT_GT(rows, 100);
  EXPECT_GT(passed, 0) << "the run goes on after the CPA";
  EXPECT_DOUBLE_EQ(first_flag, 300.0);
  EXPECT_EQ(run("--scenario " + sc + " --follower replan_onrisk=false").status, 2);
  EXPECT_EQ(run("--scenario " + sc + " --follower replan_on_risk").status, 2);
}

// Without a planner of her own the own ship's picture is still written (the default assessment), not
// left empty. By hand: ts1 4242.6 m off (3000, 3000), closing at 7.07 m/s, CPA 0 m at 600 s; she
// crosses from starboard, so the own ship gives way (Rule 15).
TEST(AsvBatch, RiskPictureIsWrittenWithoutAPlanner) {
  const std::string csv = ::testing::TempDir() + "asv_batch_risk_none.csv";
  const Output o = run("--scenario " + kScenario + " --planner none --deterministic --quiet --risk " + csv);
  ASSERT_EQ(o.status, 0) << o.out;
  std::ifstream f(csv);
  std::string header, first;
  ASSERT_TRUE(std::getline(f, header));
  ASSERT_TRUE(std::getline(f, first)) << "no rows: the picture is empty without a planner";
  std::stringstream ss(first);
  std::vector<std::string> c;
  for (std::string cell; std::getline(ss, cell, ',');)
    c.push_back(cell);
  ASSERT_EQ(c.size(), 10u) << first;
  EXPECT_EQ(c[0], "0.0");
  EXPECT_EQ(c[1], "ts1");
  EXPECT_NEAR(std::stod(c[2]), 4242.6, 0.1);
  EXPECT_NEAR(std::stod(c[3]), 600.0, 0.1);
  EXPECT_NEAR(std::stod(c[4]), 0.0, 0.1);
  EXPECT_EQ(c[8], "give_way");
}

// --plans writes one row per plan the own ship's planner made: as many as the result counts in
// plan_time_ms.count, the first at t = 0 (the run's first replan), each a status and a quoted message.
TEST(AsvBatch, PlanLogHasARowForEveryPlan) {
  const std::string csv = ::testing::TempDir() + "asv_batch_plans.csv";
  const Output o = run("--scenario " + kScenario + " --deterministic --quiet --plans " + csv);
  ASSERT_EQ(o.status, 0) << o.out;
  const std::regex count_re("\"plan_time_ms\": \\{[^}]*\"count\": ([0-9]+)");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(o.out, m, count_re)) << o.out;
  std::ifstream f(csv);
  std::string line;
  ASSERT_TRUE(std::getline(f, line));
  EXPECT_EQ(line, "t_s,reason,status,course_deg,speed_mps,message");
  const std::regex row_re("^([0-9.]+),\"[^\"]*\",(ok|fallback|no_solution),-?[0-9.]+,[0-9.]+,\"(.*)\"$");
  int rows = 0;
  while (std::getline(f, line)) {
    std::smatch r;
    ASSERT_TRUE(std::regex_match(line, r, row_re)) << line;
    if (rows++ == 0) {
      EXPECT_EQ(r[1].str(), "0.0");
    }
    EXPECT_FALSE(r[3].str().empty()) << line;
  }
  EXPECT_GT(rows, 0);
  EXPECT_EQ(rows, std::stoi(m[1].str()));
}
