#include "asv_core/papers/dssa_experiments.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace asv {

namespace {

DssaSimShip ship(const std::string& name, Eigen::Vector2d start, Eigen::Vector2d goal, double ref) {
  DssaSimShip s;
  s.name = name;
  s.start = start;
  s.goal = goal;
  // MinSPD and MaxSPD are not given (Sec. 4). Ships may slow to half their reference speed (the
  // scenarios' min_speed_fraction 0.5, see DssaConfig) and speed up by one largest speed change (8).
  s.speeds.ref = ref;
  s.speeds.min = kDssaPaperMinSpeedFraction * ref;
  s.speeds.max = ref + 8.0;
  return s;
}

// Smallest distance between two ships moving straight from a0 and b0 with velocities va and vb over
// [0, t_end].
double minDistance(const Eigen::Vector2d& a0, const Eigen::Vector2d& va, const Eigen::Vector2d& b0,
                   const Eigen::Vector2d& vb, double t_end) {
  const Eigen::Vector2d r = b0 - a0;
  const Eigen::Vector2d w = vb - va;
  const double w2 = w.squaredNorm();
  double t = 0.0;
  if (w2 > 0.0)
    t = std::min(std::max(-r.dot(w) / w2, 0.0), t_end);
  return (r + w * t).norm();
}

}  // namespace

DssaScenario dssaTwoShipScenario() {
  DssaScenario s;
  s.name = "two_ships";
  s.description =
      "Sec. 5.1: two ships side by side 184 apart, each bound 456.776 ahead to the goal on the other's "
      "side, so that their straight tracks cross at the same instant (492.4 each, the paper's 985.5/2 at "
      "detour 1.00); the offset fitted to the DSSA row (total 1150)";
  s.ships = {ship("ship1", {308, 150}, {492, 606.776}, 25.0),
             ship("ship2", {492, 150}, {308, 606.776}, 25.0)};
  s.trials = 20;
  return s;
}

DssaScenario dssaSixteenShipScenario() {
  DssaScenario s;
  s.name = "sixteen_ships";
  s.description =
      "Sec. 5.2: four ships on each side of the area in lanes 100 apart (250, 350, 450, 550), 270 from the "
      "centre, each crossing 540 to the opposite side; ships from opposite sides share lanes (head-on), "
      "ships from adjacent sides cross orthogonally";
  const double lanes[4] = {250, 350, 450, 550};
  const double near = 130, far = 670;
  int k = 0;
  for (double l : lanes) {
    s.ships.push_back(ship("w" + std::to_string(k), {near, l}, {far, l}, 25.0));  // from the left (west)
    s.ships.push_back(ship("e" + std::to_string(k), {far, l}, {near, l}, 25.0));  // from the right
    s.ships.push_back(ship("s" + std::to_string(k), {l, near}, {l, far}, 25.0));  // from below
    s.ships.push_back(ship("n" + std::to_string(k), {l, far}, {l, near}, 25.0));  // from above
    ++k;
  }
  s.trials = 50;
  return s;
}

DssaScenario dssaThreeShipScenario() {
  DssaScenario s;
  s.name = "three_ships";
  s.description =
      "Sec. 5.3: three ships in line northbound, the fastest (25) at the back at y = 0, the 10 at y = 100, "
      "the 5 at the head at y = 250; goals on the same line at 800, 700 and 520 (straight 800 + 600 + 270 "
      "= 1670, travel 32 + 60 + 54: the paper's 1709/1.02 and 49.6 x 3 / 1.02)";
  s.ships = {ship("fast", {400, 0}, {400, 800}, 25.0), ship("medium", {400, 100}, {400, 700}, 10.0),
             ship("slow", {400, 250}, {400, 520}, 5.0)};
  s.trials = 20;
  return s;
}

std::vector<DssaScenario> dssaPaperScenarios() {
  return {dssaTwoShipScenario(), dssaSixteenShipScenario(), dssaThreeShipScenario()};
}

std::vector<std::string> dssaPaperVariants() {
  return {"dssa", "dssa_plus_sc", "dssa_plus_cs", "dssa_plus_eq"};
}

std::string dssaVariantLabel(const std::string& v) {
  if (v == "dssa")
    return "DSSA";
  if (v == "dssa_plus_sc")
    return "DSSA+ s>c";
  if (v == "dssa_plus_cs")
    return "DSSA+ s<c";
  if (v == "dssa_plus_eq" || v == "dssa_plus")
    return "DSSA+ s=c";
  return v;
}

DssaPaperFigures dssaPaperFigures(const std::string& scenario, const std::string& variant) {
  // Tables 1-3 of the paper, columns DSSA, DSSA+ s>c, s<c, s=c.
  struct Row {
    const char* scenario;
    DssaPaperFigures f[4];
  };
  static const Row rows[] = {
      {"two_ships",
       {{1150.0, 23.0, 1.17, 20, 20},
        {985.5, 22.7, 1.00, 20, 20},
        {1154.0, 25.0, 1.17, 20, 20},
        {1154.0, 25.0, 1.17, 20, 20}}},
      {"sixteen_ships",
       {{9833.6, 24.6, 1.14, 32, 50},
        {8693.4, 33.2, 1.01, 50, 50},
        {9816.9, 26.5, 1.15, 47, 50},
        {9096.4, 25.3, 1.06, 49, 50}}},
      {"three_ships",
       {{1709.0, 49.6, 1.02, 20, 20},
        {1702.0, 59.3, 1.01, 1, 20},
        {1713.5, 51.4, 1.02, 20, 20},
        {1705.9, 49.5, 1.01, 17, 20}}},
  };
  const auto vars = dssaPaperVariants();
  int col = -1;
  for (std::size_t i = 0; i < vars.size(); ++i)
    if (vars[i] == variant || (variant == "dssa_plus" && vars[i] == "dssa_plus_eq"))
      col = static_cast<int>(i);
  for (const auto& r : rows)
    if (scenario == r.scenario && col >= 0)
      return r.f[col];
  return {};
}

namespace {

// One control phase (Fig. 1): per active agent, where it starts, its velocity, the fraction of the
// step it moves and whether it arrives.
struct Moves {
  std::vector<Eigen::Vector2d> p0, v;
  std::vector<double> frac;
  std::vector<bool> arrived;
  std::vector<std::size_t> docking;  // the goal within this move but off the intended track
};

// The simulation of the paper's experiments (Sec. 5): search phases of the exchange, then every ship
// moves one time step with her intention.
class DssaRun {
public:
  DssaRun(const DssaScenario& scenario, const DssaConfig& config, uint64_t seed,
          const DssaSimOptions& options);
  DssaRunResult run();

private:
  void searchPhase(double now);
  Moves plannedMoves() const;
  void dock(Moves& mv) const;
  void checkSeparation(const Moves& mv);
  void applyMoves(const Moves& mv, double now);
  void removeArrived(const Moves& mv);
  bool clearOfParked(const Eigen::Vector2d& p0, const Eigen::Vector2d& v, double t_end) const;
  void summarise(int steps);

  const DssaScenario& scenario_;
  const DssaSimOptions& options_;
  const double dt_, collide_;
  const DssaExchange exchange_;
  std::vector<ShipState> ships_;
  // Agents live for the whole run, so a ship's last known intentions of the others carry over.
  std::vector<DssaAgent> agents_;
  std::vector<std::mt19937_64> rngs_;
  std::vector<int> parked_;  // ships that arrived and stay at their goals
  DssaRunResult res_;
  long rounds_total_ = 0;
};

DssaRun::DssaRun(const DssaScenario& scenario, const DssaConfig& config, uint64_t seed,
                 const DssaSimOptions& options)
    : scenario_(scenario),
      options_(options),
      dt_(config.time_step),
      collide_(options.collision_distance > 0.0 ? options.collision_distance : config.collision_distance),
      exchange_(config),
      ships_(scenario.ships.size()) {
  res_.ships.resize(ships_.size());
  res_.min_separation = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ships_.size(); ++i) {
    const DssaSimShip& s = scenario.ships[i];
    ships_[i].id = s.name;
    ships_[i].position = s.start;
    ships_[i].course = trueBearing(s.start, s.goal);
    ships_[i].heading = ships_[i].course;
    ships_[i].speed = s.speeds.ref;
    res_.ships[i].straight = (s.goal - s.start).norm();
    if (options.record_trajectories)
      res_.ships[i].trajectory.push_back(s.start);
    agents_.emplace_back(static_cast<int>(i), config, s.speeds);
    rngs_.emplace_back(dssaAgentSeed(seed, static_cast<int>(i)));
  }
}

void DssaRun::searchPhase(double now) {
  for (auto& a : agents_) {
    a.setOwn(ships_[a.id()], scenario_.ships[a.id()].goal, now);
    for (int i : parked_)
      a.receive(dssaStationaryShip(i, ships_[i].position, ships_[i].course, now));
  }
  const DssaExchange::Result x = exchange_.run(agents_, rngs_);
  bool searched = false;
  for (const auto& a : agents_)
    searched = searched || a.neighbourCount() > 0;
  if (!searched)
    return;
  ++res_.search_phases;
  rounds_total_ += x.rounds;
  res_.max_rounds = std::max(res_.max_rounds, x.rounds);
  if (!x.quiescent)
    ++res_.non_quiescent_phases;
}

// Each ship moves one step with her intention; arrival ends her move early.
Moves DssaRun::plannedMoves() const {
  const std::size_t m = agents_.size();
  Moves mv{std::vector<Eigen::Vector2d>(m),
           std::vector<Eigen::Vector2d>(m),
           std::vector<double>(m, 1.0),
           std::vector<bool>(m, false),
           {}};
  for (std::size_t k = 0; k < m; ++k) {
    const int i = agents_[k].id();
    mv.p0[k] = ships_[i].position;
    mv.v[k] = agents_[k].intention().intendedVelocity();
    const Eigen::Vector2d goal = scenario_.ships[i].goal;
    const double len = mv.v[k].norm() * dt_;
    const double to_goal = (goal - mv.p0[k]).norm();
    if (len > 0.0) {
      const Eigen::Vector2d u = mv.v[k] * dt_ / len;
      const double along = std::min(std::max((goal - mv.p0[k]).dot(u), 0.0), len);
      if ((mv.p0[k] + u * along - goal).norm() <= options_.goal_tolerance) {
        mv.arrived[k] = true;
        mv.frac[k] = along / len;
      }
    }
    if (!mv.arrived[k] && to_goal <= std::max(len, options_.goal_tolerance))
      mv.docking.push_back(k);
  }
  return mv;
}

// The goal is within this move but off her intended track. With a 45 deg turn per step at full speed
// the goal can lie inside her turning circle, and she would circle it for ever; so she makes straight
// for it (Fig. 1's control phase moves a ship directly) when that move keeps her clear of every other
// ship's intended move over the step, and otherwise keeps her intention.
void DssaRun::dock(Moves& mv) const {
  for (std::size_t k : mv.docking) {
    const Eigen::Vector2d goal = scenario_.ships[agents_[k].id()].goal;
    const double to_goal = (goal - mv.p0[k]).norm();
    const double speed = std::max(mv.v[k].norm(), to_goal / dt_);
    const Eigen::Vector2d vd =
        to_goal > 0.0 ? Eigen::Vector2d((goal - mv.p0[k]) / to_goal * speed) : Eigen::Vector2d::Zero();
    const double fd = speed > 0.0 ? to_goal / (speed * dt_) : 0.0;
    bool clear = clearOfParked(mv.p0[k], vd, fd * dt_);
    for (std::size_t j = 0; j < mv.p0.size() && clear; ++j)
      if (j != k && minDistance(mv.p0[k], vd, mv.p0[j], mv.v[j], std::min(fd, mv.frac[j]) * dt_) < collide_)
        clear = false;
    if (clear) {
      mv.arrived[k] = true;
      mv.frac[k] = fd;
      mv.v[k] = vd;
    }
  }
}

bool DssaRun::clearOfParked(const Eigen::Vector2d& p0, const Eigen::Vector2d& v, double t_end) const {
  for (int i : parked_)
    if (minDistance(p0, v, ships_[i].position, Eigen::Vector2d::Zero(), t_end) < collide_)
      return false;
  return true;
}

void DssaRun::checkSeparation(const Moves& mv) {
  for (std::size_t a = 0; a < mv.p0.size(); ++a)
    for (int i : parked_) {
      const double d =
          minDistance(mv.p0[a], mv.v[a], ships_[i].position, Eigen::Vector2d::Zero(), mv.frac[a] * dt_);
      res_.min_separation = std::min(res_.min_separation, d);
      res_.collision = res_.collision || d < collide_;
    }
  for (std::size_t a = 0; a < mv.p0.size(); ++a)
    for (std::size_t b = a + 1; b < mv.p0.size(); ++b) {
      const double d =
          minDistance(mv.p0[a], mv.v[a], mv.p0[b], mv.v[b], std::min(mv.frac[a], mv.frac[b]) * dt_);
      res_.min_separation = std::min(res_.min_separation, d);
      if (d < collide_)
        res_.collision = true;
    }
}

void DssaRun::applyMoves(const Moves& mv, double now) {
  for (std::size_t k = 0; k < mv.p0.size(); ++k) {
    const int i = agents_[k].id();
    const DssaIntention& in = agents_[k].intention();
    ShipState& st = ships_[i];
    const Eigen::Vector2d p1 =
        mv.arrived[k] ? scenario_.ships[i].goal : Eigen::Vector2d(mv.p0[k] + mv.v[k] * dt_);
    res_.ships[i].path_length += (p1 - mv.p0[k]).norm();
    st.position = p1;
    st.course = in.course;
    st.heading = in.course;
    st.speed = mv.arrived[k] ? 0.0 : in.speed;
    if (options_.record_trajectories)
      res_.ships[i].trajectory.push_back(p1);
    if (mv.arrived[k]) {
      res_.ships[i].arrived = true;
      res_.ships[i].travel_time = now + mv.frac[k] * dt_;
    }
  }
}

// Arrived ships stop searching; they stay where they stopped (the others are told so at every search
// phase) or, with arrived_leave, leave and are forgotten so that no stale intention lingers.
void DssaRun::removeArrived(const Moves& mv) {
  for (std::size_t k = mv.p0.size(); k-- > 0;)
    if (mv.arrived[k]) {
      const int id = agents_[k].id();
      agents_.erase(agents_.begin() + static_cast<std::ptrdiff_t>(k));
      rngs_.erase(rngs_.begin() + static_cast<std::ptrdiff_t>(k));
      if (!options_.arrived_leave)
        parked_.push_back(id);
      else
        for (auto& a : agents_)
          a.forget(id);
    }
}

void DssaRun::summarise(int steps) {
  const std::size_t n = ships_.size();
  res_.steps = steps;
  res_.mean_rounds = res_.search_phases > 0 ? static_cast<double>(rounds_total_) / res_.search_phases : 0.0;
  bool all_arrived = true;
  for (std::size_t i = 0; i < n; ++i) {
    DssaShipResult& r = res_.ships[i];
    all_arrived = all_arrived && r.arrived;
    r.detour_rate = r.straight > 0.0 ? r.path_length / r.straight : 1.0;
    res_.total_path_length += r.path_length;
    res_.mean_travel_time += r.travel_time / n;
    res_.mean_detour_rate += r.detour_rate / n;
  }
  res_.success = all_arrived && !res_.collision;
}

DssaRunResult DssaRun::run() {
  int step = 0;
  for (; step < options_.max_steps && !agents_.empty(); ++step) {
    const double now = step * dt_;
    searchPhase(now);
    Moves mv = plannedMoves();
    dock(mv);
    checkSeparation(mv);
    applyMoves(mv, now);
    removeArrived(mv);
    if (res_.collision) {
      ++step;
      break;
    }
  }
  summarise(step);
  return res_;
}

}  // namespace

DssaRunResult runDssaSimulation(const DssaScenario& scenario, const DssaConfig& config, uint64_t seed,
                                const DssaSimOptions& options) {
  return DssaRun(scenario, config, seed, options).run();
}

DssaExperimentSummary runDssaExperiment(const DssaScenario& scenario, const std::string& variant, int trials,
                                        uint64_t seed, const DssaSimOptions& options) {
  const DssaConfig config = DssaConfig::preset(variant);
  DssaExperimentSummary s;
  s.scenario = scenario.name;
  s.variant = variant;
  s.trials = trials;
  s.min_separation = std::numeric_limits<double>::infinity();
  double rounds = 0;
  for (int k = 0; k < trials; ++k) {
    const DssaRunResult r = runDssaSimulation(scenario, config, seed + static_cast<uint64_t>(k), options);
    s.min_separation = std::min(s.min_separation, r.min_separation);
    s.collisions += r.collision ? 1 : 0;
    rounds += r.mean_rounds;
    s.non_quiescent_phases += r.non_quiescent_phases;
    if (!r.success)
      continue;
    ++s.successes;
    s.total_path_length += r.total_path_length;
    s.travel_time += r.mean_travel_time;
    s.detour_rate += r.mean_detour_rate;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s.total_path_length = s.successes ? s.total_path_length / s.successes : nan;
  s.travel_time = s.successes ? s.travel_time / s.successes : nan;
  s.detour_rate = s.successes ? s.detour_rate / s.successes : nan;
  s.mean_rounds = trials > 0 ? rounds / trials : 0.0;
  return s;
}

}  // namespace asv
