// asv_batch: runs a scenario faster than real time in one process, with the same core components as
// the ROS pipeline (Simulation, RiskAssessor, the planner plugins loaded through pluginlib by short
// name, planner_node's replanning policy through asv::PlanFollower, the evaluator's RunRecorder), and
// writes one run result per line (docs/evaluation.md). No ROS master is needed; pluginlib finds
// the plugins through ROS_PACKAGE_PATH (source devel/setup.bash).
//
// Targets are the simulator's ground truth (no NMEA round trip, no tracker): the batch measures the
// planners, not the sensors. Ships whose planner is dssa or dssa_plus, when there are two or more of
// them, negotiate through the in-process DssaExchange (the core DSSA code path); a single DSSA ship
// plans against the others through its plugin, as planner_node does.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <asv_core/eval/evaluation.h>
#include <asv_core/planning/dssa/dssa.h>
#include <asv_core/planning/ga/ga_planner.h>
#include <asv_core/planning/plan_follower.h>
#include <asv_core/planning/planning_cycle.h>
#include <asv_core/risk/risk_assessment.h>
#include <asv_core/sim/simulation.h>
#include <asv_core/world/scenario.h>
#include <asv_planning/plugin_loader.h>

namespace {

const char* kUsage =
    "usage: asv_batch --scenario FILE [options]\n"
    "\n"
    "Runs a scenario in one process, faster than real time, and writes one run result (JSON, one object\n"
    "per line) per run. Needs the catkin environment (source devel/setup.bash) to find the planners.\n"
    "\n"
    "options:\n"
    "  --scenario FILE      scenario file (format 1), required\n"
    "  --planner NAME       own ship's planner: aco | dssa | dssa_plus | mopso | ga | none, or any\n"
    "                       planner plugin by its pluginlib name (my_pkg/my_planner); default: the\n"
    "                       scenario's own_ship.planner; none steers for the goal\n"
    "  --agents NAME        planner of every target whose behaviour is planner (default: each its own)\n"
    "  --set P.KEY=VALUE    planner parameter, over the scenario's planner_params (repeatable), e.g.\n"
    "                       --set dssa_plus.preset=dssa_plus_sc\n"
    "  --follower KEY=VALUE a replanning-policy parameter of planner_node (planner_node.yaml; repeatable),\n"
    "                       e.g. --follower replan_on_risk=false\n"
    "  --charts SOURCE      land from gshhg or a chart file (GeoJSON, shapefile, S-57 cell) over the\n"
    "                       scenario's charts.source (the scenario needs an origin)\n"
    "  --chart-cache DIR    chart extraction cache (default $ASV_CHART_CACHE or ~/.cache/asv/charts;\n"
    "                       none: no cache)\n"
    "  --seed S             first seed (default 1)\n"
    "  --runs N             runs with seeds S .. S+N-1 (default 1)\n"
    "  --json OUT           append the results to OUT (JSON Lines); default: stdout\n"
    "  --trajectory CSV     write t_s,ship,x_m,y_m,course_deg,speed_mps,lat_deg,lon_deg rows (every\n"
    "                       --sample-period); with --runs > 1 the seed goes into the name: CSV_seed<S>.csv\n"
    "  --risk CSV           write the own ship's risk picture, one row per target every --sample-period:\n"
    "                       t_s,target,range_m,tcpa_s,dcpa_m,cri,risk_level,compliant,role,cri_eq1 (Hu et "
    "al. 2017\n"
    "                       risk level 0/1/2 and Algorithm 1 flag) as her planner assesses it (planner "
    "none:\n"
    "                       the default assessment); cri_eq1 is Wu et al. 2022 eq. (1) without Fig. 3's 0 "
    "for\n"
    "                       a passed ship; with --runs > 1 named as --trajectory\n"
    "  --plans CSV          write every plan the own ship's planner made: t_s,reason,status,course_deg,\n"
    "                       speed_mps,message (why it replanned, and the plan's own account: the shared\n"
    "                       rules' retries, the separation manoeuvre); with --runs > 1 named as "
    "--trajectory\n"
    "  --geojson FILE       write the run as GeoJSON for a GIS (tracks, closest approaches, manoeuvres,\n"
    "                       land; longitude/latitude); with --runs > 1 named as --trajectory\n"
    "  --dt DT              integration step [s] (default 0.1)\n"
    "  --sample-period P    trajectory CSV period [s] (default 5)\n"
    "  --time-budget S      wall time per plan [s] (default 0.5, planner_node's)\n"
    "  --deterministic      zero the wall-clock values (wall_time_s, plan_time_ms median/max) and give\n"
    "                       the planners a 60 s budget so that no wall-clock deadline changes a plan\n"
    "  --quiet              no progress bar and no summary lines\n"
    "  --help               this text\n"
    "\n"
    "exit status: 0 done (whatever the runs' outcomes), 2 bad arguments, scenario or planner, 1 failure.\n";

struct Options {
  std::string scenario, planner, json, trajectory, geojson, agents, risk, plans;
  bool planner_given = false;
  asv::ChartOptions charts;
  std::vector<std::pair<std::string, std::string>> params;  // "planner/key", value
  asv::ParamMap follower;                                   // PlanFollowerConfig keys
  uint64_t seed = 1;
  int runs = 1;
  double dt = 0.1;
  double sample_period = 5.0;
  double time_budget = 0.5;
  bool deterministic = false;
  bool quiet = false;
};

[[noreturn]] void usageError(const std::string& what) {
  std::cerr << "asv_batch: " << what << "\n(asv_batch --help for usage)\n";
  std::exit(2);
}

double parseNumber(const std::string& opt, const std::string& v) {
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !std::isfinite(d))
    usageError(opt + ": not a number: '" + v + "'");
  return d;
}

Options parseArgs(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc)
        usageError(a + " needs a value");
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      std::cout << kUsage;
      std::exit(0);
    } else if (a == "--scenario") {
      o.scenario = value();
    } else if (a == "--planner") {
      o.planner = value();
      o.planner_given = true;
    } else if (a == "--charts") {
      o.charts.source = value();
    } else if (a == "--chart-cache") {
      o.charts.cache_dir = value();
    } else if (a == "--agents") {
      o.agents = value();
    } else if (a == "--set") {
      const std::string kv = value();
      const size_t eq = kv.find('=');
      const size_t dot = kv.find_first_of("./");
      if (eq == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 >= eq)
        usageError("--set needs PLANNER.KEY=VALUE, got '" + kv + "'");
      o.params.emplace_back(kv.substr(0, dot) + "/" + kv.substr(dot + 1, eq - dot - 1), kv.substr(eq + 1));
    } else if (a == "--follower") {
      const std::string kv = value();
      const size_t eq = kv.find('=');
      if (eq == std::string::npos || eq == 0)
        usageError("--follower needs KEY=VALUE, got '" + kv + "'");
      o.follower.set(kv.substr(0, eq), kv.substr(eq + 1));
    } else if (a == "--seed") {
      const double s = parseNumber(a, value());
      if (s < 0 || s != std::floor(s))
        usageError("--seed must be a non-negative integer");
      o.seed = static_cast<uint64_t>(s);
    } else if (a == "--runs") {
      const double n = parseNumber(a, value());
      if (n < 1 || n != std::floor(n) || n > 1e6)
        usageError("--runs must be a positive integer");
      o.runs = static_cast<int>(n);
    } else if (a == "--json") {
      o.json = value();
    } else if (a == "--trajectory") {
      o.trajectory = value();
    } else if (a == "--risk") {
      o.risk = value();
    } else if (a == "--plans") {
      o.plans = value();
    } else if (a == "--geojson") {
      o.geojson = value();
    } else if (a == "--dt") {
      o.dt = parseNumber(a, value());
      if (!(o.dt > 0.0 && o.dt <= 10.0))
        usageError("--dt must be in (0, 10] s");
    } else if (a == "--sample-period") {
      o.sample_period = parseNumber(a, value());
      if (!(o.sample_period > 0.0))
        usageError("--sample-period must be > 0 s");
    } else if (a == "--time-budget") {
      o.time_budget = parseNumber(a, value());
      if (!(o.time_budget > 0.0))
        usageError("--time-budget must be > 0 s");
    } else if (a == "--deterministic") {
      o.deterministic = true;
    } else if (a == "--quiet") {
      o.quiet = true;
    } else {
      usageError("unknown argument '" + a + "'");
    }
  }
  if (o.scenario.empty())
    usageError("--scenario FILE is required");
  if (o.deterministic)
    o.time_budget = 60.0;
  try {
    asv::PlanFollowerConfig::fromParams(o.follower);
    o.follower.rejectUnknown("--follower");
  } catch (const std::exception& e) {
    usageError(e.what());
  }
  return o;
}

// What --follower names is what the run uses, whatever the planner's mode would set.
void keepNamedFollowerKeys(asv::PlanFollowerConfig& fc, const asv::ParamMap& named) {
  const asv::PlanFollowerConfig given = asv::PlanFollowerConfig::fromParams(named);
  if (named.has("plan_clearance"))
    fc.plan_clearance = given.plan_clearance;
  if (named.has("extremis_range"))
    fc.extremis_range = given.extremis_range;
  if (named.has("fallback_speed_factor"))
    fc.fallback_speed_factor = given.fallback_speed_factor;
}

bool isDssa(const std::string& p) {
  return p == "dssa" || p == "dssa_plus";
}

asv::DssaConfig dssaConfig(const std::string& planner, const asv::ParamMap& scenario_params) {
  // The plugins' sea-scale defaults (sea mode only): the agents of the exchange negotiate like the plugin.
  const asv::ParamMap own = scenario_params.sub(planner);
  const bool paper = asv::plannerMode(own, planner) == asv::PlannerMode::Paper;
  asv::ParamMap p = paper ? asv::ParamMap{} : asv::DssaConfig::seaDefaults();
  p.set("preset", planner);
  for (const auto& kv : own.values())
    p.set(kv.first, kv.second);
  return asv::DssaConfig::fromParams(p);
}

// An output file's name for one seed: as given for a single run, else with _seed<S> before the suffix.
std::string seedPath(const Options& o, const std::string& t, uint64_t seed) {
  if (o.runs == 1)
    return t;
  const size_t dot = t.rfind('.');
  const size_t slash = t.rfind('/');
  const std::string suffix = "_seed" + std::to_string(seed);
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return t + suffix;
  return t.substr(0, dot) + suffix + t.substr(dot);
}

class Progress {
public:
  Progress(bool enabled, int runs) : enabled_(enabled), runs_(runs) {}
  void update(int run, double fraction) {
    if (!enabled_)
      return;
    const int pct = static_cast<int>(100.0 * fraction);
    if (pct == last_pct_ && run == last_run_)
      return;
    last_pct_ = pct;
    last_run_ = run;
    const int width = 30, fill = pct * width / 100;
    std::fprintf(stderr, "\r[%s%s] run %d/%d %3d%%", std::string(fill, '#').c_str(),
                 std::string(width - fill, ' ').c_str(), run + 1, runs_, pct);
    std::fflush(stderr);
  }
  void clear() {
    if (enabled_ && last_pct_ >= 0)
      std::fprintf(stderr, "\r%*s\r", 60, "");
    last_pct_ = -1;
  }

private:
  bool enabled_;
  int runs_;
  int last_pct_ = -1, last_run_ = -1;
};

// One ship that plans through a plugin, as planner_node does.
struct PluginShip {
  size_t index;
  std::string planner;
  asv::PlannerMode mode;
  pluginlib::UniquePtr<asv::PlannerAlgorithm> plugin;
  asv::PlanFollower follower;
  asv::RiskAssessor risk;
};

std::vector<asv::PlannerTarget> plannerTargets(const asv::Simulation& sim, size_t self,
                                               asv::RiskAssessor& risk) {
  const auto& vs = sim.vessels();
  const asv::ShipState own = vs[self].shipState();
  std::vector<asv::ShipState> others;
  for (size_t j = 0; j < vs.size(); ++j)
    if (j != self && vs[j].present())
      others.push_back(vs[j].shipState());
  const std::vector<asv::TargetRisk> rs = risk.assessAll(own, others);
  std::vector<asv::PlannerTarget> out;
  for (size_t k = 0; k < others.size(); ++k)
    out.push_back(asv::toPlannerTarget(others[k], rs[k]));
  return out;
}

double wallSeconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// One seed of a scenario: the simulation, the ships that plan through plugins (as planner_node
// does), the DSSA exchange group (two or more DSSA ships negotiate, as their ROS agents do), the
// recorder and the trajectory file.
class BatchRun {
public:
  BatchRun(const Options& o, const asv::Scenario& sc, const std::string& own_planner, uint64_t seed,
           asv_planning::PluginLoader& loader);
  asv::RunResult run(Progress& progress, int run_index);

private:
  void addPluginShips(asv_planning::PluginLoader& loader);
  void addDssaGroup();
  void openTrajectory();
  void writeTrajectory();
  void writeRisk(double now, const std::vector<asv::PlannerTarget>& targets, asv::CriConfig cri);
  void watchRisk(double now);
  void writePlan(double now, const std::string& why, const asv::Plan& plan);
  void sample();
  void planPluginShip(PluginShip& ps, double now);
  void dssaPhase(double now);
  void arrivedNeighbour(asv::DssaAgent& agent, int id, double now) const;

  const std::chrono::steady_clock::time_point wall0_ = std::chrono::steady_clock::now();
  const Options& o_;
  const asv::Scenario& sc_;
  const uint64_t seed_;
  asv::Simulation sim_;
  asv::RunRecorder rec_;
  std::vector<std::string> planner_of_;  // per vessel: its planner, "" or "none" for none
  std::vector<size_t> dssa_ships_;
  bool exchange_mode_ = false;  // two or more DSSA ships: they negotiate
  std::vector<std::unique_ptr<PluginShip>> plugin_ships_;
  std::vector<asv::DssaAgent> agents_;
  std::vector<std::mt19937_64> rngs_;
  std::vector<Eigen::Vector2d> agent_goals_;
  std::unique_ptr<asv::DssaExchange> exchange_;
  double dssa_period_ = 10.0;
  std::ofstream traj_, risk_, plans_;
  double next_risk_ = 0.0;
  // The own ship's picture for --risk when no plugin of hers assesses it (planner none, or negotiating
  // DSSA): the same assessment with the default settings.
  asv::RiskAssessor watch_;
};

asv::SimConfig simConfig(const Options& o) {
  asv::SimConfig c;
  c.dt = o.dt;
  return c;
}

BatchRun::BatchRun(const Options& o, const asv::Scenario& sc, const std::string& own_planner, uint64_t seed,
                   asv_planning::PluginLoader& loader)
    : o_(o),
      sc_(sc),
      seed_(seed),
      sim_(sc, simConfig(o)),
      rec_(asv::EvaluationConfig{}, asv::RunInfo::fromScenario(sc, own_planner, seed)) {
  const auto& vs = sim_.vessels();
  planner_of_.resize(vs.size());
  planner_of_[0] = own_planner;
  for (size_t i = 1; i < vs.size(); ++i)
    if (sc.targets[i - 1].behaviour == asv::Behaviour::Planner)
      planner_of_[i] = sc.targets[i - 1].planner.empty() ? "none" : sc.targets[i - 1].planner;
  for (size_t i = 0; i < vs.size(); ++i)
    if (isDssa(planner_of_[i]))
      dssa_ships_.push_back(i);
  exchange_mode_ = dssa_ships_.size() >= 2;
  addPluginShips(loader);
  if (exchange_mode_)
    addDssaGroup();
  openTrajectory();
}

void BatchRun::addPluginShips(asv_planning::PluginLoader& loader) {
  const auto& vs = sim_.vessels();
  for (size_t i = 0; i < vs.size(); ++i) {
    const std::string& p = planner_of_[i];
    if (p.empty() || p == "none" || (exchange_mode_ && isDssa(p)))
      continue;
    asv::PlanFollowerConfig fc = asv::PlanFollowerConfig::fromParams(o_.follower);
    fc.time_budget = o_.time_budget;
    fc.seed = static_cast<int>(seed_);
    fc.cruise_speed = vs[i].cruise_speed;
    fc.min_separation = sc_.min_separation;
    const asv::ParamMap params = sc_.planner_params.sub(asv_planning::PluginLoader::parameterName(p));
    const asv::PlannerMode mode = asv::plannerMode(params, p);
    auto plugin = loader.load(p, params);
    // A method that plans once does so in paper mode, unless --follower names replan_on_risk itself.
    asv::applyPlannerMode(fc, mode, plugin->plansOnce() && !o_.follower.has("replan_on_risk"),
                          plugin->ownTrigger());
    keepNamedFollowerKeys(fc, o_.follower);
    if (sc_.min_obstacle_clearance > 0.0)
      fc.min_obstacle_clearance_m = sc_.min_obstacle_clearance;  // the waters' own (a port)
    // The risk picture's CRI (--risk) uses the GA planner's own CRI scaling (Wu et al. 2022 eq. 1-12 as
    // configured for the scenario's ship), so that it shows the values the planner decides on.
    asv::RiskConfig rc;
    if (p == "ga")
      rc.cri = asv::GaConfig::fromParams(sc_.planner_params.sub("ga")).cri;
    auto ps = std::make_unique<PluginShip>(
        PluginShip{i, p, mode, std::move(plugin), asv::PlanFollower(fc), asv::RiskAssessor(rc)});
    if (!vs[i].route.empty())
      ps->follower.setRoute(vs[i].route);
    else if (vs[i].goal)
      ps->follower.setGoal(*vs[i].goal);
    ps->follower.setObstacles(sc_.obstacles);
    plugin_ships_.push_back(std::move(ps));
  }
}

void BatchRun::addDssaGroup() {
  const auto& vs = sim_.vessels();
  const asv::DssaConfig group_cfg = dssaConfig(planner_of_[dssa_ships_.front()], sc_.planner_params);
  dssa_period_ = group_cfg.time_step;
  exchange_ = std::make_unique<asv::DssaExchange>(group_cfg);
  for (size_t i : dssa_ships_) {
    const asv::DssaConfig cfg = dssaConfig(planner_of_[i], sc_.planner_params);
    const asv::DssaShipSpeeds speeds = asv::dssaShipSpeeds(
        cfg, vs[i].cruise_speed, 0.0, std::max(vs[i].cruise_speed, asv::OwnShipLimits{}.max_speed));
    agents_.emplace_back(static_cast<int>(i), cfg, speeds);
    rngs_.emplace_back(asv::dssaAgentSeed(seed_, static_cast<int>(i)));
    agent_goals_.push_back(
        vs[i].goal ? *vs[i].goal : vs[i].position() + asv::courseSpeedToVelocity(vs[i].cruise_course, 1e6));
  }
}

void BatchRun::openTrajectory() {
  auto open = [&](std::ofstream& f, const std::string& name, const char* what, const char* header) {
    if (name.empty())
      return;
    const std::string path = seedPath(o_, name, seed_);
    f.open(path);
    if (!f)
      throw std::runtime_error(std::string("cannot write ") + what + " file " + path);
    f << header;
  };
  open(traj_, o_.trajectory, "trajectory", "t_s,ship,x_m,y_m,course_deg,speed_mps,lat_deg,lon_deg\n");
  open(risk_, o_.risk, "risk", "t_s,target,range_m,tcpa_s,dcpa_m,cri,risk_level,compliant,role,cri_eq1\n");
  open(plans_, o_.plans, "plans", "t_s,reason,status,course_deg,speed_mps,message\n");
}

// The own ship's picture as its planner saw it (the plugin ship's RiskAssessor), every sample period.
// cri is the value the planner decides on (Wu et al. 2022 Fig. 3: 0 once a target is past); cri_eq1 is
// eq. (1) as printed, without that rule, as the paper's Fig. 9 plots it.
void BatchRun::writeRisk(double now, const std::vector<asv::PlannerTarget>& targets, asv::CriConfig cri) {
  if (!risk_.is_open() || now < next_risk_ - 1e-9)
    return;
  next_risk_ += o_.sample_period;
  const asv::ShipState own = sim_.vessels()[0].shipState();
  cri.zero_when_diverging = false;
  char buf[256];
  for (const asv::PlannerTarget& t : targets) {
    const double eq1 = asv::computeCri(own, t.state, asv::computeCpa(own, t.state), cri).cri;
    std::snprintf(buf, sizeof buf, "%.1f,%s,%.1f,%.1f,%.1f,%.4f,%d,%d,%s,%.4f\n", now, t.state.id.c_str(),
                  (t.state.position - own.position).norm(), t.tcpa, t.dcpa, t.cri, static_cast<int>(t.risk),
                  t.compliant ? 1 : 0, asv::toString(t.role), eq1);
    risk_ << buf;
  }
}

void BatchRun::watchRisk(double now) {
  const bool own_plans = !plugin_ships_.empty() && plugin_ships_.front()->index == 0;
  if (risk_.is_open() && !own_plans)
    writeRisk(now, plannerTargets(sim_, 0, watch_), watch_.config().cri);
}

// A CSV field: quoted, its quotes doubled (RFC 4180).
std::string csvQuoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text)
    out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

void BatchRun::writePlan(double now, const std::string& why, const asv::Plan& plan) {
  if (!plans_.is_open())
    return;
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.1f,", now);
  plans_ << buf << csvQuoted(why) << ',' << asv::toString(plan.status);
  std::snprintf(buf, sizeof buf, ",%.1f,%.2f,", asv::radToDeg(plan.course_setpoint), plan.speed_setpoint);
  plans_ << buf << csvQuoted(plan.message) << '\n';
}

void BatchRun::writeTrajectory() {
  if (!traj_.is_open())
    return;
  char buf[256];
  for (const auto& v : sim_.vessels()) {
    const asv::GeoPoint g = sim_.frame().toGeodetic(v.position());
    std::snprintf(buf, sizeof buf, "%.1f,%s,%.1f,%.1f,%.1f,%.2f,%.7f,%.7f\n", sim_.time(), v.name.c_str(),
                  v.position().x(), v.position().y(), asv::radToDeg(v.cog()), v.sog(), g.lat_deg, g.lon_deg);
    traj_ << buf;
  }
}

void BatchRun::sample() {
  std::vector<asv::ShipSample> ss;
  ss.reserve(sim_.vessels().size());
  for (const auto& v : sim_.vessels()) {
    asv::ShipSample s;
    s.name = v.name;
    s.state = v.shipState();
    s.course_setpoint = v.course_sp;
    s.active = v.present();
    s.beam = v.beam;
    ss.push_back(std::move(s));
  }
  rec_.addSample(sim_.time(), ss);
}

// One set-point tick of a plugin ship, as planner_node's: replan when the follower says so (a plugin
// error becomes the fallback), then steer the plan's set-point.
void BatchRun::planPluginShip(PluginShip& ps, double now) {
  const asv::SimVessel& v = sim_.vessels()[ps.index];
  if (v.arrived)
    return;
  const std::vector<asv::PlannerTarget> targets = plannerTargets(sim_, ps.index, ps.risk);
  if (ps.index == 0)
    writeRisk(now, targets, ps.risk.config().cri);
  ps.follower.updateOwn(v.shipState());
  const asv::CycleResult r = asv::planningCycle(ps.follower, *ps.plugin, ps.mode, now, targets);
  if (r.replanned && ps.index == 0) {
    rec_.addPlanTime(r.proposed.compute_time);
    rec_.addPassingDistance(r.proposed.passing_distance);
    writePlan(now, r.why, r.proposed);
  }
  if (r.has_setpoint) {
    sim_.setSetpoint(v.name, r.course, r.speed);
    rec_.addSetpoint(now, v.name, r.course);
  }
}

// What an agent knows of a ship of the group that has arrived: nothing when she left the scenario; when
// she stays at her goal, a stationary ship there (she no longer searches, so she sends no intention).
void BatchRun::arrivedNeighbour(asv::DssaAgent& agent, int id, double now) const {
  const asv::SimVessel& v = sim_.vessels()[static_cast<size_t>(id)];
  if (!v.arrived)
    return;
  if (!v.stays_at_goal) {
    agent.forget(id);
    return;
  }
  agent.receive(asv::dssaStationaryShip(id, v.position(), v.shipState().course, now));
}

// One DSSA search phase (Hirayama et al. 2019, Fig. 1): every ship still under way takes part, then
// steers its intention.
void BatchRun::dssaPhase(double now) {
  const auto& vs = sim_.vessels();
  std::vector<asv::DssaAgent> active;
  std::vector<std::mt19937_64> active_rngs;
  std::vector<size_t> slot;
  for (size_t a = 0; a < agents_.size(); ++a) {
    const asv::SimVessel& v = vs[static_cast<size_t>(agents_[a].id())];
    for (size_t b = 0; b < agents_.size(); ++b)
      arrivedNeighbour(agents_[a], agents_[b].id(), now);
    if (v.arrived)
      continue;
    agents_[a].setOwn(v.shipState(), agent_goals_[a], now);
    slot.push_back(a);
  }
  if (slot.empty())
    return;
  for (size_t a : slot) {
    active.push_back(std::move(agents_[a]));
    active_rngs.push_back(rngs_[a]);
  }
  const auto t0 = std::chrono::steady_clock::now();
  exchange_->run(active, active_rngs);
  const double took = wallSeconds(t0);
  if (isDssa(planner_of_[0]) && !vs[0].arrived)
    rec_.addPlanTime(took);
  for (size_t k = 0; k < slot.size(); ++k) {
    agents_[slot[k]] = std::move(active[k]);
    rngs_[slot[k]] = active_rngs[k];
    const asv::DssaIntention& in = agents_[slot[k]].intention();
    const std::string& name = vs[static_cast<size_t>(agents_[slot[k]].id())].name;
    sim_.setSetpoint(name, in.course, in.speed);
    rec_.addSetpoint(now, name, in.course);
  }
}

asv::RunResult BatchRun::run(Progress& progress, int run_index) {
  const double setpoint_period = 1.0;  // planner_node's setpoint_rate (1 Hz)
  double next_tick = 0.0, next_dssa = 0.0, next_traj = 0.0;
  size_t events_done = 0;
  sample();
  const long steps = static_cast<long>(std::ceil(sc_.duration / o_.dt - 1e-9));
  for (long k = 0; !sim_.finished(); ++k) {
    const double now = sim_.time();
    if (now >= next_traj - 1e-9) {
      writeTrajectory();
      next_traj += o_.sample_period;
    }
    if (now >= next_tick - 1e-9) {
      next_tick += setpoint_period;
      watchRisk(now);
      for (auto& ps : plugin_ships_)
        planPluginShip(*ps, now);
    }
    if (exchange_mode_ && now >= next_dssa - 1e-9) {
      next_dssa += dssa_period_;
      dssaPhase(now);
    }
    sim_.step();
    sample();
    const auto& ev = sim_.events();
    for (; events_done < ev.size(); ++events_done)
      rec_.addEvent(ev[events_done]);
    if (k % 200 == 0)
      progress.update(run_index, std::min(1.0, static_cast<double>(k) / std::max<long>(1, steps)));
  }
  writeTrajectory();
  rec_.setWallTime(wallSeconds(wall0_));
  asv::RunResult r = rec_.finish();
  if (o_.deterministic)
    asv::zeroWallClock(r);
  if (!o_.geojson.empty()) {
    const std::string path = seedPath(o_, o_.geojson, seed_);
    std::ofstream g(path);
    g << rec_.geoJson(r);
    if (!g)
      throw std::runtime_error("cannot write GeoJSON file " + path);
  }
  return r;
}

// Runs one seed; returns the result.
asv::RunResult runOnce(const Options& o, const asv::Scenario& sc, const std::string& own_planner,
                       uint64_t seed, asv_planning::PluginLoader& loader, Progress& progress, int run_index) {
  return BatchRun(o, sc, own_planner, seed, loader).run(progress, run_index);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parseArgs(argc, argv);
  asv::Scenario sc;
  try {
    sc = asv::loadScenario(o.scenario, o.charts);
  } catch (const std::exception& e) {
    std::cerr << "asv_batch: bad scenario: " << e.what() << "\n";
    return 2;
  }
  for (const auto& kv : o.params)
    sc.planner_params.set(kv.first, kv.second);
  if (!o.agents.empty())
    for (auto& t : sc.targets)
      if (t.behaviour == asv::Behaviour::Planner)
        t.planner = o.agents;
  std::string planner = o.planner_given ? o.planner : sc.own.planner;
  if (planner.empty())
    planner = "none";
  std::unique_ptr<asv_planning::PluginLoader> loader;
  try {
    loader = std::make_unique<asv_planning::PluginLoader>();
  } catch (const std::exception& e) {
    std::cerr << "asv_batch: cannot create the plugin loader (source devel/setup.bash?): " << e.what()
              << "\n";
    return 2;
  }
  // Any planner pluginlib knows runs: ours by short name, another package's by its pluginlib name.
  const std::vector<std::string> declared = loader->declared();
  auto checkPlanner = [&](const std::string& p, const std::string& who) {
    const std::string full = asv_planning::PluginLoader::fullName(p);
    if (p == "none" || std::find(declared.begin(), declared.end(), full) != declared.end())
      return true;
    std::string list;
    for (const auto& d : declared)
      list += (list.empty() ? "" : ", ") + d;
    std::cerr << "asv_batch: unknown planner '" << p << "' for " << who << " (declared: " << list
              << ", none)\n";
    return false;
  };
  if (!checkPlanner(planner, "the own ship"))
    return 2;
  for (const auto& t : sc.targets)
    if (t.behaviour == asv::Behaviour::Planner && !t.planner.empty() && !checkPlanner(t.planner, t.name))
      return 2;

  std::ofstream json_file;
  std::ostream* out = &std::cout;
  if (!o.json.empty()) {
    json_file.open(o.json, std::ios::app);
    if (!json_file) {
      std::cerr << "asv_batch: cannot write " << o.json << "\n";
      return 2;
    }
    out = &json_file;
  }
  Progress progress(!o.quiet && isatty(STDERR_FILENO), o.runs);
  for (int r = 0; r < o.runs; ++r) {
    const uint64_t seed = o.seed + static_cast<uint64_t>(r);
    asv::RunResult result;
    try {
      result = runOnce(o, sc, planner, seed, *loader, progress, r);
    } catch (const std::runtime_error& e) {
      progress.clear();
      const std::string what = e.what();
      std::cerr << "asv_batch: " << what << "\n";
      // A plugin that cannot be loaded is a usage error (unknown or unbuilt planner).
      return what.find("cannot load planner") != std::string::npos ? 2 : 1;
    } catch (const std::invalid_argument& e) {
      progress.clear();
      std::cerr << "asv_batch: bad configuration: " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      progress.clear();
      std::cerr << "asv_batch: " << e.what() << "\n";
      return 1;
    }
    progress.clear();
    *out << asv::toJson(result) << "\n";
    out->flush();
    if (!o.quiet)
      std::cerr << asv::summaryLine(result) << "\n";
  }
  return 0;
}
