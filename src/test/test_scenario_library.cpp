// The scenario library (asv_bringup/scenarios/*.yaml): every file loads, is named after its file, says
// what it reproduces, passes its planner_params to the planner it names, starts its ships clear of each
// other and runs in the simulator; the paper scenarios carry the same situations as the core's paper
// scenario functions (lazarowska_scenarios.h, dssa_experiments.h, hu_scenarios.h, wu_scenarios.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "asv_core/papers/dssa_experiments.h"
#include "asv_core/papers/hu_scenarios.h"
#include "asv_core/papers/lazarowska_scenarios.h"
#include "asv_core/papers/wu_scenarios.h"
#include "asv_core/planning/aco/aco_planner.h"
#include "asv_core/planning/dssa/dssa.h"
#include "asv_core/planning/ga/ga_planner.h"
#include "asv_core/planning/mopso/mopso_planner.h"
#include "asv_core/risk/colregs.h"
#include "asv_core/risk/cpa.h"
#include "asv_core/risk/domain.h"
#include "asv_core/sim/simulation.h"
#include "asv_core/world/scenario.h"

using namespace asv;
namespace fs = std::filesystem;

namespace {

const std::string kDir = std::string(ASV_SOURCE_DIR) + "/asv_bringup/scenarios";
constexpr double kPosTol = 1.0;     // [m]
constexpr double kAngTol = 1e-3;    // [rad]
constexpr double kSpeedTol = 1e-3;  // [m/s]

std::vector<fs::path> scenarioFiles() {
  std::vector<fs::path> out;
  if (fs::is_directory(kDir))
    for (const auto& e : fs::directory_iterator(kDir))
      if (e.path().extension() == ".yaml")
        out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

Scenario load(const std::string& name) {
  return loadScenario(kDir + "/" + name + ".yaml");
}

ShipState toState(const ScenarioShip& s) {
  ShipState st;
  st.id = s.name;
  st.position = s.position;
  st.course = st.heading = s.course;
  st.speed = s.speed;
  st.length = s.length;
  return st;
}

double angleDiff(double a, double b) {
  return std::fabs(wrapPi(a - b));
}

void expectNear(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double tol, const std::string& what) {
  EXPECT_LE((a - b).norm(), tol) << what << ": (" << a.x() << ", " << a.y() << ") vs (" << b.x() << ", "
                                 << b.y() << ")";
}

// The scenario's ships equal a planning problem's own ship, goal and targets (in order).
void expectSameProblem(const Scenario& s, const PlanningProblem& p) {
  SCOPED_TRACE(s.name);
  expectNear(s.own.position, p.own.position, kPosTol, "own position");
  EXPECT_LE(angleDiff(s.own.course, p.own.course), kAngTol);
  EXPECT_NEAR(s.own.speed, p.own.speed, kSpeedTol);
  ASSERT_TRUE(s.own.goal.has_value());
  expectNear(*s.own.goal, p.goal, kPosTol, "own goal");
  ASSERT_EQ(s.targets.size(), p.targets.size());
  for (size_t i = 0; i < s.targets.size(); ++i) {
    SCOPED_TRACE(s.targets[i].name);
    expectNear(s.targets[i].position, p.targets[i].state.position, kPosTol, "target position");
    EXPECT_NEAR(s.targets[i].speed, p.targets[i].state.speed, kSpeedTol);
    if (p.targets[i].state.speed > 0.0) {
      EXPECT_LE(angleDiff(s.targets[i].course, p.targets[i].state.course), kAngTol);
    }
  }
}

const std::vector<std::string> kExpected = {"lazarowska_1",
                                            "lazarowska_2",
                                            "dssa_two_ships",
                                            "dssa_16_ships",
                                            "dssa_three_overtaking",
                                            "hu_overtaking_open",
                                            "hu_overtaking_restricted",
                                            "hu_multi_target",
                                            "hu_non_compliant",
                                            "wu_port",
                                            "head_on",
                                            "crossing_give_way",
                                            "crossing_stand_on",
                                            "overtaking",
                                            "being_overtaken",
                                            "congested_port",
                                            "island"};

}  // namespace

TEST(ScenarioLibrary, ExpectedFilesExist) {
  ASSERT_TRUE(fs::is_directory(kDir)) << kDir;
  for (const auto& n : kExpected)
    EXPECT_TRUE(fs::exists(kDir + "/" + n + ".yaml")) << n;
  EXPECT_TRUE(fs::exists(kDir + "/README.md"));
}

TEST(ScenarioLibrary, EveryFileLoadsAndIsComplete) {
  const auto files = scenarioFiles();
  ASSERT_GE(files.size(), kExpected.size());
  for (const auto& f : files) {
    SCOPED_TRACE(f.filename().string());
    Scenario s;
    ASSERT_NO_THROW(s = loadScenario(f.string()));
    EXPECT_EQ(s.format, 1);
    EXPECT_EQ(s.name, f.stem().string());
    EXPECT_GE(s.description.size(), 40u) << "description should say what it reproduces";
    EXPECT_TRUE(s.has_origin);
    EXPECT_GT(s.min_separation, 0.0);
    // scenario.launch and the batch runner name the own ship "own" by default.
    EXPECT_EQ(s.own.name, "own");
    ASSERT_TRUE(s.own.goal.has_value()) << "the own ship needs a goal";
    ASSERT_GT(s.own.speed, 0.0);
    // Long enough for the own ship to reach its goal: straight-line time + 20 %.
    const double straight = (*s.own.goal - s.own.position).norm() / s.own.speed;
    EXPECT_GE(s.duration, 1.2 * straight) << "straight-line time " << straight << " s";
    // Own ship not inside an obstacle at the goal either.
    for (const auto& o : s.obstacles)
      EXPECT_FALSE(pointInPolygon(o.polygon, *s.own.goal)) << o.name;
    for (const auto& t : s.targets)
      for (const auto& o : s.obstacles)
        EXPECT_FALSE(pointInPolygon(o.polygon, t.position)) << t.name << " starts inside " << o.name;
  }
}

// Every planner_params subtree names one of the five planners the library uses and is accepted by that
// planner's fromParams (which rejects unknown keys and validates the values).
TEST(ScenarioLibrary, PlannerParamsAreAccepted) {
  const std::vector<std::string> known{"aco", "dssa", "dssa_plus", "mopso", "ga"};
  for (const auto& f : scenarioFiles()) {
    SCOPED_TRACE(f.filename().string());
    const Scenario s = loadScenario(f.string());
    std::set<std::string> prefixes;
    for (const auto& kv : s.planner_params.values())
      prefixes.insert(kv.first.substr(0, kv.first.find('/')));
    for (const auto& p : prefixes) {
      ASSERT_NE(std::find(known.begin(), known.end(), p), known.end()) << "planner_params." << p;
      const ParamMap sub = s.planner_params.sub(p);
      if (p == "aco") {
        EXPECT_NO_THROW(AcoConfig::fromParams(sub));
      } else if (p == "dssa" || p == "dssa_plus") {
        ParamMap withPreset = sub;
        if (!withPreset.has("preset"))
          withPreset.set("preset", p);
        EXPECT_NO_THROW(DssaConfig::fromParams(withPreset));
      } else if (p == "mopso") {
        EXPECT_NO_THROW(MopsoConfig::fromParams(sub));
      } else if (p == "ga") {
        EXPECT_NO_THROW(GaConfig::fromParams(sub));
      }
    }
  }
}

TEST(ScenarioLibrary, Lazarowska) {
  const Scenario s1 = load("lazarowska_1");
  EXPECT_NEAR(radToDeg(s1.own.course), 66.0, 1e-9);
  EXPECT_EQ(s1.own.planner, "aco");
  expectSameProblem(s1, lazarowskaScenario1());
  EXPECT_EQ(s1.targets.size(), 4u);

  const Scenario s2 = load("lazarowska_2");
  EXPECT_NEAR(radToDeg(s2.own.course), 61.0, 1e-9);
  EXPECT_EQ(s2.own.planner, "aco");
  expectSameProblem(s2, lazarowskaScenario2());
  EXPECT_EQ(s2.targets.size(), 7u);
  for (const Scenario* s : {&s1, &s2}) {
    EXPECT_DOUBLE_EQ(s->min_separation, 926.0);
    for (const auto& t : s->targets)
      EXPECT_EQ(t.behaviour, Behaviour::Constant);
  }
}

TEST(ScenarioLibrary, Dssa) {
  const std::map<std::string, DssaScenario> files = {{"dssa_two_ships", dssaTwoShipScenario()},
                                                     {"dssa_16_ships", dssaSixteenShipScenario()},
                                                     {"dssa_three_overtaking", dssaThreeShipScenario()}};
  for (const auto& [name, core] : files) {
    SCOPED_TRACE(name);
    const Scenario s = load(name);
    EXPECT_DOUBLE_EQ(s.min_separation, 40.0);
    ASSERT_EQ(s.targets.size() + 1, core.ships.size());
    EXPECT_EQ(s.planningShips().size(), core.ships.size()) << "every ship runs the planner";
    for (size_t i = 0; i < core.ships.size(); ++i) {
      const ScenarioShip& ship = i == 0 ? s.own : s.targets[i - 1];
      const DssaSimShip& c = core.ships[i];
      SCOPED_TRACE(c.name);
      if (i > 0) {
        EXPECT_EQ(ship.name, c.name);
        EXPECT_EQ(ship.behaviour, Behaviour::Planner);
      }
      EXPECT_EQ(ship.planner, "dssa_plus");
      expectNear(ship.position, c.start, kPosTol, "start");
      ASSERT_TRUE(ship.goal.has_value());
      expectNear(*ship.goal, c.goal, kPosTol, "goal");
      EXPECT_NEAR(ship.speed, c.speeds.ref, kSpeedTol);
      EXPECT_LE(angleDiff(ship.course, trueBearing(c.start, c.goal)), kAngTol);
      EXPECT_TRUE(ship.stays_at_goal) << "Fig. 1: an arrived ship stays where she stopped";
    }
    // The paper's units, not the plugin's sea-scale defaults.
    ParamMap p = s.planner_params.sub("dssa_plus");
    p.set("preset", "dssa_plus");
    const DssaConfig cfg = DssaConfig::fromParams(p);
    const DssaConfig paper = DssaConfig::preset("dssa_plus");
    EXPECT_DOUBLE_EQ(cfg.time_window, paper.time_window);
    EXPECT_DOUBLE_EQ(cfg.time_step, paper.time_step);
    EXPECT_DOUBLE_EQ(cfg.detection_range, paper.detection_range);
    EXPECT_DOUBLE_EQ(cfg.collision_distance, paper.collision_distance);
    EXPECT_DOUBLE_EQ(cfg.min_speed_fraction, kDssaPaperMinSpeedFraction);
    EXPECT_DOUBLE_EQ(cfg.max_speed_over_ref, 8.0);
    EXPECT_DOUBLE_EQ(cfg.speed_change_max, paper.speed_change_max);
    EXPECT_DOUBLE_EQ(cfg.speed_change_step, paper.speed_change_step);
  }
}

TEST(ScenarioLibrary, Hu) {
  const Scenario open = load("hu_overtaking_open");
  expectSameProblem(open, huOvertakingOpenWater());
  EXPECT_TRUE(open.obstacles.empty());

  const Scenario restricted = load("hu_overtaking_restricted");
  const PlanningProblem pr = huOvertakingRestrictedWater();
  expectSameProblem(restricted, pr);
  ASSERT_EQ(restricted.obstacles.size(), pr.obstacles.size());
  ASSERT_EQ(restricted.obstacles[0].polygon.size(), pr.obstacles[0].polygon.size());
  for (size_t k = 0; k < pr.obstacles[0].polygon.size(); ++k)
    expectNear(restricted.obstacles[0].polygon[k], pr.obstacles[0].polygon[k], kPosTol, "land vertex");

  const Scenario multi = load("hu_multi_target");
  expectSameProblem(multi, huMultiTarget());
  ASSERT_EQ(multi.targets.size(), 4u);
  EXPECT_EQ(multi.targets[3].speed, 0.0) << "D is a static target";

  const Scenario nc = load("hu_non_compliant");
  expectSameProblem(nc, huNonCompliantTarget(0.0));
  ASSERT_EQ(nc.targets.size(), 1u);
  EXPECT_EQ(nc.targets[0].behaviour, Behaviour::NonCompliant);
  // From the own ship: crossing from port, the own ship stands on (the target should give way).
  const ShipState own = toState(nc.own), tgt = toState(nc.targets[0]);
  EXPECT_EQ(classifyEncounter(own, tgt, computeCpa(own, tgt), ColregsConfig{}).role, OwnRole::StandOn);

  for (const Scenario* s : {&open, &restricted, &multi, &nc}) {
    EXPECT_EQ(s->own.planner, "mopso") << s->name;
    EXPECT_DOUBLE_EQ(s->min_separation, 926.0);
  }
}

TEST(ScenarioLibrary, Wu) {
  const Scenario s = load("wu_port");
  EXPECT_EQ(s.own.model, "wu_asv_40m");
  EXPECT_EQ(s.own.planner, "ga");
  EXPECT_NEAR(s.own.length, kWuAsvLength, 1e-9);
  EXPECT_NEAR(s.own.speed, kWuAsvSpeed, kSpeedTol);
  EXPECT_DOUBLE_EQ(s.min_separation, 50.0);
  expectNear(s.own.position, Eigen::Vector2d::Zero(), kPosTol, "own");
  // Each target stands at the core's relative position when the own ship, holding 000 at 12 kn,
  // reaches the moment its encounter forms (330 s, 447 s, 447 s, 800 s).
  std::vector<std::pair<PlannerTarget, double>> core;
  core.push_back({wuHeadOn().targets.at(0), 330.0});
  for (const auto& t : wuCrossing().targets)
    core.push_back({t, 447.0});
  core.push_back({wuOvertaking().targets.at(0), 800.0});
  ASSERT_EQ(s.targets.size(), core.size());
  const Eigen::Vector2d own_v = courseSpeedToVelocity(s.own.course, s.own.speed);
  for (const auto& [ct, t_enc] : core) {
    const ScenarioShip* sh = nullptr;
    for (const auto& t : s.targets)
      if (t.name == ct.state.id)
        sh = &t;
    ASSERT_NE(sh, nullptr) << ct.state.id;
    SCOPED_TRACE(sh->name);
    EXPECT_NEAR(sh->speed, ct.state.speed, kSpeedTol);
    EXPECT_LE(angleDiff(sh->course, ct.state.course), kAngTol);
    const Eigen::Vector2d rel = sh->position + courseSpeedToVelocity(sh->course, sh->speed) * t_enc -
                                (s.own.position + own_v * t_enc);
    expectNear(rel, ct.state.position, kPosTol, "relative position at the encounter");  // core own at 0
  }
  // The CRI scaled as the core scales it.
  const GaConfig g = GaConfig::fromParams(s.planner_params.sub("ga"));
  const CriConfig c = wuAsvCriConfig();
  EXPECT_NEAR(g.cri.safe_encounter.domain_unit_m, c.safe_encounter.domain_unit_m, 1e-9);
  EXPECT_NEAR(g.cri.safe_encounter.turn90_time_s, c.safe_encounter.turn90_time_s, 1e-9);
  EXPECT_NEAR(g.cri.safe_encounter.advance_m, c.safe_encounter.advance_m, 1e-9);
  EXPECT_NEAR(g.cri.dlma_m, c.dlma_m, 1e-6);
  EXPECT_NEAR(g.cri.attention_range_m, c.attention_range_m, 1e-6);
  const GaConfig paper = wuAsvGaConfig();
  EXPECT_EQ(g.population_size, paper.population_size);
  EXPECT_EQ(g.generations, paper.generations);
  EXPECT_DOUBLE_EQ(g.cri_threshold, paper.cri_threshold);
}

TEST(ScenarioLibrary, StandardEncounters) {
  struct Case {
    const char* name;
    Encounter encounter;
    OwnRole role;
    Behaviour behaviour;
  };
  const Case cases[] = {
      {"head_on", Encounter::HeadOn, OwnRole::BothGiveWay, Behaviour::Constant},
      {"crossing_give_way", Encounter::CrossingGiveWay, OwnRole::GiveWay, Behaviour::Constant},
      {"crossing_stand_on", Encounter::CrossingStandOn, OwnRole::StandOn, Behaviour::GiveWay},
      {"overtaking", Encounter::Overtaking, OwnRole::GiveWay, Behaviour::Constant},
      {"being_overtaken", Encounter::BeingOvertaken, OwnRole::StandOn, Behaviour::GiveWay},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const Scenario s = load(c.name);
    EXPECT_TRUE(s.own.planner.empty()) << "the launch file or the batch runner chooses the planner";
    EXPECT_EQ(s.own.model, "kinematic");
    EXPECT_GE(s.own.length, 100.0) << "merchant-size";
    EXPECT_NEAR(mpsToKnots(s.own.speed), 12.0, 1e-9);
    ASSERT_TRUE(s.own.goal.has_value());
    EXPECT_NEAR((*s.own.goal - s.own.position).norm(), nmToMetres(12.0), kPosTol);
    EXPECT_LE(angleDiff(trueBearing(s.own.position, *s.own.goal), s.own.course), kAngTol);
    ASSERT_EQ(s.targets.size(), 1u);
    const double range_nm = (s.targets[0].position - s.own.position).norm() / nmToMetres(1.0);
    EXPECT_GE(range_nm, 6.0 - 1e-9);
    EXPECT_LE(range_nm, 8.0 + 1e-9);
    EXPECT_EQ(s.targets[0].behaviour, c.behaviour);
    const ShipState own = toState(s.own), tgt = toState(s.targets[0]);
    const Cpa cpa = computeCpa(own, tgt);
    const EncounterGeometry g = classifyEncounter(own, tgt, cpa, ColregsConfig{});
    EXPECT_EQ(g.encounter, c.encounter) << toString(g.encounter);
    EXPECT_EQ(g.role, c.role) << toString(g.role);
    EXPECT_LT(cpa.dcpa, 0.5 * s.min_separation) << "a real risk of collision";
    EXPECT_GT(cpa.tcpa, 0.0);
    EXPECT_LT(cpa.tcpa, s.duration);
  }
}

TEST(ScenarioLibrary, CongestedPort) {
  const Scenario s = load("congested_port");
  EXPECT_GE(s.targets.size() + 1, 20u);
  EXPECT_EQ(s.own.planner, "mopso");
  EXPECT_EQ(s.obstacles.size(), 2u);
  std::set<char> classes;
  std::set<Behaviour> behaviours;
  std::vector<const ScenarioShip*> all{&s.own};
  for (const auto& t : s.targets) {
    classes.insert(t.ais_class);
    behaviours.insert(t.behaviour);
    all.push_back(&t);
    EXPECT_GT(t.length, 0.0) << t.name << ": sizes are given";
    // Small craft (under 15 m) carry class B, the rest class A.
    EXPECT_EQ(t.ais_class, t.length < 15.0 ? 'B' : 'A') << t.name;
  }
  EXPECT_EQ(classes, (std::set<char>{'A', 'B'}));
  for (Behaviour b : {Behaviour::Constant, Behaviour::Waypoints, Behaviour::GiveWay, Behaviour::NonCompliant})
    EXPECT_TRUE(behaviours.count(b)) << toString(b);
  double closest = 1e12;
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j)
      closest = std::min(closest, (all[i]->position - all[j]->position).norm());
  EXPECT_GE(closest, 300.0);
}

// Every scenario builds in the simulator (vessel presets found, models set up), starts with no hulls
// touching and runs a few simulated seconds without a collision or a non-finite state.
TEST(ScenarioLibrary, RunsInTheSimulator) {
  // The CMake build points asv_core at src/config/vessels; a direct compile needs the environment.
  setenv("ASV_VESSEL_PRESET_DIR", (std::string(ASV_SOURCE_DIR) + "/src/config/vessels").c_str(), 0);
  for (const auto& f : scenarioFiles()) {
    SCOPED_TRACE(f.filename().string());
    const Scenario sc = loadScenario(f.string());
    std::unique_ptr<Simulation> sim;
    ASSERT_NO_THROW(sim = std::make_unique<Simulation>(sc));
    const auto& v = sim->vessels();
    ASSERT_EQ(v.size(), sc.targets.size() + 1);
    for (size_t i = 0; i < v.size(); ++i) {
      ASSERT_TRUE(v[i].model != nullptr) << v[i].name;
      EXPECT_EQ(v[i].model_name, i == 0 ? sc.own.model : sc.targets[i - 1].model);
      for (size_t j = i + 1; j < v.size(); ++j)
        EXPECT_FALSE(Simulation::hullsTouch(v[i], v[j])) << v[i].name << " / " << v[j].name;
    }
    // A few seconds: short enough for the DSSA unit scenarios (25 m/s in an 800 m area, first
    // conflicts after ~5 s) not to meet yet.
    const double horizon = std::min(10.0, 0.03 * sc.duration);
    const Eigen::Vector2d own0 = sim->own().position();
    while (sim->time() < horizon - 1e-9)
      sim->step();
    EXPECT_FALSE(sim->collided());
    for (const auto& e : sim->events())
      EXPECT_NE(e.type, SimEvent::Collision) << e.a << " / " << e.b;
    for (const auto& vv : sim->vessels())
      EXPECT_TRUE(vv.state().finite()) << vv.name;
    // The own ship is under way at about its scenario speed.
    const double moved = (sim->own().position() - own0).norm();
    EXPECT_NEAR(moved / sim->time(), sc.own.speed, 0.1 * sc.own.speed + 0.05);
  }
}

// With nobody planning, the whole run: the only collisions are the own ship's (the situations are
// collision courses by design); two targets never run into each other, so a run's collisions are the
// planner's business. Scenarios whose targets plan (DSSA) are left out: there every ship is meant to act.
TEST(ScenarioLibrary, TargetsDoNotRunIntoEachOther) {
  setenv("ASV_VESSEL_PRESET_DIR", (std::string(ASV_SOURCE_DIR) + "/src/config/vessels").c_str(), 0);
  for (const auto& f : scenarioFiles()) {
    SCOPED_TRACE(f.filename().string());
    const Scenario sc = loadScenario(f.string());
    if (sc.planningShips().size() > 1)
      continue;
    SimConfig cfg;
    cfg.dt = 0.2;
    Simulation sim(sc, cfg);
    while (!sim.finished())
      sim.step();
    for (const auto& e : sim.events())
      if (e.type == SimEvent::Collision) {
        EXPECT_TRUE(e.a == sc.own.name || e.b == sc.own.name)
            << e.a << " / " << e.b << " collide at " << e.time << " s";
      }
  }
}
