// What every planner algorithm takes and gives, free of ROS. The asv_planning plugins are thin
// adapters from these structs to the ROS messages; the batch runner calls the same algorithms.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/common/param_map.h"
#include "asv_core/common/types.h"
#include "asv_core/risk/colregs.h"
#include "asv_core/risk/domain.h"
#include "asv_core/risk/risk_assessment.h"
#include "asv_core/risk/risk_level.h"
#include "asv_core/world/obstacles.h"

namespace asv {

// A target as the planner sees it: its motion plus the risk picture risk_node computed.
struct PlannerTarget {
  ShipState state;
  RiskLevel risk = RiskLevel::None;       // Hu et al. risk level
  bool compliant = true;                  // Hu et al. Algorithm 1 flag
  Encounter encounter = Encounter::None;  // from the own ship's point of view
  OwnRole role = OwnRole::None;
  double cri = 0.0;   // Wu et al. CRI
  double tcpa = 0.0;  // [s]
  double dcpa = 0.0;  // [m]
};

// The own ship's manoeuvring limits the planners respect.
struct OwnShipLimits {
  double max_speed = 10.0;  // [m/s]
  double min_speed = 0.0;   // [m/s]
  // [rad/s] omega of Lazarowska (2015) eq. (6), the steady rate of turn. The paper measures it in
  // turning trials and gives no value: 1 deg/s is our choice, a moderate rate for a small vessel.
  double turn_rate = 0.0175;
  double turn_delay = 10.0;  // [s] t01 of eq. (6): time before the turn starts
};

struct PlanningProblem {
  double time = 0.0;  // [s] scenario (or ROS) time of the problem
  ShipState own;      // own ship now
  OwnShipLimits limits;
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();  // [m] final waypoint (ENU)
  std::vector<Eigen::Vector2d> route;  // [m] waypoints still to pass before the goal (may be empty)
  std::vector<PlannerTarget> targets;
  // [m/s] the speed the ship sails at when nothing is in her way (the follower's cruise speed; 0:
  // unknown). A plan that keeps her speed asks for this rather than for own.speed: the speed she has
  // after a turn, fed back as the set-point, drifts upward under an integrating speed control.
  double cruise_speed = 0.0;
  // Targets the own ship stands on for (Rule 17(a)(i): left out of `targets` while the give-way ship is
  // expected to act). Not for the planners: the shared rules refuse a plan that closes them more than
  // holding course would (planUnderSharedRules).
  std::vector<PlannerTarget> stand_on_for;
  // The ships of stand_on_for she has stood on for since an earlier plan, their CPA still ahead, at
  // risk still or freed of it by the give-way ship's action (PlanFollower::standingOn). While there is
  // one, and she keeps out of the way of no ship, the shared rules keep her course and speed
  // (holdCoursePlan) instead of any plan, a route bend's included, when the hold keeps every other
  // rule: Rule 17(a)(i) lasts until the ships are past.
  std::vector<PlannerTarget> standing_on;
  std::vector<StaticObstacle> obstacles;
  bool has_bounds = false;  // environment boundaries (Lazarowska eq. 1-3)
  Eigen::Vector2d bounds_min = Eigen::Vector2d::Zero(), bounds_max = Eigen::Vector2d::Zero();  // [m]
  uint64_t seed = 1;         // every stochastic planner draws from this seed only
  double time_budget = 1.0;  // [s] wall time the planner may use; then it returns its best
  // [m] the passing distance the situation demands (a scenario's safety.min_separation_m); every
  // planner keeps its own safe distance at least kSeparationMargin times this. 0: the paper's own.
  double min_separation = 0.0;
  // [m] how far from static obstacles (land) every plan must keep (PlanFollowerConfig's
  // min_obstacle_clearance_m; 0: no requirement). Planners that model land use it; the shared layer
  // (planUnderSharedRules) refuses a plan that comes closer.
  double min_obstacle_clearance = 0.0;
  double prediction_horizon = 1200.0;  // [s] how far ahead a plan without waypoints is followed
  // [m] In restricted waters, the largest passing distance a planner's own safety distance may ask for
  // (restrictedPassingDistance; the plan follower sets it in sea mode, and lowers min_separation to it
  // there): the sea-scale distances of the papers (MOPSO's 1 nm d_min, ACO's 1 nm hexagon, GA's SDA) and
  // a scenario's evaluation threshold cannot be kept in a harbour, where they put every ship inside the
  // domain. 0: open water, the planners' own. The floor stays kSeparationMargin x min_separation.
  double passing_cap = 0.0;
};

// [m] The smallest passing distance planned for in restricted waters: our choice, 50 m. Harbour GNSS
// and AIS positions are each good to some 10-30 m, and a planned pass must outlast both errors and the
// ships' half-beams; masters in the New York hour pass launches at 20-120 m.
constexpr double kRestrictedPassingFloor = 50.0;

// The passing distance in restricted waters (PlanningProblem::passing_cap): 0 in open water (no land
// within kOpenWater of the ship); else the starboard extent of her Kijima and Nakiri (2003) domain for
// restricted waters (domain.h: from her length and speed), the wider of its two sides, kept whichever
// side a ship passes on, at least kRestrictedPassingFloor. Her length 0: 100 m (our choice, a mid-size
// ship).
double restrictedPassingDistance(const Eigen::Vector2d& position, double length, double speed,
                                 const std::vector<StaticObstacle>& obstacles);
// A planner's own safety distance under the problem's cap (itself when there is none).
inline double cappedPassing(double own, const PlanningProblem& p) {
  return p.passing_cap > 0.0 ? std::min(own, p.passing_cap) : own;
}

// The speed a plan that keeps the ship's speed asks for: PlanningProblem::cruise_speed, else own.speed.
inline double keptSpeed(const PlanningProblem& p) {
  return p.cruise_speed > 0.0 ? p.cruise_speed : p.own.speed;
}

// The point the ship steers for next: the land route's first point, else the goal.
inline Eigen::Vector2d nextWayPoint(const PlanningProblem& p) {
  return p.route.empty() ? p.goal : p.route.front();
}

// Margin on PlanningProblem::min_separation: plans are made at kinematic constant-velocity prediction,
// but the ship follows them with turn delays and the targets are tracked with noise. Our choice (10 %).
constexpr double kSeparationMargin = 1.1;
// Sea mode (planUnderSharedRules) asks the planner first, in open water, for a plan that passes every
// target at this multiple of min_separation: the distance a watch officer prefers to the minimum she
// accepts. It keeps that plan when it is Ok, keeps the ship's way and the shared rules; otherwise the
// plan is made for min_separation itself. Our choice: 2, the preferred passing range of the
// evaluator's safety score (r_pref = 2 r_min, docs/evaluation.md).
constexpr double kPreferredSeparation = 2.0;
// [m] Open water, for the preferred passing distance: no land within 1 nm of the own ship, nor within
// that distance (our choice: a port basin or a channel is narrower).
constexpr double kOpenWater = 1852.0;

// [s] The longest pass the preferred distance is judged over (passingHorizon, safety_net.h): an hour,
// our choice (a 10 kn ship overtaking a 7 kn one gains about 3 nm in it).
constexpr double kLongestPass = 3600.0;

// [s] The longest the net holds a turn for the preferred distance (not for the minimum): 20 minutes, our
// choice. A longer swing for a wider pass costs more time than the wider pass is worth, and can keep the
// ship from her goal.
constexpr double kLongestHold = 1200.0;

struct PlannedWaypoint {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] ENU
  double time = 0.0;    // [s] planned arrival, relative to PlanningProblem::time
  double course = 0.0;  // [rad] nautical course on the leg ending here
  double speed = 0.0;   // [m/s] speed on that leg
};

enum class PlanStatus : uint8_t { Ok = 0, NoSolution = 1, Fallback = 2 };
const char* toString(PlanStatus s);

struct Plan {
  PlanStatus status = PlanStatus::NoSolution;
  std::vector<PlannedWaypoint> waypoints;  // starts at the own ship's position (time 0)
  double course_setpoint = 0.0;            // [rad] nautical course to steer now
  double speed_setpoint = 0.0;             // [m/s] speed to hold now
  double cost = 0.0;                       // algorithm-specific objective (lower is better)
  double compute_time = 0.0;               // [s] wall time spent
  std::string message;                     // why, for humans
  // [m] the passing distance in restricted waters the plan was made under (PlanningProblem::passing_cap
  // raised to the floor, kSeparationMargin x min_separation); 0: open water, the planner's own.
  double passing_distance = 0.0;
  // The follower's fallback in a narrow fairway (Rules 9, 8(e)): steered along the fairway's starboard
  // edge, the point renewed as she moves, instead of held on course_setpoint.
  bool along_fairway_edge = false;
};

// A planner's mode, key `mode`: `sea` (default), the published method with the stack's named extensions
// for use at sea; `paper`, the method as published, those extensions off (each algorithm's config lists
// them). Throws std::invalid_argument on another value.
enum class PlannerMode { Sea, Paper };
PlannerMode plannerMode(const ParamMap& params, const std::string& algorithm);
// The same for the value itself ("sea" or "paper"; `algorithm` names it in the error).
PlannerMode parsePlannerMode(const std::string& mode, const std::string& algorithm);

// The area round a target that a planner keeps the own ship out of, at the problem's time (for display).
struct TargetDomain {
  std::string target_id;
  Polygon polygon;  // [m] ENU
};

// The separation rule every plan keeps (planUnderSharedRules): a circle of kSeparationMargin x
// min_separation round each of the problem's targets, as a 36-gon; none when min_separation is 0.
std::vector<TargetDomain> separationDomains(const PlanningProblem& problem);

// The planner interface, the one every planner implements (ACO, DSSA, DSSA+, MOPSO, GA, a third
// party's) and the one pluginlib loads by class name in planner_node and asv_batch (base class type
// "asv::PlannerAlgorithm", nav_core's shape): a default constructor, then initialize(); ROS-free, so
// the same class runs on a boat, in the simulator and in a unit test.
class PlannerAlgorithm {
public:
  virtual ~PlannerAlgorithm() = default;
  // Second step of the construction, as planner_node and asv_batch make planners: in sea mode (key
  // `mode`, default sea) the algorithm's seaDefaults() with `config` over them, in paper mode `config`
  // alone (the paper's own values). Throws std::invalid_argument naming a bad or unknown key.
  void initialize(const ParamMap& config);
  // Reads the algorithm's parameters as given (keys documented by each algorithm), over its own
  // defaults; throws std::invalid_argument naming a bad or unknown key.
  virtual void configure(const ParamMap& params) = 0;
  // Plans for the problem within problem.time_budget; never throws on a feasible problem.
  virtual Plan plan(const PlanningProblem& problem) = 0;
  virtual std::string name() const = 0;
  // The parameters given to initialize() with the sea defaults it added: what a caller needs to build
  // the same algorithm elsewhere (the distributed DSSA agent does).
  const ParamMap& parameters() const { return parameters_; }
  // The domains this algorithm plans with round the problem's targets; by default the separation rule
  // every plan keeps. An algorithm with a domain of its own (ACO's hexagon) gives that.
  virtual std::vector<TargetDomain> domains(const PlanningProblem& problem) const {
    return separationDomains(problem);
  }
  // The published method computes its trajectory once and sails it: in paper mode the follower does not
  // replan when a target's risk rises (applyPlannerMode). False by default: the methods replan.
  virtual bool plansOnce() const { return false; }
  // The published method checks its own trigger at every control cycle and decides (or holds) in the
  // planner: in paper mode the follower asks it every cycle (replan_each_cycle). False by default.
  virtual bool ownTrigger() const { return false; }

protected:
  PlannerAlgorithm() = default;
  // Sea-scale values where the algorithm's own defaults follow its paper's units (DSSA's); sea mode
  // only. None by default.
  virtual ParamMap seaDefaults() const { return {}; }

private:
  ParamMap parameters_;
};

// Wall-clock budget helper for anytime algorithms.
class Deadline {
public:
  explicit Deadline(double seconds)
      : start_(std::chrono::steady_clock::now()),
        end_(start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                          std::chrono::duration<double>(seconds))) {}
  bool expired() const { return std::chrono::steady_clock::now() >= end_; }
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

private:
  std::chrono::steady_clock::time_point start_, end_;
};

// A target as the planners see it: its state and its risk picture (level, compliance flag, encounter
// and role, CRI, TCPA and DCPA).
PlannerTarget toPlannerTarget(const ShipState& target, const TargetRisk& risk);

}  // namespace asv
