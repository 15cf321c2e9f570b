// DSSA (Kim et al. 2017) and DSSA+ (Hirayama, Miyake, Shiota & Okimoto 2019): distributed stochastic
// search for multi-ship collision avoidance. Equation, figure and section numbers refer to the DSSA+
// paper: Hirayama, Miyake, Shiota & Okimoto, "DSSA+: Distributed Collision Avoidance Algorithm in an
// Environment where Both Course and Speed Changes are Allowed", TransNav 2019.
//
// The per-ship logic (DssaAgent) is separate from the message exchange: the ROS layer runs one agent per
// planner node and exchanges DssaIntention messages over a topic; DssaExchange runs the same agents
// in-process, round by round (Fig. 2), for the batch runner and the paper's experiments.
//
// Units: SI inside (m, s, rad, m/s), nautical courses (clockwise from north), positive course change =
// to starboard. The paper's experiments are unitless (an 800 x 800 area, speed 25 per time unit); they
// run here as metres and seconds, which is why the defaults below are the paper's numbers read in SI.
// For a real ship scale time_window, time_step, detection_range, collision_distance and the speed
// changes to its size and speed (e.g. from rosparam).
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/common/param_map.h"
#include "asv_core/common/types.h"
#include "asv_core/planning/planning.h"

namespace asv {

struct DssaConfig {
  // false: DSSA (course changes only, the speed is kept); true: DSSA+ (course and speed changes, Sec. 4).
  bool speed_changes = false;
  // Not in the papers (DSSA is built for congested waters where the COLREGs "do not work well",
  // Sec. 1): when true, a plan made through PlanningProblem (DssaPlanner::plan) in which the own ship
  // is the give-way vessel of a head-on or crossing encounter searches only starboard course
  // changes and no speed increase (Rules 14, 15, 16). false (the paper's search) by default; the sea
  // defaults (seaDefaults()) turn it on. Key "colregs".
  bool colregs = false;
  // Set per plan from `colregs` (not a parameter): restricts Dom as described above.
  bool starboard_only = false;
  // [-] alpha of EF (Sec. 3.2, Sec. 4): weight of the course inefficiency |theta_dest - theta(crs)|/180deg.
  // The paper gives only ratios (alpha = 10 beta, beta = 10 alpha, alpha = beta, Sec. 5); 1 is our
  // choice: a collision within the window costs CR >= 1 (TCPA <= TimeWindow), so a 45 deg turn
  // (EF 0.25) always pays for avoiding one.
  double alpha = 1.0;
  // [-] beta of EF (Sec. 4): weight of the speed inefficiency |clamp(CurSPD + spc) - RefSPD| / MaxSPD.
  // Ignored by DSSA. Default 0.1: the preset dssa_plus_sc (alpha = 10 beta).
  double beta = 0.1;
  // [-] probability p that a ship with a positive improvement adopts its new intention (Fig. 2).
  // Paper, Sec. 5: 0.8.
  double p = 0.8;
  // [s] TimeWindow: how far ahead both ships' positions are predicted (appendix). Paper, Sec. 5: 20.
  double time_window = 20.0;
  // [s] length of one time step of Fig. 1 (one control phase). Not stated; 1, the time unit of the
  // paper's speed (25 per time unit; its travel times of 23.0 = 575 / 25 imply one move per unit).
  double time_step = 1.0;
  // [m] radius of the detection range: ships farther away are not neighbours (Sec. 3.1). Paper: 500.
  double detection_range = 500.0;
  // [m] "self will collide with j" (Sec. 3.2) when DCPA (appendix) is below this. The paper says only
  // "sufficiently small" (appendix). 40 (1.6 moves of the paper's ships, under half their 100 m lane
  // spacing) is our choice after a sweep over 40-50 against all three tables, see docs/results/dssa.md.
  double collision_distance = 40.0;
  // [s] floor of TCPA in CR = TimeWindow/TCPA: guards the division when a collision is imminent (CR is
  // then at most time_window / tcpa_floor). TCPA = 0 itself (the CPA is now, the ships separate
  // afterwards: appendix rules 2 and 4) is not a future collision and costs CR = 0.
  double tcpa_floor = 0.01;
  // [rad] largest course change of the domain, either side (Sec. 3.2: +-45 deg; Fig. 3).
  double course_change_max = 45.0 * 3.14159265358979323846 / 180.0;
  // [rad] step of the course changes (Sec. 3.2: 5 deg). crs_dest is added when within +-course_change_max.
  double course_change_step = 5.0 * 3.14159265358979323846 / 180.0;
  // [m/s] largest speed change of DSSA+, either side (Sec. 4: 8 "kt" = 8 distance units per time unit).
  double speed_change_max = 8.0;
  // [m/s] step of the speed changes (Sec. 4: 2).
  double speed_change_step = 2.0;
  // [-] most rounds of intention exchange in one search phase (Fig. 2's "time limit", not given). After
  // it every ship keeps its current intention. Our choice: 100 (the paper's cases settle in < 30).
  int max_rounds = 100;
  // [s] wall-clock limit of one search phase (Fig. 1/2's time limit); <= 0: rounds only. Deterministic
  // runs should rely on max_rounds. Default 0.
  double max_search_time = 0.0;
  // [m/s] RefSPD of DssaPlanner (Sec. 4); <= 0: the own ship's planning speed (PlanningProblem::own,
  // the cruise speed; limits.max_speed if it has none). Default 0. Agents
  // take RefSPD/MinSPD/MaxSPD from DssaShipSpeeds instead.
  double ref_speed = 0.0;
  // [m/s] MaxSPD (Sec. 4, the clamp of CurSPD + spc) = RefSPD + this when > 0; <= 0: the host's limit
  // (the own ship's limits.max_speed, the ROS agent's max_speed, asv_batch's OwnShipLimits). The paper
  // gives no MaxSPD; its experiments here use 8 (one largest speed change above RefSPD). Default 0.
  double max_speed_over_ref = 0.0;
  // [-] MinSPD (Sec. 4) = this x RefSPD when > 0 (never below the host's limit); 0: the host's limit.
  // The paper gives no MinSPD but implies one above zero: Sec. 5.3 says speed changes alone cannot
  // avoid collision when a 25 overtakes a 10 (so the 25's MinSPD exceeds 10), and Table 2's s>c ships
  // average 16.4 (so it is below that). Its experiments here use kDssaPaperMinSpeedFraction. Default 0.
  double min_speed_fraction = 0.0;

  // Throws std::invalid_argument naming the first bad field.
  void validate() const;

  // Keys (SI, angles in degrees at this edge): mode (sea | paper: the preset's weight scale, see
  // preset()), preset (applied first), speed_changes, alpha, beta, p,
  // time_window, time_step, detection_range, collision_distance, tcpa_floor, course_change_max_deg,
  // course_change_step_deg, speed_change_max, speed_change_step, max_rounds, max_search_time,
  // ref_speed, max_speed_over_ref, min_speed_fraction. Unknown keys are rejected; the result is validated.
  static DssaConfig fromParams(const ParamMap& params);
  // fromParams with `preset` as the preset unless the parameters name one: how a planner named
  // "dssa" or "dssa_plus" reads its parameters (DssaPlanner, and the ROS agents from the plugin's).
  static DssaConfig fromParams(ParamMap params, const std::string& preset);
  // The sea-scale defaults every ROS and batch run in sea mode starts from (the paper's values are in its own
  // units: an 800 x 800 area, TimeWindow 20, detection range 500): a 10-minute window, intentions
  // exchanged within 6 nm, "collide" below 0.5 nm, a 10 s search step, speed changes of up to 4 m/s
  // (about 8 kn) in 1 m/s steps. Our choice; docs/results/dssa.md.
  static ParamMap seaDefaults();

  // The paper's variants (Sec. 5), all with p = 0.8, TimeWindow 20, detection range 500:
  //   "dssa"          DSSA: course changes only, alpha = 1;
  //   "dssa_plus_sc"  DSSA+ s>c ("speed over course"): alpha = 10 beta (alpha 1, beta 0.1), speed
  //                   changes preferred;
  //   "dssa_plus_cs"  DSSA+ s<c ("course over speed"): beta = 10 alpha (alpha 1, beta 10), course
  //                   changes preferred;
  //   "dssa_plus_eq"  DSSA+ s=c: alpha = beta = 1;
  //   "dssa_plus"     alias of dssa_plus_eq, the planner plugin's default (the only variant without
  //                   a weak spot in the paper's tables).
  // The paper gives only the ratios. `paper` (mode paper) reads them with the smaller weight 1, as the
  // text states them ("alpha 10 times higher than beta"): s>c is alpha 10, beta 1. Sea mode keeps
  // alpha = 1 throughout, so that a predicted collision (CR >= 1) always outweighs a 45 deg turn
  // (EF 0.25). Our choice; docs/results/dssa.md shows how the outcome depends on this scale.
  // Throws std::invalid_argument for any other name.
  static DssaConfig preset(const std::string& name, bool paper = false);
  static std::vector<std::string> presetNames();
};

// RefSPD, MinSPD, MaxSPD of one ship (Sec. 4), m/s.
struct DssaShipSpeeds {
  double ref = 25.0;
  double min = 0.0;
  double max = 25.0;
};

// One ship's RefSPD, MinSPD and MaxSPD (Sec. 4) from the config and the host's view of the ship.
// RefSPD = config.ref_speed when > 0, else the cruise speed (the speed the ship is planned at; the
// maximum as RefSPD would make DSSA+ speed up in every encounter), else the limit; MaxSPD = RefSPD +
// config.max_speed_over_ref when that is > 0, else max_limit (and RefSPD no more than it);
// MinSPD = the larger of min_limit and config.min_speed_fraction x RefSPD, within [0, MaxSPD].
DssaShipSpeeds dssaShipSpeeds(const DssaConfig& config, double cruise_speed, double min_limit,
                              double max_limit);

// One ship's tentative intention as exchanged between ships (Sec. 3.2, Sec. 4): what the ship will
// steer and at what speed after one time step, and where it is now.
struct DssaIntention {
  int id = 0;               // ship id (MMSI in the ROS layer)
  int round = 0;            // exchange round in which it was decided (0: the initial intention)
  double stamp = 0;         // [s] time at which `position` and `velocity` were valid
  double course = 0;        // [rad] absolute course intended (current heading + crs)
  double speed_change = 0;  // [m/s] spc relative to the current speed (0 in DSSA)
  double speed = 0;         // [m/s] speed intended: clamp(CurSPD + spc, MinSPD, MaxSPD)
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] ENU, at `stamp`
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();  // [m/s] ENU, over ground at `stamp`
  bool satisfied = false;  // the sender's improvement was 0 in this round (Fig. 2)

  Eigen::Vector2d intendedVelocity() const { return courseSpeedToVelocity(course, speed); }
};

// What the others know of a ship that reached her goal and stays there (Fig. 1: only a ship "who does
// not reach her goal" moves): a stopped ship at `position` as of `now`, satisfied. She no longer
// searches, so her host sends this for her at every search phase.
DssaIntention dssaStationaryShip(int id, const Eigen::Vector2d& position, double course, double now);

// One ship's half of Fig. 2. Not thread-safe; one agent per ship.
class DssaAgent {
public:
  DssaAgent(int id, const DssaConfig& config, const DssaShipSpeeds& speeds);

  // Starts a search phase (Fig. 1): own state now (position, heading = course, speed), goal, time.
  // Rebuilds the domain and resets the intention to the current heading and speed (Fig. 2, first box).
  // Neighbours' intentions received earlier are kept (last known, extrapolated along their intended
  // velocity from their stamp to `now`) until a newer one arrives or forget() is called.
  void setOwn(const ShipState& state, const Eigen::Vector2d& goal, double now = 0.0);
  // Not in the paper (open sea): static obstacles. A candidate whose move over TimeWindow comes closer
  // to land than `required` [m] gets kLandInefficiency added to its EF, so that it is chosen only when
  // every candidate would. Call before setOwn(); `obstacles` must outlive the agent's use of it.
  void setLand(const std::vector<StaticObstacle>* obstacles, double required);
  static constexpr double kLandInefficiency = 1e6;

  // Stores a neighbour's intention (replaces an older one of the same ship; an older round of the
  // same stamp is ignored). Own messages are ignored.
  void receive(const DssaIntention& from_neighbour);
  // Drops what is known of a ship (it left, arrived, or its messages are too old).
  void forget(int id);

  // One round of Fig. 2 for this ship: costs of the domain against the intentions received so far,
  // improvement and new_intention; adopts new_intention with probability p when improvement > 0 (with
  // probability 1 when the ship has no neighbour: Fig. 1's control phase steers it directly).
  // Returns the intention to send.
  DssaIntention decide(int round, std::mt19937_64& rng);

  const DssaIntention& intention() const { return intention_; }
  bool changed() const { return changed_; }      // the last decide() changed the intention
  bool satisfied() const { return satisfied_; }  // the last decide() found improvement = 0
  double improvement() const { return improvement_; }
  int id() const { return id_; }
  const DssaConfig& config() const { return config_; }
  const Eigen::Vector2d& position() const { return position_; }

  // Neighbours within the detection range now (after extrapolation).
  int neighbourCount() const;
  // Cost_self(crs, spc) (Sec. 3.2 / Sec. 4) against the intentions received so far. crs relative to the
  // current heading [rad], spc [m/s]; need not be in the domain.
  double cost(double crs, double spc) const;
  // The two terms of it, for tests and diagnostics.
  double collisionRisk(double crs, double spc) const;
  double inefficiency(double crs, double spc) const;
  // Course change to the destination, crs_dest (Sec. 3.2) [rad], in [-pi, pi).
  double destinationCourseChange() const;
  // Number of (crs, spc) pairs in the domain now (at most 20 in DSSA, 180 in DSSA+; Fig. 3; one course
  // more, straight for the goal, when the goal is within this step's move but beyond the turn limit).
  int domainSize() const { return static_cast<int>(cand_.size()); }

private:
  struct Candidate {
    double crs = 0, spc = 0;  // relative course [rad], speed change [m/s]
    double course = 0, speed = 0;
    Eigen::Vector2d disp = Eigen::Vector2d::Zero();  // own displacement over TimeWindow [m]
    double ef = 0;
  };
  struct Neighbour {
    DssaIntention msg;
    Eigen::Vector2d pos = Eigen::Vector2d::Zero();   // extrapolated to now_
    Eigen::Vector2d disp = Eigen::Vector2d::Zero();  // displacement over TimeWindow
    bool in_range = false;
    bool dirty = true;
    std::vector<double> cr;  // CR against this neighbour per candidate
  };

  Candidate makeCandidate(double crs, double spc) const;
  double crAgainst(const Candidate& c, const Neighbour& n) const;
  void refresh(Neighbour& n) const;

  int id_;
  DssaConfig config_;
  DssaShipSpeeds speeds_;
  Eigen::Vector2d position_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d goal_ = Eigen::Vector2d::Zero();
  double heading_ = 0, speed_ = 0, now_ = 0, theta_dest_ = 0;
  const std::vector<StaticObstacle>* land_ = nullptr;
  double land_required_ = 0.0;
  std::vector<Candidate> cand_;
  std::vector<Neighbour> nb_;
  std::vector<double> total_;
  int current_ = 0;  // index of the intention in cand_
  DssaIntention intention_;
  bool changed_ = false, satisfied_ = false;
  double improvement_ = 0;
};

// Uniform [0, 1) from 53 bits: the same on every standard library (uniform_real_distribution is not).
inline double dssaUniform(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0);
}
// Per-ship generator seed from a run seed and a ship id (splitmix64), so a ship draws the same numbers
// whether it runs in-process or in its own node.
uint64_t dssaAgentSeed(uint64_t seed, int id);

// In-process exchange of Fig. 2 over N agents: round 0 delivers every initial intention; then each
// round every agent decides from what it has received, and all new intentions are delivered (to the
// agents within the sender's detection range) at once. Stops at quiescence (every agent satisfied, so
// none changed: Fig. 2) or at max_rounds / max_search_time.
class DssaExchange {
public:
  struct Result {
    int rounds = 0;          // decision rounds run
    bool quiescent = false;  // ended by quiescence, not by a limit
    long messages = 0;       // intentions delivered
  };
  // Return true to drop the message of `from` to `to` in `round` (tests, lossy links).
  using DropFilter = std::function<bool(int round, int from, int to)>;

  explicit DssaExchange(const DssaConfig& config) : config_(config) {}
  void setDropFilter(DropFilter f) { drop_ = std::move(f); }

  // agents[i] draws from rngs[i]; both vectors are the same size. Agents must have had setOwn().
  Result run(std::vector<DssaAgent>& agents, std::vector<std::mt19937_64>& rngs) const;

private:
  void deliver(std::vector<DssaAgent>& agents, int round, Result& r) const;

  DssaConfig config_;
  DropFilter drop_;
};

// The single-agent use (Sec. 3.2's cost with the others fixed): the own ship decides against targets
// that do not run DSSA, each taken to keep its course and speed as its intention. Rounds of Fig. 2 run
// against those fixed intentions until the own ship is satisfied.
class DssaPlanner : public PlannerAlgorithm {
public:
  explicit DssaPlanner(const std::string& preset = "dssa");
  void configure(const ParamMap& params) override;
  Plan plan(const PlanningProblem& problem) override;
  std::string name() const override { return config_.speed_changes ? "dssa_plus" : "dssa"; }
  const DssaConfig& config() const { return config_; }

protected:
  // The paper's defaults are in its own units (DssaConfig::seaDefaults).
  ParamMap seaDefaults() const override { return DssaConfig::seaDefaults(); }

private:
  std::string preset_;
  DssaConfig config_;
};

// DSSA+ (Hirayama et al. 2019): course and speed changes; default-constructible for pluginlib.
class DssaPlusPlanner : public DssaPlanner {
public:
  DssaPlusPlanner() : DssaPlanner("dssa_plus") {}
};

}  // namespace asv
