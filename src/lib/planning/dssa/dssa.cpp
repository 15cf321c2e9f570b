#include "asv_core/planning/dssa/dssa.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "asv_core/planning/land_route.h"
#include "asv_core/risk/cpa.h"

namespace asv {

namespace {

// Below this a cost difference is rounding, not an improvement: without it two candidates of equal cost
// computed in a different order could make a ship flip between them and never be satisfied.
constexpr double kImprovementEps = 1e-9;
constexpr double kDestOnGridTol = 1.0e-3 * 3.14159265358979323846 / 180.0;  // [rad] 0.001 deg

void require(bool ok, const char* field, const char* what) {
  if (!ok)
    throw std::invalid_argument(std::string("DssaConfig.") + field + ": " + what);
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// DssaConfig

void DssaConfig::validate() const {
  require(std::isfinite(alpha) && alpha >= 0.0, "alpha", "must be finite and >= 0");
  require(std::isfinite(beta) && beta >= 0.0, "beta", "must be finite and >= 0");
  require(std::isfinite(p) && p > 0.0 && p <= 1.0, "p", "must be in (0, 1]");
  require(std::isfinite(time_window) && time_window > 0.0, "time_window", "must be > 0");
  require(std::isfinite(time_step) && time_step > 0.0, "time_step", "must be > 0");
  require(std::isfinite(detection_range) && detection_range > 0.0, "detection_range", "must be > 0");
  require(std::isfinite(collision_distance) && collision_distance >= 0.0, "collision_distance",
          "must be >= 0");
  require(std::isfinite(tcpa_floor) && tcpa_floor > 0.0, "tcpa_floor", "must be > 0");
  require(std::isfinite(course_change_max) && course_change_max >= 0.0 && course_change_max <= kPi,
          "course_change_max", "must be in [0, 180] deg");
  require(std::isfinite(course_change_step) && course_change_step > 0.0, "course_change_step", "must be > 0");
  require(std::isfinite(speed_change_max) && speed_change_max >= 0.0, "speed_change_max", "must be >= 0");
  require(std::isfinite(speed_change_step) && speed_change_step > 0.0, "speed_change_step", "must be > 0");
  // The domain is built on a grid; a runaway grid would make every round slow, not wrong, so cap it.
  require(course_change_max / course_change_step <= 360.0, "course_change_step", "gives > 721 courses");
  require(speed_change_max / speed_change_step <= 100.0, "speed_change_step", "gives > 201 speeds");
  require(max_rounds >= 1, "max_rounds", "must be >= 1");
  require(std::isfinite(max_search_time), "max_search_time", "must be finite");
  require(std::isfinite(ref_speed), "ref_speed", "must be finite");
  require(std::isfinite(max_speed_over_ref), "max_speed_over_ref", "must be finite");
  require(std::isfinite(min_speed_fraction) && min_speed_fraction >= 0.0 && min_speed_fraction <= 1.0,
          "min_speed_fraction", "must be in [0, 1]");
}

DssaShipSpeeds dssaShipSpeeds(const DssaConfig& config, double cruise_speed, double min_limit,
                              double max_limit) {
  DssaShipSpeeds s;
  const double wanted = config.ref_speed > 0.0 ? config.ref_speed : cruise_speed;
  if (config.max_speed_over_ref > 0.0) {
    s.ref = wanted > 0.1 ? wanted : std::max(max_limit, 1e-6);
    s.max = s.ref + config.max_speed_over_ref;
  } else {
    s.max = std::max(max_limit, 1e-6);
    s.ref = config.ref_speed > 0.0 ? config.ref_speed : (wanted > 0.1 ? std::min(wanted, s.max) : s.max);
  }
  s.min = std::min(std::max({min_limit, config.min_speed_fraction * s.ref, 0.0}), s.max);
  return s;
}

DssaIntention dssaStationaryShip(int id, const Eigen::Vector2d& position, double course, double now) {
  DssaIntention m;
  m.id = id;
  m.stamp = now;
  m.course = course;
  m.position = position;
  m.satisfied = true;
  return m;
}

ParamMap DssaConfig::seaDefaults() {
  ParamMap p;
  p.set("time_window", 600.0);
  p.set("detection_range", 11112.0);
  p.set("collision_distance", 926.0);
  p.set("time_step", 10.0);
  p.set("speed_change_max", 4.0);
  p.set("speed_change_step", 1.0);
  p.set("colregs", "true");
  return p;
}

DssaConfig DssaConfig::fromParams(const ParamMap& params) {
  const bool paper = plannerMode(params, "dssa") == PlannerMode::Paper;
  DssaConfig c = preset(params.getString("preset", "dssa"), paper);
  c.speed_changes = params.getBool("speed_changes", c.speed_changes);
  c.colregs = params.getBool("colregs", c.colregs);
  c.alpha = params.getDouble("alpha", c.alpha);
  c.beta = params.getDouble("beta", c.beta);
  c.p = params.getDouble("p", c.p);
  c.time_window = params.getDouble("time_window", c.time_window);
  c.time_step = params.getDouble("time_step", c.time_step);
  c.detection_range = params.getDouble("detection_range", c.detection_range);
  c.collision_distance = params.getDouble("collision_distance", c.collision_distance);
  c.tcpa_floor = params.getDouble("tcpa_floor", c.tcpa_floor);
  c.course_change_max = degToRad(params.getDouble("course_change_max_deg", radToDeg(c.course_change_max)));
  c.course_change_step = degToRad(params.getDouble("course_change_step_deg", radToDeg(c.course_change_step)));
  c.speed_change_max = params.getDouble("speed_change_max", c.speed_change_max);
  c.speed_change_step = params.getDouble("speed_change_step", c.speed_change_step);
  c.max_rounds = params.getInt("max_rounds", c.max_rounds);
  c.max_search_time = params.getDouble("max_search_time", c.max_search_time);
  c.ref_speed = params.getDouble("ref_speed", c.ref_speed);
  c.max_speed_over_ref = params.getDouble("max_speed_over_ref", c.max_speed_over_ref);
  c.min_speed_fraction = params.getDouble("min_speed_fraction", c.min_speed_fraction);
  params.rejectUnknown("dssa");
  c.validate();
  return c;
}

DssaConfig DssaConfig::preset(const std::string& name, bool paper) {
  DssaConfig c;
  if (name == "dssa") {
    c.speed_changes = false;
    c.alpha = 1.0;
    c.beta = 0.0;
  } else if (name == "dssa_plus_sc") {  // s>c: alpha 10 times beta (Sec. 5)
    c.speed_changes = true;
    c.alpha = paper ? 10.0 : 1.0;
    c.beta = paper ? 1.0 : 0.1;
  } else if (name == "dssa_plus_cs") {  // s<c: alpha 10 times lower than beta
    c.speed_changes = true;
    c.alpha = 1.0;
    c.beta = 10.0;
  } else if (name == "dssa_plus_eq" || name == "dssa_plus") {  // s=c
    c.speed_changes = true;
    c.alpha = 1.0;
    c.beta = 1.0;
  } else {
    std::string msg = "DssaConfig::preset: unknown preset '" + name + "'; known:";
    for (const auto& n : presetNames())
      msg += " " + n;
    throw std::invalid_argument(msg);
  }
  return c;
}

std::vector<std::string> DssaConfig::presetNames() {
  return {"dssa", "dssa_plus_sc", "dssa_plus_cs", "dssa_plus_eq", "dssa_plus"};
}

// ---------------------------------------------------------------------------------------------------
// DssaAgent

DssaAgent::DssaAgent(int id, const DssaConfig& config, const DssaShipSpeeds& speeds)
    : id_(id), config_(config), speeds_(speeds) {
  config_.validate();
  if (!(std::isfinite(speeds.min) && std::isfinite(speeds.max) && std::isfinite(speeds.ref) &&
        speeds.min >= 0.0 && speeds.max > 0.0 && speeds.min <= speeds.max))
    throw std::invalid_argument("DssaShipSpeeds: need 0 <= min <= max, max > 0, all finite");
  intention_.id = id_;
}

DssaAgent::Candidate DssaAgent::makeCandidate(double crs, double spc) const {
  Candidate c;
  c.crs = crs;
  c.spc = spc;
  c.course = wrapTwoPi(heading_ + crs);
  // DSSA keeps the current speed; DSSA+ clamps CurSPD + spc to [MinSPD, MaxSPD] (EF of Sec. 4).
  c.speed = config_.speed_changes ? std::min(std::max(speed_ + spc, speeds_.min), speeds_.max) : speed_;
  c.disp = courseSpeedToVelocity(c.course, c.speed) * config_.time_window;
  // EF (Sec. 3.2): alpha |theta_dest - theta(crs)| / 180 deg, the angle taken the short way round so
  // that it lies in [0, 180] deg.
  c.ef = config_.alpha * std::fabs(wrapPi(theta_dest_ - c.course)) / kPi;
  // DSSA+ (Sec. 4): + beta |min(max(CurSPD + spc, MinSPD), MaxSPD) - RefSPD| / MaxSPD.
  if (config_.speed_changes)
    c.ef += config_.beta * std::fabs(c.speed - speeds_.ref) / speeds_.max;
  if (land_ && land_required_ > 0.0 &&
      trackObstacleDistance({position_, position_ + c.disp}, *land_) < land_required_)
    c.ef += kLandInefficiency;
  return c;
}

void DssaAgent::setLand(const std::vector<StaticObstacle>* obstacles, double required) {
  land_ = obstacles;
  land_required_ = required;
}

double DssaAgent::destinationCourseChange() const {
  return wrapPi(theta_dest_ - heading_);
}

void DssaAgent::setOwn(const ShipState& state, const Eigen::Vector2d& goal, double now) {
  position_ = state.position;
  goal_ = goal;
  heading_ = state.course;
  speed_ = state.speed;
  now_ = now;
  theta_dest_ = trueBearing(position_, goal_);

  // Dom (Sec. 3.2, Sec. 4, Fig. 3). Ordered so that ties go to the least manoeuvre: crs_dest first (it
  // costs no course inefficiency), then 0, +step, -step, ... (starboard before port), and within a
  // course spc 0, -step, +step, ... (slowing before speeding up).
  cand_.clear();
  std::vector<double> courses;
  const double crs_dest = destinationCourseChange();
  const int nc = static_cast<int>(std::floor(config_.course_change_max / config_.course_change_step + 1e-9));
  bool dest_on_grid = false;
  for (int k = 0; k <= nc; ++k)
    for (int s : {1, -1}) {
      if (k == 0 && s < 0)
        continue;
      if (config_.starboard_only && s < 0 && k > 0)
        continue;  // give-way under the COLREGs: no port course change
      const double crs = s * k * config_.course_change_step;
      // A destination course within 0.001 deg of a grid course is that course: a scenario's rounded
      // initial course must not add a second, all but equal candidate that changes the tie-breaks.
      if (std::fabs(crs - crs_dest) < kDestOnGridTol)
        dest_on_grid = true;
      courses.push_back(crs);
    }
  if (std::fabs(crs_dest) <= config_.course_change_max + kDestOnGridTol && !dest_on_grid &&
      !(config_.starboard_only && crs_dest < 0.0))
    courses.insert(courses.begin(), crs_dest);
  // Not in the paper: when the goal lies within this step's move but outside +-course_change_max, a
  // ship limited to the domain's turns would circle it for ever (the goal inside her turning circle).
  // Fig. 1's control phase moves a ship directly, so she may then make straight for the goal; the
  // move is costed like any other (docs/results/dssa.md, "arrival").
  if (std::fabs(crs_dest) > config_.course_change_max + 1e-12 &&
      (goal_ - position_).norm() <= speed_ * config_.time_step)
    courses.push_back(crs_dest);
  std::vector<double> spcs{0.0};
  if (config_.speed_changes) {
    const int ns = static_cast<int>(std::floor(config_.speed_change_max / config_.speed_change_step + 1e-9));
    for (int k = 1; k <= ns; ++k) {
      spcs.push_back(-k * config_.speed_change_step);
      if (!config_.starboard_only)
        spcs.push_back(k * config_.speed_change_step);
    }
  }
  cand_.reserve(courses.size() * spcs.size());
  for (double crs : courses)
    for (double spc : spcs)
      cand_.push_back(makeCandidate(crs, spc));

  // Fig. 2, first box: every ship first takes her current heading (and speed) as her intention.
  current_ = 0;
  for (std::size_t i = 0; i < cand_.size(); ++i)
    if (cand_[i].crs == 0.0 && cand_[i].spc == 0.0) {
      current_ = static_cast<int>(i);
      break;
    }
  total_.assign(cand_.size(), 0.0);
  for (auto& n : nb_)
    n.dirty = true;

  intention_ = DssaIntention{};
  intention_.id = id_;
  intention_.round = 0;
  intention_.stamp = now_;
  intention_.course = cand_[current_].course;
  intention_.speed_change = 0.0;
  intention_.speed = cand_[current_].speed;
  intention_.position = position_;
  intention_.velocity = courseSpeedToVelocity(heading_, speed_);
  intention_.satisfied = false;
  changed_ = false;
  satisfied_ = false;
  improvement_ = 0.0;
}

void DssaAgent::receive(const DssaIntention& m) {
  if (m.id == id_)
    return;
  for (auto& n : nb_) {
    if (n.msg.id != m.id)
      continue;
    if (m.stamp < n.msg.stamp || (m.stamp == n.msg.stamp && m.round < n.msg.round))
      return;  // out of order: keep the newer one
    const bool same = m.stamp == n.msg.stamp && m.course == n.msg.course && m.speed == n.msg.speed &&
                      m.position == n.msg.position;
    n.msg = m;
    if (!same)
      n.dirty = true;
    return;
  }
  Neighbour n;
  n.msg = m;
  n.dirty = true;
  nb_.push_back(std::move(n));
}

void DssaAgent::forget(int id) {
  nb_.erase(std::remove_if(nb_.begin(), nb_.end(), [id](const Neighbour& n) { return n.msg.id == id; }),
            nb_.end());
}

void DssaAgent::refresh(Neighbour& n) const {
  // A last known intention from an earlier time step is carried forward along the intended velocity,
  // which is how that ship moved since (Fig. 1: every ship moves with her chosen intention).
  const Eigen::Vector2d v = n.msg.intendedVelocity();
  n.pos = n.msg.position + v * (now_ - n.msg.stamp);
  n.disp = v * config_.time_window;
  n.in_range = (n.pos - position_).norm() <= config_.detection_range;
}

double DssaAgent::crAgainst(const Candidate& c, const Neighbour& n) const {
  // TCPA and DCPA by the appendix's rules over one TimeWindow.
  const WindowedCpa w =
      windowedCpa(position_, position_ + c.disp, n.pos, n.pos + n.disp, config_.time_window);
  // CR (Sec. 3.2 / Sec. 4): TimeWindow / TCPA when self will collide with j, i.e. DCPA below the
  // collision distance. TCPA = 0 means the CPA is now and the ships only separate afterwards: no
  // collision ahead to weigh (and the formula would divide by zero).
  if (w.dcpa >= config_.collision_distance || w.tcpa <= 0.0)
    return 0.0;
  return config_.time_window / std::max(w.tcpa, config_.tcpa_floor);
}

int DssaAgent::neighbourCount() const {
  int k = 0;
  for (const auto& n : nb_) {
    Neighbour t;
    t.msg = n.msg;
    refresh(t);
    k += t.in_range ? 1 : 0;
  }
  return k;
}

double DssaAgent::collisionRisk(double crs, double spc) const {
  const Candidate c = makeCandidate(crs, spc);
  double cr = 0.0;
  for (const auto& n : nb_) {
    Neighbour t;
    t.msg = n.msg;
    refresh(t);
    if (t.in_range)
      cr += crAgainst(c, t);
  }
  return cr;
}

double DssaAgent::inefficiency(double crs, double spc) const {
  return makeCandidate(crs, spc).ef;
}

double DssaAgent::cost(double crs, double spc) const {
  return collisionRisk(crs, spc) + inefficiency(crs, spc);
}

DssaIntention DssaAgent::decide(int round, std::mt19937_64& rng) {
  const std::size_t nc = cand_.size();
  for (std::size_t i = 0; i < nc; ++i)
    total_[i] = cand_[i].ef;
  bool any_neighbour = false;
  for (auto& n : nb_) {
    // Only neighbours whose intention changed since the last round are recomputed: after the first
    // rounds most ships hold still, which keeps a 16-ship search phase within a few milliseconds.
    if (n.dirty) {
      refresh(n);
      n.cr.resize(nc);
      if (n.in_range)
        for (std::size_t i = 0; i < nc; ++i)
          n.cr[i] = crAgainst(cand_[i], n);
      n.dirty = false;
    }
    if (!n.in_range)
      continue;
    any_neighbour = true;
    const double* cr = n.cr.data();
    for (std::size_t i = 0; i < nc; ++i)
      total_[i] += cr[i];
  }

  // improvement_self and new_intention_self (Sec. 3.2). The paper writes Cost_self(0) - Cost_self(crs),
  // 0 being the current heading, which is the intention of the first round (Fig. 2); from the second
  // round on we measure against the current intention, as distributed stochastic search does (Zhang et
  // al. 2005), since otherwise a ship that has turned away could never be satisfied and quiescence
  // would need every ship back on her heading.
  // Scanning in domain order from the current intention, a candidate must beat the best so far by more
  // than rounding to take its place: ties keep the current intention, else the earlier entry.
  std::size_t best = static_cast<std::size_t>(current_);
  for (std::size_t i = 0; i < nc; ++i)
    if (total_[i] < total_[best] - kImprovementEps)
      best = i;
  improvement_ = total_[current_] - total_[best];
  satisfied_ = !(improvement_ > kImprovementEps);
  changed_ = false;
  if (!satisfied_) {
    // Fig. 2: overwrite intention with new_intention with probability p. A ship alone in her detection
    // range skips the search (Fig. 1) and takes it directly.
    const bool adopt = !any_neighbour || dssaUniform(rng) < config_.p;
    if (adopt) {
      current_ = static_cast<int>(best);
      changed_ = true;
    }
  } else {
    improvement_ = 0.0;
  }
  const Candidate& c = cand_[current_];
  intention_.round = round;
  intention_.course = c.course;
  intention_.speed_change = c.spc;
  intention_.speed = c.speed;
  intention_.satisfied = satisfied_;
  return intention_;
}

// ---------------------------------------------------------------------------------------------------
// Exchange

uint64_t dssaAgentSeed(uint64_t seed, int id) {
  uint64_t z = seed + 0x9E3779B97F4A7C15ull * (static_cast<uint64_t>(static_cast<uint32_t>(id)) + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

void DssaExchange::deliver(std::vector<DssaAgent>& agents, int round, Result& r) const {
  const double range2 = config_.detection_range * config_.detection_range;
  for (std::size_t i = 0; i < agents.size(); ++i) {
    const DssaIntention& m = agents[i].intention();
    for (std::size_t k = 0; k < agents.size(); ++k) {
      if (k == i || (agents[k].position() - m.position).squaredNorm() > range2)
        continue;
      if (drop_ && drop_(round, agents[i].id(), agents[k].id()))
        continue;
      agents[k].receive(m);
      ++r.messages;
    }
  }
}

DssaExchange::Result DssaExchange::run(std::vector<DssaAgent>& agents,
                                       std::vector<std::mt19937_64>& rngs) const {
  if (rngs.size() != agents.size())
    throw std::invalid_argument("DssaExchange::run: one generator per agent");
  Result r;
  const Deadline deadline(config_.max_search_time > 0.0 ? config_.max_search_time : 1e9);
  deliver(agents, 0, r);  // the initial intentions: current headings (Fig. 2)
  for (int round = 1; round <= config_.max_rounds; ++round) {
    bool all_satisfied = true;
    for (std::size_t i = 0; i < agents.size(); ++i) {
      agents[i].decide(round, rngs[i]);
      all_satisfied = all_satisfied && agents[i].satisfied();
    }
    r.rounds = round;
    if (all_satisfied) {  // quiescence (Fig. 2)
      r.quiescent = true;
      break;
    }
    deliver(agents, round, r);
    if (config_.max_search_time > 0.0 && deadline.expired())
      break;
  }
  return r;
}

// ---------------------------------------------------------------------------------------------------
// Single-agent planner

DssaPlanner::DssaPlanner(const std::string& preset) : preset_(preset), config_(DssaConfig::preset(preset)) {}

void DssaPlanner::configure(const ParamMap& params) {
  config_ = DssaConfig::fromParams(params, preset_);
}

DssaConfig DssaConfig::fromParams(ParamMap params, const std::string& preset) {
  if (!params.has("preset"))
    params.set("preset", preset);
  return fromParams(params);
}

Plan DssaPlanner::plan(const PlanningProblem& problem) {
  // "Collide" below at least the situation's demanded passing distance (planning.h).
  DssaConfig cfg = config_;
  cfg.collision_distance =
      std::max(cfg.collision_distance, kSeparationMargin * std::max(0.0, problem.min_separation));
  const Deadline deadline(problem.time_budget > 0.0 ? problem.time_budget : 1e9);
  Plan out;
  if (!problem.own.finite()) {
    out.message = "dssa: own ship state is not finite";
    return out;
  }
  const DssaShipSpeeds sp =
      dssaShipSpeeds(cfg, problem.own.speed, problem.limits.min_speed, problem.limits.max_speed);
  if (cfg.colregs)
    for (const auto& t : problem.targets)
      if (t.encounter == Encounter::HeadOn || t.encounter == Encounter::CrossingGiveWay)
        cfg.starboard_only = true;  // Rules 14-16 (see DssaConfig::colregs)
  DssaAgent agent(0, cfg, sp);
  // Land (not in the paper): steer for the route's next point round it, never onto it.
  const Eigen::Vector2d next = nextWayPoint(problem);
  agent.setLand(&problem.obstacles, landRequirement(problem));
  agent.setOwn(problem.own, next, problem.time);
  int id = 1;
  for (const auto& t : problem.targets) {
    if (!t.state.finite())
      continue;
    DssaIntention m;
    m.id = id++;
    m.stamp = problem.time;
    m.course = t.state.course;
    m.speed = t.state.speed;
    m.position = t.state.position;
    m.velocity = t.state.velocity();
    m.satisfied = true;
    agent.receive(m);
  }
  std::mt19937_64 rng(dssaAgentSeed(problem.seed, 0));
  int rounds = 0;
  for (int round = 1; round <= cfg.max_rounds; ++round) {
    agent.decide(round, rng);
    rounds = round;
    if (agent.satisfied() || deadline.expired())
      break;
  }
  const DssaIntention& in = agent.intention();
  const double crs = wrapPi(in.course - problem.own.course);
  out.status = PlanStatus::Ok;
  out.course_setpoint = in.course;
  out.speed_setpoint = in.speed;
  out.cost = agent.cost(crs, in.speed_change);
  PlannedWaypoint w0;
  w0.position = problem.own.position;
  w0.course = in.course;
  w0.speed = in.speed;
  PlannedWaypoint w1 = w0;
  w1.time = cfg.time_window;
  w1.position = problem.own.position + in.intendedVelocity() * cfg.time_window;
  out.waypoints = {w0, w1};
  out.compute_time = deadline.elapsed();
  const double cr = agent.collisionRisk(crs, in.speed_change);
  out.message = std::string(name()) + ": crs " +
                std::to_string(static_cast<int>(std::lround(radToDeg(crs)))) + " deg, spc " +
                std::to_string(in.speed_change) + " m/s after " + std::to_string(rounds) + " round(s)" +
                (cr > 0.0 ? "; collision risk remains within the window" : "");
  return out;
}

}  // namespace asv
