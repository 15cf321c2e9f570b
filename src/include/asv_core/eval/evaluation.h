// Run evaluation: the metrics and the COLREGs score of one run, and its JSON (docs/evaluation.md).
// asv_batch (in-process) and evaluator_node (over ROS topics) feed the same RunRecorder,
// so both write the same result for the same trajectories.
//
// The COLREGs score follows the structure of Woerner, Benjamin, Novitzky & Leonard (2019),
// "Quantifying protocol evaluation for autonomous collision avoidance", Autonomous Robots 43:967-991:
// a safety score from the range at CPA with preferred, minimum and near-miss ranges (piecewise), times
// rule penalties for Rule 8 (alteration readily apparent), Rules 13-16 (give-way acts early, turns to
// starboard in head-on and crossing encounters, does not cross ahead of the stand-on ship) and Rule 17
// (stand-on keeps course and speed until the give-way ship's action is clearly lacking). The paper's
// notional algorithms leave every threshold to the evaluator; ours are the fields of EvaluationConfig
// and docs/evaluation.md gives every formula.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/common/geometry.h"
#include "asv_core/common/param_map.h"
#include "asv_core/common/types.h"
#include "asv_core/risk/colregs.h"
#include "asv_core/risk/risk_level.h"
#include "asv_core/sim/simulation.h"

namespace asv {

struct EvaluationConfig {
  // Safety score of a target from the smallest range to it (Woerner's range at CPA): 1 at or beyond
  // r_pref, falling linearly to safety_at_r_min at r_min, then linearly to 0 at r_nm (near miss), 0
  // below; 0 for a collision.
  // true: r_min = the scenario's safety.min_separation_m, r_pref = 2 r_min, r_nm = r_min / 5 (the
  // defaults below are exactly that for the default 0.5 nm); false: the three values below.
  bool ranges_from_scenario = true;
  double r_pref_m = 1852.0;      // [m] preferred passing range (1 nm)
  double r_min_m = 926.0;        // [m] minimum acceptable passing range (0.5 nm)
  double r_nm_m = 185.2;         // [m] near-miss range (0.1 nm)
  double safety_at_r_min = 0.5;  // [-] safety score at r_min, in (0, 1)

  // Entry criterion: the rules of a target are evaluated from the first instant at which a risk of
  // collision exists on the ships' actual motion: 0 < TCPA <= entry_tcpa_s and DCPA < entry_dcpa_m.
  double entry_tcpa_s = 1800.0;  // [s] 30 min
  double entry_dcpa_m = 1852.0;  // [m] 1 nm (Hu's d_min)

  // An "action": the own course over ground differs from its course at entry by at least
  // action_course_deg, or its speed has fallen by at least action_speed_fraction of the entry speed.
  double action_course_deg = 5.0;      // [deg]
  double action_speed_fraction = 0.2;  // [-]
  // Rule 8(b): an alteration is readily apparent when the largest course change reaches
  // apparent_course_deg, or the speed falls by apparent_speed_fraction (the equivalent speed change).
  double apparent_course_deg = 30.0;     // [deg]
  double apparent_speed_fraction = 0.5;  // [-]
  // Rule 16 (and 8(a), "in ample time"): the give-way ship's first action is early when, just before
  // it, the range was at least early_range_m or the TCPA at least early_tcpa_s.
  double early_range_m = 3704.0;  // [m] 2 nm
  double early_tcpa_s = 480.0;    // [s] 8 min
  // Rule 16 asks for early action "so far as possible": a ship that enters the rules already inside
  // the early range and TCPA (a close start, or a risk the target created late) is early when her first
  // apparent action (or the end of the risk, when the target removed it first) comes within
  // reaction_s of the entry. Our choice: about the time to see, decide and put the helm over.
  double reaction_s = 60.0;  // [s]
  // Rule 15: crossing the stand-on ship's track ahead of it, closer than this, is "crossing ahead".
  double cross_ahead_range_m = 3704.0;  // [m] 2 nm
  // Rule 17: the give-way ship's action is "clearly lacking" once the target is urgent (Hu et al. 2017
  // risk level 2: 0 <= TCPA <= t_safe and DCPA < d_safe), which is also when Hu's Algorithm 1 flags a
  // target that went from risk 1 straight to 2.
  HuRiskConfig hu;
  // Rule 17 with several ships: a duty to keep out of the way of another ship excuses an early stand-on
  // action only when that ship's TCPA is within duty_tcpa_s at the action and, duty_effect_s later,
  // the action has widened its CPA without cutting the stand-on target's (our reading).
  double duty_tcpa_s = 900.0;   // [s] 15 min: the other ship's own action window
  double duty_effect_s = 60.0;  // [s] when the action's effect on the CPAs is measured
  // Rule 17(b): the give-way ship alone can no longer avoid the close-quarters situation once none of
  // her actions (a turn of up to 90 deg to either side, half speed or a stop), taken extremis_delay_s
  // after the instant (the helm and the swing), keeps r_min (our reading).
  double extremis_delay_s = 60.0;  // [s]

  // Penalties (fractions of the target's score removed; the score is safety x prod(1 - p)).
  double penalty_rule8 = 0.3;       // x (1 - alteration / apparent): not readily apparent
  double penalty_late = 0.3;        // x lateness in [0, 1]; full penalty when no action at all
  double penalty_port = 0.5;        // Rule 14/15 (and 17(c)): a turn to port while the risk lasted
  double penalty_ahead = 0.5;       // Rule 15: crossed ahead of the stand-on ship
  double penalty_stand_on = 0.5;    // Rule 17: the stand-on ship acted before it was allowed to
  double penalty_succession = 0.3;  // Rule 8(b): more than two small alterations in one sense in a row
  double penalty_extremis = 0.5;    // Rule 17(b): the stand-on ship held on into r_min, an action open

  // Manoeuvres: a course set-point change of at least manoeuvre_threshold_deg from the last settled
  // set-point; later changes within manoeuvre_window_s of its start belong to the same manoeuvre.
  double manoeuvre_threshold_deg = 5.0;  // [deg]
  double manoeuvre_window_s = 30.0;      // [s]

  // Trajectories are kept at this period for the rule checks (minimum distances use every sample).
  double sample_period_s = 1.0;  // [s] 0: keep every sample

  ColregsConfig colregs;  // encounter classification (as risk_node)

  // Throws std::invalid_argument naming the first bad field.
  void validate() const;
  // Keys: the field names above (hu/t_safe_s, hu/d_safe_m, hu/t_max_s, hu/d_min_m,
  // colregs/head_on_half_angle_deg, colregs/stern_sector_start_deg, colregs/max_range_m); unknown keys
  // are rejected; the result is validated.
  static EvaluationConfig fromParams(const ParamMap& params);
};

// What the recorder is told about the run before it starts.
struct RunInfo {
  std::string scenario;
  std::string planner;  // the own ship's planner short name, "none" without one
  uint64_t seed = 0;
  double min_separation = 926.0;  // [m] the scenario's safety.min_separation_m
  bool multi_agent = false;       // write "ships": every ship that plans gets an entry
  struct Ship {
    std::string name;
    std::optional<Eigen::Vector2d> goal;  // [m] ENU
    std::string planner;                  // "" for traffic without a planner
  };
  std::vector<Ship> ships;                // ships[0] is the own ship; every sample lists ships by these names
  std::vector<StaticObstacle> obstacles;  // static obstacles (land), ENU [m]
  GeoPoint origin;                        // of the ENU frame (the scenario's; 0 N 0 E without one)
  // The own ship's voyage plan, sailed from route_start (her place at t = 0): the run reports how far
  // she strayed from it. Empty: none.
  Route route;
  Eigen::Vector2d route_start = Eigen::Vector2d::Zero();
  std::optional<HumanRecord> human;  // the logged master's figures, to compare the run with

  // From a scenario: the own ship first, then the targets in file order.
  static RunInfo fromScenario(const Scenario& scenario, const std::string& planner, uint64_t seed);
};

// One ship at one instant.
struct ShipSample {
  std::string name;
  ShipState state;  // position, course and speed over ground, heading
  double course_setpoint = std::numeric_limits<double>::quiet_NaN();  // [rad]; NaN when unknown
  bool active = true;  // false once the ship has arrived and left the scenario
  double beam = 0.0;   // [m] with state.length, the hull outline checked against land (0: a point)
};

struct Manoeuvre {
  double time = 0.0;           // [s] when the set-point first changed
  double course_change = 0.0;  // [rad] positive to starboard
};

struct TargetResult {
  std::string name;
  Encounter encounter = Encounter::None;
  OwnRole role = OwnRole::None;
  double min_distance = std::numeric_limits<double>::quiet_NaN();   // [m]
  double tcpa_at_start = std::numeric_limits<double>::quiet_NaN();  // [s]
  double dcpa_at_start = std::numeric_limits<double>::quiet_NaN();  // [m]
  // Where the closest approach happened (the first sample at min_distance): time and both positions.
  double closest_time = std::numeric_limits<double>::quiet_NaN();  // [s]
  Eigen::Vector2d own_at_closest = Eigen::Vector2d::Zero();        // [m] ENU
  Eigen::Vector2d target_at_closest = Eigen::Vector2d::Zero();     // [m] ENU
  bool evaluated = false;  // the entry criterion was met: the rules were checked
  bool collision = false;
  double safety = 1.0;  // [0, 1]
  double score = 1.0;   // [0, 1] safety x prod(1 - penalties)
  bool colregs_ok = true;
  std::vector<std::string> notes;
  int first_side = 0;  // of the first alteration while the risk lasted: +1 starboard, -1 port, 0 none
};

// One ship's view of the run (the own ship's fills the top level; multi-agent runs list every
// planning ship under "ships").
struct ShipResult {
  std::string name;
  std::string planner;
  bool collision = false;
  bool grounding = false;  // the hull touched a static obstacle (a grounding event or a sample)
  double min_separation = std::numeric_limits<double>::quiet_NaN();  // [m] to any other ship
  // [m] hull outline to the nearest static obstacle over the run's samples; NaN without obstacles
  double min_obstacle_distance = std::numeric_limits<double>::quiet_NaN();
  bool arrived = false;
  double time_to_goal = std::numeric_limits<double>::quiet_NaN();  // [s]
  double path_length = 0.0;                                        // [m]
  double path_ratio = std::numeric_limits<double>::quiet_NaN();    // [-] only when arrived
  std::vector<Manoeuvre> manoeuvres;
  std::vector<TargetResult> targets;
  double colregs_score = 1.0;
};

struct RunResult {
  std::string scenario, planner;
  uint64_t seed = 0;
  GeoPoint origin;  // of the positions' ENU frame: the JSON gives them as latitude/longitude
  ShipResult own;
  bool collision = false;              // the own ship touched another ship
  int collisions_between_targets = 0;  // pairs of other ships that touched each other
  bool safety_violation = false;
  struct PlanTime {
    double median_ms = std::numeric_limits<double>::quiet_NaN();
    double max_ms = std::numeric_limits<double>::quiet_NaN();
    long count = 0;
  } plan_time;
  double wall_time = 0.0;  // [s]
  bool multi_agent = false;
  std::vector<ShipResult> ships;
  // With a human record (RunInfo::human): our min_separation and time_to_goal over the master's (NaN
  // without a separation, or when not arrived).
  std::optional<HumanRecord> human;
  double separation_vs_human = std::numeric_limits<double>::quiet_NaN();
  double time_vs_human = std::numeric_limits<double>::quiet_NaN();
  // With a voyage plan: the own ship's largest distance from the route (the nearest leg; routeDeviation)
  // while she sailed, and the time she spent outside a leg's corridor.
  struct RouteStats {
    std::size_t legs = 0;           // 0: no route
    double max_xte = 0.0;           // [m]
    double outside_corridor = 0.0;  // [s]
  } route;
  // [m] The smallest and largest passing distance the own ship's plans kept in restricted waters
  // (addPassingDistance); NaN when every plan was made in open water.
  double passing_min = std::numeric_limits<double>::quiet_NaN();
  double passing_max = std::numeric_limits<double>::quiet_NaN();
};

// Safety score of a passing range r (see EvaluationConfig).
double safetyScore(double r, double r_pref, double r_min, double r_nm, double at_r_min);

class RunRecorder {
public:
  // Throws std::invalid_argument for a bad config or a RunInfo without ships.
  RunRecorder(const EvaluationConfig& config, const RunInfo& info);

  // A sample of every ship at time t (increasing). Ships are matched by name; unknown names and
  // missing ships are ignored (a ship may appear late or be absent from a message).
  void addSample(double t, const std::vector<ShipSample>& ships);
  // A course set-point of one ship (e.g. a <ship>/cmd message between samples). Samples carrying a
  // set-point feed the same series.
  void addSetpoint(double t, const std::string& ship, double course);
  // Wall time of one plan of the own ship [s] (plan_time_ms).
  void addPlanTime(double seconds);
  // The passing distance one plan of the own ship kept in restricted waters (Plan::passing_distance;
  // 0: open water, not counted): passing_distance_m.
  void addPassingDistance(double metres);
  void addEvent(const SimEvent& event);
  void setWallTime(double seconds) { wall_time_ = seconds; }

  size_t sampleCount() const { return samples_; }
  double lastTime() const { return last_t_; }
  // Evaluates everything recorded so far.
  RunResult finish() const;
  // The run as a GeoJSON FeatureCollection (RFC 7946, longitude/latitude WGS84) that any GIS opens:
  // every ship's track (LineString, property "kind": "track"), the own ship's closest approach to
  // each target ("closest_approach": a Point at the own ship with distance and time, and the
  // LineString between the two ships), her manoeuvres (Points) and the land ("land" Polygons).
  std::string geoJson(const RunResult& result) const;

private:
  struct Point {
    double t;
    ShipState s;
    bool active;
  };
  struct Track {
    std::vector<Point> points;  // thinned to sample_period_s
    double last_kept = -1e300;
    bool have_first = false;
    Eigen::Vector2d first_pos = Eigen::Vector2d::Zero();
    Eigen::Vector2d last_pos = Eigen::Vector2d::Zero();
    bool have_last = false;
    double path_length = 0.0;
    std::vector<std::pair<double, double>> setpoints;  // (t, course) on change
  };
  // The instants at which ships i and j are both in the scenario, and the passage of a target from the
  // entry into the rules to the closest approach (evaluation.cpp).
  using Instants = std::vector<std::pair<const Point*, const Point*>>;
  struct Passage;
  // A ship that ship i had to keep out of the way of, from the entry into the rules to the closest
  // approach [s].
  struct GiveWayDuty {
    std::string target;
    size_t ship;  // its index
    double from, to;
  };
  int index(const std::string& name) const;
  // Ship i's hull in sample s against every static obstacle: min_obstacle_, grounded_.
  void checkLand(size_t i, const ShipSample& s);
  // The own ship at p (time t) against the voyage plan: route_stats_.
  void followRoute(double t, const Eigen::Vector2d& p);
  ShipResult evaluateShip(size_t i) const;
  // Ships i and j over the run: their common instants, the CPA at each and the entry into the rules
  // (ke; both.size() when none).
  struct PairHistory {
    Instants both;
    std::vector<Cpa> cpas;
    size_t ke = 0;
  };
  PairHistory pairHistory(size_t i, size_t j) const;
  TargetResult evaluatePair(size_t i, size_t j, const PairHistory& h, const std::vector<GiveWayDuty>& duties,
                            const std::vector<Manoeuvre>& manoeuvres) const;
  Instants commonInstants(size_t i, size_t j) const;
  size_t entryInstant(const Instants& both, std::vector<Cpa>& cpas) const;
  // The ships ship i had to keep out of the way of (pairs[j]: ship j's history with ship i).
  std::vector<GiveWayDuty> giveWayDuties(const std::vector<PairHistory>& pairs) const;
  Passage passage(const Instants& both, const std::vector<Cpa>& cpas, size_t ke) const;
  // The last sample of the passage (ke to kc) before the target's own motion removed the risk.
  size_t riskRemoved(const Instants& both, size_t ke, size_t kc) const;
  bool inRisk(const Passage& p, size_t k) const;
  void finishTurn(Passage& p) const;
  // Rule 16: how early sample k is, 1 or more for early (an action at time t_act after the entry).
  double earliness(const Passage& p, size_t k, double t_act) const;
  void judgeGiveWay(const Passage& p, TargetResult& r, double& factor,
                    const std::vector<GiveWayDuty>& duties) const;
  void judgeRemovedRisk(const Passage& p, TargetResult& r, double& factor) const;
  void judgeEarly(const Passage& p, TargetResult& r, double& factor) const;
  void judgeSuccession(const Passage& p, TargetResult& r, double& factor) const;
  void judgeCrossAhead(const Passage& p, TargetResult& r, double& factor) const;
  void judgePortTurn(const Passage& p, TargetResult& r, double& factor, const char* rule,
                     const std::vector<GiveWayDuty>& duties) const;
  // The first alternative open to the own ship at sample k ("" when none was): a turn to starboard of
  // `course`, or half speed on it (a port turn was forced when none was open).
  std::string alternativeOpen(const Passage& p, size_t k, double course) const;
  bool keepsClear(const Passage& p, const Point& own, const Eigen::Vector2d& v1, double hold,
                  const Eigen::Vector2d& v2) const;
  std::string forcedNote(const Passage& p) const;
  void judgeStandOn(const Passage& p, TargetResult& r, double& factor,
                    const std::vector<GiveWayDuty>& duties) const;
  bool giveWayAloneKeepsClear(const Passage& p, size_t k) const;
  void judgeExtremis(const Passage& p, TargetResult& r, double& factor) const;
  const Point* sampleAt(size_t k, double t) const;
  std::optional<Cpa> cpaAt(size_t i, size_t j, double t) const;
  std::string dutyNotReal(const Passage& p, const GiveWayDuty& d, double t_action) const;
  void finishScore(TargetResult& r, double factor) const;
  std::vector<Manoeuvre> manoeuvres(const Track& tr) const;

  EvaluationConfig cfg_;
  RunInfo info_;
  double r_pref_, r_min_, r_nm_;
  std::vector<Track> tracks_;
  std::vector<std::vector<double>> min_dist_;  // pairwise, while both active
  struct Closest {
    double t = 0.0;
    Eigen::Vector2d a = Eigen::Vector2d::Zero(), b = Eigen::Vector2d::Zero();  // ship i's, ship j's
  };
  std::vector<std::vector<Closest>> closest_;  // [i][j]: where min_dist_[i][j] was reached
  std::vector<std::vector<char>> collided_;    // pairwise collision events
  std::vector<char> grounded_;                 // per ship: grounding event or hull on land
  std::vector<double> min_obstacle_;           // per ship [m]: hull to the nearest obstacle
  std::vector<double> arrival_;                // arrival time per ship (NaN: none)
  std::vector<double> plan_times_;
  RunResult::RouteStats route_stats_;
  std::pair<double, double> passing_{std::numeric_limits<double>::infinity(), 0.0};  // (min, max) [m]
  double route_last_t_ = std::numeric_limits<double>::quiet_NaN();  // the own ship's previous sample
  double wall_time_ = 0.0;
  double last_t_ = -1e300;
  size_t samples_ = 0;
};

// Deterministic JSON (fixed key order, fixed precision, null for NaN/inf). pretty: indented over
// several lines (evaluator_node's file); otherwise one line (JSON Lines).
std::string toJson(const RunResult& result, bool pretty = false);
// The same result without its wall-clock keys' values: wall_time_s and plan_time_ms median/max are 0
// (count is kept). For determinism checks and --deterministic.
void zeroWallClock(RunResult& result);
// A short human summary (one line) and a per-target table (several lines) for logs.
std::string summaryLine(const RunResult& result);
std::string summaryTable(const RunResult& result);

}  // namespace asv
