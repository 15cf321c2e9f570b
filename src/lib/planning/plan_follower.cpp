#include "asv_core/planning/plan_follower.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "asv_core/common/format.h"
#include "asv_core/common/geometry.h"
#include "asv_core/common/units.h"
#include "asv_core/planning/land_route.h"
#include "asv_core/planning/safety_net.h"
#include "asv_core/risk/colregs.h"
#include "asv_core/world/fairway.h"

namespace asv {

namespace {
// Over this last stretch of the route the line of sight comes back from the starboard lane of a narrow
// fairway to the goal, so that the ship arrives at it (a berth need not lie on the lane). Our choice:
// 600 m, two lookaheads.
constexpr double kFairwayTaper = 600.0;
// A ship more than kLaneTolerance from the starboard lane of a narrow fairway joins it at a point
// kLaneJoinRatio times that distance ahead (at least the line-of-sight lookahead, at most
// kLaneJoinMax): across at about 11 deg, not over the whole leg. Our choices: 25 m (a few beams), 5, 1.5 km.
constexpr double kLaneTolerance = 25.0;
constexpr double kLaneJoinRatio = 5.0;
constexpr double kLaneJoinMax = 1500.0;
// Rule 9(e): a ship the own ship overtakes within this distance ahead in a narrow fairway, with no room
// to pass her, is followed at her speed. Our choice: 500 m, a few cables; farther off she closes in.
constexpr double kOvertakeLook = 500.0;
// The starboard lane or edge is at most this far across from the route (the master's voyage plan, made
// on a better chart than ours). Our choice, 150 m.
constexpr double kMaxLaneShift = 150.0;
}  // namespace

void PlanFollowerConfig::validate() const {
  auto require = [](bool ok, const char* what) {
    if (!ok)
      throw std::invalid_argument(std::string("plan follower: ") + what + " (see planner_node.yaml)");
  };
  require(cruise_speed >= 0.0, "cruise_speed must be >= 0 m/s");
  require(replan_period > 0 && min_replan_interval >= 0,
          "replan_period must be > 0, min_replan_interval >= 0 s");
  require(time_budget > 0, "time_budget must be > 0 s");
  require(waypoint_acceptance > 0, "waypoint_acceptance must be > 0 m");
  require(fallback_speed_factor >= 0 && fallback_speed_factor <= 1,
          "fallback_speed_factor must be in [0, 1]");
  require(extremis_range >= 0 && plan_clearance >= 0, "extremis_range and plan_clearance must be >= 0 m");
  require(prediction_horizon > 0, "prediction_horizon must be > 0 s");
  require(min_separation >= 0 && risk_clear_time >= 0, "min_separation and risk_clear_time must be >= 0");
  require(degraded_plan_hold >= 0, "degraded_plan_hold must be >= 0 s");
  require(duty_window_s >= 0, "duty_window_s must be >= 0 s");
  require(min_obstacle_clearance_m >= 0, "min_obstacle_clearance_m must be >= 0 m");
  require(narrow_fairway_width_m >= 0, "narrow_fairway_width_m must be >= 0 m");
  require(limits.max_speed > 0 && limits.min_speed >= 0 && limits.min_speed <= limits.max_speed,
          "speeds must satisfy 0 <= min_speed <= max_speed, max_speed > 0");
  require(limits.turn_rate > 0 && limits.turn_delay >= 0, "turn_rate must be > 0, turn_delay >= 0");
}

PlanFollowerConfig PlanFollowerConfig::fromParams(const ParamMap& p) {
  PlanFollowerConfig c;
  c.cruise_speed = p.getDouble("cruise_speed", c.cruise_speed);
  c.replan_period = p.getDouble("replan_period", c.replan_period);
  c.min_replan_interval = p.getDouble("min_replan_interval", c.min_replan_interval);
  c.time_budget = p.getDouble("time_budget", c.time_budget);
  c.waypoint_acceptance = p.getDouble("waypoint_acceptance", c.waypoint_acceptance);
  c.fallback_speed_factor = p.getDouble("fallback_speed_factor", c.fallback_speed_factor);
  c.extremis_range = p.getDouble("extremis_range", c.extremis_range);
  c.plan_clearance = p.getDouble("plan_clearance", c.plan_clearance);
  c.prediction_horizon = p.getDouble("prediction_horizon", c.prediction_horizon);
  c.seed = p.getInt("seed", c.seed);
  c.min_separation = p.getDouble("min_separation", c.min_separation);
  c.stand_on_policy = p.getBool("stand_on_policy", c.stand_on_policy);
  c.duty_window_s = p.getDouble("duty_window_s", c.duty_window_s);
  c.replan_on_risk = p.getBool("replan_on_risk", c.replan_on_risk);
  c.risk_clear_time = p.getDouble("risk_clear_time", c.risk_clear_time);
  c.restricted_passing = p.getBool("restricted_passing", c.restricted_passing);
  c.narrow_fairway_width_m = p.getDouble("narrow_fairway_width_m", c.narrow_fairway_width_m);
  c.degraded_plan_hold = p.getDouble("degraded_plan_hold", c.degraded_plan_hold);
  c.min_obstacle_clearance_m = p.getDouble("min_obstacle_clearance_m", c.min_obstacle_clearance_m);
  c.limits.max_speed = p.getDouble("max_speed", c.limits.max_speed);
  c.limits.min_speed = p.getDouble("min_speed", c.limits.min_speed);
  c.limits.turn_rate = p.getDouble("turn_rate", c.limits.turn_rate);
  c.limits.turn_delay = p.getDouble("turn_delay", c.limits.turn_delay);
  c.validate();
  return c;
}

bool riskBlindPlanning(bool risk_fresh, double now, double first_input, double stale_after) {
  return !risk_fresh && first_input >= 0.0 && now - first_input >= stale_after;
}

std::vector<PlannerTarget> selectPlannerTargets(const std::string& own_id,
                                                const std::vector<ShipState>& tracks,
                                                const std::map<std::string, PlannerTarget>& assessed,
                                                bool risk_alive) {
  std::vector<PlannerTarget> out;
  for (const ShipState& s : tracks) {
    if (s.id == own_id || !allFinite({s.position.x(), s.position.y(), s.course, s.speed}))
      continue;
    auto it = assessed.find(s.id);
    if (risk_alive && it == assessed.end())
      continue;
    PlannerTarget t = it == assessed.end() ? PlannerTarget() : it->second;
    t.state = s;
    out.push_back(t);
  }
  return out;
}

bool altersToPort(const Plan& plan, const PlanningProblem& problem) {
  if (plan.status != PlanStatus::Ok || !std::isfinite(plan.course_setpoint))
    return false;
  const double threshold = degToRad(5.0);
  // The evaluator judges a passage by its larger departure, and the follower's flown track overshoots a
  // planned leg by several degrees: a port departure within this of the starboard one is the larger.
  // Our choice: 10 deg.
  const double overshoot = degToRad(10.0);
  // The legs that begin before the last target's CPA are the manoeuvre (later ones are the way on). A
  // plan may hold on and then turn, or swing to starboard and then back across its course to port
  // (ACO's lattice paths do).
  double encounter_end = 0.0;
  for (const auto& t : problem.targets)
    encounter_end = std::max(encounter_end, computeCpa(problem.own, t.state).tcpa);
  double starboard = 0.0, port = 0.0;
  bool legs = false;
  const auto& w = plan.waypoints;
  for (size_t k = 1; k < w.size() && w[k - 1].time <= encounter_end; ++k) {
    const Eigen::Vector2d leg = w[k].position - w[k - 1].position;
    if (leg.norm() < 1.0)
      continue;
    const double alteration = wrapPi(courseOf(leg) - problem.own.course);
    starboard = std::max(starboard, alteration);
    port = std::max(port, -alteration);
    legs = true;
  }
  if (!legs)
    port = -wrapPi(plan.course_setpoint - problem.own.course);
  return port > threshold && port + overshoot > starboard;
}

namespace {

// A plan the ship will sail: Ok, or a planner's least-violation Fallback (MOPSO's when no particle is
// feasible), which the follower steers all the same. NoSolution is the follower's to handle.
bool sailed(const Plan& plan) {
  return plan.status != PlanStatus::NoSolution;
}

// The plan keeps clear of land, flown as the follower and later plans fly it (planRoute).
bool clearOfLand(const Plan& plan, const PlanningProblem& problem, double required) {
  return !sailed(plan) || routeKeepsOffLand(planRoute(plan, problem), problem, required);
}

}  // namespace

namespace {

// The preferred passing distance is not worth the ship's way: a plan that slows her below half the
// speed she plans for (the evaluator's apparent speed change, Rule 8) is not kept for it. Our choice.
bool keepsWay(const Plan& plan, const PlanningProblem& problem) {
  const double slowest = 0.5 * problem.own.speed;
  if (plan.speed_setpoint < slowest)
    return false;
  for (size_t k = 1; k < plan.waypoints.size(); ++k)
    if (plan.waypoints[k].speed < slowest)
      return false;
  return true;
}

// The minimum separation under a restricted-waters cap (0: none): the ship's own domain, not the
// situation's sea-scale minimum, is what she can keep there.
double cappedSeparation(double min_separation, double cap) {
  return cap > 0.0 ? std::min(min_separation, cap) : min_separation;
}

// The own ship has to keep out of the way of a target (Rules 13-15: she overtakes it, meets it head-on or
// it crosses from her starboard side).
bool keepsOutOfTheWay(const PlannerTarget& t) {
  return givesWay(ownRole(t.encounter));
}

// She keeps out of the way of some target and has no other duty: no ship she stands on for, no other
// encounter (a target with none is only passing).
bool onlyKeepsOutOfTheWay(const PlanningProblem& pr) {
  const auto& ts = pr.targets;
  return pr.stand_on_for.empty() &&
         std::any_of(ts.begin(), ts.end(), [](const auto& t) { return keepsOutOfTheWay(t); }) &&
         std::all_of(ts.begin(), ts.end(),
                     [](const auto& t) { return keepsOutOfTheWay(t) || t.encounter == Encounter::None; });
}

// Land lies within `range` of the own ship (open water is kOpenWater without it, planning.h).
bool landWithin(const PlanningProblem& problem, double range) {
  return trackObstacleDistance({problem.own.position}, problem.obstacles) < range;
}

// Why a plan breaks a shared rule, or "" when it keeps them all.
struct RuleCheck {
  const PlanningProblem& problem;
  double land_required = 0.0;
  bool give_way = false;     // she gives way in a head-on or crossing encounter (Rules 14, 15)
  bool port_side = false;    // a ship crossing from her port side, which she stood on for (Rule 17(c))
  bool keeps_clear = false;  // she keeps out of the way of some target (Rules 13-15)

  std::string broken(const Plan& p) const {
    if (!clearOfLand(p, problem, land_required))
      return "came within " + std::to_string(static_cast<int>(land_required)) + " m of land";
    // The minimum itself: the planners aim at kSeparationMargin x it (planning.h), and so does the
    // separation manoeuvre, so a plan a little under their aim is still kept.
    const double wanted = problem.min_separation;
    if (sailed(p) && wanted > 0.0) {
      const double sep = planSeparation(p, problem);
      if (sep < wanted)
        return "passed " + std::to_string(static_cast<int>(sep)) + " m from a ship, under " +
               std::to_string(static_cast<int>(wanted)) + " m";
    }
    if (p.status == PlanStatus::Ok && closesStandOn(p))
      return kClosesStandOn;
    if ((give_way || port_side) && altersToPort(p, problem))
      return give_way ? "altered to port, Rules 14/15"
                      : "altered to port for a ship on the port side, Rule 17(c)";
    return "";
  }

  // Rule 17(a)(i): the plan takes the ship closer to a ship she stands on for than holding course and
  // speed would, and inside the margin on the minimum separation. While she keeps out of the way of
  // another ship that duty comes first (she cannot hold her course and speed for one ship and keep out
  // of the way of another: Rules 16 and 17(d), the evaluator's reading for several ships), and the ship
  // she stands on for is only to be passed at the minimum separation.
  bool closesStandOn(const Plan& p) const {
    if (problem.stand_on_for.empty() || !(problem.min_separation > 0.0))
      return false;
    PlanningProblem watched = problem;
    watched.targets = problem.stand_on_for;
    const double planned = planSeparation(p, watched);
    if (keeps_clear)
      return planned < problem.min_separation;
    return planned < kSeparationMargin * problem.min_separation && planned < holdSeparation(watched) - 1.0;
  }
  // How close holding course and speed passes the ships she stands on for: the same for every plan
  // judged, so worked out once (a hold is searched over many predicted passes, holdCoursePlan).
  double holdSeparation(const PlanningProblem& watched) const {
    if (!hold_separation)
      hold_separation = planSeparation(holdCoursePlan(problem, problem.stand_on_for), watched);
    return *hold_separation;
  }
  mutable std::optional<double> hold_separation{};
  static constexpr const char* kClosesStandOn = "closed a ship the own ship stands on for, Rule 17(a)(i)";

  // The separation net's problem for a manoeuvre that must keep every rule (one to take instead of a
  // port plan). While she keeps out of the way of some ship, a ship she stands on for is to be passed at
  // the minimum separation (closesStandOn), so the net keeps its margin from it too: a manoeuvre that
  // runs into it would be refused.
  PlanningProblem netProblem() const {
    PlanningProblem q = problem;
    if (keeps_clear)
      q.targets.insert(q.targets.end(), q.stand_on_for.begin(), q.stand_on_for.end());
    return q;
  }
};

// The preferred passing distance first, in open water (kOpenWater, planning.h): in a port or a channel
// the minimum separation is the standard, and the wider pass only costs time. In this order:
// 1. the planner's plan for it, when it keeps the preferred distance over the whole pass (passingHorizon:
//    a slow overtaking lasts beyond the prediction horizon);
// 2. when keeping out of the way is the own ship's only duty, the net's turn to starboard at full speed
//    that does (a planner's plan can fall short: a search horizon that ends before a slow overtaking's
//    CPA, a return leg the planner does not score). Not with other duties: in crowded waters a wide
//    swing for one ship runs into the others and costs arrivals;
// 3. the planner's plan for it as it is, when it keeps the minimum.
// Each only when it keeps the ship's way and every shared rule; `spent` gets the planner's time.
std::optional<Plan> preferredPlan(const std::function<Plan(const PlanningProblem&)>& make,
                                  const PlanningProblem& problem, const RuleCheck& check, double& spent) {
  const double preferred = kPreferredSeparation * problem.min_separation;
  if (landWithin(problem, std::max(preferred, kOpenWater)))
    return std::nullopt;
  PlanningProblem wide = problem;
  wide.min_separation = preferred;
  Plan plan = make(wide);
  spent = plan.compute_time;
  PlanningProblem whole_pass = wide;
  whole_pass.prediction_horizon = passingHorizon(wide);
  const bool usable = plan.status == PlanStatus::Ok && keepsWay(plan, problem) && check.broken(plan).empty();
  const std::string label =
      " (for the preferred distance, " + std::to_string(static_cast<int>(preferred)) + " m";
  if (usable && planSeparation(plan, whole_pass) >= preferred) {
    plan.message += label + ")";
    return plan;
  }
  if (onlyKeepsOutOfTheWay(problem)) {
    double predicted = 0.0;
    Plan net = separationManoeuvre(whole_pass, check.land_required, "preferred distance: " + plan.message,
                                   NetOptions::preferredDistance(), &predicted);
    if (keepsWay(net, problem) && predicted >= preferred && check.broken(net).empty()) {
      net.compute_time = spent;
      return net;
    }
  }
  if (!usable)
    return std::nullopt;
  plan.message += label + "; not kept over the whole pass)";
  return plan;
}

// Rule 17(a)(i): while she stands on for a ship in a risk of collision (PlanningProblem::standing_on)
// and keeps out of the way of none, she keeps her course and speed until it is past, through a bend of
// her route too (the give-way ship acts on the course she holds): the hold (holdCoursePlan), when it
// keeps every other rule (land, the minimum separation from the other ships). No planner is asked.
// In open water only (kOpenWater): in a harbour or a channel her route's bends follow the water (Rule
// 9), and a hold that passes the other ships of a crowded port at its small minimum would keep the
// planner from them.
std::optional<Plan> standOn(const PlanningProblem& problem, const RuleCheck& check) {
  if (problem.standing_on.empty() || check.keeps_clear || landWithin(problem, kOpenWater))
    return std::nullopt;
  Plan hold = holdCoursePlan(problem, problem.standing_on);
  if (!check.broken(hold).empty())
    return std::nullopt;
  hold.message = "stand on (Rule 17(a)(i)) for " + problem.standing_on.front().state.id + " until past";
  return hold;
}

}  // namespace

void applyPlannerMode(PlanFollowerConfig& cfg, PlannerMode mode, bool plans_once, bool own_trigger) {
  if (mode != PlannerMode::Paper)
    return;
  cfg.stand_on_policy = false;
  cfg.min_separation = 0.0;
  cfg.restricted_passing = false;
  cfg.narrow_fairway_width_m = 0.0;
  // No paper replans because a plan passes a ship closer than the stack's plan_clearance, and none
  // turns hard to starboard in extremis or slows when its planner finds nothing: a failed plan holds
  // course and speed. Still this stack's own in paper mode (docs/results): replanning on rising risk
  // (unless the method plans once), when the picture goes stale, at a route waypoint or when land comes
  // within the clearance, and the stop short of land.
  cfg.plan_clearance = 0.0;
  cfg.extremis_range = 0.0;
  cfg.fallback_speed_factor = 1.0;
  if (plans_once)
    cfg.replan_on_risk = false;
  cfg.replan_each_cycle = own_trigger;
}

Plan planInMode(const std::function<Plan(const PlanningProblem&)>& make, const PlanningProblem& problem,
                PlannerMode mode) {
  return mode == PlannerMode::Paper ? make(problem) : planUnderSharedRules(make, problem);
}

Plan planUnderSharedRules(const std::function<Plan(const PlanningProblem&)>& make, PlanningProblem problem,
                          int retries) {
  RuleCheck check{problem};
  check.land_required = landRequirement(problem);
  for (const auto& t : problem.targets) {
    check.give_way |= t.encounter == Encounter::HeadOn || t.encounter == Encounter::CrossingGiveWay;
    check.port_side |= t.encounter == Encounter::CrossingStandOn;
    check.keeps_clear |= keepsOutOfTheWay(t);
  }
  if (std::optional<Plan> hold = standOn(problem, check))
    return *hold;
  const bool separation_net = problem.min_separation > 0.0 && !problem.targets.empty();
  double preferred_time = 0.0;
  if (separation_net)
    if (std::optional<Plan> wide = preferredPlan(make, problem, check, preferred_time))
      return *wide;
  Plan first = make(problem);
  first.compute_time += preferred_time;
  const std::string why = check.broken(first);
  if (why.empty() && (first.status != PlanStatus::NoSolution || !separation_net))
    return first;
  if (first.status == PlanStatus::NoSolution) {  // the net instead of the follower's blind fallback
    Plan net = separationManoeuvre(problem, check.land_required, "no solution: " + first.message);
    net.compute_time = first.compute_time;
    return net;
  }
  if (why == RuleCheck::kClosesStandOn) {  // the planner cannot know: stand on until she is past
    Plan hold = holdCoursePlan(problem, problem.stand_on_for);
    if (check.broken(hold).empty()) {
      hold.compute_time = first.compute_time;
      hold.message = "stand on (Rule 17(a)(i)): the plan (" + first.message + ") " + why;
      return hold;
    }
  }
  const PlanningProblem original = problem;
  for (int k = 1; k <= retries; ++k) {
    problem.seed += 0x9E3779B9ULL * static_cast<uint64_t>(k);
    Plan again = make(problem);
    if (check.broken(again).empty()) {
      again.message += " (retry " + std::to_string(k) + ": the first plan " + why + ")";
      again.compute_time += first.compute_time;
      return again;
    }
  }
  // The rules in order of weight: land and separation are safety, a port alteration is a rule finding.
  // The net's manoeuvre tries starboard first: taken when it keeps every rule; else the port plan stays.
  if (why.rfind("altered to port", 0) == 0) {
    if (separation_net) {
      Plan net = separationManoeuvre(check.netProblem(), check.land_required, "the plan " + why);
      if (check.broken(net).empty()) {
        net.compute_time = first.compute_time;
        return net;
      }
    }
    first.message += " (port alteration kept: no starboard plan in " + std::to_string(retries) + " retries)";
    return first;
  }
  if (!separation_net) {  // land alone: the follower's fallback stops rather than run aground
    Plan none;
    none.status = PlanStatus::NoSolution;
    none.compute_time = first.compute_time;
    none.message = "every plan in " + std::to_string(retries + 1) + " tries " + why;
    return none;
  }
  Plan net = separationManoeuvre(original, check.land_required,
                                 "every plan in " + std::to_string(retries + 1) + " tries " + why);
  net.compute_time = first.compute_time;
  return net;
}

PlanFollower::PlanFollower(const PlanFollowerConfig& config) : cfg_(config) {
  cfg_.validate();
}

void PlanFollower::updateOwn(const ShipState& own) {
  if (!own_ && cfg_.cruise_speed <= 0.0)
    cfg_.cruise_speed = std::max(0.5, own.speed);
  own_ = own;
  if (!pending_route_.empty() && !progress_)
    progress_ = RouteProgress(std::exchange(pending_route_, {}), own.position);
  if (progress_ && progress_->update(own.position, std::max(own.speed, legSpeed()), cfg_.limits.turn_rate,
                                     cfg_.waypoint_acceptance))
    leg_changed_ = true;
}

void PlanFollower::setRoute(Route route) {
  if (route.empty())
    throw std::invalid_argument("plan follower: a route needs at least one waypoint");
  goal_ = route.back().position;
  progress_.reset();
  pending_route_.clear();
  if (own_)
    progress_ = RouteProgress(std::move(route), own_->position);
  else
    pending_route_ = std::move(route);
  have_plan_ = false;  // replan along the new route
}

std::optional<double> PlanFollower::crossTrackError() const {
  if (!progress_ || !own_)
    return std::nullopt;
  return progress_->crossTrackError(own_->position);
}

double PlanFollower::legSpeed() const {
  return progress_ && progress_->target().speed > 0.0 ? progress_->target().speed : cfg_.cruise_speed;
}

std::optional<Eigen::Vector2d> PlanFollower::starboardSide(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                                           const Eigen::Vector2d& q, const RouteWaypoint& leg,
                                                           bool edge) const {
  if (!(cfg_.narrow_fairway_width_m > 0.0) || !((b - a).norm() > 1.0))
    return std::nullopt;
  const Eigen::Vector2d along = (b - a).normalized();
  const Fairway f =
      fairwayAcross(q, along, obstacles_, leg.port_xtd, leg.starboard_xtd, cfg_.narrow_fairway_width_m);
  if (!(f.width() < cfg_.narrow_fairway_width_m))
    return std::nullopt;
  const double clearance = cfg_.min_obstacle_clearance_m;
  const double offset =
      std::clamp(edge ? starboardEdgeOffset(f, clearance) : starboardLaneOffset(f, clearance), -kMaxLaneShift,
                 kMaxLaneShift);
  return q + offset * Eigen::Vector2d(along.y(), -along.x());
}

std::optional<Eigen::Vector2d> PlanFollower::laneAhead(double lookahead, bool edge) const {
  if (!progress_ || !own_)
    return std::nullopt;
  const Eigen::Vector2d q = progress_->lineOfSight(own_->position, lookahead);
  const auto side =
      starboardSide(progress_->legStart(), progress_->target().position, q, progress_->target(), edge);
  if (!side)
    return std::nullopt;
  const double weight =
      progress_->onLastLeg() ? std::min(1.0, (progress_->goal() - q).norm() / kFairwayTaper) : 1.0;
  const Eigen::Vector2d lane = q + weight * (*side - q);
  if (!wayClearOfLand(own_->position, lane))
    return std::nullopt;
  return lane;
}

bool PlanFollower::wayClearOfLand(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const {
  const double required = landRequirement(from, to, obstacles_, cfg_.min_obstacle_clearance_m);
  return !(required > 0.0) || trackObstacleDistance({from, to}, obstacles_) >= required;
}

std::optional<Eigen::Vector2d> PlanFollower::fairwayLineOfSight(bool edge) const {
  return laneAhead(kLineOfSightLookahead * cfg_.waypoint_acceptance, edge);
}

std::optional<Eigen::Vector2d> PlanFollower::laneJoin() const {
  const auto abeam = laneAhead(0.0, false);
  if (!abeam)
    return std::nullopt;
  const double gap = (*abeam - own_->position).norm();
  if (gap < kLaneTolerance)
    return std::nullopt;
  const double ahead =
      std::clamp(kLaneJoinRatio * gap, kLineOfSightLookahead * cfg_.waypoint_acceptance, kLaneJoinMax);
  if (progress_->lineOfSight(own_->position, ahead) == progress_->target().position)
    return std::nullopt;  // the waypoint itself, in the lane, is nearer
  return laneAhead(ahead, false);
}

std::vector<Eigen::Vector2d> PlanFollower::wayAhead() const {
  std::vector<Eigen::Vector2d> way;
  if (progress_)
    way = progress_->waypointsBeforeGoal();
  way.push_back(goalOrAhead());
  return way;
}

PlanningProblem PlanFollower::buildProblem(double now, const std::vector<PlannerTarget>& targets) const {
  PlanningProblem pr;
  pr.time = now;
  pr.own = *own_;
  pr.own.speed = std::max(pr.own.speed, legSpeed());  // plan for the cruising (or the leg's) speed
  pr.cruise_speed = legSpeed();
  pr.limits = cfg_.limits;
  pr.goal = goalOrAhead();
  pr.obstacles = obstacles_;
  if (progress_) {
    pr.route = progress_->waypointsBeforeGoal();  // the voyage plan's next waypoints
    // Rule 9(a): in a narrow fairway each is moved to the starboard lane across its leg.
    const Route& r = progress_->route();
    Eigen::Vector2d from = pr.own.position;
    for (size_t k = 0; k < pr.route.size(); ++k) {
      const size_t i = progress_->active() + k;
      const Eigen::Vector2d a = i == progress_->active() ? progress_->legStart() : r[i - 1].position;
      const auto lane = starboardSide(a, r[i].position, r[i].position, r[i], false);
      if (lane && wayClearOfLand(from, *lane))
        pr.route[k] = *lane;
      from = pr.route[k];
    }
    // A ship out of the lane joins it ahead of her (laneJoin).
    if (auto join = laneJoin())
      pr.route.insert(pr.route.begin(), *join);
  }
  // Round land: the planners steer for a way round it to the next point (none when the straight way is
  // clear). Land beyond the reach (speed x horizon) of the straight way is left to a later plan.
  const Eigen::Vector2d next = nextWayPoint(pr);
  const double required = landRequirement(pr.own.position, next, obstacles_, cfg_.min_obstacle_clearance_m);
  const double reach = std::max(pr.own.speed, 0.5) * cfg_.prediction_horizon;
  if (required > 0.0 &&
      trackObstacleDistance(truncateTrack({pr.own.position, next}, reach), obstacles_) < required)
    if (auto round = landRoute(pr.own.position, next, obstacles_, cfg_.min_obstacle_clearance_m, required)) {
      if (!pr.route.empty())
        round->push_back(next);
      pr.route.insert(pr.route.begin(), round->begin(), round->end());
    }
  pr.seed = static_cast<uint64_t>(cfg_.seed) + replans_;
  pr.time_budget = cfg_.time_budget;
  pr.min_obstacle_clearance = cfg_.min_obstacle_clearance_m;
  pr.prediction_horizon = cfg_.prediction_horizon;
  pr.passing_cap = passingCap();
  pr.min_separation = cappedSeparation(cfg_.min_separation, pr.passing_cap);
  for (const auto& t : targets) {
    if (t.state.id == own_->id || !t.state.finite())
      continue;
    if (standingOn(t)) {
      pr.stand_on_for.push_back(t);
      pr.standing_on.push_back(t);
      continue;
    }
    if (standsOnFor(t) || dutyWaits(t, targets)) {
      pr.stand_on_for.push_back(t);
      continue;
    }
    pr.targets.push_back(t);
  }
  return pr;
}

bool PlanFollower::standsOnFor(const PlannerTarget& t) const {
  // The give-way ship is expected to act while Hu's compliance flag holds.
  return cfg_.stand_on_policy && t.role == OwnRole::StandOn && t.compliant && t.risk != RiskLevel::Urgent;
}

bool PlanFollower::standingOn(const PlannerTarget& t) const {
  if (!cfg_.stand_on_policy || !(t.tcpa > 0.0) || !t.compliant || standing_on_.count(t.state.id) == 0)
    return false;
  if (t.risk != RiskLevel::None)
    return standsOnFor(t);
  // No risk now: while its CPA is within the prediction horizon and the geometry gives her no duty to
  // keep out of its way (she may have become the overtaking ship).
  return t.tcpa <= cfg_.prediction_horizon && !keepsOutOfTheWay(t);
}

double PlanFollower::passingCap() const {
  if (!cfg_.restricted_passing || !own_)
    return 0.0;
  return restrictedPassingDistance(own_->position, own_->length, legSpeed(), obstacles_);
}

double PlanFollower::separationHere() const {
  return cappedSeparation(cfg_.min_separation, passingCap());
}

bool PlanFollower::dutyWaits(const PlannerTarget& t, const std::vector<PlannerTarget>& all) const {
  if (!cfg_.stand_on_policy || !keepsOutOfTheWay(t) || t.risk == RiskLevel::Urgent)
    return false;
  return std::any_of(all.begin(), all.end(), [&](const PlannerTarget& o) {
    return standsOnFor(o) && o.tcpa > 0.0 && (t.tcpa > cfg_.duty_window_s || t.tcpa > o.tcpa + kDutyLead);
  });
}

Plan PlanFollower::fallback(const std::vector<PlannerTarget>& targets, const std::string& why,
                            std::optional<double> hold_course) const {
  Plan f;
  f.status = PlanStatus::Fallback;
  f.course_setpoint = hold_course.value_or(own_->course);
  f.speed_setpoint = cfg_.cruise_speed * cfg_.fallback_speed_factor;
  f.message = "fallback (" + why + "): hold course, slow to " + std::to_string(cfg_.fallback_speed_factor) +
              " of speed";
  std::string extremis;
  for (const auto& t : targets)
    if (t.risk == RiskLevel::Urgent && (t.state.position - own_->position).norm() < cfg_.extremis_range) {
      // In extremis (Rule 17(b), Rule 2(b)): hard to starboard at full speed.
      f.course_setpoint = wrapTwoPi(f.course_setpoint + kPi / 2);
      f.speed_setpoint = cfg_.cruise_speed;
      f.message = "fallback (" + why + "): in extremis with " + t.state.id + ", hard starboard";
      extremis = "; in extremis with " + t.state.id;
      break;
    }
  if (fairwayFallback(f, why + extremis))
    return f;
  // Holding course (or turning hard) onto land is no fallback: the ship stops instead (a grounding is
  // as bad as a collision; Rule 8(e): taking all way off is an action to avoid a collision too).
  const double required =
      landRequirement(own_->position, wayAhead().front(), obstacles_, cfg_.min_obstacle_clearance_m);
  if (required > 0.0 &&
      trackObstacleDistance(landTrack(f, own_->position, f.speed_setpoint * cfg_.prediction_horizon),
                            obstacles_) < required) {
    f.speed_setpoint = 0.0;
    f.message = "fallback (" + why + "): land ahead on the present course, stop";
  }
  return f;
}

bool PlanFollower::fairwayFallback(Plan& f, const std::string& why) const {
  const auto edge = fairwayLineOfSight(true);
  const Eigen::Vector2d p = own_->position;
  if (!edge)
    return false;  // not in a narrow fairway, or land on the way to its edge: the open-water fallback
  f.status = PlanStatus::Fallback;
  f.along_fairway_edge = true;
  f.waypoints = {PlannedWaypoint{p, 0.0, 0.0, 0.0}, PlannedWaypoint{*edge, 0.0, 0.0, 0.0}};
  f.course_setpoint = courseOf(*edge - p);
  f.speed_setpoint = cfg_.cruise_speed * cfg_.fallback_speed_factor;
  f.message = "fallback (" + why + "): narrow fairway, slow to " +
              std::to_string(cfg_.fallback_speed_factor) + " of speed at its starboard edge";
  return true;
}

std::optional<Plan> PlanFollower::waitForRoom(const std::vector<PlannerTarget>& targets,
                                              double passing) const {
  const auto lane = fairwayLineOfSight(false);
  if (!lane)
    return std::nullopt;  // not in a narrow fairway
  const Eigen::Vector2d p = own_->position, leg = progress_->target().position - progress_->legStart();
  if (!(leg.norm() > 1.0))
    return std::nullopt;
  const Eigen::Vector2d along = leg.normalized();
  if (!(passing > 0.0))
    passing = kSeparationMargin * cfg_.min_separation;
  for (const auto& t : targets) {
    const double ahead = (t.state.position - p).dot(along);
    if (t.encounter != Encounter::Overtaking || !t.state.finite() || ahead <= 0.0 || ahead > kOvertakeLook)
      continue;
    const Fairway f = fairwayAcross(t.state.position, along, obstacles_, progress_->target().port_xtd,
                                    progress_->target().starboard_xtd, cfg_.narrow_fairway_width_m);
    const double room = std::max(f.port, f.starboard);
    const double need = passing + fairwayBankClearance(f, cfg_.min_obstacle_clearance_m);
    if (room >= need)
      continue;
    Plan w;
    w.status = PlanStatus::Ok;
    w.speed_setpoint = std::clamp(t.state.speed, 0.0, legSpeed());
    w.course_setpoint = courseOf(*lane - p);
    w.waypoints = {PlannedWaypoint{p, 0.0, w.course_setpoint, w.speed_setpoint},
                   PlannedWaypoint{*lane, 0.0, w.course_setpoint, w.speed_setpoint}};
    w.message = strFormat(
        "Rule 9(e): no room to overtake %s in the narrow fairway (%.0f m beside her, %.0f m "
        "needed): following her at %.1f m/s",
        t.state.id.c_str(), room, need, w.speed_setpoint);
    return w;
  }
  return std::nullopt;
}

double PlanFollower::predictedClearance(const std::vector<PlannerTarget>& targets) const {
  // The rest of the current plan flown from where the ship is now, as setpoint() flies it (then
  // straight for the goal), against every target holding its course and speed.
  if (!own_ || targets.empty())
    return 1e12;
  const double cruise = std::max(0.1, speed_sp_ > 0.0 ? speed_sp_ : cfg_.cruise_speed);
  PredictedRoute route{{own_->position}, {}};
  if (plan_.waypoints.size() < 2 || plan_.status == PlanStatus::Fallback) {
    route.points.push_back(own_->position + courseSpeedToVelocity(course_sp_, 1e5));
    route.speeds.push_back(cruise);
  } else {
    for (size_t i = wp_index_; i < plan_.waypoints.size(); ++i) {
      route.points.push_back(plan_.waypoints[i].position);
      route.speeds.push_back(plan_.waypoints[i].speed > 0.0 ? plan_.waypoints[i].speed : cruise);
    }
    for (const Eigen::Vector2d& w : wayAhead()) {
      route.points.push_back(w);
      route.speeds.push_back(plan_.speed_setpoint > 0.0 ? plan_.speed_setpoint : legSpeed());
    }
    route.ends_at_goal = goal_.has_value();
  }
  std::vector<PlannerTarget> others;
  for (const auto& t : targets)
    if (t.state.id != own_->id)
      others.push_back(t);
  return std::min(1e12, routeClearance(route, others, cfg_.prediction_horizon));
}

bool PlanFollower::landAhead() const {
  const double required =
      landRequirement(own_->position, wayAhead().front(), obstacles_, cfg_.min_obstacle_clearance_m);
  if (!(required > 0.0))
    return false;
  const double reach = std::max(speed_sp_, cfg_.cruise_speed) * cfg_.prediction_horizon;
  std::vector<Eigen::Vector2d> track{own_->position};
  if (plan_.waypoints.size() >= 2) {
    for (size_t i = wp_index_; i < plan_.waypoints.size(); ++i)
      track.push_back(plan_.waypoints[i].position);
    if (wp_index_ >= plan_.waypoints.size() && goal_)
      for (const Eigen::Vector2d& w : wayAhead())
        track.push_back(w);  // past the plan the ship steers for the route and the goal
    track = truncateTrack(track, reach);
  } else {
    track = landTrack(plan_, own_->position, reach);
  }
  return trackObstacleDistance(track, obstacles_) < required;
}

Eigen::Vector2d PlanFollower::goalOrAhead() const {
  return goal_ ? *goal_ : own_->position + courseSpeedToVelocity(own_->course, 20000.0);
}

bool PlanFollower::replanNeeded(double now, const std::vector<PlannerTarget>& targets, std::string& why) {
  if (!have_plan_)
    return why = "first plan", true;
  if (recovered_) {
    recovered_ = false;
    return why = "picture back after degraded operation", true;
  }
  if (reconfigured_) {
    reconfigured_ = false;
    return why = "parameters changed", true;
  }
  const double since = now - last_plan_time_;
  if (since < cfg_.min_replan_interval)
    return false;
  if (cfg_.replan_each_cycle)
    return why = "the method's own trigger, checked every cycle", true;
  if (leg_changed_) {
    leg_changed_ = false;
    return why = "route: waypoint passed, next leg", true;
  }
  for (const auto& t : targets)
    if (waiting_duties_.count(t.state.id) != 0 && !dutyWaits(t, targets))
      return why = "the duty to keep out of the way of " + t.state.id + " is due", true;
  for (const auto& t : targets) {
    auto it = known_levels_.find(t.state.id);
    if (t.risk == RiskLevel::None) {
      // The risk has cleared once it stays none, with the CPA past, for risk_clear_time: a new one
      // later is news again. A risk that falls while the CPA is still ahead is the plan working (or
      // tracking noise round Hu's d_min), not a new encounter: it does not re-arm the trigger.
      if (it != known_levels_.end() && t.tcpa > 0.0) {
        none_since_.erase(t.state.id);
        continue;
      }
      if (it != known_levels_.end()) {
        auto since = none_since_.emplace(t.state.id, now).first;
        if (now - since->second >= cfg_.risk_clear_time) {
          known_levels_.erase(it);
          none_since_.erase(since);
        }
      }
      continue;
    }
    none_since_.erase(t.state.id);
    const RiskLevel before = it == known_levels_.end() ? RiskLevel::None : it->second;
    // Only rises replan: a level that falls (or flickers round a threshold) would make the ship dither.
    if (cfg_.replan_on_risk && static_cast<int>(t.risk) > static_cast<int>(before)) {
      why = "risk of " + t.state.id + " " + std::to_string(static_cast<int>(before)) + " -> " +
            std::to_string(static_cast<int>(t.risk));
      return true;
    }
  }
  if (plan_.status == PlanStatus::Ok && landAhead()) {
    why = "plan predicted to pass within " + std::to_string(static_cast<int>(cfg_.min_obstacle_clearance_m)) +
          " m of land";
    return true;
  }
  // A plan is kept while it stays safe; periodic replanning of a safe plan would only make the ship weave.
  // The bar is plan_clearance, raised to the situation's minimum separation when there is one: a plan
  // predicted to pass inside the distance the situation demands is not safe.
  // Ships she stands on for are left out, as the plan left them out: holding course may pass one
  // inside the minimum (the give-way ship is to act), and a new plan every replan window would only
  // draw new searches until one slips through a turn the rules forbid. When that ship does not act, its
  // compliance flag falls or its risk turns urgent, and it counts here again.
  std::vector<PlannerTarget> watched;
  std::copy_if(targets.begin(), targets.end(), std::back_inserter(watched), [&](const PlannerTarget& t) {
    return !standingOn(t) && !standsOnFor(t) && !dutyWaits(t, targets);
  });
  const double clearance = predictedClearance(watched);
  if (clearance < std::max(cfg_.plan_clearance, separationHere())) {
    why = "plan predicted to pass within " + std::to_string(static_cast<int>(clearance)) + " m";
    return true;
  }
  if (since >= cfg_.replan_period && plan_.status != PlanStatus::Ok)
    return why = "periodic (last plan not ok)", true;
  return false;
}

std::vector<PlannerTarget> PlanFollower::deadReckon(std::vector<PlannerTarget> targets, double stamp,
                                                    double now) {
  for (PlannerTarget& t : targets)
    t.state.position += courseSpeedToVelocity(t.state.course, t.state.speed) * (now - stamp);
  return targets;
}

const Plan& PlanFollower::degrade(double now, const std::vector<PlannerTarget>& last_known,
                                  const std::string& cause) {
  if (degraded_since_ < 0.0)
    degraded_since_ = now;
  if (!own_)
    return plan_;
  const bool keep =
      have_plan_ && plan_.status == PlanStatus::Ok && now - degraded_since_ <= cfg_.degraded_plan_hold &&
      predictedClearance(last_known) >= std::max(cfg_.plan_clearance, separationHere()) && !landAhead();
  if (keep)
    return plan_;
  // The course held is the one she had when the plan was given up, not wherever she drifts since.
  // Every last known ship inside extremis_range counts as urgent (her risk cannot be assessed), so the
  // fallback's hard turn and its stop short of land are checked again at every call.
  const bool holding =
      have_plan_ && plan_.status == PlanStatus::Fallback && plan_.message.rfind("degraded", 0) == 0;
  if (!holding)
    degraded_course_ = own_->course;
  std::vector<PlannerTarget> marked = last_known;
  for (PlannerTarget& t : marked)
    if ((t.state.position - own_->position).norm() < cfg_.extremis_range)
      t.risk = RiskLevel::Urgent;
  Plan f = fallback(marked, "no picture: " + cause, degraded_course_);
  f.message = "degraded: " + f.message;
  if (holding && f.course_setpoint == plan_.course_setpoint && f.speed_setpoint == plan_.speed_setpoint)
    return plan_;  // the same action: the plan in force (and its first message) stays
  return acceptPlan(std::move(f), now, {}, "degraded");
}

void PlanFollower::reconfigure(PlanFollowerConfig config) {
  if (config.cruise_speed <= 0.0)
    config.cruise_speed = cfg_.cruise_speed;
  config.validate();
  cfg_ = config;
  reconfigured_ = true;
}

void PlanFollower::recover() {
  if (degraded_since_ < 0.0)
    return;
  degraded_since_ = -1.0;
  recovered_ = true;
}

const Plan& PlanFollower::acceptPlan(Plan plan, double now, const std::vector<PlannerTarget>& targets,
                                     const std::string& why) {
  if (plan.status == PlanStatus::NoSolution) {
    const double compute = plan.compute_time;
    plan = fallback(targets, "no solution: " + plan.message);
    plan.compute_time = compute;
  }
  // Rules 9 and 8(e): in a narrow fairway no plan that breaks a rule (a planner's least-violation plan,
  // the separation net's stop) is sailed: the ship slows at the fairway's starboard edge instead.
  if (plan.status == PlanStatus::Fallback && !plan.along_fairway_edge)
    fairwayFallback(plan, "no plan keeps every rule: " + plan.message);
  if (plan.status == PlanStatus::Ok)
    if (auto wait = waitForRoom(targets, plan.passing_distance)) {
      wait->compute_time = plan.compute_time;
      wait->passing_distance = plan.passing_distance;
      plan = std::move(*wait);
    }
  if (plan.status == PlanStatus::Fallback)
    ++fallbacks_;
  (void)why;
  plan_ = std::move(plan);
  have_plan_ = true;
  wp_index_ = 1;
  last_plan_time_ = now;
  ++replans_;
  waiting_duties_.clear();
  for (const auto& t : targets)
    if (dutyWaits(t, targets))
      waiting_duties_.insert(t.state.id);
  // A ship missing from this picture (a track lost for a cycle, or no picture at all: degraded
  // operation) keeps its place for a prediction horizon (its CPA was within one): standingOn checks it
  // again when it is back. A ship seen at risk starts it (standingOn then asks standsOnFor).
  std::map<std::string, double> standing;
  for (const auto& entry : standing_on_) {
    const std::string& id = entry.first;
    if (now - entry.second <= cfg_.prediction_horizon &&
        std::none_of(targets.begin(), targets.end(),
                     [&id](const PlannerTarget& t) { return t.state.id == id; }))
      standing.insert(entry);
  }
  for (const auto& t : targets)
    if (t.risk == RiskLevel::None ? standingOn(t) : t.tcpa > 0.0 && standsOnFor(t))
      standing.emplace(t.state.id, now);
  standing_on_ = std::move(standing);
  for (const auto& t : targets) {
    RiskLevel& known = known_levels_[t.state.id];
    if (static_cast<int>(t.risk) > static_cast<int>(known))
      known = t.risk;
  }
  return plan_;
}

bool PlanFollower::setpoint(double& course_out, double& speed_out) {
  if (!have_plan_ || !own_)
    return false;
  const Eigen::Vector2d p = own_->position;
  double course = plan_.course_setpoint, speed = plan_.speed_setpoint;
  const auto& wps = plan_.waypoints;
  if (plan_.along_fairway_edge) {
    if (const auto edge = fairwayLineOfSight(true))
      course = courseOf(*edge - p);
  } else if (plan_.status != PlanStatus::Fallback && wps.size() >= 2) {
    while (wp_index_ < wps.size() && (wps[wp_index_].position - p).norm() < cfg_.waypoint_acceptance)
      ++wp_index_;
    if (wp_index_ < wps.size()) {
      course = courseOf(wps[wp_index_].position - p);
      if (wps[wp_index_].speed > 0.0)
        speed = wps[wp_index_].speed;
    } else if (const auto lane = fairwayLineOfSight(false)) {
      course = courseOf(*lane - p);
    } else if (progress_) {
      course = courseOf(progress_->lineOfSight(p, kLineOfSightLookahead * cfg_.waypoint_acceptance) - p);
    } else if (goal_) {
      course = courseOf(*goal_ - p);  // past the plan: back to the goal
    }
  }
  if (!(speed > 0.0) && plan_.status != PlanStatus::Fallback)
    speed = legSpeed();
  if (!std::isfinite(course) || !std::isfinite(speed))
    return false;
  course_sp_ = wrapTwoPi(course);
  speed_sp_ = std::clamp(speed, 0.0, cfg_.limits.max_speed);
  course_out = course_sp_;
  speed_out = speed_sp_;
  return true;
}

}  // namespace asv
