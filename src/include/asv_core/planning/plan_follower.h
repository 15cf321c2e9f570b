// The replanning policy and the plan-to-set-point logic of planner_node, free of ROS, so that
// planner_node (over topics) and asv_batch (in-process) replan and steer the same way:
//  - replan on the first plan, when a target's Hu risk level rises above what the last plan saw, when
//    the rest of the plan flown from here would pass a target closer than plan_clearance, and
//    periodically while the last plan is not Ok; never faster than min_replan_interval;
//  - a plan that fails (NoSolution or an exception) becomes the fallback: hold course at a fraction of
//    the speed, or hard to starboard when an urgent target is within extremis_range (Rules 17(b), 2(b)),
//    or stopped when that course would take the ship onto land;
//  - no plan may bring the ship closer to land than min_obstacle_clearance_m, or pass a target closer than
//    the minimum separation when another plan or the separation manoeuvre keeps it (planUnderSharedRules);
//  - set-points steer for the next plan waypoint not yet within waypoint_acceptance, then for the goal;
//  - with a voyage plan (setRoute), the planners steer for the route's next waypoint (the goal is its
//    last), a waypoint is passed at the wheel-over point of its turn, passing one replans, and past the
//    plan the ship rejoins the active leg by line of sight (not the straight line to the goal);
//  - in a narrow fairway of the route (Rule 9, fairway.h) the route's waypoints and the line of sight
//    are moved across the leg into the fairway's starboard lane, and the fallback steers for its
//    starboard edge at the fallback speed (Rule 8(e)) instead of holding course or stopping in it; a
//    ship she overtakes there without room to pass is followed at her speed (Rule 9(e)).
// Times are the caller's clock (simulation or ROS time) in seconds.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "asv_core/common/param_map.h"
#include "asv_core/planning/land_route.h"
#include "asv_core/planning/planning.h"
#include "asv_core/world/route.h"

namespace asv {

// Past the plan the ship steers for a point this many waypoint acceptance radii ahead on the active leg
// (300 m by default): a line-of-sight lookahead of a few ship lengths, which brings her back onto the
// leg at about 18 deg from 100 m off it. Our choice.
constexpr double kLineOfSightLookahead = 2.0;

// Field names and defaults are planner_node's parameters (asv_planning/config/planner_node.yaml).
struct PlanFollowerConfig {
  double cruise_speed = 0.0;           // [m/s] 0: the own speed at the first update (at least 0.5 m/s)
  double replan_period = 30.0;         // [s] replan this often while the last plan is not Ok
  double min_replan_interval = 2.0;    // [s]
  double time_budget = 0.5;            // [s] wall time per plan
  double waypoint_acceptance = 150.0;  // [m]
  double fallback_speed_factor = 0.5;  // [-] fallback speed = cruise speed x this
  double extremis_range = 926.0;       // [m]
  double plan_clearance = 370.4;       // [m]
  double prediction_horizon = 1200.0;  // [s]
  int seed = 1;                        // plan k uses seed + k
  double min_separation = 0.0;         // [m] passing distance the planners must keep (0: their own)
  bool stand_on_policy = true;         // Rule 17(a)(i): a compliant give-way target below Hu's urgent
                                       // level is left out of the problem: the own ship stands on
  // [s] Rule 17 with several ships: while she stands on for a ship, a duty to keep out of the way of
  // another whose CPA is more than this away waits (dutyWaits). 15 min, the referee's duty_tcpa_s: a
  // ship that far off is not yet in its own action window (our reading, docs/evaluation.md).
  double duty_window_s = 900.0;
  // [m] every plan keeps the track this far from static obstacles (land); a ship already closer may not
  // halve her distance. 0.1 nm, as MOPSO's land clearance (Hu et al. 2017 Fig. 4(b)): our choice.
  double min_obstacle_clearance_m = 185.2;
  // [s] degraded operation (degrade()): the plan in force is kept at most this long after the data was
  // lost, and only while it still passes the last known targets; our choice: a minute, within which a
  // ship at 12 kn sails 370 m and a crossing target's position estimate is still a few hundred metres good
  double degraded_plan_hold = 60.0;
  // A target's rising risk level replans (Hu et al. 2017: the path is re-planned as the risk is
  // assessed). false: only a plan predicted unsafe, one that reaches land or one that is not Ok
  // replans, so a trajectory computed once with every target in view is sailed as computed (the
  // experiments of Lazarowska 2015 and Wu et al. 2022 plan once per encounter).
  bool replan_on_risk = true;
  // Ask the planner again every min_replan_interval, whatever else happens: for a method whose published
  // form checks its own trigger at every control cycle and decides in the planner (Wu et al. 2022: the
  // CRI against 0.61, hold_decision) in paper mode, where the stack's triggers are off. Default false.
  bool replan_each_cycle = false;
  // In restricted waters (land within 1 nm), the planners' sea-scale safety distances are capped at the
  // ship's Kijima and Nakiri (2003) domain (restrictedPassingDistance, planning.h). Off in paper mode.
  bool restricted_passing = true;
  // [m] Rule 9: on a route, a fairway (fairway.h: across the leg, from land or the leg's corridor to land
  // or corridor) narrower than this is a narrow channel: the ship keeps to its starboard side, and the
  // fallback slows her at its starboard edge instead of stopping in it. 1 nm: our choice (a harbour
  // channel, a river; a ferry crossing a river sees the river's length, not its width). 0: off (paper
  // mode).
  double narrow_fairway_width_m = 1852.0;
  double risk_clear_time = 60.0;  // [s] a target's risk must stay none, with its CPA past, this
                                  // long before a new rise replans again (tracking noise flickers
                                  // round thresholds; a plan that works lowers the risk)
  OwnShipLimits limits;

  void validate() const;  // throws std::invalid_argument
  // Keys: the field names; limits as max_speed, min_speed, turn_rate, turn_delay. Unknown keys are
  // not rejected here (the caller owns the namespace).
  static PlanFollowerConfig fromParams(const ParamMap& params);
};

// The planner is first asked for the preferred passing distance (kPreferredSeparation x min_separation,
// planning.h); that plan is kept when it is Ok and keeps the rules below. Otherwise the problem as given
// goes on as follows. The rules every planner's plan must keep, whatever the algorithm; a plan that breaks
// one is refused and the planner asked again with another seed, up to `retries` times:
//  - land: a plan whose track (landTrack) comes closer to a static obstacle than landRequirement()
//    allows. If none keeps clear, the result is NoSolution (the follower's fallback, which stops
//    rather than run aground);
//  - separation (safety_net.h): with a minimum separation and targets, a plan predicted to pass one of
//    the problem's targets closer than min_separation. If none keeps it, or the planner finds no
//    solution, the separation manoeuvre (separationManoeuvre) is flown instead;
//  - Rules 14 and 15: when the own ship gives way in a head-on or crossing encounter (a target of the
//    problem with that encounter), a first alteration more than 5 deg to port; Rule 17(c): the same
//    when a ship crosses from her port side (she stood on, and now acts). If none complies, the
//    separation manoeuvre (starboard first) when it keeps every rule; else the first plan is kept with a
//    note in its message.
// A planner's Fallback (a least-violation plan, which the follower sails all the same) keeps the land
// and separation rules too. `make` is the planner (it may throw; the exception propagates).
Plan planUnderSharedRules(const std::function<Plan(const PlanningProblem&)>& make, PlanningProblem problem,
                          int retries = 3);
// The plan takes the ship to port before the other ships are past (Rules 14, 15, 17(c)): of its legs
// that begin before the last target's CPA, the largest departure to port of the present course is over
// 5 deg and more than the largest to starboard less 10 deg (the evaluator judges the larger departure
// of the flown track, which overshoots a planned leg); a plan without legs, by its course set-point. A
// swing to starboard and back across the course to port as far counts. Ok plans only.
bool altersToPort(const Plan& plan, const PlanningProblem& problem);

// Paper mode (plannerMode, planning.h) runs the method as published: the shared rules above, the
// follower's stand-on policy, its minimum separation, its replanning when a plan passes closer than
// plan_clearance and its fallback (slow down; hard starboard in extremis) are this stack's sea
// extensions, so they are off (a failed plan holds course and speed). applyPlannerMode sets the follower
// for the mode (and, in paper mode, for a method that plans once, PlannerAlgorithm::plansOnce: no
// replanning on rising risk; for one with its own trigger, PlannerAlgorithm::ownTrigger: a plan asked
// every cycle, replan_each_cycle); planInMode asks the planner under the shared rules at sea and alone in
// paper mode.
void applyPlannerMode(PlanFollowerConfig& cfg, PlannerMode mode, bool plans_once = false,
                      bool own_trigger = false);
Plan planInMode(const std::function<Plan(const PlanningProblem&)>& make, const PlanningProblem& problem,
                PlannerMode mode);

// Whether a plan may use tracked targets that no risk assessment covers (risk-blind: no encounter, no
// role, so the own ship could give way to a ship it must stand on for). Only when the risk picture has
// gone silent: no fresh assessment, and the node has waited stale_after since its first input. Before
// that, at start-up, tracks reach the planner before their first assessment: they are left out.
// Times in seconds on one clock; first_input < 0: nothing received yet.
bool riskBlindPlanning(bool risk_fresh, double now, double first_input, double stale_after);

// The targets a plan is made against (planner_node's policy): the fresh tracks (`tracks`), each with
// the risk picture of its assessment when `assessed` (by id; only the risk fields are used) has one.
// The ship's own track (`own_id`) and tracks with a non-finite position or velocity are left out. A
// track no assessment covers (a new track, the start of a run) is left out while the risk picture is
// alive (`risk_alive`); once it has gone silent (riskBlindPlanning) every track is kept, risk-blind:
// no encounter, no role.
std::vector<PlannerTarget> selectPlannerTargets(const std::string& own_id,
                                                const std::vector<ShipState>& tracks,
                                                const std::map<std::string, PlannerTarget>& assessed,
                                                bool risk_alive);

class PlanFollower {
public:
  explicit PlanFollower(const PlanFollowerConfig& config = {});

  void setGoal(const Eigen::Vector2d& goal) {
    goal_ = goal;
    pending_route_.clear();
    progress_.reset();
    have_plan_ = false;  // replan towards the new goal
  }
  // A voyage plan (at least one waypoint; the last is the goal), sailed from the leg nearest to the ship
  // at the next updateOwn(). Replaces the goal and any route.
  void setRoute(Route route);
  // The route being sailed, once the ship's position is known (else empty).
  const std::optional<RouteProgress>& routeProgress() const { return progress_; }
  // Signed cross-track error from the active leg [m], positive to starboard; nullopt without a route.
  std::optional<double> crossTrackError() const;
  const std::optional<Eigen::Vector2d>& goal() const { return goal_; }
  void setObstacles(const std::vector<StaticObstacle>& obstacles) { obstacles_ = obstacles; }
  // The own ship now (the first call fixes the cruise speed when it is 0).
  void updateOwn(const ShipState& own);
  bool hasOwn() const { return own_.has_value(); }

  // The problem for the targets now (each with its risk picture).
  PlanningProblem buildProblem(double now, const std::vector<PlannerTarget>& targets) const;
  // Rule 17(a)(i): she stands on for `t` (keeps her course and speed) while it is a compliant give-way
  // ship and the situation is not yet urgent (17(a)(ii), 17(b): then she acts). Such a ship is left out
  // of the problem, and out of the plan's predicted-clearance trigger.
  bool standsOnFor(const PlannerTarget& t) const;
  // Rule 17(a)(i) until the ship is past: `t` is a ship she stood on for (standsOnFor) in a risk an
  // earlier plan saw, its CPA still ahead (TCPA > 0), and she still stands on for it (standsOnFor) or
  // its risk has fallen to none (the give-way ship's action) with the CPA within the prediction horizon
  // and no duty for her to keep out of its way. A risk the give-way ship removed does not end her duty
  // to keep her course and speed (the referee judges a stand-on alteration up to the closest approach),
  // and holding on is safe then: on the present motion there is no risk. A stand-on situation no
  // earlier plan saw does not count (her own turn may have made it; the planner's plan is judged by
  // closesStandOn). Ends at a plan that sees the CPA past, the ship not compliant or urgent, or a risk
  // giving her another role (a ship missing from that plan's picture keeps its place for a prediction
  // horizon), and with the stand-on policy off. Such a ship is left out of the plan-clearance trigger
  // too.
  bool standingOn(const PlannerTarget& t) const;
  // Rule 17 with several ships: while she stands on for some ship of `all` (standsOnFor) that is not yet
  // past, her duty to keep out of the way of `t` (not urgent) waits while its CPA is more than
  // duty_window_s away, or comes more than kDutyLead after that ship's: she keeps her course and speed
  // for the first, and `t` is watched as a ship she stands on for (the plan may not close it) until the
  // duty is due, which replans. Off with the stand-on policy.
  // [s] 8 min, the referee's Rule 16 early_tcpa_s: with the stand-on ship past, she still acts early.
  static constexpr double kDutyLead = 480.0;
  bool dutyWaits(const PlannerTarget& t, const std::vector<PlannerTarget>& all) const;
  // Restricted waters (restricted_passing): the cap on the passing distance where she is
  // (restrictedPassingDistance; 0 in open water, paper mode or before her state is known), and the
  // minimum separation in force there: the situation's, at most that cap. The planners get both
  // (buildProblem), and the plan-clearance trigger judges a plan by the same separation, so that a plan
  // made for the cap is not replanned for the sea-scale minimum every cycle.
  double passingCap() const;
  double separationHere() const;
  bool replanNeeded(double now, const std::vector<PlannerTarget>& targets, std::string& why);
  // Targets of a picture taken at `stamp`, moved on to `now` at their course and speed.
  static std::vector<PlannerTarget> deadReckon(std::vector<PlannerTarget> targets, double stamp, double now);
  // hold_course: the course to hold (default: the present course over ground).
  Plan fallback(const std::vector<PlannerTarget>& targets, const std::string& why,
                std::optional<double> hold_course = std::nullopt) const;
  // Stores a plan made at `now` (NoSolution becomes the fallback; in a narrow fairway any fallback the
  // fairway fallback, and an Ok plan waitForRoom's when there is no room to overtake) and the risk
  // levels it saw.
  // Returns the plan in force.
  const Plan& acceptPlan(Plan plan, double now, const std::vector<PlannerTarget>& targets,
                         const std::string& why);
  // Degraded operation, while the picture the plans are made on is lost (the risk assessment or the
  // tracks gone stale, a stage upstream down): absence of data is not absence of danger, so no new plan
  // is made. The plan in force is kept while it is Ok, younger than degraded_plan_hold since the loss
  // began, and still passes the last known targets (`last_known`, dead-reckoned to now) by
  // plan_clearance and land by the required clearance; otherwise the ship holds the course she had when
  // the plan was given up, at fallback_speed_factor of the cruise speed: the fallback, checked again at
  // every call, with its stop short of land and its hard turn to starboard for any last known ship
  // inside extremis_range (counted urgent: her risk cannot be assessed). `cause` is shown in the plan's
  // message. Returns the plan in force.
  const Plan& degrade(double now, const std::vector<PlannerTarget>& last_known, const std::string& cause);
  // The data is back: the next replanNeeded() asks for a plan at once ("picture back").
  void recover();
  // New settings while running (the node's live parameters). Validated first: on a bad value it throws
  // and nothing changes. A cruise speed of 0 keeps the one in force. The plan in force is flown until
  // the next replanNeeded(), which asks for a plan under the new settings at once ("parameters
  // changed"): a larger min_separation must not wait for the next risk change.
  void reconfigure(PlanFollowerConfig config);
  bool degraded() const { return degraded_since_ >= 0.0; }

  // Course and speed to steer now; false while there is no plan (or no own state).
  bool setpoint(double& course, double& speed);

  bool havePlan() const { return have_plan_; }
  const Plan& plan() const { return plan_; }
  uint64_t replans() const { return replans_; }
  uint64_t fallbacks() const { return fallbacks_; }
  const PlanFollowerConfig& config() const { return cfg_; }
  double cruiseSpeed() const { return cfg_.cruise_speed; }

private:
  double predictedClearance(const std::vector<PlannerTarget>& targets) const;
  // The rest of the plan in force, flown from here, comes closer to land than landRequirement.
  bool landAhead() const;
  // The goal, or 20 km ahead on the present course without one.
  Eigen::Vector2d goalOrAhead() const;
  // The way on past a plan: the route's waypoints still to pass and the goal (goalOrAhead()).
  std::vector<Eigen::Vector2d> wayAhead() const;
  // The speed to sail now: the active leg's, else the cruise speed.
  double legSpeed() const;
  // Rule 9(a): the point q of the leg a->b (whose waypoint `leg` carries the corridor) moved across the
  // leg to the starboard lane of a narrow fairway, or to its starboard edge (`edge`); nullopt when the
  // fairway at q is not narrow (or the rule is off).
  std::optional<Eigen::Vector2d> starboardSide(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                               const Eigen::Vector2d& q, const RouteWaypoint& leg,
                                               bool edge) const;
  // In a narrow fairway, the point the ship steers for past a plan: the one on the active leg ahead of
  // her (RouteProgress::lineOfSight) moved to the fairway's starboard lane (or edge), less so over the
  // last kFairwayTaper before the goal so that she arrives. nullopt without a route or a narrow fairway.
  std::optional<Eigen::Vector2d> fairwayLineOfSight(bool edge) const;
  // The same for a point `lookahead` ahead of her abeam point on the active leg; nullopt too when the way
  // to it is not clear of land (wayClearOfLand).
  std::optional<Eigen::Vector2d> laneAhead(double lookahead, bool edge) const;
  // The straight way from `from` to `to` keeps landRequirement from land (a lane point is found across
  // its leg; the way to it may still pass a pier's end).
  bool wayClearOfLand(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const;
  // Where a ship out of the starboard lane of a narrow fairway joins it (kLaneJoinRatio); nullopt when
  // she is in it (or there is none), or the active waypoint comes first.
  std::optional<Eigen::Vector2d> laneJoin() const;
  // Rules 9 and 8(e): in a narrow fairway a fallback `f` (the follower's, in extremis too, or a
  // planner's least-violation plan) becomes a slow passage along the starboard edge
  // (Plan::along_fairway_edge; waypoints: the ship, the edge point), its compute time kept; false, `f`
  // untouched, outside one or when land lies between the ship and the edge.
  bool fairwayFallback(Plan& f, const std::string& why) const;
  // Rule 9(e): in a narrow fairway the own ship overtakes only with room to pass. A ship she overtakes
  // (Encounter::Overtaking) within kOvertakeLook ahead along the leg, beside which neither side of the
  // fairway leaves `passing` (0: kSeparationMargin x min_separation) plus the bank clearance, is
  // followed in the starboard lane at her speed (an Ok plan saying so); nullopt otherwise.
  std::optional<Plan> waitForRoom(const std::vector<PlannerTarget>& targets, double passing) const;

  PlanFollowerConfig cfg_;
  std::optional<Eigen::Vector2d> goal_;
  Route pending_route_;                    // the voyage plan given, until the ship's position is known
  std::optional<RouteProgress> progress_;  // the voyage plan sailed (it holds the route from then on)
  bool leg_changed_ = false;               // a route waypoint was passed: replan for the next leg
  std::vector<StaticObstacle> obstacles_;
  std::optional<ShipState> own_;
  std::map<std::string, RiskLevel> known_levels_;
  std::set<std::string> waiting_duties_;  // ships whose give-way duty waited at the last plan (dutyWaits)
  std::map<std::string, double> standing_on_;  // ships she stands on for until past (standingOn): last seen
  std::map<std::string, double> none_since_;   // when a known target's risk was last seen falling to none
  Plan plan_;
  bool have_plan_ = false;
  size_t wp_index_ = 1;
  double last_plan_time_ = -1e300;
  double course_sp_ = 0.0, speed_sp_ = 0.0;
  double degraded_since_ = -1.0;  // when degraded operation began (< 0: not degraded)
  double degraded_course_ = 0.0;  // the course held in degraded operation
  bool recovered_ = false;        // the picture came back: replan at once
  bool reconfigured_ = false;     // the settings changed: replan at once
  uint64_t replans_ = 0, fallbacks_ = 0;
};

}  // namespace asv
