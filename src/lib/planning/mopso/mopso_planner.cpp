#include "asv_core/planning/mopso/mopso_planner.h"
#include "asv_core/common/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace asv {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::invalid_argument("mopso config: " + what);
}

bool finitePositive(double v) {
  return std::isfinite(v) && v > 0.0;
}

// Uniform in [0, 1) from 53 random bits: std::uniform_real_distribution is not specified bit for bit
// across standard libraries, and the plan must not depend on which one built us.
double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0);
}
double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * uniform01(rng);
}
size_t uniformIndex(std::mt19937_64& rng, size_t n) {
  return std::min(n - 1, static_cast<size_t>(uniform01(rng) * static_cast<double>(n)));
}

}  // namespace

// ------------------------------------------------------------------------------------------------
// Config

void MopsoConfig::validate() const {
  require(particles >= 2, "particles must be >= 2");
  require(generations >= 0, "generations must be >= 0");
  require(repository_size >= 1, "repository_size must be >= 1");
  require(grid_divisions >= 1 && grid_divisions <= 1000, "grid_divisions must be in [1, 1000]");
  require(std::isfinite(inertia) && inertia >= 0.0, "inertia must be >= 0");
  require(std::isfinite(c1) && c1 >= 0.0, "c1 must be >= 0");
  require(std::isfinite(c2) && c2 >= 0.0, "c2 must be >= 0");
  require(std::isfinite(leader_fitness_x) && leader_fitness_x > 1.0, "leader_fitness_x must be > 1");
  require(finitePositive(mutation_rate), "mutation_rate must be > 0");
  require(finitePositive(d_min_m), "d_min_m must be > 0 m");
  require(finitePositive(safety_scale_a), "safety_scale_a must be > 0 s/m");
  require(finitePositive(cpa_horizon_s), "cpa_horizon_s must be > 0 s");
  require(std::isfinite(min_alteration_deg) && min_alteration_deg >= 0.0, "min_alteration_deg must be >= 0");
  require(std::isfinite(max_alteration_deg) && max_alteration_deg >= min_alteration_deg,
          "max_alteration_deg must be >= min_alteration_deg");
  require(std::isfinite(search_alteration_deg) && search_alteration_deg >= min_alteration_deg &&
              search_alteration_deg <= 180.0,
          "search_alteration_deg must be in [min_alteration_deg, 180]");
  require(finitePositive(t_min_s), "t_min_s must be > 0 s");
  require(std::isfinite(t_max_s) && t_max_s > t_min_s, "t_max_s must be > t_min_s");
  require(std::isfinite(land_clearance_m) && land_clearance_m >= 0.0, "land_clearance_m must be >= 0 m");
  require(std::isfinite(selection_margin_m) && selection_margin_m >= 0.0,
          "selection_margin_m must be >= 0 m");
  require(finitePositive(min_speed_mps), "min_speed_mps must be > 0 m/s");
}

MopsoConfig MopsoConfig::paper() {
  MopsoConfig c;
  c.inflate = false;
  c.rule17c_pass = false;
  c.min_alteration_deg = 15.0;
  return c;
}

MopsoConfig MopsoConfig::fromParams(const ParamMap& p) {
  MopsoConfig c = plannerMode(p, "mopso") == PlannerMode::Paper ? paper() : MopsoConfig{};
  c.particles = p.getInt("particles", c.particles);
  c.generations = p.getInt("generations", c.generations);
  c.repository_size = p.getInt("repository_size", c.repository_size);
  c.grid_divisions = p.getInt("grid_divisions", c.grid_divisions);
  c.inertia = p.getDouble("inertia", c.inertia);
  c.c1 = p.getDouble("c1", c.c1);
  c.c2 = p.getDouble("c2", c.c2);
  c.leader_fitness_x = p.getDouble("leader_fitness_x", c.leader_fitness_x);
  c.mutation_rate = p.getDouble("mutation_rate", c.mutation_rate);
  c.d_min_m = p.getDouble("d_min_m", c.d_min_m);
  c.safety_scale_a = p.getDouble("safety_scale_a", c.safety_scale_a);
  c.cpa_horizon_s = p.getDouble("cpa_horizon_s", c.cpa_horizon_s);
  c.min_alteration_deg = p.getDouble("min_alteration_deg", c.min_alteration_deg);
  c.max_alteration_deg = p.getDouble("max_alteration_deg", c.max_alteration_deg);
  c.search_alteration_deg = p.getDouble("search_alteration_deg", c.search_alteration_deg);
  c.t_min_s = p.getDouble("t_min_s", c.t_min_s);
  c.t_max_s = p.getDouble("t_max_s", c.t_max_s);
  c.prefer_starboard = p.getBool("prefer_starboard", c.prefer_starboard);
  c.inflate = p.getBool("inflate", c.inflate);
  c.rule17c_pass = p.getBool("rule17c_pass", c.rule17c_pass);
  c.land_clearance_m = p.getDouble("land_clearance_m", c.land_clearance_m);
  c.selection_margin_m = p.getDouble("selection_margin_m", c.selection_margin_m);
  c.min_speed_mps = p.getDouble("min_speed_mps", c.min_speed_mps);
  p.rejectUnknown("mopso");
  c.validate();
  return c;
}

// ------------------------------------------------------------------------------------------------
// Geometry and objectives

EvasionPath evasionPath(const Eigen::Vector2d& a, double own_course, double speed, const Eigen::Vector2d& c,
                        double course_after_c, double alteration, double duration) {
  EvasionPath p;
  p.a = a;
  p.c = c;
  p.speed = speed;
  p.duration = duration;
  p.course_ab = wrapTwoPi(own_course + alteration);
  p.l_ab = speed * duration;
  p.vel_ab = courseSpeedToVelocity(p.course_ab, speed);
  p.b = a + p.vel_ab * duration;
  const Eigen::Vector2d bc = c - p.b;
  p.l_bc = bc.norm();
  p.l_ac = (c - a).norm();
  p.course_bc = p.l_bc > 0.0 ? courseOf(bc) : p.course_ab;
  p.vel_bc = p.l_bc > 0.0 ? Eigen::Vector2d(bc * (speed / p.l_bc)) : p.vel_ab;
  p.course_after_c = course_after_c;
  p.vel_after = courseSpeedToVelocity(course_after_c, speed);
  return p;
}

PathCpa pathCpa(const EvasionPath& path, const ShipState& target, double horizon) {
  const Eigen::Vector2d vt = target.velocity();
  const double t1 = path.duration;
  const double t2 = path.speed > 0.0 ? path.l_bc / path.speed : 0.0;
  struct Leg {
    double start;
    Eigen::Vector2d from, vel;
    double length;  // [s]
  };
  const Leg legs[3] = {
      {0.0, path.a, path.vel_ab, t1},
      {t1, path.b, path.vel_bc, t2},
      {t1 + t2, path.c, path.vel_after, std::numeric_limits<double>::infinity()},
  };
  PathCpa best;
  best.dcpa = std::numeric_limits<double>::infinity();
  for (const Leg& leg : legs) {
    if (leg.start > horizon)
      break;
    const double span = std::min(leg.length, horizon - leg.start);
    const Eigen::Vector2d r0 = target.position + vt * leg.start - leg.from;
    const Eigen::Vector2d w = vt - leg.vel;
    const double w2 = w.squaredNorm();
    const double s = w2 > 1e-12 ? std::clamp(-r0.dot(w) / w2, 0.0, span) : 0.0;
    const double d = (r0 + w * s).norm();
    if (d < best.dcpa) {
      best.dcpa = d;
      best.tcpa = leg.start + s;
    }
  }
  // The range is at its least right now: it opens from here on, the CPA lies in the past.
  best.opening = best.tcpa <= 0.0;
  return best;
}

double safetyTerm(const PathCpa& cpa, double d_min, double a) {
  if (cpa.dcpa >= d_min)
    return d_min - cpa.dcpa;  // eq. (8), first branch
  if (cpa.opening || cpa.tcpa <= 0.0)
    return -1.0;  // eq. (8) second branch as TCPA -> 0-: a past CPA is no risk (eq. (1) needs TCPA >= 0)
  constexpr double kMaxExponent = 50.0;
  return std::exp(std::min(a * (d_min - cpa.dcpa) / cpa.tcpa, kMaxExponent)) - 1.0;  // eq. (8)
}

double safetyObjective(const EvasionPath& path, const std::vector<PlannerTarget>& targets,
                       const MopsoConfig& cfg) {
  double f = -cfg.d_min_m;  // no target: as if every DCPA were 2 d_min
  bool any = false;
  for (const PlannerTarget& t : targets) {
    const double fi = safetyTerm(pathCpa(path, t.state, cfg.cpa_horizon_s), cfg.d_min_m, cfg.safety_scale_a);
    f = any ? std::max(f, fi) : fi;  // eq. (8): max over the targets
    any = true;
  }
  return f;
}

double smoothnessObjective(const EvasionPath& path) {
  return std::fabs(wrapPi(path.course_bc - path.course_ab));  // pi - angle ABC, see eq. (9) in the header
}

double huEq9Printed(double alteration, double speed, double duration, double l_ac) {
  const double d = std::fabs(alteration);
  const double vt = speed * duration;
  // atan2 keeps the angle at C right when B lies beyond C along AC (denominator < 0).
  return kPi - d - std::atan2(vt * std::sin(d), l_ac - vt * std::cos(d));
}

double pathLengthObjective(const EvasionPath& path) {
  return path.speed * path.duration + path.l_bc;  // eq. (10)
}

// ------------------------------------------------------------------------------------------------
// Constraints

double apparentAlterationViolation(double alteration, const MopsoConfig& cfg) {
  return std::max(0.0, degToRad(cfg.min_alteration_deg) - std::fabs(alteration));  // eq. (3)
}

double efficiencyViolation(double alteration, bool urgent, const MopsoConfig& cfg) {
  if (urgent)
    return 0.0;  // eq. (4) binds only "if risk = 1": in extremis any alteration may be needed
  return std::max(0.0, std::fabs(alteration) - degToRad(cfg.max_alteration_deg));
}

double durationViolation(double duration, const MopsoConfig& cfg) {
  return std::max(0.0, cfg.t_min_s - duration) + std::max(0.0, duration - cfg.t_max_s);  // eq. (5)
}

double starboardViolation(double alteration, const MopsoConfig& cfg) {
  return std::max(0.0, degToRad(cfg.min_alteration_deg) - alteration);  // eq. (6)
}

double safetyViolation(double f) {
  return std::max(0.0, f);  // eq. (11)
}

namespace {
// The length inside plus the clearance, or else the shortfall from it: continuous where the distance
// reaches 0. The distance is only asked for when nothing is inside.
template <class Inside, class Distance>
double violation(double clearance, Inside inside, Distance distance) {
  const double in = inside();
  return in > 0.0 ? in + clearance : std::max(0.0, clearance - distance());
}
}  // namespace

double landViolation(const Polygon& poly, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                     double clearance) {
  if (poly.size() < 3)
    return 0.0;
  // Cheap reject: bounding boxes more than the clearance apart.
  Eigen::Vector2d lo = poly[0], hi = poly[0];
  for (const auto& v : poly) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const Eigen::Vector2d slo = p.cwiseMin(q), shi = p.cwiseMax(q);
  if (slo.x() > hi.x() + clearance || shi.x() < lo.x() - clearance || slo.y() > hi.y() + clearance ||
      shi.y() < lo.y() - clearance)
    return 0.0;
  return violation(
      clearance, [&] { return segmentLengthInside(poly, p, q); },
      [&] { return segmentPolygonDistance(poly, p, q); });
}

double landViolation(const StaticObstacle& o, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                     double clearance) {
  if (!o.index)
    return landViolation(o.polygon, p, q, clearance);  // with its cheap box reject
  return violation(
      clearance, [&] { return o.index->lengthInside(p, q); },
      [&] { return o.index->boundaryDistance(p, q); });
}

// ------------------------------------------------------------------------------------------------
// Dominance, grid, repository

namespace {
inline bool paretoDominatesInline(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return a[0] <= b[0] && a[1] <= b[1] && a[2] <= b[2] && (a[0] < b[0] || a[1] < b[1] || a[2] < b[2]);
}
inline bool dominates(const MopsoEvaluation& a, const MopsoEvaluation& b) {
  const bool fa = a.feasible(), fb = b.feasible();
  if (fa != fb)
    return fa;
  if (!fa && a.violation != b.violation)
    return a.violation < b.violation;
  return paretoDominatesInline(a.objectives, b.objectives);
}
}  // namespace

bool paretoDominates(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return paretoDominatesInline(a, b);
}

bool constrainedDominates(const MopsoEvaluation& a, const MopsoEvaluation& b) {
  return dominates(a, b);
}

void AdaptiveGrid::rebuild(const std::vector<std::array<double, 3>>& points) {
  if (points.empty()) {
    built_ = false;
    return;
  }
  lo_ = hi_ = points[0];
  for (const auto& p : points)
    for (size_t k = 0; k < 3; ++k) {
      lo_[k] = std::min(lo_[k], p[k]);
      hi_[k] = std::max(hi_[k], p[k]);
    }
  for (size_t k = 0; k < 3; ++k) {
    double span = hi_[k] - lo_[k];
    if (!(span > 1e-12 * std::max(1.0, std::fabs(lo_[k]))))
      span = 1e-6 * std::max(1.0, std::fabs(lo_[k]));  // one value only: any width puts it mid-grid
    const double half_cell = 0.5 * span / divisions_;
    lo_[k] -= half_cell;
    hi_[k] += half_cell;
  }
  built_ = true;
}

bool AdaptiveGrid::contains(const std::array<double, 3>& p) const {
  if (!built_)
    return false;
  for (size_t k = 0; k < 3; ++k)
    if (!(p[k] >= lo_[k] && p[k] <= hi_[k]))
      return false;
  return true;
}

int AdaptiveGrid::cubeOf(const std::array<double, 3>& p) const {
  int index = 0;
  for (int k = 2; k >= 0; --k) {
    const double u = (p[k] - lo_[k]) / (hi_[k] - lo_[k]);
    int i = static_cast<int>(std::floor(u * divisions_));
    i = std::clamp(i, 0, divisions_ - 1);
    index = index * divisions_ + i;
  }
  return index;
}

void MopsoRepository::regrid() {
  std::vector<std::array<double, 3>> pts;
  pts.reserve(members_.size());
  for (const auto& m : members_)
    pts.push_back(m.eval.objectives);
  grid_.rebuild(pts);
  roulette_valid_ = false;
  cube_.resize(members_.size());
  for (size_t i = 0; i < members_.size(); ++i)
    cube_[i] = grid_.cubeOf(members_[i].eval.objectives);
}

int MopsoRepository::density(size_t i) const {
  return static_cast<int>(std::count(cube_.begin(), cube_.end(), cube_.at(i)));
}

bool MopsoRepository::add(const MopsoSolution& s) {
  // One pass: the archive is mutually non-dominated and the relation is transitive, so once s has
  // dominated a member no other member can dominate s.
  size_t w = 0;
  for (size_t i = 0; i < members_.size(); ++i) {
    const MopsoEvaluation& m = members_[i].eval;
    if (w == i &&
        (dominates(m, s.eval) || (m.objectives == s.eval.objectives && m.violation == s.eval.violation)))
      return false;
    if (dominates(s.eval, m))
      continue;
    if (w != i) {
      members_[w] = members_[i];
      cube_[w] = cube_[i];
    }
    ++w;
  }
  members_.resize(w);
  cube_.resize(w);
  members_.push_back(s);
  roulette_valid_ = false;
  // Coello et al. IV-A: the grid is recomputed only when a newcomer lies outside it.
  if (grid_.contains(s.eval.objectives))
    cube_.push_back(grid_.cubeOf(s.eval.objectives));
  else
    regrid();
  return true;
}

void MopsoRepository::truncate(std::mt19937_64& rng) {
  if (static_cast<int>(members_.size()) <= capacity_)
    return;
  std::vector<int> sorted = cube_;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::pair<int, int>> counts;  // (cube, occupancy), by cube
  for (int c : sorted) {
    if (counts.empty() || counts.back().first != c)
      counts.push_back({c, 0});
    ++counts.back().second;
  }
  while (static_cast<int>(members_.size()) > capacity_) {
    size_t worst = 0;
    for (size_t k = 1; k < counts.size(); ++k)
      if (counts[k].second > counts[worst].second)
        worst = k;
    const int cube = counts[worst].first;
    size_t nth = uniformIndex(rng, static_cast<size_t>(counts[worst].second));
    size_t victim = 0;
    for (size_t i = 0; i < cube_.size(); ++i)
      if (cube_[i] == cube && nth-- == 0) {
        victim = i;
        break;
      }
    members_.erase(members_.begin() + static_cast<long>(victim));
    cube_.erase(cube_.begin() + static_cast<long>(victim));
    --counts[worst].second;
  }
  roulette_valid_ = false;
}

bool MopsoRepository::insert(const MopsoSolution& s, std::mt19937_64& rng) {
  if (!add(s))
    return false;
  truncate(rng);
  for (const auto& m : members_)
    if (m.alteration == s.alteration && m.duration == s.duration && m.eval.objectives == s.eval.objectives)
      return true;
  return false;
}

void MopsoRepository::insertAll(const std::vector<MopsoSolution>& batch, std::mt19937_64& rng) {
  for (const MopsoSolution& s : batch)
    add(s);
  truncate(rng);
}

const MopsoSolution& MopsoRepository::selectLeader(double x, std::mt19937_64& rng) const {
  if (!roulette_valid_ || roulette_x_ != x) {
    by_cube_.resize(cube_.size());
    for (size_t i = 0; i < cube_.size(); ++i)
      by_cube_[i] = {cube_[i], static_cast<int>(i)};
    std::sort(by_cube_.begin(), by_cube_.end());
    runs_.clear();
    roulette_total_ = 0.0;
    for (size_t i = 0; i < by_cube_.size();) {
      size_t j = i;
      while (j < by_cube_.size() && by_cube_[j].first == by_cube_[i].first)
        ++j;
      runs_.push_back({i, j});
      roulette_total_ += x / static_cast<double>(j - i);  // hypercube fitness, Coello et al. IV-A
      i = j;
    }
    roulette_x_ = x;
    roulette_valid_ = true;
  }
  double r = uniform01(rng) * roulette_total_;
  size_t pick = runs_.size() - 1;
  for (size_t k = 0; k < runs_.size(); ++k) {
    r -= x / static_cast<double>(runs_[k].second - runs_[k].first);
    if (r < 0.0) {
      pick = k;
      break;
    }
  }
  const auto& run = runs_[pick];
  return members_[by_cube_[run.first + uniformIndex(rng, run.second - run.first)].second];
}

// ------------------------------------------------------------------------------------------------
// Rule selection

const char* toString(HuAction a) {
  switch (a) {
    case HuAction::StandOn:
      return "stand_on";
    case HuAction::GiveWay:
      return "give_way";
    case HuAction::Rule2Evade:
      return "rule_2b_evade";
    case HuAction::None:
      break;
  }
  return "none";
}

RuleSelection selectRule(const PlanningProblem& problem, const MopsoConfig& cfg) {
  RuleSelection sel;
  int rule2 = -1, give_way = -1, stand_on = -1;
  auto earlier = [&](int cur, int i) {
    return cur < 0 || problem.targets[i].tcpa < problem.targets[cur].tcpa ? i : cur;
  };
  for (size_t k = 0; k < problem.targets.size(); ++k) {
    const PlannerTarget& t = problem.targets[k];
    const int i = static_cast<int>(k);
    if (t.risk == RiskLevel::Urgent)
      sel.urgent = true;
    switch (ruleDecision(t.risk, t.compliant)) {
      case RuleDecision::Rule2:
        rule2 = earlier(rule2, i);
        break;
      case RuleDecision::RuleApplies:
        // Fig. 1 zones through the role. A target at risk with no COLREGs role (static, unclassified)
        // gives the own ship no stand-on privilege: it keeps out of the way.
        if (t.role == OwnRole::StandOn)
          stand_on = earlier(stand_on, i);
        else
          give_way = earlier(give_way, i);
        break;
      case RuleDecision::NoRule:
        break;
    }
  }
  auto name = [&](int i) { return problem.targets[i].state.id; };
  if (rule2 >= 0) {
    sel.action = HuAction::Rule2Evade;
    sel.target = rule2;
    sel.reason = "Rule 2(b): target '" + name(rule2) + "' is non-compliant at risk 2 (Table 1 x); evade";
  } else if (give_way >= 0) {
    const PlannerTarget& t = problem.targets[give_way];
    sel.action = HuAction::GiveWay;
    sel.target = give_way;
    sel.reason =
        "give-way to '" + name(give_way) + "' (" + toString(t.encounter) + ", risk " + toString(t.risk) + ")";
  } else if (stand_on >= 0) {
    sel.action = HuAction::StandOn;
    sel.target = stand_on;
    sel.reason = "stand-on (Rule 17) for '" + name(stand_on) + "': keep course and speed";
  } else {
    // Section 2: re-planning also starts when an obstacle lies between two waypoints.
    const Eigen::Vector2d a = problem.own.position;
    const Eigen::Vector2d c = nextWayPoint(problem);
    for (const StaticObstacle& o : problem.obstacles)
      if (obstacleLengthInside(o, a, c) > 0.0) {
        sel.action = HuAction::GiveWay;
        sel.reason = "static obstacle '" + o.name + "' on the route";
        return sel;
      }
    sel.reason = "no risk of collision (Table 1 +): follow the route";
  }
  (void)cfg;
  return sel;
}

// ------------------------------------------------------------------------------------------------
// Evaluation

MopsoContext makeContext(const PlanningProblem& problem, const MopsoConfig& cfg, bool urgent) {
  MopsoContext ctx;
  ctx.a = problem.own.position;
  ctx.c = nextWayPoint(problem);
  ctx.own_course = problem.own.course;
  ctx.speed = problem.own.speed >= cfg.min_speed_mps ? problem.own.speed : problem.limits.max_speed;
  // After C the ship follows its route on: to the waypoint after C, else on along A->C.
  Eigen::Vector2d after = ctx.c - ctx.a;
  if (problem.route.size() >= 2)
    after = problem.route[1] - problem.route[0];
  else if (problem.route.size() == 1)
    after = problem.goal - problem.route[0];
  if (after.squaredNorm() <= 0.0)
    after = ctx.c - ctx.a;
  ctx.course_after_c = after.squaredNorm() > 0.0 ? courseOf(after) : ctx.own_course;
  ctx.urgent = urgent;
  ctx.impose_starboard = cfg.prefer_starboard;
  ctx.targets = &problem.targets;
  ctx.obstacles = &problem.obstacles;
  ctx.has_bounds = problem.has_bounds;
  ctx.bounds_min = problem.bounds_min;
  ctx.bounds_max = problem.bounds_max;
  return ctx;
}

MopsoEvaluation evaluateCandidate(double alteration, double duration, const MopsoContext& ctx,
                                  const MopsoConfig& cfg) {
  const EvasionPath path =
      evasionPath(ctx.a, ctx.own_course, ctx.speed, ctx.c, ctx.course_after_c, alteration, duration);
  MopsoEvaluation e;
  static const std::vector<PlannerTarget> kNone;
  e.objectives[0] = safetyObjective(path, ctx.targets ? *ctx.targets : kNone, cfg);
  e.objectives[1] = smoothnessObjective(path);
  e.objectives[2] = pathLengthObjective(path);

  double v = apparentAlterationViolation(alteration, cfg) + efficiencyViolation(alteration, ctx.urgent, cfg) +
             durationViolation(duration, cfg) / cfg.t_max_s + safetyViolation(e.objectives[0]);
  if (ctx.impose_starboard)
    v += starboardViolation(alteration, cfg);
  double land = 0.0;
  if (ctx.obstacles)
    for (const StaticObstacle& o : *ctx.obstacles)
      land += landViolation(o, path.a, path.b, cfg.land_clearance_m) +
              landViolation(o, path.b, path.c, cfg.land_clearance_m);
  if (ctx.has_bounds) {
    const Eigen::Vector2d out =
        (ctx.bounds_min - path.b).cwiseMax(0.0) + (path.b - ctx.bounds_max).cwiseMax(0.0);
    land += out.norm();
  }
  e.violation = v + land / cfg.d_min_m;
  return e;
}

int selectFromFront(const std::vector<MopsoSolution>& front, const MopsoConfig& cfg) {
  int best_margin = -1, safest = -1;
  for (size_t k = 0; k < front.size(); ++k) {
    const MopsoSolution& s = front[k];
    if (!s.eval.feasible())
      continue;
    const int i = static_cast<int>(k);
    if (safest < 0 || s.f() < front[safest].f())
      safest = i;
    if (s.f() <= -cfg.selection_margin_m) {
      const MopsoSolution* b = best_margin >= 0 ? &front[best_margin] : nullptr;
      if (!b || s.h() < b->h() || (s.h() == b->h() && s.g() < b->g()))
        best_margin = i;
    }
  }
  return best_margin >= 0 ? best_margin : safest;
}

// Rule 17(c): a stand-on ship that must act (here Rule 2(b) against a give-way target that did not)
// shall not, if the circumstances admit, alter to port for a vessel on her own port side. When the
// starboard pass found nothing that keeps d_min and the Rule 2(b) target is on the port side, the
// starboard solution of that pass that passes every target farthest is kept, provided it keeps the
// situation's minimum separation (d_safe without one); only when none does may the port pass run
// (Rule 17(b): whatever best aids to avoid collision). Returns its index in `front`, or -1.
namespace {
int rule17cStarboard(const PlanningProblem& problem, const RuleSelection& rule, const MopsoContext& ctx,
                     const MopsoConfig& cfg, const std::vector<MopsoSolution>& front) {
  if (rule.action != HuAction::Rule2Evade || rule.target < 0)
    return -1;
  const PlannerTarget& t = problem.targets[static_cast<size_t>(rule.target)];
  if (relativeBearing(problem.own, t.state.position) <= kPi)
    return -1;  // not on the port side
  const double keep = problem.min_separation > 0.0 ? problem.min_separation : HuRiskConfig{}.d_safe_m;
  int best = -1;
  double best_dcpa = keep;
  for (size_t k = 0; k < front.size(); ++k) {
    const MopsoSolution& s = front[k];
    if (s.alteration <= 0.0)
      continue;
    const EvasionPath path =
        evasionPath(ctx.a, ctx.own_course, ctx.speed, ctx.c, ctx.course_after_c, s.alteration, s.duration);
    double dcpa = std::numeric_limits<double>::infinity();
    for (const PlannerTarget& o : problem.targets)
      dcpa = std::min(dcpa, pathCpa(path, o.state, cfg.cpa_horizon_s).dcpa);
    if (dcpa >= best_dcpa) {
      best_dcpa = dcpa;
      best = static_cast<int>(k);
    }
  }
  return best;
}
}  // namespace

// ------------------------------------------------------------------------------------------------
// Planner

MopsoPlanner::MopsoPlanner(const MopsoConfig& cfg) : cfg_(cfg) {
  cfg_.validate();
}

void MopsoPlanner::configure(const ParamMap& params) {
  cfg_ = MopsoConfig::fromParams(params);
}

std::vector<MopsoSolution> MopsoPlanner::optimise(const MopsoContext& ctx, const MopsoConfig& cfg,
                                                  uint64_t seed, const Deadline& deadline,
                                                  MopsoResult& stats) const {
  std::mt19937_64 rng(seed);
  const double dmax = degToRad(cfg.search_alteration_deg);
  const std::array<double, 2> lo{{-dmax, cfg.t_min_s}}, hi{{dmax, cfg.t_max_s}};
  const size_t n = static_cast<size_t>(cfg.particles);

  struct Particle {
    std::array<double, 2> x, v, best;
    MopsoEvaluation eval, best_eval;
  };
  std::vector<Particle> swarm(n);
  MopsoRepository repo(cfg.repository_size, cfg.grid_divisions);
  auto solution = [](const std::array<double, 2>& x, const MopsoEvaluation& e) {
    MopsoSolution s;
    s.alteration = x[0];
    s.duration = x[1];
    s.eval = e;
    return s;
  };

  // Coello et al. Fig. 1 steps 1-5: random positions, zero velocities, archive, pbest = position.
  for (Particle& p : swarm) {
    for (size_t d = 0; d < 2; ++d) {
      p.x[d] = uniform(rng, lo[d], hi[d]);
      p.v[d] = 0.0;
    }
    p.eval = evaluateCandidate(p.x[0], p.x[1], ctx, cfg);
    ++stats.evaluations;
    p.best = p.x;
    p.best_eval = p.eval;
  }
  std::vector<MopsoSolution> batch;
  batch.reserve(n);
  // Only the swarm's own non-dominated positions can enter the archive: filtering them first saves
  // most of the archive comparisons.
  std::vector<size_t> cand;
  cand.reserve(n);
  auto archive = [&]() {
    // Once anything feasible exists, no infeasible position can be non-dominated.
    bool any_feasible = !repo.members().empty() && repo.members().front().eval.feasible();
    for (const Particle& p : swarm)
      any_feasible = any_feasible || p.eval.feasible();
    cand.clear();
    for (size_t i = 0; i < n; ++i)
      if (!any_feasible || swarm[i].eval.feasible())
        cand.push_back(i);
    batch.clear();
    for (size_t i : cand) {
      bool dominated = false;
      for (size_t j : cand)
        if (j != i && dominates(swarm[j].eval, swarm[i].eval)) {
          dominated = true;
          break;
        }
      if (!dominated)
        batch.push_back(solution(swarm[i].x, swarm[i].eval));
    }
    repo.insertAll(batch, rng);
  };
  archive();

  const double gens = std::max(1, cfg.generations);
  for (int gen = 0; gen < cfg.generations; ++gen) {
    if (deadline.expired())
      break;
    // Mutation of Coello et al. IV-C: probability and reach both shrink as (1 - gen/G)^(5/pM).
    const double shrink = std::pow(1.0 - gen / gens, 5.0 / cfg.mutation_rate);
    for (Particle& p : swarm) {
      const MopsoSolution& leader = repo.selectLeader(cfg.leader_fitness_x, rng);
      const std::array<double, 2> lx{{leader.alteration, leader.duration}};
      for (size_t d = 0; d < 2; ++d) {
        const double r1 = uniform01(rng), r2 = uniform01(rng);
        // Step 6(a): VEL = W VEL + R1 (PBEST - POP) + R2 (REP[h] - POP).
        p.v[d] = cfg.inertia * p.v[d] + cfg.c1 * r1 * (p.best[d] - p.x[d]) + cfg.c2 * r2 * (lx[d] - p.x[d]);
        p.x[d] += p.v[d];
        // Step 6(c): a particle leaving the box takes the boundary value and reverses its velocity.
        if (p.x[d] < lo[d]) {
          p.x[d] = lo[d];
          p.v[d] = -p.v[d];
        } else if (p.x[d] > hi[d]) {
          p.x[d] = hi[d];
          p.v[d] = -p.v[d];
        }
      }
      if (uniform01(rng) < shrink) {
        const size_t d = uniformIndex(rng, 2);
        const double reach = (hi[d] - lo[d]) * shrink;
        p.x[d] = uniform(rng, std::max(lo[d], p.x[d] - reach), std::min(hi[d], p.x[d] + reach));
      }
      p.eval = evaluateCandidate(p.x[0], p.x[1], ctx, cfg);
      ++stats.evaluations;
    }
    // Step 6(f)-(g): archive the new non-dominated positions (the grid adapts inside insert).
    archive();
    // Step 6(h): personal best; when neither dominates, either one at random.
    for (Particle& p : swarm) {
      if (dominates(p.eval, p.best_eval) || (!dominates(p.best_eval, p.eval) && uniform01(rng) < 0.5)) {
        p.best = p.x;
        p.best_eval = p.eval;
      }
    }
    ++stats.generations_run;
  }
  std::vector<MopsoSolution> front = repo.members();
  std::sort(front.begin(), front.end(), [](const MopsoSolution& a, const MopsoSolution& b) {
    if (a.eval.feasible() != b.eval.feasible())
      return a.eval.feasible();
    if (a.h() != b.h())
      return a.h() < b.h();
    if (a.g() != b.g())
      return a.g() < b.g();
    return a.f() < b.f();
  });
  return front;
}

Plan MopsoPlanner::plan(const PlanningProblem& problem) {
  // d_min of eq. (8) is at least the situation's demanded passing distance (planning.h).
  MopsoConfig cfg = cfg_;
  cfg.d_min_m = cappedPassing(cfg.d_min_m, problem);  // restricted waters (planning.h)
  if (cfg.inflate)
    cfg.d_min_m = std::max(cfg.d_min_m, kSeparationMargin * std::max(0.0, problem.min_separation));
  const Deadline deadline(problem.time_budget);
  last_ = MopsoResult{};
  Plan out;
  last_.rule = selectRule(problem, cfg);
  const RuleSelection& rule = last_.rule;
  const MopsoContext base = makeContext(problem, cfg, rule.urgent);
  const double v = base.speed;

  if (rule.action == HuAction::None || rule.action == HuAction::StandOn) {
    // Stand-on (Rule 17(a)(i)): keep course and speed, one leg on the present course as long as the
    // way to C. No risk: follow the route, i.e. head for C (section 2: the evasion path A-B-C ends on
    // the route; "keep course" after an evasion would leave the ship on its evasion leg for good).
    const double l_ac = (base.c - base.a).norm();
    const double horizon = l_ac > 0.0 ? l_ac / v : cfg.cpa_horizon_s;
    const double course =
        rule.action == HuAction::None && l_ac > 1.0 ? courseOf(base.c - base.a) : problem.own.course;
    PlannedWaypoint a{base.a, 0.0, course, v};
    PlannedWaypoint ahead{base.a + courseSpeedToVelocity(course, v * horizon), horizon, course, v};
    out.waypoints = {a, ahead};
    out.status = PlanStatus::Ok;
    out.course_setpoint = course;
    out.speed_setpoint = v;
    out.cost = 0.0;
    out.message = rule.reason;
    out.compute_time = deadline.elapsed();
    return out;
  }

  MopsoContext ctx = base;
  ctx.impose_starboard = cfg.prefer_starboard;
  last_.pass = 1;
  last_.pareto_front = optimise(ctx, cfg, problem.seed, deadline, last_);
  int idx = selectFromFront(last_.pareto_front, cfg);
  if (idx < 0 && cfg.prefer_starboard && cfg.rule17c_pass) {
    idx = rule17cStarboard(problem, rule, ctx, cfg, last_.pareto_front);
    if (idx >= 0)
      last_.pass = 3;
  }
  if (idx < 0 && cfg.prefer_starboard) {
    // Section 2.3: no feasible starboard manoeuvre, so (6) is relaxed and port is allowed.
    ctx.impose_starboard = false;
    last_.pass = 2;
    last_.pareto_front = optimise(ctx, cfg, problem.seed ^ 0x9E3779B97F4A7C15ULL, deadline, last_);
    idx = selectFromFront(last_.pareto_front, cfg);
  }
  bool feasible = idx >= 0 && last_.pareto_front[idx].eval.feasible();
  if (last_.pass == 3)
    feasible = true;  // inside d_min by Rule 17(c)'s choice, outside the minimum separation
  if (!feasible && !last_.pareto_front.empty())
    idx = 0;  // least violation: the archive holds only the least-violating solutions when none is feasible
  if (idx < 0) {
    out.status = PlanStatus::NoSolution;
    out.message = rule.reason + "; no candidate evaluated";
    out.compute_time = deadline.elapsed();
    return out;
  }
  last_.chosen = idx;
  const MopsoSolution& s = last_.pareto_front[idx];
  const EvasionPath path =
      evasionPath(ctx.a, ctx.own_course, v, ctx.c, ctx.course_after_c, s.alteration, s.duration);
  out.waypoints = {PlannedWaypoint{path.a, 0.0, problem.own.course, v},
                   PlannedWaypoint{path.b, path.duration, path.course_ab, v},
                   PlannedWaypoint{path.c, path.duration + path.l_bc / v, path.course_bc, v}};
  out.course_setpoint = path.course_ab;
  out.speed_setpoint = v;
  out.cost = s.h();
  out.status = feasible ? PlanStatus::Ok : PlanStatus::Fallback;
  std::ostringstream m;
  m.precision(4);
  m << rule.reason << "; " << (s.alteration >= 0.0 ? "starboard " : "port ")
    << radToDeg(std::fabs(s.alteration)) << " deg for " << s.duration << " s (f " << s.f() << ", g " << s.g()
    << " rad, h " << s.h() << " m); pass " << last_.pass;
  if (last_.pass == 1)
    m << " (eq. 6 imposed)";
  else if (last_.pass == 3)
    m << " (Rule 17(c): no turn to port for a ship on the port side)";
  else
    m << " (eq. 6 relaxed)";
  if (!feasible)
    m << "; no feasible solution, least-violation plan (violation " << s.eval.violation << ")";
  out.message = m.str();
  out.compute_time = deadline.elapsed();
  return out;
}

}  // namespace asv
