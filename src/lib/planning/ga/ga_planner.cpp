#include "asv_core/planning/ga/ga_planner.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "asv_core/planning/land_route.h"

namespace asv {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::invalid_argument("ga: " + what);
}

bool finitePositive(double v) {
  return std::isfinite(v) && v > 0.0;
}
bool finiteNonNegative(double v) {
  return std::isfinite(v) && v >= 0.0;
}

}  // namespace

void GaConfig::validate() const {
  require(population_size >= 2, "population_size must be >= 2");
  require(generations >= 0, "generations must be >= 0");
  require(crossover_probability >= 0.0 && crossover_probability <= 1.0,
          "crossover_probability must be in [0, 1]");
  require(mutation_probability >= 0.0 && mutation_probability <= 1.0,
          "mutation_probability must be in [0, 1]");
  require(chromosome_bits >= 2 && chromosome_bits <= 16, "chromosome_bits must be in [2, 16]");
  require(finitePositive(max_alteration_deg) && max_alteration_deg <= 180.0,
          "max_alteration_deg must be in (0, 180] deg");
  require(elite_count >= 0 && elite_count < population_size, "elite_count must be in [0, population_size)");
  require(cri_threshold >= 0.0 && cri_threshold <= 1.0, "cri_threshold must be in [0, 1]");
  require(finiteNonNegative(similar_cri_margin), "similar_cri_margin must be >= 0");
  require(finiteNonNegative(safety_penalty), "safety_penalty must be >= 0");
  require(finiteNonNegative(colregs_penalty), "colregs_penalty must be >= 0");
  require(finiteNonNegative(new_risk_penalty), "new_risk_penalty must be >= 0");
  require(finiteNonNegative(turn_penalty), "turn_penalty must be >= 0");
  require(finiteNonNegative(min_leg_time_s), "min_leg_time_s must be >= 0 s");
  cri.validate();
  colregs.validate();
}

GaConfig GaConfig::paper() {
  GaConfig c;
  c.elite_count = 0;
  c.safety_penalty = c.colregs_penalty = c.new_risk_penalty = c.turn_penalty = 0.0;
  c.cri.as_printed = true;
  c.hold_decision = true;
  return c;
}

GaConfig GaConfig::fromParams(const ParamMap& p) {
  GaConfig c = plannerMode(p, "ga") == PlannerMode::Paper ? paper() : GaConfig{};
  c.population_size = p.getInt("population_size", c.population_size);
  c.generations = p.getInt("generations", c.generations);
  c.crossover_probability = p.getDouble("crossover_probability", c.crossover_probability);
  c.mutation_probability = p.getDouble("mutation_probability", c.mutation_probability);
  c.chromosome_bits = p.getInt("chromosome_bits", c.chromosome_bits);
  c.max_alteration_deg = p.getDouble("max_alteration_deg", c.max_alteration_deg);
  c.elite_count = p.getInt("elite_count", c.elite_count);
  c.cri_threshold = p.getDouble("cri_threshold", c.cri_threshold);
  c.similar_cri_margin = p.getDouble("similar_cri_margin", c.similar_cri_margin);
  c.hold_decision = p.getBool("hold_decision", c.hold_decision);
  c.safety_penalty = p.getDouble("safety_penalty", c.safety_penalty);
  c.colregs_penalty = p.getDouble("colregs_penalty", c.colregs_penalty);
  c.new_risk_penalty = p.getDouble("new_risk_penalty", c.new_risk_penalty);
  c.turn_penalty = p.getDouble("turn_penalty", c.turn_penalty);
  c.min_leg_time_s = p.getDouble("min_leg_time_s", c.min_leg_time_s);

  CriConfig& r = c.cri;
  r.c_dcpa = p.getDouble("cri/c_dcpa", r.c_dcpa);
  r.c_tcpa = p.getDouble("cri/c_tcpa", r.c_tcpa);
  r.c_b = p.getDouble("cri/c_b", r.c_b);
  r.c_d = p.getDouble("cri/c_d", r.c_d);
  r.c_k = p.getDouble("cri/c_k", r.c_k);
  r.dlma_m = p.getDouble("cri/dlma_m", r.dlma_m);
  r.attention_range_m = p.getDouble("cri/attention_range_m", r.attention_range_m);
  r.speed_ratio_w = p.getDouble("cri/speed_ratio_w", r.speed_ratio_w);
  r.arena_cb = p.getDouble("cri/arena_cb", r.arena_cb);
  r.peak_bearing_deg = p.getDouble("cri/peak_bearing_deg", r.peak_bearing_deg);
  r.zero_when_diverging = p.getBool("cri/zero_when_diverging", r.zero_when_diverging);
  r.as_printed = p.getBool("cri/as_printed", r.as_printed);
  r.safe_encounter.domain_unit_m = p.getDouble("cri/domain_unit_m", r.safe_encounter.domain_unit_m);
  r.safe_encounter.turn90_time_s = p.getDouble("cri/turn90_time_s", r.safe_encounter.turn90_time_s);
  r.safe_encounter.advance_m = p.getDouble("cri/advance_m", r.safe_encounter.advance_m);

  ColregsConfig& g = c.colregs;
  g.head_on_half_angle_deg = p.getDouble("colregs/head_on_half_angle_deg", g.head_on_half_angle_deg);
  g.stern_sector_start_deg = p.getDouble("colregs/stern_sector_start_deg", g.stern_sector_start_deg);
  g.max_range_m = p.getDouble("colregs/max_range_m", g.max_range_m);

  p.rejectUnknown("ga");
  c.validate();
  return c;
}

// ---------------------------------------------------------------------------------------------------

double decodeAlteration(uint32_t code, int bits, double max_alteration) {
  const uint32_t max_code = (1u << bits) - 1u;
  code = std::min(code, max_code);
  return -max_alteration + 2.0 * max_alteration * static_cast<double>(code) / static_cast<double>(max_code);
}

uint32_t encodeAlteration(double alteration, int bits, double max_alteration) {
  const uint32_t max_code = (1u << bits) - 1u;
  const double x = (alteration + max_alteration) / (2.0 * max_alteration) * static_cast<double>(max_code);
  if (!(x > 0.0))
    return 0u;  // also NaN
  if (x >= static_cast<double>(max_code))
    return max_code;
  return static_cast<uint32_t>(std::lround(x));
}

void rouletteCumulative(const std::vector<double>& cost, std::vector<double>& cumulative) {
  cumulative.resize(cost.size());
  if (cost.empty())
    return;
  const auto mm = std::minmax_element(cost.begin(), cost.end());
  const double lo = *mm.first, hi = *mm.second, span = hi - lo;
  double sum = 0.0;
  for (size_t i = 0; i < cost.size(); ++i) {
    // Windowing: without the 5 % floor the worst individual could never be drawn; with equal costs the
    // wheel is uniform.
    sum += span > 0.0 ? (hi - cost[i]) + 0.05 * span : 1.0;
    cumulative[i] = sum;
  }
}

size_t rouletteSelect(const std::vector<double>& cumulative, double u) {
  if (cumulative.empty())
    return 0;
  const double target = u * cumulative.back();
  const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), target);
  return std::min(static_cast<size_t>(it - cumulative.begin()), cumulative.size() - 1);
}

bool singlePointCrossover(uint32_t& a, uint32_t& b, int bits, double pc, GaRng& rng) {
  if (!(rng.uniform() < pc))
    return false;
  const int cut = 1 + static_cast<int>(rng.below(static_cast<uint32_t>(bits - 1)));  // [1, bits - 1]
  const uint32_t low = (1u << cut) - 1u;                                             // genes below the cut
  const uint32_t a0 = a;
  a = (a & ~low) | (b & low);
  b = (b & ~low) | (a0 & low);
  return true;
}

int mutateGene(uint32_t& code, int bits, double pm, GaRng& rng) {
  if (!(rng.uniform() < pm))
    return -1;
  const int pos = static_cast<int>(rng.below(static_cast<uint32_t>(bits)));
  code ^= 1u << pos;
  return pos;
}

// ---------------------------------------------------------------------------------------------------

GaFitness::GaFitness(const PlanningProblem& problem, const GaConfig& cfg) : cfg_(cfg), own_(problem.own) {
  // Fig. 3's rule (TCPA < 0: passed, no danger, CRI 0) decides whether to act, on the original course.
  // A candidate heading is scored by eq. (1)-(6) themselves, which use |TCPA| (eq. 3) and are
  // continuous: zeroing there would make "turn until the target diverges" a cliff the GA falls off
  // (in an overtaking, a turn of 50-70 deg that merely stops the closing).
  candidate_cri_ = cfg_.cri;
  candidate_cri_.zero_when_diverging = false;
  own_.id.clear();  // the candidate copies made per evaluation then never allocate
  sda_floor_ = kSeparationMargin * std::max(0.0, problem.min_separation);
  passing_cap_ = problem.passing_cap;
  const Eigen::Vector2d next = nextWayPoint(problem);
  reference_course_ = (next - own_.position).norm() > 1e-6 ? trueBearing(own_.position, next) : own_.course;
  next_ = next;
  land_ = &problem.obstacles;
  land_required_ = landRequirement(problem);
  land_reach_ = std::max(problem.own.speed, 0.5) * problem.prediction_horizon;
  own_.course = own_.heading = reference_course_;

  const Eigen::Vector2d v_own = own_.velocity();
  for (size_t i = 0; i < problem.targets.size(); ++i) {
    const ShipState& s = problem.targets[i].state;
    if (!s.finite())
      continue;  // a target without a usable state cannot be avoided by any heading
    Target t;
    t.state = s;
    t.velocity = s.velocity();
    t.unit_velocity = s.speed > 0.0 ? Eigen::Vector2d(t.velocity / s.speed) : Eigen::Vector2d::Zero();
    t.true_bearing = trueBearing(own_.position, s.position);
    GaTargetInfo info;
    info.index = i;
    const Cpa cpa = computeCpa(own_.position, v_own, s.position, t.velocity);
    info.geometry = classifyEncounter(own_, s, cpa, cfg_.colregs);
    info.cri = computeCri(own_, s, cpa, cfg_.cri, info.geometry.relative_bearing).cri;
    t.encounter = info.geometry.encounter;
    max_cri_ = std::max(max_cri_, info.cri);
    targets_.push_back(t);
    info_.push_back(info);
  }
  // Section 4, 2): priority to the largest CRI; the CRIs of similar targets are summed.
  for (size_t k = 0; k < targets_.size(); ++k) {
    GaTargetInfo& info = info_[k];
    info.priority = max_cri_ > 0.0 && info.cri > 0.0 && info.cri >= max_cri_ - cfg_.similar_cri_margin;
    info.engaged = info.priority || info.cri > cfg_.cri_threshold;
    targets_[k].priority = info.priority;
    targets_[k].engaged = info.engaged;
  }
}

Cpa GaFitness::cpa(size_t i, double alteration) const {
  const Target& t = targets_.at(i);
  const Eigen::Vector2d v = courseSpeedToVelocity(reference_course_ + alteration, own_.speed);
  return computeCpa(own_.position, v, t.state.position, t.velocity);
}

double GaFitness::legTime(double alteration) const {
  double t = cfg_.min_leg_time_s;
  for (size_t k = 0; k < info_.size(); ++k)
    if (info_[k].priority)
      t = std::max(t, cpa(k, alteration).tcpa);
  return t;
}

GaCostTerms GaFitness::terms(double alteration) const {
  GaCostTerms j;
  ShipState cand = own_;
  cand.course = cand.heading = wrapTwoPi(reference_course_ + alteration);
  const double sc = std::sin(cand.course), cc = std::cos(cand.course);
  const Eigen::Vector2d v_own(own_.speed * sc, own_.speed * cc);
  const Eigen::Vector2d starboard(cc, -sc);
  int violations = 0;
  double shortfall = 0.0;

  for (const Target& t : targets_) {
    const Cpa cpa = computeCpa(own_.position, v_own, t.state.position, t.velocity);
    const double rb = wrapTwoPi(t.true_bearing - cand.heading);
    const CriResult r = computeCri(cand, t.state, cpa, candidate_cri_, rb);  // eq. (1)-(6) for the candidate
    if (t.priority)
      j.risk += r.cri;
    else
      j.new_risk += std::max(0.0, r.cri - cfg_.cri_threshold);

    const bool ahead_in_time = cpa.relative_motion && cpa.tcpa > 0.0;
    // Eq. (7): DCPA >= SDA, SDA = d1 = 1.5 rho(theta) of eq. (10), for a CPA still to come within the
    // attention range (farther targets are not yet part of the encounter).
    // SDA is capped in restricted waters (PlanningProblem::passing_cap) and floored at the situation's
    // demanded passing distance (PlanningProblem::min_separation).
    const double sda = std::max(passing_cap_ > 0.0 ? std::min(r.d1, passing_cap_) : r.d1, sda_floor_);
    if ((ahead_in_time || !cpa.relative_motion) && cpa.range <= cfg_.cri.attention_range_m && sda > 0.0 &&
        cpa.dcpa < sda)
      shortfall += (sda - cpa.dcpa) / sda;

    if (!t.engaged)
      continue;
    // Section 2.1 (and Rule 17(c)).
    switch (t.encounter) {
      case Encounter::HeadOn:
        if (alteration < 0.0)
          ++violations;  // "the ASV should turn right"
        if (ahead_in_time && (cpa.target_at_cpa - cpa.own_at_cpa).dot(starboard) > 1e-3)
          ++violations;  // "... and pass on the left side of the TSs": port to port
        break;
      case Encounter::CrossingStandOn:
        if (alteration < 0.0)
          ++violations;  // Rule 17(c): no alteration to port for a vessel on the own port side
        [[fallthrough]];
      case Encounter::CrossingGiveWay:
        // "The ASV should pass astern of TSs": at the CPA the own ship must not lie ahead of the target.
        if (ahead_in_time && (cpa.own_at_cpa - cpa.target_at_cpa).dot(t.unit_velocity) > 0.0)
          ++violations;
        break;
      default:
        break;  // overtaking: either side (section 2.1); stand-on when overtaken: no side rule
    }
  }
  j.new_risk *= cfg_.new_risk_penalty;
  j.safety = cfg_.safety_penalty * shortfall;
  j.colregs = cfg_.colregs_penalty * violations;
  j.turn = cfg_.turn_penalty * std::fabs(alteration) / degToRad(cfg_.max_alteration_deg);
  if (land_required_ > 0.0) {
    const Eigen::Vector2d leg_end = own_.position + v_own * legTime(alteration);
    if (trackObstacleDistance(truncateTrack({own_.position, leg_end, next_}, land_reach_), *land_) <
        land_required_)
      j.land = kLandCost;
  }
  j.total = j.risk + j.new_risk + j.safety + j.colregs + j.turn + j.land;
  return j;
}

// ---------------------------------------------------------------------------------------------------

GaRunResult runGa(const GaFitness& fitness, const GaConfig& cfg, uint64_t seed, const Deadline* deadline) {
  const int bits = cfg.chromosome_bits;
  const uint32_t n_codes = 1u << bits;
  const double max_alt = degToRad(cfg.max_alteration_deg);
  const size_t pop_size = static_cast<size_t>(cfg.population_size);
  const size_t elites = static_cast<size_t>(cfg.elite_count);
  GaRng rng(seed);
  GaRunResult res;

  // The coding is discrete: at most 2^bits distinct fitness values, each computed once.
  std::vector<double> cache(n_codes, std::numeric_limits<double>::quiet_NaN());
  auto evaluate = [&](uint32_t code) {
    double& c = cache[code];
    if (std::isnan(c)) {
      c = fitness.cost(decodeAlteration(code, bits, max_alt));
      ++res.evaluations;
    }
    return c;
  };
  // Ties go to the smaller alteration (then the smaller code), so the result never depends on the order
  // in which equal candidates turned up.
  auto better = [&](uint32_t a, double ca, uint32_t b, double cb) {
    if (ca != cb)
      return ca < cb;
    const double da = std::fabs(decodeAlteration(a, bits, max_alt));
    const double db = std::fabs(decodeAlteration(b, bits, max_alt));
    return da != db ? da < db : a < b;
  };

  std::vector<uint32_t> pop(pop_size), next(pop_size);
  std::vector<double> cost(pop_size), cumulative(pop_size);
  std::vector<char> taken(pop_size);
  bool have_best = false;
  auto score = [&]() {
    for (size_t i = 0; i < pop_size; ++i) {
      cost[i] = evaluate(pop[i]);
      if (!have_best || better(pop[i], cost[i], res.code, res.cost)) {
        res.code = pop[i];
        res.cost = cost[i];
        have_best = true;
      }
    }
  };

  for (auto& g : pop)  // section 3.2 step 2: random initial population
    g = rng.below(n_codes);
  score();

  for (int gen = 0; gen < cfg.generations; ++gen) {
    if (deadline && deadline->expired()) {
      res.deadline_hit = true;
      break;
    }
    std::fill(taken.begin(), taken.end(), 0);
    for (size_t e = 0; e < elites; ++e) {
      size_t best = pop_size;
      for (size_t i = 0; i < pop_size; ++i)
        if (!taken[i] && (best == pop_size || better(pop[i], cost[i], pop[best], cost[best])))
          best = i;
      taken[best] = 1;
      next[e] = pop[best];
    }
    rouletteCumulative(cost, cumulative);
    for (size_t i = elites; i < pop_size; i += 2) {
      uint32_t a = pop[rouletteSelect(cumulative, rng.uniform())];  // step 4
      uint32_t b = pop[rouletteSelect(cumulative, rng.uniform())];
      singlePointCrossover(a, b, bits, cfg.crossover_probability, rng);  // step 5
      mutateGene(a, bits, cfg.mutation_probability, rng);                // step 6
      mutateGene(b, bits, cfg.mutation_probability, rng);
      next[i] = a;
      if (i + 1 < pop_size)
        next[i + 1] = b;
    }
    pop.swap(next);
    score();  // step 7
    ++res.generations;
  }
  res.alteration = decodeAlteration(res.code, bits, max_alt);
  return res;
}

// ---------------------------------------------------------------------------------------------------

GaPlanner::GaPlanner(const GaConfig& cfg) : cfg_(cfg) {
  cfg_.validate();
}

void GaPlanner::configure(const ParamMap& params) {
  cfg_ = GaConfig::fromParams(params);
  held_ = {};
}

namespace {

std::string fmt(const char* f, double a, double b = 0.0, double c = 0.0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

// Appends the remaining route and the goal, timed at the given speed from `from` at `t0`.
void appendRoute(const PlanningProblem& p, Eigen::Vector2d from, double t0, double speed,
                 std::vector<PlannedWaypoint>& out) {
  std::vector<Eigen::Vector2d> pts = p.route;
  pts.push_back(p.goal);
  double t = t0;
  for (const auto& q : pts) {
    const double d = (q - from).norm();
    PlannedWaypoint w;
    w.position = q;
    w.course = d > 1e-9 ? trueBearing(from, q) : (out.empty() ? 0.0 : out.back().course);
    w.speed = speed;
    t += speed > 0.0 ? d / speed : 0.0;
    w.time = t;
    out.push_back(w);
    from = q;
  }
}

// The plan below the threshold (Fig. 3): the course to the goal; also the return to the original course
// once the risk on it has cleared.
Plan goalPlan(const PlanningProblem& problem, const GaFitness& fitness, double threshold) {
  Plan plan;
  plan.status = PlanStatus::Ok;
  plan.speed_setpoint = keptSpeed(problem);  // the paper's decision is the heading only
  plan.course_setpoint = fitness.referenceCourse();
  PlannedWaypoint start;
  start.position = problem.own.position;
  start.speed = plan.speed_setpoint;
  start.course = plan.course_setpoint;
  plan.waypoints.push_back(start);
  appendRoute(problem, start.position, 0.0, plan.speed_setpoint, plan.waypoints);
  plan.cost = 0.0;
  plan.message = fitness.targets().empty()
                     ? "ga: no targets; course to goal"
                     : fmt("ga: largest CRI %.3f <= threshold %.2f; course to goal %.1f deg",
                           fitness.maxCri(), threshold, radToDeg(fitness.referenceCourse()));
  return plan;
}

std::string targetId(const PlanningProblem& problem, size_t index) {
  const std::string& id = problem.targets[index].state.id;
  return id.empty() ? std::to_string(index) : id;
}

// The evasive plan on the original course + `alteration`: own position, the end of the evasive leg (the
// last priority target's CPA on the new heading), the remaining route and the goal.
Plan evasivePlan(const PlanningProblem& problem, const GaFitness& fitness, double alteration, double cost,
                 const std::string& how) {
  const double speed = keptSpeed(problem);
  const double course = wrapTwoPi(fitness.referenceCourse() + alteration);
  Plan plan;
  plan.status = PlanStatus::Ok;
  plan.speed_setpoint = speed;  // the paper's decision is the heading only
  plan.course_setpoint = course;
  plan.cost = cost;
  const double leg_time = fitness.legTime(alteration);
  std::string ids;
  for (const GaTargetInfo& t : fitness.targets())
    if (t.priority)
      ids += (ids.empty() ? "" : ",") + targetId(problem, t.index) + "(" + toString(t.geometry.encounter) +
             fmt(" CRI %.3f)", t.cri);
  PlannedWaypoint start, leg;
  start.position = problem.own.position;
  start.speed = speed;
  start.course = course;
  plan.waypoints.push_back(start);
  leg.position = problem.own.position + courseSpeedToVelocity(course, speed) * leg_time;
  leg.time = leg_time;
  leg.course = course;
  leg.speed = speed;
  plan.waypoints.push_back(leg);
  appendRoute(problem, leg.position, leg_time, speed, plan.waypoints);
  plan.message = "ga: avoid " + ids +
                 fmt("; alteration %+.2f deg (positive = starboard) to %.1f deg; cost %.4f",
                     radToDeg(alteration), radToDeg(course), cost) +
                 " " + how;
  return plan;
}

}  // namespace

Plan GaPlanner::plan(const PlanningProblem& problem) {
  const Deadline deadline(problem.time_budget);
  if (!problem.own.finite() || !std::isfinite(problem.goal.x()) || !std::isfinite(problem.goal.y())) {
    Plan plan;
    plan.status = PlanStatus::NoSolution;
    plan.message = "ga: own ship state or goal not finite";
    return plan;
  }
  if (problem.time < last_time_)
    held_ = {};  // a new run
  last_time_ = problem.time;
  const GaFitness fitness(problem, cfg_);
  if (!fitness.triggered()) {
    held_ = {};
    Plan plan = goalPlan(problem, fitness, cfg_.cri_threshold);
    plan.compute_time = deadline.elapsed();
    return plan;
  }
  std::vector<std::string> above;  // the targets this decision is for
  for (const GaTargetInfo& t : fitness.targets())
    if (t.priority || t.cri > cfg_.cri_threshold)
      above.push_back(targetId(problem, t.index));
  const bool covered = std::all_of(above.begin(), above.end(), [&](const std::string& id) {
    return std::find(held_.targets.begin(), held_.targets.end(), id) != held_.targets.end();
  });
  Plan plan;
  if (cfg_.hold_decision && !held_.targets.empty() && covered) {
    const double alteration = std::remainder(held_.course - fitness.referenceCourse(), kTwoPi);
    plan = evasivePlan(problem, fitness, alteration, fitness.cost(alteration),
                       fmt("(decided at t = %.0f s, held)", held_.time));
  } else {
    const GaRunResult run = runGa(fitness, cfg_, problem.seed, &deadline);
    plan = evasivePlan(problem, fitness, run.alteration, run.cost,
                       "after " + std::to_string(run.generations) + " generations" +
                           (run.deadline_hit ? " (time budget reached)" : ""));
    if (cfg_.hold_decision)
      held_ = {wrapTwoPi(fitness.referenceCourse() + run.alteration), problem.time, above};
  }
  plan.compute_time = deadline.elapsed();
  return plan;
}

}  // namespace asv
