// COLREGs-compliant path re-planning of Hu, Naeem et al. (2017), "COLREGs-Compliant Path Planning for
// Autonomous Surface Vehicles: A Multiobjective Optimization Approach", IFAC-PapersOnLine 50(1),
// sections 2.2-3, solved with the MOPSO of Coello, Pulido & Lechuga (2004), "Handling multiple objectives
// with particle swarm optimization", IEEE TEC 8(3) 256-279.
//
// Rule selection (section 2.2, Table 1, Fig. 1): each target's risk level and compliance flag (Algorithm
// 1, asv_core/risk/risk_level.h) give a Table 1 decision; with "rule applies" the own role from the COLREGs
// zones (asv_core/risk/colregs.h) says stand on (keep course and speed) or give way (plan). A non-compliant
// target at risk 2 (Table 1 "x", Rule 2(b)) makes the own ship evade whatever the other rules say.
//
// Decision x = [theta', t] (eq. 7): the ship at A steers theta' for t seconds to the sub-waypoint B, then
// heads back to the next waypoint C. We carry theta' as the alteration delta = theta' - theta from the own
// ship's current course theta (positive = starboard), the quantity (3), (4) and (6) constrain.
//
// Objectives F = [f, g, h] (eq. 8-10), constraints (3)-(6), f <= 0 (11) and the land polygons of
// Fig. 4(b); all are free functions below so that each can be checked on its own. Deviations from the
// printed paper (each argued at the function): eq. (9) is used through its supplement; CPAs are taken
// over the whole piecewise-linear path within a horizon; a target whose closest approach is now and
// opening is past its CPA.
#pragma once

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/common/param_map.h"
#include "asv_core/planning/planning.h"

namespace asv {

// Every field: unit, meaning, default, source. fromParams() keys are the field names.
struct MopsoConfig {
  // --- MOPSO (Coello et al. 2004, section IV and the settings of section V) ---
  int particles = 50;         // [-] swarm size; Hu et al. section 4 ("a population of 50 particles")
  int generations = 40;       // [-] iterations; Hu et al. section 4 ("typically within 30-40 generations")
  int repository_size = 100;  // [-] capacity of the external archive of non-dominated solutions;
                              // Coello et al. section V (100)
  int grid_divisions = 30;    // [-] adaptive-grid divisions per objective; Coello et al. section V (30)
  double inertia = 0.4;       // [-] W of the velocity update; Coello et al. section IV (W = 0.4)
  double c1 = 1.0;            // [-] weight of the pull to the particle's own best (Coello: R1 alone, so 1)
  double c2 = 1.0;            // [-] weight of the pull to the leader from the repository (Coello: 1)
  double leader_fitness_x = 10.0;  // [-] x of the hypercube fitness x / (particles in it), x > 1;
                                   // Coello et al. section IV-A (x = 10)
  double mutation_rate = 0.5;      // [-] pM of the mutation operator whose reach and probability shrink as
                                   // (1 - gen/generations)^(5/pM); Coello et al. section IV-C (0.5)

  // --- Problem (Hu et al. sections 2.3 and 3.1) ---
  double d_min_m = 1852.0;        // [m] d_min of eq. (8), the desirable DCPA; as eq. (1) (1 nm, risk.md)
  double safety_scale_a = 1.0;    // [s/m] a of eq. (8); not given. 1 s/m: 100 m inside d_min with
                                  // 100 s to the CPA gives f_i = e - 1, of the order of one unit
  double cpa_horizon_s = 1200.0;  // [s] DCPA_i/TCPA_i are the closest approach within this time; a CPA
                                  // later than t_max is no risk by eq. (1), so the default is t_max (20 min)
  // [deg] eq. (3) and (6): the least alteration, readily apparent (Rule 8(b)). The paper's 15 in paper
  // mode; sea mode 30, the alteration the referee (evaluation.h apparent_course_deg) and the ACO
  // planner's sea mode take as readily apparent.
  double min_alteration_deg = 30.0;
  double max_alteration_deg = 60.0;     // [deg] eq. (4): efficiency bound, waived at risk 2; paper 60
  double search_alteration_deg = 90.0;  // [deg] the swarm searches delta in [-this, +this]; our choice:
                                        // beyond the beam a "sub-waypoint" turns the ship back
  double t_min_s = 60.0;    // [s] t_min of eq. (5); not given: 1 min keeps the new course readily apparent
  double t_max_s = 1800.0;  // [s] t_max of eq. (5); not given: 30 min, enough to open 1 nm at 15 deg
                            // and 8 kn, short enough to keep near the planned route
  bool prefer_starboard = true;  // impose eq. (6) in a first pass, relax it only if that finds nothing
  // Sea-mode extension (not in the paper, which only relaxes eq. (6)): before the relaxed pass, against a
  // Rule 2(b) target on the own port side, keep a starboard plan of the first pass that keeps the
  // situation's minimum separation (pass 3, Rule 17(c)). Paper mode: false.
  bool rule17c_pass = true;
  // Sea-mode extension (not in the paper): d_min of eq. (8) is raised to kSeparationMargin x the
  // situation's minimum separation (planning.h) when that is larger. Paper mode: false, d_min as set.
  bool inflate = true;
  double land_clearance_m = 185.2;  // [m] a leg must keep this far from every static polygon (Fig. 4(b));
                                    // not given: 0.1 nm
  // [m] selection rule: among the feasible Pareto solutions with f <= -margin (DCPA >= d_min + margin)
  // take the shortest (least h); if none has that margin, the safest (least f). Our choice: 0.05 nm
  // of slack for tracking errors
  double selection_margin_m = 92.6;
  double min_speed_mps = 0.1;  // [m/s] below this the own ship counts as stopped and the legs are
                               // timed at OwnShipLimits::max_speed

  void validate() const;  // throws std::invalid_argument naming the bad field
  // Hu et al. (2017) and nothing else: the sea-mode extensions above off (`inflate`, `rule17c_pass`).
  static MopsoConfig paper();
  // Reads the keys above and `mode` (sea | paper: which defaults the others start from); absent keys
  // keep the defaults; rejects unknown keys.
  static MopsoConfig fromParams(const ParamMap& params);
};

// --- Geometry of one candidate (Fig. 2) ---

struct EvasionPath {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();  // [m] current position A
  Eigen::Vector2d b = Eigen::Vector2d::Zero();  // [m] sub-waypoint B
  Eigen::Vector2d c = Eigen::Vector2d::Zero();  // [m] next waypoint C
  double speed = 0.0;                           // [m/s] v, held on every leg
  double duration = 0.0;                        // [s] t, time on A->B
  double course_ab = 0.0;                       // [rad] theta' (nautical)
  double course_bc = 0.0;                       // [rad] course of B->C
  double course_after_c = 0.0;  // [rad] course the ship holds after C (the nominal route's next leg)
  double l_ab = 0.0, l_bc = 0.0, l_ac = 0.0;  // [m]
  // [m/s] ENU velocities on A->B, B->C and after C (kept so the CPA needs no trigonometry)
  Eigen::Vector2d vel_ab = Eigen::Vector2d::Zero(), vel_bc = Eigen::Vector2d::Zero(),
                  vel_after = Eigen::Vector2d::Zero();
};

// own_course: theta [rad]; alteration: delta = theta' - theta [rad, + starboard]; duration t [s].
EvasionPath evasionPath(const Eigen::Vector2d& a, double own_course, double speed, const Eigen::Vector2d& c,
                        double course_after_c, double alteration, double duration);

// Closest approach of a constant-velocity target to the own ship following A->B->C and then
// course_after_c, for 0 <= time <= horizon. tcpa = 0 with `opening` set means the range only grows:
// the CPA is in the past.
struct PathCpa {
  double dcpa = 0.0;  // [m]
  double tcpa = 0.0;  // [s] from now
  bool opening = false;
};
PathCpa pathCpa(const EvasionPath& path, const ShipState& target, double horizon);

// --- Objectives (eq. 8-10) ---

// f_i of eq. (8): d_min - DCPA when DCPA >= d_min, else exp(a (d_min - DCPA) / TCPA) - 1. A past CPA
// (tcpa 0, opening) inside d_min gives -1, the limit of the printed form as TCPA -> 0 from below (no
// future approach: no risk, eq. (1) needs TCPA >= 0). The exponent is capped at 50 so that the value
// stays finite for the grid.
double safetyTerm(const PathCpa& cpa, double d_min, double a);
// f of eq. (8): the largest f_i over the targets; -inf-free: with no targets, -d_min (nothing near).
double safetyObjective(const EvasionPath& path, const std::vector<PlannerTarget>& targets,
                       const MopsoConfig& cfg);
// g: heading change at B, pi - angle ABC [rad]. Eq. (9) as printed is the interior angle ABC of the
// triangle of Fig. 2 (pi - delta - the angle at C, whose tangent is vt sin delta / (l - vt cos delta);
// with l = l_AB = vt it would collapse to pi/2 - delta/2, so l must be l_AC). Minimising ABC itself
// would reward the sharpest turn, against the text ("minimise the sum of heading changes"); its
// supplement, delta + angle at C, is exactly the alteration at A plus the course difference at C
// back onto the route, which is what we minimise.
double smoothnessObjective(const EvasionPath& path);
// The interior angle ABC, eq. (9) as printed with l = l_AC [rad]; for tests and documentation.
double huEq9Printed(double alteration, double speed, double duration, double l_ac);
// h of eq. (10): vt + l_BC [m].
double pathLengthObjective(const EvasionPath& path);

// --- Constraints: each returns its violation (0 = satisfied, larger = worse) ---

double apparentAlterationViolation(double alteration, const MopsoConfig& cfg);  // eq. (3) [rad]
double efficiencyViolation(double alteration, bool urgent,
                           const MopsoConfig& cfg);                    // eq. (4) [rad]; 0 if urgent
double durationViolation(double duration, const MopsoConfig& cfg);     // eq. (5) [s]
double starboardViolation(double alteration, const MopsoConfig& cfg);  // eq. (6) [rad]
double safetyViolation(double f);                                      // eq. (11): max(0, f)
// Static obstacles (Fig. 4(b)): length inside plus the shortfall from the clearance [m]; 0 = clear.
double landViolation(const Polygon& poly, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                     double clearance);
// The same through the obstacle's index when it has one (a coastline).
double landViolation(const StaticObstacle& o, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                     double clearance);

// --- MOPSO building blocks ---

struct MopsoEvaluation {
  std::array<double, 3> objectives{{0.0, 0.0, 0.0}};  // f, g, h
  double violation = 0.0;                             // total; 0 = feasible
  bool feasible() const { return violation <= 0.0; }
};

// Pareto dominance (minimisation): a no worse in every objective and better in one.
bool paretoDominates(const std::array<double, 3>& a, const std::array<double, 3>& b);
// Coello et al. section IV-D: feasible beats infeasible; of two infeasible the lesser violation wins
// (equal violations fall back to Pareto); of two feasible, Pareto dominance.
bool constrainedDominates(const MopsoEvaluation& a, const MopsoEvaluation& b);

// Adaptive grid of Coello et al. section IV-A: the objective-space box of the archive, widened by half
// a cell each side, cut into `divisions` per objective.
class AdaptiveGrid {
public:
  explicit AdaptiveGrid(int divisions = 30) : divisions_(divisions) {}
  void rebuild(const std::vector<std::array<double, 3>>& points);
  bool contains(const std::array<double, 3>& p) const;
  // Linear hypercube index; points outside are clamped to the border cells.
  int cubeOf(const std::array<double, 3>& p) const;
  int divisions() const { return divisions_; }
  const std::array<double, 3>& lower() const { return lo_; }
  const std::array<double, 3>& upper() const { return hi_; }

private:
  int divisions_;
  bool built_ = false;
  std::array<double, 3> lo_{{0, 0, 0}}, hi_{{0, 0, 0}};
};

struct MopsoSolution {
  double alteration = 0.0;  // [rad] delta = theta' - theta, + starboard
  double duration = 0.0;    // [s] t
  MopsoEvaluation eval;
  double f() const { return eval.objectives[0]; }
  double g() const { return eval.objectives[1]; }
  double h() const { return eval.objectives[2]; }
};

// The external archive (Coello et al. section IV-A/B): non-dominated solutions under
// constrainedDominates, at most `capacity`, thinned from the most crowded hypercubes.
class MopsoRepository {
public:
  MopsoRepository(int capacity, int divisions) : capacity_(capacity), grid_(divisions) {}
  // Adds s unless an archived solution dominates it (or equals it); drops what s dominates; then
  // truncates. Returns true when s was kept.
  bool insert(const MopsoSolution& s, std::mt19937_64& rng);
  // The same for a whole swarm, truncating once at the end (Coello et al. Fig. 1 step 6(f)).
  void insertAll(const std::vector<MopsoSolution>& batch, std::mt19937_64& rng);
  // Roulette over occupied hypercubes with fitness x / count, then a uniform member of the cube.
  const MopsoSolution& selectLeader(double x, std::mt19937_64& rng) const;
  const std::vector<MopsoSolution>& members() const { return members_; }
  const AdaptiveGrid& grid() const { return grid_; }
  // Occupancy of the hypercube holding member i.
  int density(size_t i) const;

private:
  bool add(const MopsoSolution& s);  // without truncation
  // While over capacity, removes a uniform member of the most crowded hypercube (Coello et al. IV-B).
  void truncate(std::mt19937_64& rng);
  void regrid();
  int capacity_;
  AdaptiveGrid grid_;
  std::vector<MopsoSolution> members_;
  std::vector<int> cube_;  // hypercube of each member
  // Occupied cubes for the roulette, rebuilt lazily after a change: (cube, member) sorted by cube, and
  // the [begin, end) runs of each cube in it.
  mutable bool roulette_valid_ = false;
  mutable std::vector<std::pair<int, int>> by_cube_;
  mutable std::vector<std::pair<size_t, size_t>> runs_;
  mutable double roulette_total_ = 0.0, roulette_x_ = 0.0;
};

// Rule selection (section 2.2, Table 1).
enum class HuAction : uint8_t {
  None = 0,       // no risk of collision (Table 1 "+") and the route is clear: carry on
  StandOn = 1,    // Rule 17: keep course and speed
  GiveWay = 2,    // a rule requires the own ship to keep out of the way (or a static obstacle blocks)
  Rule2Evade = 3  // Rule 2(b): a non-compliant target at risk 2; evade whatever the other rules say
};
const char* toString(HuAction a);
struct RuleSelection {
  HuAction action = HuAction::None;
  int target = -1;      // index of the target that decided it (-1: none or an obstacle)
  bool urgent = false;  // some target at risk 2: eq. (4) is waived
  std::string reason;
};
RuleSelection selectRule(const PlanningProblem& problem, const MopsoConfig& cfg);

struct MopsoResult {
  RuleSelection rule;
  std::vector<MopsoSolution> pareto_front;  // archive of the last pass (feasible ones first if any)
  int chosen = -1;                          // index into pareto_front, -1 when no plan was optimised
  // 1: eq. (6) imposed; 2: relaxed; 3: Rule 17(c) kept a starboard plan inside d_min; 0: no optimisation
  int pass = 0;
  int generations_run = 0;  // over both passes
  long evaluations = 0;
};

// Everything a candidate needs, fixed for one planning call.
struct MopsoContext {
  Eigen::Vector2d a = Eigen::Vector2d::Zero(), c = Eigen::Vector2d::Zero();
  double own_course = 0.0, speed = 0.0, course_after_c = 0.0;
  bool urgent = false;           // eq. (4) waived
  bool impose_starboard = true;  // eq. (6) active
  const std::vector<PlannerTarget>* targets = nullptr;
  const std::vector<StaticObstacle>* obstacles = nullptr;
  bool has_bounds = false;
  Eigen::Vector2d bounds_min = Eigen::Vector2d::Zero(), bounds_max = Eigen::Vector2d::Zero();
};
MopsoContext makeContext(const PlanningProblem& problem, const MopsoConfig& cfg, bool urgent);
// F(x) and the total violation of (3)-(6), (11), land and bounds. Angles count in radians, time in
// units of t_max, distances in units of d_min.
MopsoEvaluation evaluateCandidate(double alteration, double duration, const MopsoContext& ctx,
                                  const MopsoConfig& cfg);

// The documented selection rule (see MopsoConfig::selection_margin_m); -1 when no member is feasible.
int selectFromFront(const std::vector<MopsoSolution>& front, const MopsoConfig& cfg);

class MopsoPlanner : public PlannerAlgorithm {
public:
  explicit MopsoPlanner(const MopsoConfig& cfg = {});
  void configure(const ParamMap& params) override;
  Plan plan(const PlanningProblem& problem) override;
  std::string name() const override { return "mopso"; }
  const MopsoConfig& config() const { return cfg_; }
  const MopsoResult& lastResult() const { return last_; }
  const std::vector<MopsoSolution>& lastParetoFront() const { return last_.pareto_front; }

private:
  // One MOPSO run (Coello et al. Fig. 1 pseudo-code); returns the archive.
  std::vector<MopsoSolution> optimise(const MopsoContext& ctx, const MopsoConfig& cfg, uint64_t seed,
                                      const Deadline& deadline, MopsoResult& stats) const;
  MopsoConfig cfg_;
  MopsoResult last_;
};

}  // namespace asv
