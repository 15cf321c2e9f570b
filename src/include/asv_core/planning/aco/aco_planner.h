// Ant colony optimisation trajectory planner of Lazarowska (2015), "Ship's Trajectory Planning for
// Collision Avoidance at Sea Based on Ant Colony Optimisation", J. Navigation 68(2).
//
// The own ship keeps its speed and alters course only (eq. 4); targets keep course and speed. Every
// target carries the hexagon domain (section 3), static obstacles are convex or concave polygons and
// the environment may be bounded (eq. 1-3). Artificial ants walk a grid construction graph of own-ship
// positions (Fig. 6) from the own position to the final waypoint, choosing each next vertex by the
// action choice rule (eq. 7); vertex pheromone evaporates and is deposited after every iteration
// (eq. 8); the shortest feasible path (eq. 9) is the plan.
//
// Choices the paper leaves open (grid, neighbourhood, deposit amount, the minimum first alteration,
// the waypoint reduction of the best path) are parameters of AcoConfig, documented there and in
// docs/results/aco.md.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/common/param_map.h"
#include "asv_core/common/units.h"
#include "asv_core/planning/planning.h"
#include "asv_core/risk/domain.h"

namespace asv {

// Parameters of the ACO planner. ParamMap keys (fromParams) carry the unit of the edge value in their
// name (`row_spacing_m`, `min_first_alteration_deg`); fields are SI.
struct AcoConfig {
  // --- ACO (section 2.3 and the values of section 3) ---
  double tau0 = 1.0;    // [-] key tau0: initial pheromone on every vertex (2.3.1). Paper: 1.
  double rho = 0.1;     // [-] key rho: evaporation rate in (0, 1], eq. (8). Paper: 0.1.
  double alpha = 1.0;   // [-] key alpha: pheromone exponent of eq. (7), >= 0. Paper: 1.
  double beta = 1.0;    // [-] key beta: visibility exponent of eq. (7), >= 0. Paper: 1.
  int iterations = 20;  // [-] key iterations: number of colony iterations (termination). Paper: 20.
  int ants = 10;        // [-] key ants: ants per iteration. Paper: 10.
  // [-] key deposit: Q of the pheromone deposit of eq. (8). Not given in the paper. Each ant with a
  // complete path adds Q * D / L to every vertex of that path, D the straight distance from the own
  // ship to the final waypoint, L the path length of eq. (9). A 1/L deposit in metres would be ~1e-4
  // against tau0 = 1 and the trail would never matter in 20 iterations; D / L is 1 for the straight
  // path and falls with every detour, so the trail is of the order of tau0. Default 1.
  double deposit = 1.0;

  // --- Construction graph (Fig. 6; spacing and neighbourhood are not given in the paper) ---
  // The graph is a lattice aligned with the line from the own ship to the final waypoint ("course up"
  // as the paper's figures): rows perpendicular to it every row_spacing along it, columns parallel to
  // it every column_spacing across it. An ant moves from row i to row i + 1, at most lateral_steps columns
  // sideways, so every walk ends at the final waypoint after exactly (rows - 1) steps (the paper's "maximum
  // number of ant's steps").
  double row_spacing = 0.5 * 1852.0;       // [m] key row_spacing_m: along-track spacing (shrunk so that the
                                           // final waypoint is on the last row). Default 0.5 nm.
  double column_spacing = 0.125 * 1852.0;  // [m] key column_spacing_m: cross-track spacing.
                                           // Default 0.125 nm.
  // [-] key lateral_steps: K, the neighbourhood: columns an ant may shift per row (1..16). With the
  // default spacings K = 3 gives leg directions 0, +-14.0, +-26.6 and +-36.9 deg off the base line;
  // waypoint reduction (smooth) then straightens the lattice path into legs of any direction.
  // Chosen over 0.25 nm rows and K = 1, 2, 4, 5 on Scenarios 1-2 (20 seeds): shortest mean reduced
  // path within 0.2 %, fewest legs, and the widest turn that still keeps ants near the base line.
  int lateral_steps = 3;
  double half_width = 3.0 * 1852.0;  // [m] key half_width_m: cross-track extent of the lattice on
                                     // each side of the base line, inside the eq. (1) bounds when
                                     // those are given. Default 3 nm.
  // Key long_edges: an ant may move from row i to any later row i + r (r <= 32), at most r *
  // lateral_steps columns sideways (the same widest leg direction; lateral_steps <= 4), instead of to
  // row i + 1 only. With eta = 1 / edge length (2.3.2) the summed weight of each later row is about the
  // same, so a walk is a few long legs (~ln(rows)). Paper mode's graph, our reading of the lost Fig. 6:
  // cells of 0.75 nm (square when wp_e is a whole number of cells out; rows shrink to fit otherwise),
  // lateral_steps 1 (legs up to 45 deg off the base line), long edges. Why: every course the paper
  // prints is a grid slope off its base line, atan(1/5) = 11.3, atan(1/4) = 14.0, atan(1/3) = 18.4 deg
  // (Scenario 1: 077, 052 from 066; Scenario 2: 050, 079 from 061), and Scenario 1's answer, cells
  // (5, 1) then (9, 0), puts wp_e 9 cells out; 0.75 nm = 6.75 nm / 9, wp_e calibrated in
  // lazarowska_scenarios.h. Sea mode (false) keeps one row per move and smooths the staircase instead.
  bool long_edges = false;
  // Key danger_by_course: step (3) as printed, a target is dangerous when its course line crosses the
  // own ship's ahead of both (parallel courses: when the direct route enters her domain). Our safety
  // net on it: the direct route is returned only when it also enters no domain. False (sea mode): a
  // target is dangerous when the direct route enters her domain.
  bool danger_by_course = false;

  // --- Manoeuvres (COLREGs Rule 8(b) and the manoeuvre time, eq. 5-6) ---
  // [rad] key min_first_alteration_deg: the first course alteration away from the present course must
  // be at least this large to be "readily apparent" (Rule 8(b)); 0 disables. The paper reports 11 deg
  // alterations; we default to 30 deg, the evaluator's apparent alteration (evaluation.h) and the usual
  // guidance for a substantial one (docs/results/aco.md).
  double min_first_alteration = degToRad(30.0);
  // [rad] key max_alteration_deg: largest single course alteration, (0, 120] deg. Eq. (6) is only
  // meaningful below ~133 deg (the tangent term grows past the turn time). Default 90 deg.
  double max_alteration = degToRad(90.0);
  // key smooth: waypoint reduction of the best ant path (not in the paper): the lattice path is
  // replaced by the fewest straight legs through its vertices that are still feasible in time
  // (greedy farthest-visible shortcut), which only shortens eq. (9) and turns a staircase of lattice
  // moves into the few apparent alterations the paper reports. Default true.
  bool smooth = true;
  // [s] key max_time_s: wall-clock limit of the search (termination by time, 2.3.4); the smaller of
  // this and PlanningProblem::time_budget applies; 0 = the problem's budget only. Default 0.
  double max_time = 0.0;

  // Hexagon domain round every target (keys domain_a_m ... domain_e_m). Paper (section 3): a = 1 nm
  // bow, b = 0.6 nm amidships, c = 0.6 nm starboard, d = 0.25 nm stern, e = 0.25 nm port.
  HexagonDomainConfig domain;
  // Not in the paper, whose COLREGs are "the size and shape of the domain" (Table 1): round a target
  // for which the own ship is the give-way vessel of a head-on or crossing encounter, the bow
  // (a) and starboard (c) extents are multiplied by this, so that the shortest trajectory passes the
  // target's port side or astern (Rules 14, 15) even when tracking noise puts it a little off the own
  // track. Key colregs_factor; 1 = the paper's domain. Our choice: 2.
  double colregs_factor = 2.0;
  // Not in the paper: no side of a target's hexagon closer than 1.3 x the problem's min_separation
  // (inflatedDomain in aco_planner.cpp). Key inflate; false = the paper's extents.
  bool inflate = true;

  // Key mode (planning.h): sea, the defaults above; paper, Lazarowska (2015) alone: no minimum first
  // alteration, no waypoint reduction, colregs_factor 1, no inflation, long_edges, and step (3)'s
  // dangerous target as printed (AcoDiagnostics::dangerous_targets) (the keys still override).
  static AcoConfig paper();
  // Throws std::invalid_argument naming the bad field.
  void validate() const;
  // Reads the keys above (no prefix: pass params.sub("aco") for an "aco/..." tree), starting from the
  // defaults; throws std::invalid_argument on a bad value or on any unknown key.
  static AcoConfig fromParams(const ParamMap& params);
};

// The environment E of eq. (1)-(3): boundaries, static obstacles E_stat and the moving target domains
// E_dyn(t). Times are seconds after PlanningProblem::time; the targets' states are taken at that time
// and extrapolated at constant course and speed (the paper's assumption).
// The hexagon round target t: `domain`, with a and c times colregs_factor when the own ship meets her
// head-on or gives way to her (AcoConfig::colregs_factor).
HexagonDomainConfig targetDomain(const PlannerTarget& t, const HexagonDomainConfig& domain,
                                 double colregs_factor);

class AcoEnvironment {
public:
  // colregs_factor: AcoConfig::colregs_factor (1: the same domain round every target).
  AcoEnvironment(const PlanningProblem& problem, const HexagonDomainConfig& domain,
                 double colregs_factor = 1.0);

  // Inside the eq. (1) boundaries (when given) and outside every static polygon.
  bool pointStaticFree(const Eigen::Vector2d& p) const;
  // The straight segment a-b stays inside the boundaries and touches no static polygon.
  bool segmentStaticFree(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
  // p at time t lies outside every target's domain.
  bool pointDynamicFree(const Eigen::Vector2d& p, double t) const;
  // The own ship sailing straight from a (time ta) to b (time tb) at constant velocity never enters
  // any target's domain. Exact, not sampled: relative to a target the own ship moves on a straight
  // segment in the target's frame, tested against the (convex) hexagon by half-plane clipping.
  bool segmentDynamicFree(const Eigen::Vector2d& a, double ta, const Eigen::Vector2d& b, double tb) const;
  // Same test against target j only.
  bool segmentHitsTarget(size_t j, const Eigen::Vector2d& a, double ta, const Eigen::Vector2d& b,
                         double tb) const;
  size_t targetCount() const { return targets_.size(); }
  // Index of the first static obstacle containing p, or -1.
  int obstacleAt(const Eigen::Vector2d& p) const;

private:
  struct Obstacle {
    StaticObstacle shape;    // with its index, for coastlines
    Eigen::Vector2d lo, hi;  // bounding box
  };
  struct MovingTarget {
    Eigen::Vector2d p0, v;  // [m], [m/s] ENU position at t = 0 and velocity
    double sin_c = 0.0, cos_c = 1.0;
    // Its domain polygon in the target frame (x starboard, y forward), counter-clockwise, as
    // half-planes n . p <= h; lo/hi its bounding box.
    Eigen::Matrix<double, 2, 6> normal;
    Eigen::Matrix<double, 1, 6> offset;
    Eigen::Vector2d lo, hi;
  };
  bool hitsTarget(const MovingTarget& tg, const Eigen::Vector2d& a, double ta, const Eigen::Vector2d& b,
                  double tb) const;

  bool has_bounds_ = false;
  Eigen::Vector2d bounds_min_, bounds_max_;
  std::vector<Obstacle> obstacles_;
  std::vector<MovingTarget> targets_;
};

// The construction graph of Fig. 6: lattice vertices (own-ship positions) between the own ship (row 0)
// and the final waypoint (last row), with the vertices that can never be part of a path removed:
// outside the bounds or the reachable diamond, inside a static obstacle, or with no statically free
// way on to the final waypoint. Target domains depend on when the own ship gets there, so they are
// tested during construction, per leg and in time.
class AcoGraph {
public:
  AcoGraph(const PlanningProblem& problem, const AcoConfig& cfg, const AcoEnvironment& env);

  int rows() const { return rows_; }          // N + 1: row 0 the own ship, row N the final waypoint
  int columns() const { return 2 * m_ + 1; }  // columns -m..m
  int halfColumns() const { return m_; }
  int lateralSteps() const { return k_; }
  int vertexCount() const { return rows_ * columns(); }
  int id(int row, int col) const { return row * columns() + col + m_; }
  int rowOf(int id) const { return id / columns(); }
  int colOf(int id) const { return id % columns() - m_; }
  int startId() const { return id(0, 0); }
  int goalId() const { return id(rows_ - 1, 0); }
  const Eigen::Vector2d& position(int id) const { return pos_[id]; }
  // In the graph: usable by an ant (see class comment).
  bool inGraph(int id) const { return alive_[id] != 0; }
  // The lattice edge from `id` to row + 1, column + k (|k| <= K) is free of static obstacles.
  bool edgeStaticFree(int id, int k) const { return edge_ok_[id * (2 * k_ + 1) + k + k_] != 0; }
  // A vertex the own ship may occupy at time t: in the graph and outside every target domain then.
  bool vertexFreeAt(int id, double t, const AcoEnvironment& env) const {
    return inGraph(id) && env.pointDynamicFree(pos_[id], t);
  }
  double rowSpacing() const { return ds_; }
  double columnSpacing() const { return dl_; }
  const Eigen::Vector2d& alongTrack() const { return u_; }
  const Eigen::Vector2d& crossTrack() const { return n_; }  // to starboard of alongTrack()

private:
  int rows_ = 0, m_ = 0, k_ = 0;
  double ds_ = 0.0, dl_ = 0.0;
  Eigen::Vector2d u_, n_;
  std::vector<Eigen::Vector2d> pos_;
  std::vector<uint8_t> alive_;
  std::vector<uint8_t> edge_ok_;
};

// What the last plan() did, for tests, reports and the rviz layer.
struct AcoDiagnostics {
  int iterations_run = 0;  // completed colony iterations
  int ants_completed = 0;  // ants that reached the final waypoint over all iterations
  int ants_dead = 0;       // ants boxed in before the final waypoint (discarded)
  int graph_vertices = 0;  // vertices in the construction graph
  // Step (3): sea mode, targets whose domain the unaltered route to the goal enters; paper mode, as
  // printed, targets whose course line crosses the own ship's ahead of both ships.
  int dangerous_targets = 0;
  bool direct_route = false;  // no dangerous target: the direct route was returned, no ACO run
  bool stopped_by_time = false;
  double best_walk_length = 0.0;           // [m] eq. (9) of the best lattice path
  std::vector<Eigen::Vector2d> best_walk;  // the best lattice path (before waypoint reduction)
  std::vector<double> command_times;       // [s] when each course alteration is ordered (eq. 6)
};

class AcoPlanner : public PlannerAlgorithm {
public:
  explicit AcoPlanner(const AcoConfig& cfg = {});
  void configure(const ParamMap& params) override;
  Plan plan(const PlanningProblem& problem) override;
  std::string name() const override { return "aco"; }
  // The hexagon round each target as plan() uses it: inflated to the problem's min_separation, and
  // colregs_factor for a head-on or give-way target (targetDomain).
  std::vector<TargetDomain> domains(const PlanningProblem& problem) const override;
  // Lazarowska (2015) computes the trajectory once, before the encounter, and the ship sails it.
  bool plansOnce() const override { return true; }
  const AcoConfig& config() const { return cfg_; }
  const AcoDiagnostics& diagnostics() const { return diag_; }

  // Manoeuvre time t_m of eq. (6) for a course alteration dpsi [rad] (sign ignored), with omega and t01
  // from OwnShipLimits (turn_rate, turn_delay).
  static double manoeuvreTime(double dpsi, const OwnShipLimits& limits);

private:
  AcoConfig cfg_;
  AcoDiagnostics diag_;
};

}  // namespace asv
