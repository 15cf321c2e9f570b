#include "asv_core/eval/evaluation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "asv_core/common/format.h"
#include "asv_core/risk/cpa.h"

namespace asv {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kFar = 1e300;

void require(bool ok, const std::string& what) {
  if (!ok)
    throw std::invalid_argument("evaluation: " + what);
}

double sideOf(const Eigen::Vector2d& u, const Eigen::Vector2d& rel) {
  return u.x() * rel.y() - u.y() * rel.x();
}

// The least distance between two ships moving at constant velocities for `duration` seconds from a and b:
// the distance from the origin to the segment their relative position sweeps.
double closestOnLeg(const Eigen::Vector2d& a, const Eigen::Vector2d& va, const Eigen::Vector2d& b,
                    const Eigen::Vector2d& vb, double duration) {
  return pointSegmentDistance(Eigen::Vector2d::Zero(), b - a, b - a + (vb - va) * duration);
}

}  // namespace

// ---------------------------------------------------------------------------------------------------

void EvaluationConfig::validate() const {
  auto pos = [](double v) { return std::isfinite(v) && v > 0.0; };
  auto frac = [](double v) { return std::isfinite(v) && v >= 0.0 && v <= 1.0; };
  require(pos(r_nm_m) && r_min_m > r_nm_m && r_pref_m > r_min_m && std::isfinite(r_pref_m),
          "ranges must satisfy 0 < r_nm_m < r_min_m < r_pref_m");
  require(safety_at_r_min > 0.0 && safety_at_r_min < 1.0, "safety_at_r_min must be in (0, 1)");
  require(pos(entry_tcpa_s) && pos(entry_dcpa_m), "entry_tcpa_s and entry_dcpa_m must be > 0");
  require(pos(duty_tcpa_s) && pos(duty_effect_s), "duty_tcpa_s and duty_effect_s must be > 0");
  require(std::isfinite(extremis_delay_s) && extremis_delay_s >= 0.0, "extremis_delay_s must be >= 0");
  require(pos(action_course_deg) && action_course_deg < 180.0, "action_course_deg must be in (0, 180)");
  require(action_speed_fraction > 0.0 && action_speed_fraction <= 1.0,
          "action_speed_fraction must be in (0, 1]");
  require(
      pos(apparent_course_deg) && apparent_course_deg <= 180.0 && apparent_course_deg >= action_course_deg,
      "apparent_course_deg must be in [action_course_deg, 180]");
  require(apparent_speed_fraction > 0.0 && apparent_speed_fraction <= 1.0,
          "apparent_speed_fraction must be in (0, 1]");
  require(pos(early_range_m) && pos(early_tcpa_s), "early_range_m and early_tcpa_s must be > 0");
  require(std::isfinite(reaction_s) && reaction_s >= 0.0, "reaction_s must be >= 0");
  require(pos(cross_ahead_range_m), "cross_ahead_range_m must be > 0");
  require(frac(penalty_rule8) && frac(penalty_late) && frac(penalty_port) && frac(penalty_ahead) &&
              frac(penalty_stand_on) && frac(penalty_succession) && frac(penalty_extremis),
          "penalties must be in [0, 1]");
  require(pos(manoeuvre_threshold_deg) && manoeuvre_threshold_deg < 180.0,
          "manoeuvre_threshold_deg must be in (0, 180)");
  require(std::isfinite(manoeuvre_window_s) && manoeuvre_window_s >= 0.0, "manoeuvre_window_s must be >= 0");
  require(std::isfinite(sample_period_s) && sample_period_s >= 0.0, "sample_period_s must be >= 0");
  hu.validate();
  colregs.validate();
}

EvaluationConfig EvaluationConfig::fromParams(const ParamMap& p) {
  EvaluationConfig c;
  c.ranges_from_scenario = p.getBool("ranges_from_scenario", c.ranges_from_scenario);
  c.r_pref_m = p.getDouble("r_pref_m", c.r_pref_m);
  c.r_min_m = p.getDouble("r_min_m", c.r_min_m);
  c.r_nm_m = p.getDouble("r_nm_m", c.r_nm_m);
  c.safety_at_r_min = p.getDouble("safety_at_r_min", c.safety_at_r_min);
  c.entry_tcpa_s = p.getDouble("entry_tcpa_s", c.entry_tcpa_s);
  c.entry_dcpa_m = p.getDouble("entry_dcpa_m", c.entry_dcpa_m);
  c.action_course_deg = p.getDouble("action_course_deg", c.action_course_deg);
  c.action_speed_fraction = p.getDouble("action_speed_fraction", c.action_speed_fraction);
  c.apparent_course_deg = p.getDouble("apparent_course_deg", c.apparent_course_deg);
  c.apparent_speed_fraction = p.getDouble("apparent_speed_fraction", c.apparent_speed_fraction);
  c.early_range_m = p.getDouble("early_range_m", c.early_range_m);
  c.early_tcpa_s = p.getDouble("early_tcpa_s", c.early_tcpa_s);
  c.reaction_s = p.getDouble("reaction_s", c.reaction_s);
  c.cross_ahead_range_m = p.getDouble("cross_ahead_range_m", c.cross_ahead_range_m);
  c.hu.t_max_s = p.getDouble("hu/t_max_s", c.hu.t_max_s);
  c.hu.d_min_m = p.getDouble("hu/d_min_m", c.hu.d_min_m);
  c.hu.t_safe_s = p.getDouble("hu/t_safe_s", c.hu.t_safe_s);
  c.hu.d_safe_m = p.getDouble("hu/d_safe_m", c.hu.d_safe_m);
  c.penalty_rule8 = p.getDouble("penalty_rule8", c.penalty_rule8);
  c.penalty_late = p.getDouble("penalty_late", c.penalty_late);
  c.penalty_port = p.getDouble("penalty_port", c.penalty_port);
  c.penalty_ahead = p.getDouble("penalty_ahead", c.penalty_ahead);
  c.penalty_stand_on = p.getDouble("penalty_stand_on", c.penalty_stand_on);
  c.penalty_succession = p.getDouble("penalty_succession", c.penalty_succession);
  c.duty_tcpa_s = p.getDouble("duty_tcpa_s", c.duty_tcpa_s);
  c.duty_effect_s = p.getDouble("duty_effect_s", c.duty_effect_s);
  c.extremis_delay_s = p.getDouble("extremis_delay_s", c.extremis_delay_s);
  c.penalty_extremis = p.getDouble("penalty_extremis", c.penalty_extremis);
  c.manoeuvre_threshold_deg = p.getDouble("manoeuvre_threshold_deg", c.manoeuvre_threshold_deg);
  c.manoeuvre_window_s = p.getDouble("manoeuvre_window_s", c.manoeuvre_window_s);
  c.sample_period_s = p.getDouble("sample_period_s", c.sample_period_s);
  c.colregs.head_on_half_angle_deg =
      p.getDouble("colregs/head_on_half_angle_deg", c.colregs.head_on_half_angle_deg);
  c.colregs.stern_sector_start_deg =
      p.getDouble("colregs/stern_sector_start_deg", c.colregs.stern_sector_start_deg);
  c.colregs.max_range_m = p.getDouble("colregs/max_range_m", c.colregs.max_range_m);
  p.rejectUnknown("evaluation");
  c.validate();
  return c;
}

RunInfo RunInfo::fromScenario(const Scenario& sc, const std::string& planner, uint64_t seed) {
  RunInfo info;
  info.scenario = sc.name;
  info.planner = planner.empty() ? "none" : planner;
  info.seed = seed;
  info.min_separation = sc.min_separation;
  info.obstacles = sc.obstacles;
  info.origin = sc.origin;
  info.ships.push_back({sc.own.name, sc.own.goal, info.planner});
  info.route = sc.own.route;
  info.route_start = sc.own.position;
  info.human = sc.human;
  for (const auto& t : sc.targets) {
    const bool plans = t.behaviour == Behaviour::Planner;
    info.ships.push_back({t.name, t.goal, plans ? (t.planner.empty() ? "none" : t.planner) : ""});
    info.multi_agent = info.multi_agent || plans;
  }
  return info;
}

double safetyScore(double r, double r_pref, double r_min, double r_nm, double at_r_min) {
  if (!std::isfinite(r) || r >= r_pref)
    return 1.0;
  if (r >= r_min)
    return at_r_min + (1.0 - at_r_min) * (r - r_min) / (r_pref - r_min);
  if (r > r_nm)
    return at_r_min * (r - r_nm) / (r_min - r_nm);
  return 0.0;
}

// ---------------------------------------------------------------------------------------------------

RunRecorder::RunRecorder(const EvaluationConfig& config, const RunInfo& info) : cfg_(config), info_(info) {
  cfg_.validate();
  require(!info_.ships.empty(), "RunInfo lists no ships (the own ship comes first)");
  require(std::isfinite(info_.min_separation) && info_.min_separation > 0.0,
          "RunInfo.min_separation must be > 0 m");
  if (cfg_.ranges_from_scenario) {
    r_min_ = info_.min_separation;
    r_pref_ = 2.0 * r_min_;
    r_nm_ = r_min_ / 5.0;
  } else {
    r_pref_ = cfg_.r_pref_m;
    r_min_ = cfg_.r_min_m;
    r_nm_ = cfg_.r_nm_m;
  }
  const size_t n = info_.ships.size();
  tracks_.resize(n);
  min_dist_.assign(n, std::vector<double>(n, kFar));
  closest_.assign(n, std::vector<Closest>(n));
  collided_.assign(n, std::vector<char>(n, 0));
  grounded_.assign(n, 0);
  min_obstacle_.assign(n, kFar);
  arrival_.assign(n, kNaN);
}

int RunRecorder::index(const std::string& name) const {
  for (size_t i = 0; i < info_.ships.size(); ++i)
    if (info_.ships[i].name == name)
      return static_cast<int>(i);
  return -1;
}

void RunRecorder::addSample(double t, const std::vector<ShipSample>& ships) {
  if (!std::isfinite(t))
    return;
  ++samples_;
  last_t_ = std::max(last_t_, t);
  std::vector<std::pair<int, const ShipSample*>> present;
  for (const auto& s : ships) {
    const int i = index(s.name);
    if (i < 0 || !s.state.finite())
      continue;
    present.emplace_back(i, &s);
    Track& tr = tracks_[i];
    const Eigen::Vector2d p = s.state.position;
    if (!tr.have_first) {
      tr.have_first = true;
      tr.first_pos = p;
    }
    if (tr.have_last && s.active)
      tr.path_length += (p - tr.last_pos).norm();
    tr.last_pos = p;
    tr.have_last = true;
    if (tr.points.empty() || t - tr.last_kept >= cfg_.sample_period_s - 1e-9) {
      tr.points.push_back({t, s.state, s.active});
      tr.last_kept = t;
    }
    if (std::isfinite(s.course_setpoint))
      addSetpoint(t, s.name, s.course_setpoint);
    if (s.active)
      checkLand(static_cast<size_t>(i), s);
    if (i == 0 && s.active)
      followRoute(t, p);
  }
  for (size_t a = 0; a < present.size(); ++a)
    for (size_t b = a + 1; b < present.size(); ++b) {
      const auto& [i, si] = present[a];
      const auto& [j, sj] = present[b];
      if (i == j || !si->active || !sj->active)
        continue;
      const double d = (si->state.position - sj->state.position).norm();
      if (d < min_dist_[i][j]) {
        closest_[i][j] = {t, si->state.position, sj->state.position};
        closest_[j][i] = {t, sj->state.position, si->state.position};
      }
      min_dist_[i][j] = std::min(min_dist_[i][j], d);
      min_dist_[j][i] = min_dist_[i][j];
    }
}

void RunRecorder::followRoute(double t, const Eigen::Vector2d& p) {
  if (info_.route.empty())
    return;
  const RouteDeviation d = routeDeviation(info_.route, info_.route_start, p);
  route_stats_.max_xte = std::max(route_stats_.max_xte, std::abs(d.xte));
  if (d.outside_corridor && std::isfinite(route_last_t_))
    route_stats_.outside_corridor += t - route_last_t_;
  route_last_t_ = t;
}

void RunRecorder::checkLand(size_t i, const ShipSample& s) {
  if (info_.obstacles.empty())
    return;
  const Polygon hull =
      hullOutline(s.state.position, s.state.heading, std::max(0.0, s.state.length), std::max(0.0, s.beam));
  for (const StaticObstacle& o : info_.obstacles) {
    const double d = polygonObstacleDistance(hull, o, min_obstacle_[i]);  // exact where it can matter
    min_obstacle_[i] = std::min(min_obstacle_[i], d);
    if (d <= 0.0)
      grounded_[i] = 1;
  }
}

void RunRecorder::addSetpoint(double t, const std::string& ship, double course) {
  const int i = index(ship);
  if (i < 0 || !std::isfinite(course) || !std::isfinite(t))
    return;
  auto& sp = tracks_[i].setpoints;
  course = wrapTwoPi(course);
  if (sp.empty() || std::fabs(wrapPi(course - sp.back().second)) > 1e-9)
    sp.emplace_back(t, course);
}

void RunRecorder::addPlanTime(double seconds) {
  if (std::isfinite(seconds) && seconds >= 0.0)
    plan_times_.push_back(seconds);
}

void RunRecorder::addPassingDistance(double metres) {
  if (std::isfinite(metres) && metres > 0.0) {
    passing_.first = std::min(passing_.first, metres);
    passing_.second = std::max(passing_.second, metres);
  }
}

void RunRecorder::addEvent(const SimEvent& e) {
  const int a = index(e.a), b = index(e.b);
  switch (e.type) {
    case SimEvent::Grounding:
      if (a >= 0)
        grounded_[a] = 1;
      break;
    case SimEvent::Collision:
      if (a >= 0 && b >= 0)
        collided_[a][b] = collided_[b][a] = 1;
      break;
    case SimEvent::Arrival:
      if (a >= 0 && !std::isfinite(arrival_[a]))
        arrival_[a] = e.time;
      break;
    case SimEvent::NearMiss:
      break;  // recomputed from the samples against the scenario's threshold
  }
}

std::vector<Manoeuvre> RunRecorder::manoeuvres(const Track& tr) const {
  std::vector<Manoeuvre> out;
  const auto& sp = tr.setpoints;
  if (sp.empty())
    return out;
  const double thr = degToRad(cfg_.manoeuvre_threshold_deg);
  // The reference is the course the ship sailed at the start, so a first plan that turns away from it
  // is a manoeuvre.
  double anchor = tr.points.empty() ? sp.front().second : tr.points.front().s.course;
  size_t i = 0;
  while (i < sp.size()) {
    if (std::fabs(wrapPi(sp[i].second - anchor)) < thr) {
      ++i;
      continue;
    }
    const double t0 = sp[i].first;
    double last = sp[i].second;
    size_t j = i + 1;
    while (j < sp.size() && sp[j].first <= t0 + cfg_.manoeuvre_window_s + 1e-9)
      last = sp[j++].second;
    const double change = wrapPi(last - anchor);
    if (std::fabs(change) >= thr)
      out.push_back({t0, change});
    anchor = last;
    i = j;
  }
  return out;
}

// What the own ship did in a target's passage, from the entry into the rules (ke) to the closest
// approach (kc), counted only at the samples at which the risk of collision with this target lasted
// (inRisk): its largest turns to either side and its largest speed loss relative to the entry, its first
// action (ka) and first readily apparent action (kp), and a turn to port (kport: the first alteration
// to port, or a swing across the entry course to port after one to starboard). Sample indices are
// both.size() when there is none.
struct RunRecorder::Passage {
  const Instants& both;
  const std::vector<Cpa>& cpas;
  EncounterGeometry g;
  size_t ke = 0, kc = 0, ka = 0, kp = 0;
  size_t kr = 0;            // the last sample before the target's own motion removed the risk
  bool risk_lasted = true;  // to the closest approach, or brought back by the own ship's motion
  double max_stbd = 0.0, max_port = 0.0, speed_drop = 0.0;  // [rad], [rad], [-]
  double alter_deg = 0.0;                                   // [deg] the larger turn
  const char* side = "starboard";                           // of the larger turn
  int first_side = 0;                                       // of the first alteration: +1 starboard, -1 port
  size_t kport = 0;
  bool swing = false;           // kport is a swing across the entry course, not the first alteration
  double swing_from_deg = 0.0;  // [deg] the starboard alteration before the swing
  size_t own = 0, target = 0;   // the ships' indices (set by evaluatePair)
  const std::vector<Manoeuvre>* manoeuvres = nullptr;  // the own ship's, over the run (evaluatePair)
};

namespace {

// A rule finding: the score's factor loses the fraction p and the note says why.
void penalise(TargetResult& r, double& factor, double p, const std::string& note) {
  if (p <= 0.0)
    return;
  factor *= 1.0 - p;
  r.colregs_ok = false;
  r.notes.push_back(note);
}

}  // namespace

RunRecorder::Instants RunRecorder::commonInstants(size_t i, size_t j) const {
  const auto& A = tracks_[i].points;
  const auto& B = tracks_[j].points;
  Instants both;
  for (size_t a = 0, b = 0; a < A.size() && b < B.size();) {
    if (std::fabs(A[a].t - B[b].t) < 1e-6) {
      if (A[a].active && B[b].active)
        both.emplace_back(&A[a], &B[b]);
      ++a;
      ++b;
    } else if (A[a].t < B[b].t) {
      ++a;
    } else {
      ++b;
    }
  }
  return both;
}

// The risk of collision with the target lasts at sample k of the passage while the target's own motion
// has not removed it (k <= kr), and whenever the ships' actual motion brings the CPA ahead below
// entry_dcpa_m again: a turn that re-creates the risk with this ship is judged for it, whatever a copy
// of the own ship held on her entry course would have done.
bool RunRecorder::inRisk(const Passage& p, size_t k) const {
  return k <= p.kr || (p.cpas[k].tcpa > 0.0 && p.cpas[k].dcpa < cfg_.entry_dcpa_m);
}

RunRecorder::Passage RunRecorder::passage(const Instants& both, const std::vector<Cpa>& cpas,
                                          size_t ke) const {
  Passage p{both, cpas, classifyEncounter(both[ke].first->s, both[ke].second->s, cpas[ke], cfg_.colregs)};
  p.ke = p.kc = ke;
  for (size_t k = ke; k < both.size(); ++k)
    if (cpas[k].range < cpas[p.kc].range)
      p.kc = k;
  const ShipState& own_e = both[ke].first->s;
  const double c_ref = own_e.course, v_ref = own_e.speed;
  const double act_course = degToRad(cfg_.action_course_deg);
  const double apparent_course = degToRad(cfg_.apparent_course_deg);
  p.ka = p.kp = p.kport = both.size();
  p.kr = riskRemoved(both, ke, p.kc);
  p.risk_lasted = p.kr == p.kc;
  for (size_t k = ke; k <= p.kc; ++k) {
    if (!inRisk(p, k))
      continue;  // a turn made when there was no risk with this ship is not one for it
    p.risk_lasted = p.risk_lasted || k > p.kr;
    const ShipState& s = both[k].first->s;
    const double dev = wrapPi(s.course - c_ref);
    const double drop = v_ref > 0.1 ? std::max(0.0, 1.0 - s.speed / v_ref) : 0.0;
    if (p.first_side == 0 && std::fabs(dev) >= act_course)
      p.first_side = dev > 0.0 ? 1 : -1;
    // A swing across the entry course to port counts while the ships' actual motion still holds a risk.
    const bool actual_risk = cpas[k].tcpa > 0.0 && cpas[k].dcpa < cfg_.entry_dcpa_m;
    if (p.kport == both.size() && dev <= -act_course && (p.first_side < 0 || actual_risk)) {
      p.kport = k;
      p.swing = p.first_side > 0;
      p.swing_from_deg = radToDeg(p.max_stbd);
    }
    p.max_stbd = std::max(p.max_stbd, dev);
    p.max_port = std::max(p.max_port, -dev);
    p.speed_drop = std::max(p.speed_drop, drop);
    if (p.ka == both.size() && (std::fabs(dev) >= act_course || drop >= cfg_.action_speed_fraction))
      p.ka = k;
    if (p.kp == both.size() && (std::fabs(dev) >= apparent_course || drop >= cfg_.apparent_speed_fraction))
      p.kp = k;
  }
  finishTurn(p);
  p.alter_deg = radToDeg(std::max(p.max_stbd, p.max_port));
  p.side = p.max_stbd >= p.max_port ? "starboard" : "port";
  return p;
}

// Rule 8 judges the size of the action taken: a turn away from the entry course still under way when
// the target's own motion removed the risk (kr) is measured to its end, the sample after which the
// course stops moving the same way; the samples after kr count for nothing else (timing, port turns).
// Without this, a 36 deg turn ordered at once and partly made (8 deg) when the target's own turn
// removed the risk would be judged an 8 deg one.
void RunRecorder::finishTurn(Passage& p) const {
  const size_t kr = p.kr;
  if (kr >= p.kc || kr <= p.ke)
    return;
  const double c_ref = p.both[p.ke].first->s.course;
  auto dev = [&](size_t k) { return wrapPi(p.both[k].first->s.course - c_ref); };
  const double sense = dev(kr) - dev(kr - 1);
  if (std::fabs(sense) < 1e-6 || sense * dev(kr) <= 0.0)
    return;  // not turning away from the entry course at kr
  const double side = sense > 0.0 ? 1.0 : -1.0;
  double& largest = sense > 0.0 ? p.max_stbd : p.max_port;
  for (size_t k = kr + 1; k <= p.kc && (dev(k) - dev(k - 1)) * sense > 0.0; ++k)
    largest = std::max(largest, side * dev(k));
}

double RunRecorder::earliness(const Passage& p, size_t k, double t_act) const {
  if (t_act - p.both[p.ke].first->t <= cfg_.reaction_s)
    return 1.0;  // as early as possible: within reaction_s of the entry into the rules
  return std::max(p.cpas[k].range / cfg_.early_range_m, p.cpas[k].tcpa / cfg_.early_tcpa_s);
}

// Rules 14, 15 and 17(c) govern while there is a risk of collision with the target. When the target's
// own motion has removed it (our reading) a later turn to port, made for another ship, is not one for
// this encounter. It is removed from sample k on when at every sample from k to kc the own ship
// dead-reckoned from the entry on her entry course and speed (so that no action of hers counts) would
// keep at least entry_dcpa_m from the target: the least range so far, and the CPA ahead with the target
// holding its course and speed, both at least entry_dcpa_m. Returns the sample before k (kc when the
// risk lasts to the closest approach).
size_t RunRecorder::riskRemoved(const Instants& both, size_t ke, size_t kc) const {
  const ShipState& entry = both[ke].first->s;
  const Eigen::Vector2d v = courseSpeedToVelocity(entry.course, entry.speed);
  auto ghost = [&](size_t k) { return entry.position + v * (both[k].first->t - both[ke].first->t); };
  std::vector<double> least(kc + 1, kFar);  // the least range from ke to k, and the CPA ahead of k
  double so_far = kFar;
  for (size_t k = ke; k <= kc; ++k) {
    const ShipState& t = both[k].second->s;
    so_far = std::min(so_far, (ghost(k) - t.position).norm());
    const Cpa c = computeCpa(ghost(k), v, t.position, t.velocity());
    least[k] = std::min(so_far, c.tcpa > 0.0 ? c.dcpa : c.range);
  }
  size_t kr = kc;
  for (size_t k = kc + 1; k-- > ke && least[k] >= cfg_.entry_dcpa_m;)
    kr = k > ke ? k - 1 : ke;
  return kr;
}

// The give-way ship (and both ships head-on): Rules 8, 14, 15 and 16.
void RunRecorder::judgeGiveWay(const Passage& p, TargetResult& r, double& factor,
                               const std::vector<GiveWayDuty>& duties) const {
  if (p.ka == p.both.size() && !p.risk_lasted) {
    judgeRemovedRisk(p, r, factor);
    return;
  }
  // Rule 8: readily apparent.
  const double apparent =
      std::max(p.alter_deg / cfg_.apparent_course_deg, p.speed_drop / cfg_.apparent_speed_fraction);
  if (apparent < 1.0)
    penalise(r, factor, cfg_.penalty_rule8 * (1.0 - apparent),
             std::string("rule 8: ") + p.side +
                 strFormat(" turn %.0f deg (speed -%.0f %%) < %.0f deg apparent", p.alter_deg,
                           100.0 * p.speed_drop, cfg_.apparent_course_deg));
  judgeSuccession(p, r, factor);
  judgeEarly(p, r, factor);
  // Rules 14 and 15: starboard.
  if (p.kport < p.both.size() &&
      (p.g.encounter == Encounter::HeadOn || p.g.encounter == Encounter::CrossingGiveWay))
    judgePortTurn(p, r, factor, p.g.encounter == Encounter::HeadOn ? "rule 14" : "rule 15", duties);
  if (p.g.encounter == Encounter::CrossingGiveWay)
    judgeCrossAhead(p, r, factor);
}

// Rule 15: not across the stand-on ship's bow. The first time the own ship crosses the target's track
// line after entry decides.
void RunRecorder::judgeCrossAhead(const Passage& p, TargetResult& r, double& factor) const {
  const Instants& both = p.both;
  for (size_t k = p.ke + 1; k < both.size(); ++k) {
    const ShipState& t0 = both[k - 1].second->s;
    const ShipState& t1 = both[k].second->s;
    const Eigen::Vector2d u0 = courseSpeedToVelocity(t0.course, 1.0);
    const Eigen::Vector2d u1 = courseSpeedToVelocity(t1.course, 1.0);
    const Eigen::Vector2d rel0 = both[k - 1].first->s.position - t0.position;
    const Eigen::Vector2d rel1 = both[k].first->s.position - t1.position;
    const double s0 = sideOf(u0, rel0), s1 = sideOf(u1, rel1);
    if ((s0 < 0.0) == (s1 < 0.0))
      continue;
    if (u1.dot(rel1) > 0.0 && rel1.norm() < cfg_.cross_ahead_range_m)
      penalise(r, factor, cfg_.penalty_ahead,
               strFormat("rule 15: crossed %.0f m ahead of the stand-on ship at t=%.0f s", rel1.norm(),
                         both[k].first->t));
    break;
  }
}

// The target's own motion removed the risk before the own ship acted: no action was due after that, so
// Rules 8 and 16 judge only whether she had been late while it lasted (the range and TCPA at kr).
void RunRecorder::judgeRemovedRisk(const Passage& p, TargetResult& r, double& factor) const {
  const Cpa& c = p.cpas[p.kr];
  const double early = earliness(p, p.kr, p.both[p.kr].first->t);
  if (early < 1.0)
    penalise(r, factor, cfg_.penalty_late * (1.0 - early),
             strFormat("rule 16: no action while the risk lasted (to t=%.0f s, %.0f m and %.0f s from CPA): "
                       "late",
                       p.both[p.kr].first->t, c.range, c.tcpa));
  else
    r.notes.push_back(
        strFormat("the target's own motion removed the risk at t=%.0f s, before an action "
                  "was due: rules 8 and 16 not evaluated",
                  p.both[std::min(p.kr + 1, p.kc)].first->t));
}

// Rule 16: early and substantial. Judged at the first readily apparent action (kp: apparent_course_deg
// or apparent_speed_fraction), so that a small early nudge does not make a late large turn early; at the
// first action when none was apparent (Rule 8 then counts too).
void RunRecorder::judgeEarly(const Passage& p, TargetResult& r, double& factor) const {
  const Instants& both = p.both;
  if (p.ka == both.size()) {
    penalise(r, factor, cfg_.penalty_late, "rule 16: the give-way ship took no action");
    return;
  }
  const size_t ka = p.kp < both.size() ? p.kp : p.ka;
  const size_t kb = ka > p.ke ? ka - 1 : p.ke;
  const double range = p.cpas[kb].range, tcpa = p.cpas[kb].tcpa;
  const double early = earliness(p, kb, both[ka].first->t);
  if (early < 1.0)
    penalise(
        r, factor, cfg_.penalty_late * (1.0 - early),
        strFormat("rule 16: first %saction at t=%.0f s, %.0f m and %.0f s from CPA: late (early: %.0f m "
                  "or ",
                  p.kp < both.size() ? "apparent " : "", both[ka].first->t, range, tcpa, cfg_.early_range_m) +
            strFormat("%.0f s)", cfg_.early_tcpa_s));
}

// Rule 8(b): "a succession of small alterations of course and/or speed should be avoided". More than
// two manoeuvres in one sense in a row, each smaller than apparent_course_deg, within the passage.
void RunRecorder::judgeSuccession(const Passage& p, TargetResult& r, double& factor) const {
  const double t0 = p.both[p.ke].first->t, t1 = p.both[p.kc].first->t;
  int run = 0, sense = 0;
  std::string sizes;
  for (const Manoeuvre& m : *p.manoeuvres) {
    if (m.time < t0 || m.time > t1)
      continue;
    const int s = m.course_change > 0.0 ? 1 : -1;
    const bool small = std::fabs(radToDeg(m.course_change)) < cfg_.apparent_course_deg;
    if (!small || s != sense) {
      run = 0;
      sizes.clear();
    }
    sense = s;
    if (!small)
      continue;
    ++run;
    sizes += strFormat(run > 1 ? ", %.0f" : "%.0f", std::fabs(radToDeg(m.course_change)));
    if (run == 3) {
      penalise(
          r, factor, cfg_.penalty_succession,
          strFormat("rule 8(b): a succession of small alterations to %s (", s > 0 ? "starboard" : "port") +
              sizes + strFormat(" deg, each < %.0f deg)", cfg_.apparent_course_deg));
      return;
    }
  }
}

// Rules 14, 15 and 17(c): a turn to port while the risk lasts (the first alteration, or a swing across
// the entry course). A port turn that only the own ship's motion made a risk again (after kr) is excused
// when she was keeping out of the way of another ship at that moment, and named.
void RunRecorder::judgePortTurn(const Passage& p, TargetResult& r, double& factor, const char* rule,
                                const std::vector<GiveWayDuty>& duties) const {
  const double t = p.both[p.kport].first->t;
  if (p.kport > p.kr) {
    const auto duty = std::find_if(duties.begin(), duties.end(), [&](const GiveWayDuty& d) {
      return d.target != r.name && d.from <= t && t <= d.to;
    });
    if (duty != duties.end()) {
      r.notes.push_back(std::string(rule) +
                        strFormat(": the turn to port at t=%.0f s was made keeping out of the way of ", t) +
                        duty->target + ": excused");
      return;
    }
  }
  const std::string what =
      p.swing ? strFormat(
                    "swung across the entry course to %.0f deg to port at t=%.0f s (after %.0f deg to "
                    "starboard) while the risk lasted",
                    radToDeg(p.max_port), t, p.swing_from_deg)
              : strFormat("turned %.0f deg to port", radToDeg(p.max_port));
  const char* where = p.g.encounter == Encounter::HeadOn            ? " in a head-on encounter"
                      : p.g.encounter == Encounter::CrossingGiveWay ? " for a ship crossing from starboard"
                                                                    : " for a ship on the port side";
  penalise(r, factor, cfg_.penalty_port, std::string(rule) + ": " + what + where + forcedNote(p));
}

// An alternative open to the own ship at sample k (our reading, for a forced port turn and Rule
// 17(b)): an alteration of 10, 20, ... 90 deg to starboard of `course` at her speed, held until this
// target is past (its CPA on that course, at least a minute) and then back on `course` for as long
// again (at least 5 minutes), or half speed on `course`, that passes every ship (holding its course and
// speed) at the minimum separation or more and keeps the near-miss range from land (0.1 nm by default,
// the planners' default clearance from land). "" when none does.
std::string RunRecorder::alternativeOpen(const Passage& p, size_t k, double course) const {
  const Point& own = *p.both[k].first;
  const ShipState& tgt = p.both[k].second->s;
  for (int turn = 10; turn <= 90; turn += 10) {
    const Eigen::Vector2d v = courseSpeedToVelocity(course + degToRad(turn), own.s.speed);
    const Cpa c = computeCpa(own.s.position, v, tgt.position, tgt.velocity());
    const double hold = std::max(60.0, c.tcpa);
    if (keepsClear(p, own, v, hold, courseSpeedToVelocity(course, own.s.speed)))
      return strFormat("%d deg to starboard was open", turn);
  }
  const Eigen::Vector2d half = courseSpeedToVelocity(course, 0.5 * own.s.speed);
  const Cpa c = computeCpa(own.s.position, half, tgt.position, tgt.velocity());
  if (keepsClear(p, own, half, std::max(60.0, c.tcpa), half))
    return "half speed was open";
  return "";
}

// Whether the own ship, from `own`, at velocity v1 for `hold` seconds and then at v2 for as long again
// (at least 300 s), keeps r_min from every other ship (holding its course and speed from that instant)
// and the near-miss range from land.
bool RunRecorder::keepsClear(const Passage& p, const Point& own, const Eigen::Vector2d& v1, double hold,
                             const Eigen::Vector2d& v2) const {
  const double resume = std::max(300.0, hold);
  const Eigen::Vector2d bend = own.s.position + v1 * hold, end = bend + v2 * resume;
  for (size_t k = 0; k < tracks_.size(); ++k) {
    if (k == p.own)
      continue;
    const Point* at = sampleAt(k, own.t);
    if (!at)
      continue;
    const Eigen::Vector2d tv = at->s.velocity();
    const Eigen::Vector2d t_bend = at->s.position + tv * hold;
    if (closestOnLeg(own.s.position, v1, at->s.position, tv, hold) < r_min_ ||
        closestOnLeg(bend, v2, t_bend, tv, resume) < r_min_)
      return false;
  }
  for (const StaticObstacle& o : info_.obstacles)
    if (obstacleDistance(o, own.s.position, bend) < r_nm_ || obstacleDistance(o, bend, end) < r_nm_)
      return false;
  return true;
}

// The end of a port-turn note (Rules 14, 15, 17(c)): whether an alternative was open at the port turn
// itself (on the sample before it), to starboard of the entry course. Rules 14 and 15 ask the give-way
// ship to turn to starboard, Rule 17(c) the stand-on ship not to turn to port for a ship on her port
// side: the turn was forced (our reading; it adds to the note, the finding and its penalty stand) only
// when no alternative was open.
std::string RunRecorder::forcedNote(const Passage& p) const {
  const std::string open =
      alternativeOpen(p, p.kport > p.ke ? p.kport - 1 : p.ke, p.both[p.ke].first->s.course);
  return open.empty() ? "; forced: no turn of 10-90 deg to starboard nor half speed kept clear"
                      : "; not forced: " + open;
}

// Ship k's sample at time t, or nullptr when she has none then (or was not in the water).
const RunRecorder::Point* RunRecorder::sampleAt(size_t k, double t) const {
  const auto& pts = tracks_[k].points;
  const auto it =
      std::lower_bound(pts.begin(), pts.end(), t - 1e-6, [](const Point& q, double tt) { return q.t < tt; });
  return it == pts.end() || std::fabs(it->t - t) > 1e-6 || !it->active ? nullptr : &*it;
}

// The CPA of ships i and j from their samples at time t (nullopt when either is not there then).
std::optional<Cpa> RunRecorder::cpaAt(size_t i, size_t j, double t) const {
  const Point *a = sampleAt(i, t), *b = sampleAt(j, t);
  if (!a || !b)
    return std::nullopt;
  return computeCpa(a->s, b->s);
}

// A duty to keep out of the way of another ship excuses an early stand-on action only when it is real
// (our reading of Rule 17 with several ships): at the action that ship is within its own action window
// (0 < TCPA <= duty_tcpa_s), and duty_effect_s later the action has widened that ship's CPA without
// cutting this target's below the smaller of its CPA before the action and r_pref. "" when it is real,
// else why not.
std::string RunRecorder::dutyNotReal(const Passage& p, const GiveWayDuty& d, double t_action) const {
  const double before = p.ka > p.ke ? p.both[p.ka - 1].first->t : t_action;
  const double after = t_action + cfg_.duty_effect_s;
  const std::optional<Cpa> x0 = cpaAt(p.own, d.ship, before), x1 = cpaAt(p.own, d.ship, after);
  const std::optional<Cpa> s0 = cpaAt(p.own, p.target, before), s1 = cpaAt(p.own, p.target, after);
  if (!x0 || !x1 || !s0 || !s1)
    return "the ships' tracks end before the action took effect";
  if (!(x0->tcpa > 0.0 && x0->tcpa <= cfg_.duty_tcpa_s))
    return strFormat("its TCPA %.0f s is outside %.0f s", x0->tcpa, cfg_.duty_tcpa_s);
  if (x1->dcpa <= x0->dcpa)
    return strFormat("the action did not widen its CPA (%.0f m -> %.0f m)", x0->dcpa, x1->dcpa);
  if (s1->dcpa < std::min(s0->dcpa, r_pref_))
    return strFormat("the action cut this ship's CPA (%.0f m -> %.0f m)", s0->dcpa, s1->dcpa);
  return "";
}

// The stand-on ship: Rule 17 (no action before the give-way ship's action is clearly lacking; not to
// port for a ship on the port side). An early action taken while the own ship had to keep out of the
// way of another ship (`duties`) is not held against her: she cannot keep her course and speed for one
// ship and keep out of the way of another, and the rules give way to the duty to keep out of the way
// (Rules 16 and 17(d) state it for one pair; our reading for several, noted in the result). Rule 17(c)
// still applies to that action.
void RunRecorder::judgeStandOn(const Passage& p, TargetResult& r, double& factor,
                               const std::vector<GiveWayDuty>& duties) const {
  const Instants& both = p.both;
  size_t ku = both.size();
  for (size_t k = p.ke; k < both.size() && ku == both.size(); ++k)
    if (p.cpas[k].tcpa >= 0.0 && riskLevel(p.cpas[k].tcpa, p.cpas[k].dcpa, cfg_.hu) == RiskLevel::Urgent)
      ku = k;
  const bool early = p.ka < both.size() && p.ka < ku;
  const double t_action = early ? both[p.ka].first->t : 0.0;
  std::string unreal;  // why the duties at t_action do not excuse the action
  const auto duty = std::find_if(duties.begin(), duties.end(), [&](const GiveWayDuty& d) {
    if (d.target == r.name || d.from > t_action || t_action > d.to)
      return false;
    const std::string why = dutyNotReal(p, d, t_action);
    if (!why.empty() && unreal.empty())
      unreal = "; not excused by " + d.target + ": " + why;
    return why.empty();
  });
  if (early && duty != duties.end()) {
    r.notes.push_back(
        strFormat("rule 17 not applied: the stand-on ship altered at t=%.0f s while keeping out of "
                  "the way of ",
                  both[p.ka].first->t) +
        duty->target + strFormat(" (its passage t=%.0f-%.0f s)", duty->from, duty->to));
  } else if (early) {
    const std::string urgent = ku < both.size() ? strFormat("urgent only at t=%.0f s", both[ku].first->t)
                                                : std::string("never urgent");
    penalise(
        r, factor, cfg_.penalty_stand_on,
        strFormat("rule 17: the stand-on ship altered (%.0f deg, speed -%.0f %%) at t=%.0f s, before the "
                  "give-way ship's action was clearly lacking (",
                  p.alter_deg, 100.0 * p.speed_drop, both[p.ka].first->t) +
            urgent + ")" + unreal);
    return;
  }
  if (p.kport < both.size() && p.g.encounter == Encounter::CrossingStandOn)
    judgePortTurn(p, r, factor, "rule 17(c)", duties);
  judgeExtremis(p, r, factor);
}

// Whether the give-way ship alone could still keep r_min at sample k (Rule 17(b), our reading): with
// the own ship holding her course and speed, and the target holding hers for extremis_delay_s (the helm
// and the swing), then turning 0, 10, ... 90 deg to either side at her speed, or keeping her course at
// half speed or stopped; the closest approach of one of these is r_min or more. Velocity changes are
// taken as instant after the delay, which puts the point late, in the stand-on ship's favour.
bool RunRecorder::giveWayAloneKeepsClear(const Passage& p, size_t k) const {
  const ShipState& own = p.both[k].first->s;
  const ShipState& tgt = p.both[k].second->s;
  const Eigen::Vector2d vo = own.velocity(), vt = tgt.velocity();
  const double delay = cfg_.extremis_delay_s;
  if (closestOnLeg(own.position, vo, tgt.position, vt, delay) < r_min_)
    return false;
  const Eigen::Vector2d o1 = own.position + vo * delay, t1 = tgt.position + vt * delay;
  auto clear = [&](double turn_deg, double speed_factor) {
    const Cpa c = computeCpa(
        o1, vo, t1, courseSpeedToVelocity(tgt.course + degToRad(turn_deg), speed_factor * tgt.speed));
    return (c.tcpa > 0.0 ? c.dcpa : c.range) >= r_min_;
  };
  for (int turn = -90; turn <= 90; turn += 10)
    if (clear(turn, 1.0))
      return true;
  return clear(0.0, 0.5) || clear(0.0, 0.0);
}

// Rule 17(b): "When, from any cause, the vessel required to keep her course and speed finds herself so
// close that collision cannot be avoided by the action of the give-way vessel alone, she shall take
// such action as will best aid to avoid collision." Read with the minimum separation for collision
// (the referee's line): from the first sample (kx) at which the give-way ship alone could no longer keep
// r_min, the own ship made no action (action_course_deg from her course at kx, or action_speed_fraction
// of her speed) before the range fell below r_min, although an alternative was open at kx.
void RunRecorder::judgeExtremis(const Passage& p, TargetResult& r, double& factor) const {
  const Instants& both = p.both;
  size_t kx = p.ke;
  while (kx <= p.kc && (p.cpas[kx].tcpa <= 0.0 || giveWayAloneKeepsClear(p, kx)))
    ++kx;
  if (kx > p.kc)
    return;
  const ShipState& at = both[kx].first->s;
  size_t kb = kx;
  for (; kb <= p.kc && p.cpas[kb].range >= r_min_; ++kb) {
    const ShipState& s = both[kb].first->s;
    if (std::fabs(wrapPi(s.course - at.course)) >= degToRad(cfg_.action_course_deg) ||
        s.speed <= (1.0 - cfg_.action_speed_fraction) * at.speed)
      return;  // she acted
  }
  if (kb > p.kc)
    return;  // the range never fell below r_min
  const std::string open = alternativeOpen(p, kx, at.course);
  if (open.empty())
    return;
  penalise(r, factor, cfg_.penalty_extremis,
           strFormat("rule 17(b): the stand-on ship held her course and speed into %.0f m (< %.0f m) from "
                     "t=%.0f s, when the give-way ship alone could no longer keep %.0f m; ",
                     p.cpas[p.kc].range, r_min_, both[kx].first->t, r_min_) +
               open);
}

void RunRecorder::finishScore(TargetResult& r, double factor) const {
  r.score = std::clamp(r.safety * factor, 0.0, 1.0);
  if (r.collision) {
    r.notes.push_back("collision");
    r.colregs_ok = false;
  } else if (std::isfinite(r.min_distance) && r.min_distance < r_min_) {
    r.notes.push_back(strFormat("closest approach %.0f m < minimum %.0f m", r.min_distance, r_min_));
  }
}

// The entry into the rules: the first instant of a risk of collision (both.size() when none); cpas
// gets the CPA of every instant.
size_t RunRecorder::entryInstant(const Instants& both, std::vector<Cpa>& cpas) const {
  cpas.resize(both.size());
  size_t ke = both.size();
  for (size_t k = 0; k < both.size(); ++k) {
    cpas[k] = computeCpa(both[k].first->s, both[k].second->s);
    const Cpa& c = cpas[k];
    if (ke == both.size() && c.relative_motion && c.tcpa > 0.0 && c.tcpa <= cfg_.entry_tcpa_s &&
        c.dcpa < cfg_.entry_dcpa_m && c.range <= cfg_.colregs.max_range_m)
      ke = k;
  }
  return ke;
}

RunRecorder::PairHistory RunRecorder::pairHistory(size_t i, size_t j) const {
  PairHistory h;
  h.both = commonInstants(i, j);
  h.ke = entryInstant(h.both, h.cpas);
  return h;
}

std::vector<RunRecorder::GiveWayDuty> RunRecorder::giveWayDuties(
    const std::vector<PairHistory>& pairs) const {
  std::vector<GiveWayDuty> out;
  for (size_t j = 0; j < pairs.size(); ++j) {
    const PairHistory& h = pairs[j];
    if (h.ke == h.both.size())
      continue;
    const Passage p = passage(h.both, h.cpas, h.ke);
    if (givesWay(p.g.role))
      out.push_back({info_.ships[j].name, j, h.both[h.ke].first->t, h.both[p.kc].first->t});
  }
  return out;
}

TargetResult RunRecorder::evaluatePair(size_t i, size_t j, const PairHistory& h,
                                       const std::vector<GiveWayDuty>& duties,
                                       const std::vector<Manoeuvre>& manoeuvres) const {
  TargetResult r;
  r.name = info_.ships[j].name;
  r.min_distance = min_dist_[i][j] < kFar ? min_dist_[i][j] : kNaN;
  if (std::isfinite(r.min_distance)) {
    r.closest_time = closest_[i][j].t;
    r.own_at_closest = closest_[i][j].a;
    r.target_at_closest = closest_[i][j].b;
  }
  r.collision = collided_[i][j] != 0;
  r.safety = r.collision ? 0.0 : safetyScore(r.min_distance, r_pref_, r_min_, r_nm_, cfg_.safety_at_r_min);
  const Instants& both = h.both;
  if (both.empty()) {
    finishScore(r, 1.0);
    return r;
  }
  const Cpa& c0 = h.cpas.front();
  r.tcpa_at_start = c0.tcpa;
  r.dcpa_at_start = c0.dcpa;
  if (h.ke == both.size()) {
    const EncounterGeometry g =
        classifyEncounter(both.front().first->s, both.front().second->s, c0, cfg_.colregs);
    r.encounter = g.encounter;
    r.role = g.role;
    r.notes.push_back("no risk of collision developed: rules 8 and 13-17 not evaluated");
    finishScore(r, 1.0);
    return r;
  }
  r.evaluated = true;
  Passage p = passage(both, h.cpas, h.ke);
  p.own = i;
  p.target = j;
  p.manoeuvres = &manoeuvres;
  r.encounter = p.g.encounter;
  r.role = p.g.role;
  r.first_side = p.first_side;
  double factor = 1.0;
  if (givesWay(p.g.role))
    judgeGiveWay(p, r, factor, duties);
  else if (p.g.role == OwnRole::StandOn)
    judgeStandOn(p, r, factor, duties);
  finishScore(r, factor);
  return r;
}

ShipResult RunRecorder::evaluateShip(size_t i) const {
  ShipResult s;
  s.name = info_.ships[i].name;
  s.planner = info_.ships[i].planner;
  const Track& tr = tracks_[i];
  double min_sep = kFar;
  for (size_t j = 0; j < tracks_.size(); ++j) {
    if (j == i)
      continue;
    s.collision = s.collision || collided_[i][j];
    min_sep = std::min(min_sep, min_dist_[i][j]);
  }
  s.min_separation = min_sep < kFar ? min_sep : kNaN;
  s.grounding = grounded_[i] != 0;
  s.min_obstacle_distance = min_obstacle_[i] < kFar ? min_obstacle_[i] : kNaN;
  s.arrived = std::isfinite(arrival_[i]);
  s.time_to_goal = arrival_[i];
  s.path_length = tr.path_length;
  const auto& goal = info_.ships[i].goal;
  if (s.arrived && goal && tr.have_first) {
    const double straight = (*goal - tr.first_pos).norm();
    if (straight > 1.0)
      s.path_ratio = tr.path_length / straight;
  }
  s.manoeuvres = manoeuvres(tr);
  double sum = 0.0, safety_sum = 0.0;
  int evaluated = 0;
  // Each pair's instants and CPAs once, for the duties and the pair's own judgement.
  std::vector<PairHistory> pairs(tracks_.size());
  for (size_t j = 0; j < tracks_.size(); ++j)
    if (j != i)
      pairs[j] = pairHistory(i, j);
  const std::vector<GiveWayDuty> duties = giveWayDuties(pairs);
  for (size_t j = 0; j < tracks_.size(); ++j) {
    if (j == i || tracks_[j].points.empty())
      continue;
    s.targets.push_back(evaluatePair(i, j, pairs[j], duties, s.manoeuvres));
    const TargetResult& t = s.targets.back();
    safety_sum += t.score;
    if (t.evaluated) {
      sum += t.score;
      ++evaluated;
    }
  }
  if (s.collision || s.grounding)  // grounding is as bad as a collision
    s.colregs_score = 0.0;
  else if (evaluated > 0)
    s.colregs_score = sum / evaluated;
  else if (!s.targets.empty())
    s.colregs_score = safety_sum / static_cast<double>(s.targets.size());
  else
    s.colregs_score = 1.0;
  return s;
}

RunResult RunRecorder::finish() const {
  RunResult r;
  r.scenario = info_.scenario;
  r.planner = info_.planner;
  r.seed = info_.seed;
  r.origin = info_.origin;
  r.own = evaluateShip(0);
  r.own.planner = info_.planner;
  r.collision = r.own.collision;
  for (size_t i = 1; i < collided_.size(); ++i)
    for (size_t j = i + 1; j < collided_.size(); ++j)
      r.collisions_between_targets += collided_[i][j];
  r.safety_violation = std::isfinite(r.own.min_separation) && r.own.min_separation < info_.min_separation;
  if (!plan_times_.empty()) {
    std::vector<double> v = plan_times_;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    r.plan_time.median_ms = 1e3 * (n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]));
    r.plan_time.max_ms = 1e3 * v.back();
    r.plan_time.count = static_cast<long>(n);
  }
  r.wall_time = wall_time_;
  r.route = route_stats_;
  if (passing_.second > 0.0) {
    r.passing_min = passing_.first;
    r.passing_max = passing_.second;
  }
  r.route.legs = info_.route.size();
  if (info_.human) {
    r.human = info_.human;
    if (info_.human->min_separation_m > 0.0)
      r.separation_vs_human = r.own.min_separation / info_.human->min_separation_m;
    if (r.own.arrived)
      r.time_vs_human = r.own.time_to_goal / info_.human->time_s;
  }
  r.multi_agent = info_.multi_agent;
  if (r.multi_agent)
    for (size_t i = 0; i < info_.ships.size(); ++i)
      if (i == 0 || !info_.ships[i].planner.empty())
        r.ships.push_back(i == 0 ? r.own : evaluateShip(i));
  return r;
}

}  // namespace asv
