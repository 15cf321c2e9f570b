// ACO trajectory planner, Lazarowska (2015). Equation numbers refer to that paper.
#include "asv_core/planning/aco/aco_planner.h"
#include "asv_core/common/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>

namespace asv {

namespace {

constexpr int kMaxLateralSteps = 16;
constexpr int kMaxRows = 1000;  // keeps the lattice (and the pheromone table) bounded
// Longest long edge in rows: with lateral_steps <= kMaxLongEdgeSteps it bounds the neighbourhood of a
// vertex to 32 x (32 K + 1) + 32 options (1088 for K = 1, 4192 for K = 4).
constexpr int kMaxLongEdgeRows = 32;
constexpr int kMaxLongEdgeSteps = 4;
// Paper mode's grid cell [m] (square; AcoConfig::paper): see the header's long_edges.
constexpr double kLazarowskaCell = 0.75 * 1852.0;
constexpr double kStraightTol = 1e-9;   // [rad] course change below which a leg continues the last
constexpr double kMinLegLength = 1e-6;  // [m]

// q uniform in [0, 1) from the raw 64-bit stream: std::uniform_real_distribution is not specified
// bit-exactly across standard libraries, this is.
double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

Eigen::Vector2d unitOfCourse(double course) {
  return {std::sin(course), std::cos(course)};
}

void require(bool ok, const char* what) {
  if (!ok)
    throw std::invalid_argument(std::string("AcoConfig: ") + what);
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// Configuration

void AcoConfig::validate() const {
  require(std::isfinite(tau0) && tau0 > 0.0, "tau0 must be > 0");
  require(std::isfinite(rho) && rho > 0.0 && rho <= 1.0, "rho must be in (0, 1]");
  require(std::isfinite(alpha) && alpha >= 0.0, "alpha must be >= 0");
  require(std::isfinite(beta) && beta >= 0.0, "beta must be >= 0");
  require(iterations >= 1, "iterations must be >= 1");
  require(std::isfinite(colregs_factor) && colregs_factor >= 1.0, "colregs_factor must be >= 1");
  require(ants >= 1, "ants must be >= 1");
  require(std::isfinite(deposit) && deposit >= 0.0, "deposit must be >= 0");
  require(std::isfinite(row_spacing) && row_spacing > 0.0, "row_spacing_m must be > 0");
  require(std::isfinite(column_spacing) && column_spacing > 0.0, "column_spacing_m must be > 0");
  require(lateral_steps >= 1 && lateral_steps <= kMaxLateralSteps, "lateral_steps must be in 1..16");
  require(std::isfinite(half_width) && half_width >= 0.0, "half_width_m must be >= 0");
  require(!long_edges || lateral_steps <= kMaxLongEdgeSteps, "lateral_steps must be in 1..4 with long_edges");
  require(std::isfinite(max_alteration) && max_alteration > 0.0 && max_alteration <= degToRad(120.0) + 1e-12,
          "max_alteration_deg must be in (0, 120]");
  require(std::isfinite(min_first_alteration) && min_first_alteration >= 0.0 &&
              min_first_alteration <= max_alteration,
          "min_first_alteration_deg must be in [0, max_alteration_deg]");
  require(std::isfinite(max_time) && max_time >= 0.0, "max_time_s must be >= 0");
  domain.validate();
}

AcoConfig AcoConfig::paper() {
  AcoConfig c;
  c.min_first_alteration = 0.0;
  c.smooth = false;
  c.row_spacing = c.column_spacing = kLazarowskaCell;
  c.lateral_steps = 1;
  c.long_edges = true;
  c.danger_by_course = true;
  c.colregs_factor = 1.0;
  c.inflate = false;
  return c;
}

AcoConfig AcoConfig::fromParams(const ParamMap& params) {
  AcoConfig c = plannerMode(params, "aco") == PlannerMode::Paper ? paper() : AcoConfig{};
  c.tau0 = params.getDouble("tau0", c.tau0);
  c.rho = params.getDouble("rho", c.rho);
  c.alpha = params.getDouble("alpha", c.alpha);
  c.beta = params.getDouble("beta", c.beta);
  c.iterations = params.getInt("iterations", c.iterations);
  c.ants = params.getInt("ants", c.ants);
  c.deposit = params.getDouble("deposit", c.deposit);
  c.row_spacing = params.getDouble("row_spacing_m", c.row_spacing);
  c.column_spacing = params.getDouble("column_spacing_m", c.column_spacing);
  c.lateral_steps = params.getInt("lateral_steps", c.lateral_steps);
  c.half_width = params.getDouble("half_width_m", c.half_width);
  c.long_edges = params.getBool("long_edges", c.long_edges);
  c.danger_by_course = params.getBool("danger_by_course", c.danger_by_course);
  c.min_first_alteration =
      degToRad(params.getDouble("min_first_alteration_deg", radToDeg(c.min_first_alteration)));
  c.max_alteration = degToRad(params.getDouble("max_alteration_deg", radToDeg(c.max_alteration)));
  c.smooth = params.getBool("smooth", c.smooth);
  c.max_time = params.getDouble("max_time_s", c.max_time);
  c.domain.a = params.getDouble("domain_a_m", c.domain.a);
  c.domain.b = params.getDouble("domain_b_m", c.domain.b);
  c.domain.c = params.getDouble("domain_c_m", c.domain.c);
  c.domain.d = params.getDouble("domain_d_m", c.domain.d);
  c.domain.e = params.getDouble("domain_e_m", c.domain.e);
  c.colregs_factor = params.getDouble("colregs_factor", c.colregs_factor);
  c.inflate = params.getBool("inflate", c.inflate);
  params.rejectUnknown("aco");
  c.validate();
  return c;
}

// ---------------------------------------------------------------------------------------------------
// Environment, eq. (1)-(3)

namespace {

// The hexagon in the target frame (x starboard, y forward) is the ENU polygon of a ship at the origin
// heading north. With a, b, c, d, e > 0 and b < a it is convex, so a segment meets it iff clipping the
// segment by its six half-planes leaves something (Cyrus-Beck).
template <typename Target>
void setDomain(const HexagonDomainConfig& domain, Target& mt) {
  Polygon poly = HexagonDomain(domain).polygon({0.0, 0.0}, 0.0);
  double area2 = 0.0;
  for (size_t i = 0; i < poly.size(); ++i)
    area2 += cross2(poly[i], poly[(i + 1) % poly.size()]);
  if (area2 < 0.0)
    std::reverse(poly.begin(), poly.end());
  mt.lo = mt.hi = poly.front();
  for (int i = 0; i < 6; ++i) {
    const Eigen::Vector2d e = poly[(i + 1) % 6] - poly[i];
    const Eigen::Vector2d out(e.y(), -e.x());  // outward normal of a counter-clockwise polygon
    if (cross2(e, poly[(i + 2) % 6] - poly[(i + 1) % 6]) < 0.0)
      throw std::invalid_argument("AcoEnvironment: the hexagon domain is not convex");
    mt.normal.col(i) = out;
    mt.offset(i) = out.dot(poly[i]);
    mt.lo = mt.lo.cwiseMin(poly[i]);
    mt.hi = mt.hi.cwiseMax(poly[i]);
  }
}

}  // namespace

HexagonDomainConfig targetDomain(const PlannerTarget& t, const HexagonDomainConfig& domain,
                                 double colregs_factor) {
  // By the encounter alone, not the risk level: a plan made before the risk is established (a
  // predicted close pass) must already leave the target on the side the rules will want.
  if (colregs_factor == 1.0 ||
      (t.encounter != Encounter::HeadOn && t.encounter != Encounter::CrossingGiveWay))
    return domain;
  HexagonDomainConfig give_way = domain;
  give_way.a *= colregs_factor;
  give_way.c *= colregs_factor;
  return give_way;
}

AcoEnvironment::AcoEnvironment(const PlanningProblem& problem, const HexagonDomainConfig& domain,
                               double colregs_factor)
    : has_bounds_(problem.has_bounds), bounds_min_(problem.bounds_min), bounds_max_(problem.bounds_max) {
  for (const auto& o : problem.obstacles) {
    if (o.polygon.size() < 2)
      continue;
    Obstacle ob;
    ob.shape = o;
    ob.lo = ob.hi = o.polygon.front();
    for (const auto& v : o.polygon) {
      ob.lo = ob.lo.cwiseMin(v);
      ob.hi = ob.hi.cwiseMax(v);
    }
    obstacles_.push_back(std::move(ob));
  }
  for (const auto& t : problem.targets) {
    MovingTarget mt;
    mt.p0 = t.state.position;
    mt.v = t.state.velocity();
    // The domain turns with the target's course (it keeps it, section 2.2).
    mt.sin_c = std::sin(t.state.course);
    mt.cos_c = std::cos(t.state.course);
    setDomain(targetDomain(t, domain, colregs_factor), mt);
    targets_.push_back(mt);
  }
}

int AcoEnvironment::obstacleAt(const Eigen::Vector2d& p) const {
  for (size_t i = 0; i < obstacles_.size(); ++i) {
    const auto& o = obstacles_[i];
    if (p.x() < o.lo.x() || p.y() < o.lo.y() || p.x() > o.hi.x() || p.y() > o.hi.y())
      continue;
    if (insideObstacle(o.shape, p))
      return static_cast<int>(i);
  }
  return -1;
}

bool AcoEnvironment::pointStaticFree(const Eigen::Vector2d& p) const {
  if (has_bounds_ && (p.x() < bounds_min_.x() || p.y() < bounds_min_.y() || p.x() > bounds_max_.x() ||
                      p.y() > bounds_max_.y()))
    return false;
  return obstacleAt(p) < 0;
}

bool AcoEnvironment::segmentStaticFree(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
  // E is a rectangle (eq. 1), convex: both ends inside keeps the segment inside.
  if (!pointStaticFree(a) || !pointStaticFree(b))
    return false;
  const Eigen::Vector2d lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  for (const auto& o : obstacles_) {
    if (hi.x() < o.lo.x() || hi.y() < o.lo.y() || lo.x() > o.hi.x() || lo.y() > o.hi.y())
      continue;
    if (o.shape.index) {
      if (obstacleBoundaryDistance(o.shape, a, b) <= 0.0)
        return false;
      continue;
    }
    const Polygon& poly = o.shape.polygon;
    const size_t n = poly.size();
    for (size_t i = 0, j = n - 1; i < n; j = i++)
      if (segmentsIntersect(a, b, poly[j], poly[i]))
        return false;
  }
  return true;
}

bool AcoEnvironment::hitsTarget(const MovingTarget& tg, const Eigen::Vector2d& a, double ta,
                                const Eigen::Vector2d& b, double tb) const {
  const Eigen::Vector2d ra = a - (tg.p0 + tg.v * ta);
  const Eigen::Vector2d rb = b - (tg.p0 + tg.v * tb);
  const Eigen::Vector2d la(ra.x() * tg.cos_c - ra.y() * tg.sin_c, ra.x() * tg.sin_c + ra.y() * tg.cos_c);
  const Eigen::Vector2d lb(rb.x() * tg.cos_c - rb.y() * tg.sin_c, rb.x() * tg.sin_c + rb.y() * tg.cos_c);
  if ((la.x() > tg.hi.x() && lb.x() > tg.hi.x()) || (la.x() < tg.lo.x() && lb.x() < tg.lo.x()) ||
      (la.y() > tg.hi.y() && lb.y() > tg.hi.y()) || (la.y() < tg.lo.y() && lb.y() < tg.lo.y()))
    return false;
  const Eigen::Vector2d d = lb - la;
  double u0 = 0.0, u1 = 1.0;
  for (int i = 0; i < 6; ++i) {
    const double num = tg.offset(i) - tg.normal.col(i).dot(la);
    const double den = tg.normal.col(i).dot(d);
    if (den == 0.0) {
      if (num < 0.0)
        return false;
      continue;
    }
    const double u = num / den;
    if (den > 0.0)
      u1 = std::min(u1, u);
    else
      u0 = std::max(u0, u);
    if (u0 > u1)
      return false;
  }
  return true;
}

bool AcoEnvironment::segmentHitsTarget(size_t j, const Eigen::Vector2d& a, double ta,
                                       const Eigen::Vector2d& b, double tb) const {
  return hitsTarget(targets_.at(j), a, ta, b, tb);
}

bool AcoEnvironment::segmentDynamicFree(const Eigen::Vector2d& a, double ta, const Eigen::Vector2d& b,
                                        double tb) const {
  for (const auto& tg : targets_)
    if (hitsTarget(tg, a, ta, b, tb))
      return false;
  return true;
}

bool AcoEnvironment::pointDynamicFree(const Eigen::Vector2d& p, double t) const {
  return segmentDynamicFree(p, t, p, t);
}

// ---------------------------------------------------------------------------------------------------
// Construction graph, Fig. 6

AcoGraph::AcoGraph(const PlanningProblem& problem, const AcoConfig& cfg, const AcoEnvironment& env) {
  const Eigen::Vector2d start = problem.own.position, goal = nextWayPoint(problem);
  const double dist = (goal - start).norm();
  u_ = dist > 0.0 ? Eigen::Vector2d((goal - start) / dist) : unitOfCourse(problem.own.course);
  n_ = Eigen::Vector2d(u_.y(), -u_.x());  // starboard of the base line
  const double rows_f = std::ceil(dist / cfg.row_spacing - 1e-9);
  const int n_rows = static_cast<int>(std::clamp(rows_f, 1.0, static_cast<double>(kMaxRows)));
  rows_ = n_rows + 1;
  ds_ = dist / n_rows;
  dl_ = cfg.column_spacing;
  k_ = cfg.lateral_steps;
  m_ = static_cast<int>(std::floor(cfg.half_width / dl_ + 1e-9));
  const int nv = vertexCount(), ne = 2 * k_ + 1;
  pos_.resize(nv);
  std::vector<uint8_t> free(nv, 0);
  for (int i = 0; i < rows_; ++i)
    for (int j = -m_; j <= m_; ++j) {
      const int v = id(i, j);
      pos_[v] = start + u_ * (i * ds_) + n_ * (j * dl_);
      // Only the diamond between the own ship and the final waypoint can be on a forward walk.
      const bool cone = std::abs(j) <= k_ * i && std::abs(j) <= k_ * (n_rows - i);
      free[v] = cone && env.pointStaticFree(pos_[v]);
    }
  // Exact ends: the lattice must start on the own ship and end on the final waypoint.
  pos_[startId()] = start;
  pos_[goalId()] = goal;

  edge_ok_.assign(static_cast<size_t>(nv) * ne, 0);
  for (int i = 0; i + 1 < rows_; ++i)
    for (int j = -m_; j <= m_; ++j) {
      const int v = id(i, j);
      if (!free[v])
        continue;
      for (int k = -k_; k <= k_; ++k) {
        const int jj = j + k;
        if (jj < -m_ || jj > m_ || !free[id(i + 1, jj)])
          continue;
        edge_ok_[static_cast<size_t>(v) * ne + k + k_] = env.segmentStaticFree(pos_[v], pos_[id(i + 1, jj)]);
      }
    }
  // A vertex stays only if the final waypoint can be reached from it and it from the own ship through
  // statically free edges, so that no ant walks into a dead end made by land.
  alive_.assign(nv, 0);
  alive_[goalId()] = free[goalId()];
  for (int i = rows_ - 2; i >= 0; --i)
    for (int j = -m_; j <= m_; ++j) {
      const int v = id(i, j);
      if (!free[v])
        continue;
      for (int k = -k_; k <= k_ && !alive_[v]; ++k) {
        const int jj = j + k;
        if (jj >= -m_ && jj <= m_ && edge_ok_[static_cast<size_t>(v) * ne + k + k_] && alive_[id(i + 1, jj)])
          alive_[v] = 1;
      }
    }
  std::vector<uint8_t> reached(nv, 0);
  reached[startId()] = alive_[startId()];
  for (int i = 0; i + 1 < rows_; ++i)
    for (int j = -m_; j <= m_; ++j) {
      const int v = id(i, j);
      if (!reached[v])
        continue;
      for (int k = -k_; k <= k_; ++k) {
        const int jj = j + k;
        if (jj >= -m_ && jj <= m_ && edge_ok_[static_cast<size_t>(v) * ne + k + k_] && alive_[id(i + 1, jj)])
          reached[id(i + 1, jj)] = 1;
      }
    }
  for (int v = 0; v < nv; ++v)
    alive_[v] = alive_[v] && reached[v];
}

// ---------------------------------------------------------------------------------------------------
// Planner

double AcoPlanner::manoeuvreTime(double dpsi, const OwnShipLimits& limits) {
  const double a = std::abs(dpsi);
  // Eq. (6): t_m = t01 + dPsi/omega - (1/omega) tg(dPsi/2): the time on the segment A0-B of the
  // line-segment model of the turn (Fig. 4). Never below t01 for alterations up to 120 deg.
  return std::max(limits.turn_delay, limits.turn_delay + (a - std::tan(a / 2.0)) / limits.turn_rate);
}

namespace {

// Own-ship state along a path under the kinematic model (eq. 4) at constant speed.
struct Motion {
  Eigen::Vector2d pos = Eigen::Vector2d::Zero();
  double time = 0.0;    // [s]
  double course = 0.0;  // [rad] course of the leg that ends here (the present course at the start)
  double run = 0.0;     // [m] straight run since the last turning point (since the start if none)
  double length = 0.0;  // [m] path length so far, eq. (9)
  bool initial = true;  // still on the present course: no alteration ordered yet
};

struct Step {
  Motion next;
  bool inserted = false;                                 // turning point B inserted before `to`
  Eigen::Vector2d turn_point = Eigen::Vector2d::Zero();  // B (eq. 6, Fig. 4)
  double turn_time = 0.0;                                // [s] at B
};

struct TrajPoint {
  Eigen::Vector2d pos;
  double time;
  double course;  // leg ending here
};

class Search {
public:
  Search(const PlanningProblem& p, const AcoConfig& cfg, const AcoEnvironment& env, double speed)
      : p_(p), cfg_(cfg), env_(env), v_(speed) {
    initial_.pos = p.own.position;
    initial_.course = wrapTwoPi(p.own.course);
  }

  const Motion& initial() const { return initial_; }
  void enforceMinFirst(bool on) { min_first_ = on; }

  // One leg of the trajectory from m to `to`, with the rules of the manoeuvre (eq. 4-6): a course
  // alteration at m.pos needs the straight run before it to cover the manoeuvre time (the order is
  // given t_m before the turning point, after the previous one); the first alteration can be ordered
  // now, which puts the turning point B = V t_m ahead on the present course. Checks the leg against
  // E_stat (unless known free) and E_dyn(t) when `dynamic`.
  bool advance(const Motion& m, const Eigen::Vector2d& to, bool static_known, Step* s,
               bool dynamic = true) const {
    const Eigen::Vector2d d = to - m.pos;
    const double len = d.norm();
    if (len < kMinLegLength)
      return false;
    const double c = courseOf(d);
    const double dpsi = wrapPi(c - m.course);
    const double adp = std::abs(dpsi);
    s->inserted = false;
    if (adp <= kStraightTol || (adp < cfg_.max_alteration && m.run >= v_ * tm(adp))) {
      if (adp > kStraightTol && m.initial && min_first_ && adp < cfg_.min_first_alteration)
        return false;
      const double t1 = m.time + len / v_;
      if (!static_known && !env_.segmentStaticFree(m.pos, to))
        return false;
      if (dynamic && !env_.segmentDynamicFree(m.pos, m.time, to, t1))
        return false;
      const bool straight = adp <= kStraightTol;
      s->next.pos = to;
      s->next.time = t1;
      s->next.course = straight ? m.course : c;
      s->next.run = straight ? m.run + len : len;
      s->next.length = m.length + len;
      s->next.initial = m.initial && straight;
      return true;
    }
    if (!m.initial || adp > cfg_.max_alteration)
      return false;
    // Still on the present course: order the alteration now and turn at B (line-segment model of
    // Fig. 4). t_m depends on the alteration and the alteration on B: a fixed point, converged to
    // millimetres in a few steps because t_m varies slowly with the angle.
    const Eigen::Vector2d fwd = unitOfCourse(m.course);
    double alt = dpsi;
    Eigen::Vector2d b = m.pos;
    for (int it = 0; it < 8; ++it) {
      const double need = v_ * tm(std::abs(alt)) - m.run;
      const Eigen::Vector2d nb = m.pos + fwd * std::max(0.0, need);
      const Eigen::Vector2d db = to - nb;
      if (db.norm() < kMinLegLength)
        return false;
      alt = wrapPi(courseOf(db) - m.course);
      const bool done = (nb - b).squaredNorm() < 1e-6;
      b = nb;
      if (done)
        break;
    }
    const double aalt = std::abs(alt);
    if (aalt <= kStraightTol || aalt > cfg_.max_alteration ||
        (min_first_ && aalt < cfg_.min_first_alteration))
      return false;
    const double len1 = (b - m.pos).norm(), len2 = (to - b).norm();
    const double tb = m.time + len1 / v_, t1 = tb + len2 / v_;
    if (!env_.segmentStaticFree(m.pos, b) || !env_.segmentStaticFree(b, to))
      return false;
    if (dynamic &&
        (!env_.segmentDynamicFree(m.pos, m.time, b, tb) || !env_.segmentDynamicFree(b, tb, to, t1)))
      return false;
    s->inserted = true;
    s->turn_point = b;
    s->turn_time = tb;
    s->next.pos = to;
    s->next.time = t1;
    s->next.course = courseOf(to - b);
    s->next.run = len2;
    s->next.length = m.length + len1 + len2;
    s->next.initial = false;
    return true;
  }

  double tm(double adp) const { return AcoPlanner::manoeuvreTime(adp, p_.limits); }
  double speed() const { return v_; }

  // The trajectory through `points` (the own position first), with the B points, collinear runs
  // merged. False when a leg is infeasible.
  bool trajectory(const std::vector<Eigen::Vector2d>& points, std::vector<TrajPoint>* out,
                  double* length) const {
    out->clear();
    out->push_back({initial_.pos, 0.0, initial_.course});
    Motion m = initial_;
    Step s;
    for (size_t i = 1; i < points.size(); ++i) {
      if (!advance(m, points[i], false, &s))
        return false;
      if (s.inserted)
        out->push_back({s.turn_point, s.turn_time, m.course});
      out->push_back({s.next.pos, s.next.time, s.next.course});
      m = s.next;
    }
    *length = m.length;
    mergeStraight(out);
    return true;
  }

  // Waypoint reduction: from each point of the path, the farthest later point reachable by one
  // feasible leg (in time, with the manoeuvre rules) from which the rest of the original path is
  // still feasible. A shortcut moves every later point earlier in time, so the rest is re-checked;
  // the next original point always qualifies, so the reduction never gets stuck and never lengthens.
  bool reduce(const std::vector<Eigen::Vector2d>& points, std::vector<TrajPoint>* out, double* length) const {
    const size_t n = points.size() - 1;
    std::vector<Eigen::Vector2d> sel{points[0]};
    Motion m = initial_;
    Step s;
    size_t i = 0;
    while (i < n) {
      size_t j = n;
      for (; j > i; --j)
        if (advance(m, points[j], false, &s) && tailFeasible(points, j, s.next))
          break;
      if (j == i)
        return false;
      sel.push_back(points[j]);
      m = s.next;
      i = j;
    }
    return trajectory(sel, out, length);
  }

private:
  bool tailFeasible(const std::vector<Eigen::Vector2d>& points, size_t j, Motion m) const {
    Step s;
    for (size_t k = j + 1; k < points.size(); ++k) {
      if (!advance(m, points[k], false, &s))
        return false;
      m = s.next;
    }
    return true;
  }

  static void mergeStraight(std::vector<TrajPoint>* pts) {
    std::vector<TrajPoint> kept;
    kept.reserve(pts->size());
    for (size_t i = 0; i < pts->size(); ++i) {
      const bool interior = i > 0 && i + 1 < pts->size();
      if (interior && std::abs(wrapPi((*pts)[i + 1].course - (*pts)[i].course)) <= kStraightTol)
        continue;
      kept.push_back((*pts)[i]);
    }
    *pts = std::move(kept);
  }

  const PlanningProblem& p_;
  const AcoConfig& cfg_;
  const AcoEnvironment& env_;
  double v_;
  Motion initial_;
  bool min_first_ = true;
};

std::string fmt(const char* f, double a) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, a);
  return buf;
}

}  // namespace

AcoPlanner::AcoPlanner(const AcoConfig& cfg) : cfg_(cfg) {
  cfg_.validate();
}

void AcoPlanner::configure(const ParamMap& params) {
  cfg_ = AcoConfig::fromParams(params);
}

namespace {

// Steps (1)-(2), the input data: why the problem cannot be planned, or "" when it can.
std::string badInput(const PlanningProblem& problem, const Eigen::Vector2d& goal) {
  if (!allFinite({problem.own.position.x(), problem.own.position.y(), problem.own.course, problem.own.speed,
                  goal.x(), goal.y()}))
    return "own ship state or final waypoint not finite";
  for (const auto& t : problem.targets)
    if (!allFinite({t.state.position.x(), t.state.position.y(), t.state.course, t.state.speed}))
      return "target '" + t.state.id + "' has an unknown position, course or speed";
  if (!(problem.limits.turn_rate > 0.0) || !std::isfinite(problem.limits.turn_rate) ||
      !(problem.limits.turn_delay >= 0.0) || !std::isfinite(problem.limits.turn_delay))
    return "own-ship limits need turn_rate > 0 and turn_delay >= 0";
  return "";
}

// The target domain used: no side of the hexagon closer than the demanded passing distance (the
// paper's port and stern extents, 0.25 nm, are below the 0.5 nm most scenarios ask for). Every extent
// grows by the same offset, so the hexagon keeps the paper's asymmetry (starboard 0.35 nm wider than
// port), which is what makes ACO pass port to port (Rule 14) and astern of a crossing ship (Rule 15).
// ACO's best trajectory grazes the domain boundary and the kinematic turns of eq. (6) flown by the
// autopilot cut corners by up to a few hundred metres, so ACO takes a wider margin than the other
// planners: 1.3 x min_separation (our choice; docs/results/aco.md). In restricted waters the paper's
// hexagon (1 nm ahead, 0.6 nm to starboard) is first scaled down, whole, until its starboard extent is
// the problem's passing cap (planning.h), so that it keeps its shape.
HexagonDomainConfig inflatedDomain(HexagonDomainConfig domain, const PlanningProblem& problem, bool inflate) {
  if (problem.passing_cap > 0.0 && problem.passing_cap < domain.c) {
    const double k = problem.passing_cap / domain.c;
    for (double* x : {&domain.a, &domain.b, &domain.c, &domain.d, &domain.e})
      *x *= k;
  }
  const double min_separation = problem.min_separation;
  if (!inflate || !(min_separation > 0.0))
    return domain;
  const double floor = 1.3 * min_separation;
  const double smallest = std::min({domain.a, domain.b, domain.c, domain.d, domain.e});
  if (smallest < floor)
    for (double* x : {&domain.a, &domain.b, &domain.c, &domain.d, &domain.e})
      *x += floor - smallest;
  return domain;
}

// Step (5), the ant colony on the construction graph (Lazarowska 2015, Sec. 2.3): pheromone trails on
// the vertices, ants that walk forward row by row (or, with long edges, across rows) to the final
// waypoint, the best path of each iteration kept for the waypoint reduction.
class Colony {
public:
  Colony(const PlanningProblem& problem, const AcoConfig& cfg, const AcoGraph& graph, const Search& search,
         AcoDiagnostics& diag);
  // Iterates until cfg.iterations or the deadline (2.3.4). False when no ant reached the goal.
  bool run(const Deadline& deadline);
  double bestLength() const { return best_len_; }
  const std::vector<int>& bestWalk() const { return best_walk_; }
  // The best path of every iteration: the waypoint reduction is applied to each, because the lattice
  // length of eq. (9) ranks the staircases, not the straight legs the ship will sail.
  const std::vector<std::vector<int>>& elite() const { return elite_; }

private:
  struct Option {
    int vertex;
    double eta_beta;
    Motion next;
  };
  double tauAlpha(int v) const { return cfg_.alpha == 1.0 ? tau_[v] : std::pow(tau_[v], cfg_.alpha); }
  double etaBeta(int r, int k) const;
  int roulette(double total);
  bool walk(std::vector<int>* w, double* length);
  void collectOptions(int v, const Motion& m, std::vector<Option>* out) const;
  void keepIterationBest();
  void updatePheromone();

  const AcoConfig& cfg_;
  const AcoGraph& graph_;
  const Search& search_;
  AcoDiagnostics& diag_;
  const int k_max_;
  const double straight_;  // [m] the straight distance to the final waypoint
  std::vector<double> tau_;
  std::mt19937_64 rng_;
  std::vector<Option> first_;            // the first step's feasible moves, the same for every ant
  std::vector<std::vector<int>> walks_;  // this iteration's walks (partial when walk_len_ is -1: died)
  std::vector<double> walk_len_;
  std::vector<int> best_walk_;
  double best_len_ = std::numeric_limits<double>::infinity();
  std::vector<std::vector<int>> elite_;
  std::vector<Option> cand_;
  std::vector<double> weight_;
};

// Data initialisation (2.3.1): tau0 on every vertex and the first step's moves, computed once.
Colony::Colony(const PlanningProblem& problem, const AcoConfig& cfg, const AcoGraph& graph,
               const Search& search, AcoDiagnostics& diag)
    : cfg_(cfg),
      graph_(graph),
      search_(search),
      diag_(diag),
      k_max_(graph.lateralSteps()),
      straight_((nextWayPoint(problem) - problem.own.position).norm()),
      tau_(graph.vertexCount(), cfg.tau0),
      rng_(problem.seed),
      walks_(cfg.ants),
      walk_len_(cfg.ants) {
  collectOptions(graph_.startId(), search_.initial(), &first_);
}

// Visibility (2.3.2): eta = 1 / the distance to the neighbour r rows on and k columns sideways.
double Colony::etaBeta(int r, int k) const {
  const double len = std::hypot(r * graph_.rowSpacing(), k * graph_.columnSpacing());
  return cfg_.beta == 1.0 ? 1.0 / len : std::pow(1.0 / len, cfg_.beta);
}

// The feasible neighbourhood of vertex v (in state m): the next row, at most K columns sideways, or
// with long edges any later row r on, at most r K columns sideways. Each option is in the graph,
// statically free (known for lattice edges) and free of every target domain in time.
void Colony::collectOptions(int v, const Motion& m, std::vector<Option>* out) const {
  out->clear();
  const int row = graph_.rowOf(v), col = graph_.colOf(v), m_cols = graph_.halfColumns();
  const int last_r = cfg_.long_edges ? std::min(graph_.rows() - 1 - row, kMaxLongEdgeRows) : 1;
  Step s;
  for (int r = 1; r <= last_r; ++r)
    for (int k = -k_max_ * r; k <= k_max_ * r; ++k) {
      const int jj = col + k;
      if (jj < -m_cols || jj > m_cols)
        continue;
      const int q = graph_.id(row + r, jj);
      const bool lattice_edge = r == 1;
      if (!graph_.inGraph(q) || (lattice_edge && !graph_.edgeStaticFree(v, k)) ||
          !search_.advance(m, graph_.position(q), lattice_edge, &s))
        continue;
      out->push_back({q, etaBeta(r, k), s.next});
    }
}

// Action choice rule, eq. (7): P_j = tau_j^alpha eta_j^beta / sum over the feasible neighbourhood;
// roulette: q uniform in [0, 1], walk the neighbours until the summed probability exceeds q.
int Colony::roulette(double total) {
  const double q = uniform01(rng_);
  const int n = static_cast<int>(weight_.size());
  double cum = 0.0;
  for (int c = 0; c < n; ++c) {
    cum += weight_[c] / total;
    if (cum > q)
      return c;
  }
  return n - 1;
}

// Solution construction (2.3.2): one ant's walk to the final waypoint, into w. False when the ant is
// boxed in by the domains (only feasible solutions count, 2.3.4); else its length, eq. (9).
bool Colony::walk(std::vector<int>* w, double* length) {
  int v = graph_.startId();
  w->assign(1, v);
  Motion m;
  while (v != graph_.goalId()) {
    if (v == graph_.startId())
      cand_ = first_;
    else
      collectOptions(v, m, &cand_);
    weight_.clear();
    double total = 0.0;
    for (const Option& o : cand_) {
      weight_.push_back(tauAlpha(o.vertex) * o.eta_beta);
      total += weight_.back();
    }
    if (cand_.empty() || !(total > 0.0))
      return false;
    const Option& pick = cand_[roulette(total)];
    v = pick.vertex;
    m = pick.next;
    w->push_back(v);
  }
  *length = m.length;
  return true;
}

void Colony::keepIterationBest() {
  int it_best = -1;
  for (int a = 0; a < cfg_.ants; ++a)
    if (walk_len_[a] > 0.0 && (it_best < 0 || walk_len_[a] < walk_len_[it_best]))
      it_best = a;
  if (it_best >= 0 && std::find(elite_.begin(), elite_.end(), walks_[it_best]) == elite_.end())
    elite_.push_back(walks_[it_best]);
}

// Pheromone update, eq. (8): evaporation on every vertex, then each ant's deposit.
void Colony::updatePheromone() {
  for (double& t : tau_)
    t *= 1.0 - cfg_.rho;
  for (int a = 0; a < cfg_.ants; ++a) {
    if (walk_len_[a] <= 0.0)
      continue;
    const double amount = cfg_.deposit * straight_ / walk_len_[a];
    for (int v : walks_[a])
      tau_[v] += amount;
  }
}

bool Colony::run(const Deadline& deadline) {
  for (int it = 0; it < cfg_.iterations && !diag_.stopped_by_time; ++it) {
    int ants_run = 0;
    std::fill(walk_len_.begin(), walk_len_.end(), -1.0);
    for (int a = 0; a < cfg_.ants; ++a) {
      ++ants_run;
      double len = 0.0;
      if (!walk(&walks_[a], &len)) {
        ++diag_.ants_dead;
      } else {
        ++diag_.ants_completed;
        walk_len_[a] = len;
        if (len < best_len_) {
          best_len_ = len;
          best_walk_ = walks_[a];
        }
      }
      if (deadline.expired()) {
        diag_.stopped_by_time = true;
        break;
      }
    }
    keepIterationBest();
    if (diag_.stopped_by_time && ants_run < cfg_.ants)
      break;  // an unfinished iteration leaves the trail as it was
    updatePheromone();
    ++diag_.iterations_run;
  }
  return std::isfinite(best_len_);
}

// One call of AcoPlanner::plan: the problem, the planner's settings and diagnostics, the clock.
class AcoRun {
public:
  AcoRun(const PlanningProblem& problem, const AcoConfig& cfg, AcoDiagnostics& diag)
      : problem_(problem), cfg_(cfg), diag_(diag), wall_(1e9) {}
  Plan plan();

private:
  Plan fail(const std::string& why) const;
  Plan finish(const std::vector<TrajPoint>& traj, double length, const std::string& what);
  bool directRoute(const AcoEnvironment& env, const Eigen::Vector2d& goal, std::vector<TrajPoint>* traj,
                   double* len);
  Plan colonyPlan(const AcoEnvironment& env);
  bool bestTrajectory(const Colony& colony, const AcoGraph& graph, std::vector<TrajPoint>* traj, double* len);

  const PlanningProblem& problem_;
  const AcoConfig& cfg_;
  AcoDiagnostics& diag_;
  const Deadline wall_;
  double speed_ = 0.0;            // [m/s] the planning speed
  std::optional<Search> search_;  // once the input is known to be valid
};

Plan AcoRun::fail(const std::string& why) const {
  Plan plan;
  plan.status = PlanStatus::NoSolution;
  plan.message = "aco: " + why;
  plan.course_setpoint = problem_.own.course;
  plan.speed_setpoint = problem_.own.speed;
  plan.compute_time = wall_.elapsed();
  return plan;
}

// The plan of a trajectory: its waypoints at the planning speed, and the order times of the
// alterations (eq. 6: t_m before each turning point); the new course is steered now only when the
// first alteration is ordered now.
Plan AcoRun::finish(const std::vector<TrajPoint>& traj, double length, const std::string& what) {
  Plan plan;
  plan.status = PlanStatus::Ok;
  for (const auto& tp : traj)
    plan.waypoints.push_back({tp.pos, tp.time, tp.course, speed_});
  for (size_t i = 1; i + 1 < traj.size(); ++i) {
    const double alt = wrapPi(traj[i + 1].course - traj[i].course);
    diag_.command_times.push_back(traj[i].time - search_->tm(std::abs(alt)));
  }
  plan.course_setpoint = search_->initial().course;
  if (!diag_.command_times.empty() && diag_.command_times.front() <= 0.5)
    plan.course_setpoint = traj[2].course;
  plan.speed_setpoint = speed_;
  plan.cost = length;
  std::string msg = "aco: " + what + ", " + std::to_string(traj.size() - 1) + " leg(s), length " +
                    fmt("%.0f m", length) + ", courses";
  for (size_t i = 1; i < traj.size(); ++i)
    msg += fmt(" %03.0f", radToDeg(wrapTwoPi(traj[i].course)));
  plan.message = msg + " deg";
  plan.compute_time = wall_.elapsed();
  return plan;
}

// Step (3) as printed: target t's course line crosses the own ship's ahead of both. Parallel
// courses never cross; for them `enters` (the direct route enters her domain) decides.
bool coursesCross(const ShipState& own, const PlannerTarget& t, bool enters) {
  const Eigen::Vector2d u = unitOfCourse(own.course), w = unitOfCourse(t.state.course);
  const Eigen::Vector2d d = t.state.position - own.position;
  const double den = u.x() * (-w.y()) - u.y() * (-w.x());
  if (std::abs(den) < 1e-9)
    return enters;
  // own + s u = target + q w  ->  s u - q w = d (Cramer's rule).
  const double s = (d.x() * (-w.y()) - d.y() * (-w.x())) / den;
  const double q = (u.x() * d.y() - u.y() * d.x()) / den;
  return s >= 0.0 && q >= 0.0;
}

// Step (3), dangerous targets (AcoConfig::danger_by_course: as printed, else those whose domain the
// unaltered route to the final waypoint enters). Without any, and with no land and no domain in the
// way, the direct route is the shortest safe trajectory: true and that route in *traj, *len.
bool AcoRun::directRoute(const AcoEnvironment& env, const Eigen::Vector2d& goal, std::vector<TrajPoint>* traj,
                         double* len) {
  const Motion& m0 = search_->initial();
  search_->enforceMinFirst(false);
  bool direct = false;
  Step s;
  if (search_->advance(m0, goal, false, &s, false)) {
    const Eigen::Vector2d a = m0.pos, b = s.inserted ? s.turn_point : m0.pos;
    const double tb = s.inserted ? s.turn_time : 0.0;
    int entered = 0;
    for (size_t j = 0; j < env.targetCount(); ++j) {
      const bool enters = (s.inserted && env.segmentHitsTarget(j, a, 0.0, b, tb)) ||
                          env.segmentHitsTarget(j, b, tb, goal, s.next.time);
      entered += enters;
      diag_.dangerous_targets +=
          cfg_.danger_by_course ? coursesCross(problem_.own, problem_.targets[j], enters) : enters;
    }
    direct = diag_.dangerous_targets == 0 && entered == 0 && search_->trajectory({m0.pos, goal}, traj, len);
  }
  search_->enforceMinFirst(true);
  return direct;
}

// The result of the colony: the shortest lattice path, or with waypoint reduction the shortest
// reduced path among the iterations' best.
bool AcoRun::bestTrajectory(const Colony& colony, const AcoGraph& graph, std::vector<TrajPoint>* traj,
                            double* len) {
  auto positions = [&](const std::vector<int>& w) {
    std::vector<Eigen::Vector2d> pts(w.size());
    for (size_t r = 0; r < w.size(); ++r)
      pts[r] = graph.position(w[r]);
    return pts;
  };
  diag_.best_walk = positions(colony.bestWalk());
  diag_.best_walk_length = colony.bestLength();
  if (!search_->trajectory(diag_.best_walk, traj, len))
    return false;
  if (!cfg_.smooth)
    return true;
  std::vector<std::vector<int>> elite = colony.elite();
  if (std::find(elite.begin(), elite.end(), colony.bestWalk()) == elite.end())
    elite.push_back(colony.bestWalk());
  std::vector<TrajPoint> reduced;
  double rlen = 0.0;
  for (const auto& w : elite)
    if (search_->reduce(positions(w), &reduced, &rlen) && rlen < *len - 1e-6) {
      *traj = reduced;
      *len = rlen;
    }
  return true;
}

// Steps (4)-(5): the construction graph and the colony on it.
Plan AcoRun::colonyPlan(const AcoEnvironment& env) {
  const AcoGraph graph(problem_, cfg_, env);
  for (int v = 0; v < graph.vertexCount(); ++v)
    diag_.graph_vertices += graph.inGraph(v);
  if (!graph.inGraph(graph.startId()))
    return fail("no statically free way from the own ship to the final waypoint in the grid");
  Colony colony(problem_, cfg_, graph, *search_, diag_);
  // Termination by time (2.3.4); a budget <= 0 means none.
  double budget = problem_.time_budget > 0.0 ? problem_.time_budget : 1e9;
  if (cfg_.max_time > 0.0)
    budget = std::min(budget, cfg_.max_time);
  if (!colony.run(Deadline(budget)))
    return fail(std::string("no feasible trajectory (boxed in): ") + std::to_string(diag_.ants_dead) +
                " ant(s) found no way" + (diag_.stopped_by_time ? ", stopped by the time limit" : ""));
  std::vector<TrajPoint> traj;
  double len = 0.0;
  if (!bestTrajectory(colony, graph, &traj, &len))
    return fail("internal: the best path is not reproducible");
  return finish(traj, len,
                std::to_string(diag_.iterations_run) + " iteration(s), " +
                    std::to_string(diag_.ants_completed) + " ant path(s), " +
                    std::to_string(diag_.dangerous_targets) + " dangerous target(s)" +
                    (diag_.stopped_by_time ? ", stopped by the time limit" : ""));
}

// Lazarowska (2015), Sec. 2: (1)-(2) the input data, (3) the dangerous targets, (4) the construction
// graph, (5) the ant colony.
Plan AcoRun::plan() {
  const Eigen::Vector2d goal = nextWayPoint(problem_);
  if (const std::string why = badInput(problem_, goal); !why.empty())
    return fail(why);
  // Course alterations only (the paper has no speed manoeuvre): the present speed, or the maximum
  // when the ship is not under way.
  speed_ = problem_.own.speed > 0.1 ? problem_.own.speed : problem_.limits.max_speed;
  if (!(speed_ > 0.0) || !std::isfinite(speed_))
    return fail("own ship has no speed to plan with");
  const double dist = (goal - problem_.own.position).norm();
  if (dist / cfg_.row_spacing > kMaxRows)
    return fail("final waypoint too far for the grid (" + fmt("%.0f", dist / cfg_.row_spacing) + " rows)");
  const AcoEnvironment env(problem_, inflatedDomain(cfg_.domain, problem_, cfg_.inflate),
                           cfg_.colregs_factor);
  search_.emplace(problem_, cfg_, env, speed_);
  const Motion& m0 = search_->initial();
  if (dist < kMinLegLength)
    return finish({{m0.pos, 0.0, m0.course}}, 0.0, "already at the final waypoint");
  if (!env.pointStaticFree(m0.pos))
    return fail("own ship inside a static obstacle or outside the environment boundaries");
  if (!env.pointStaticFree(goal))
    return fail("final waypoint inside a static obstacle or outside the environment boundaries");
  for (size_t j = 0; j < env.targetCount(); ++j)
    if (env.segmentHitsTarget(j, m0.pos, 0.0, m0.pos, 0.0))
      return fail("own ship already inside the domain of target '" + problem_.targets[j].state.id + "'");
  std::vector<TrajPoint> traj;
  double len = 0.0;
  if (directRoute(env, goal, &traj, &len)) {
    diag_.direct_route = true;
    return finish(traj, len, "no dangerous target, direct route");
  }
  return colonyPlan(env);
}

}  // namespace

Plan AcoPlanner::plan(const PlanningProblem& problem) {
  diag_ = AcoDiagnostics{};
  return AcoRun(problem, cfg_, diag_).plan();
}

std::vector<TargetDomain> AcoPlanner::domains(const PlanningProblem& problem) const {
  const HexagonDomainConfig base = inflatedDomain(cfg_.domain, problem, cfg_.inflate);
  std::vector<TargetDomain> out;
  for (const PlannerTarget& t : problem.targets)
    out.push_back({t.state.id, HexagonDomain(targetDomain(t, base, cfg_.colregs_factor))
                                   .polygon(t.state.position, t.state.course)});
  return out;
}

}  // namespace asv
