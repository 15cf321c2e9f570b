// Genetic-algorithm collision avoidance of Wu et al. (2022), "Multi-vessels collision avoidance strategy
// for autonomous surface vehicles based on genetic algorithm in congested port environment",
// Brodogradnja 73(3), sections 2-4. The decision is one heading alteration in [-90, 90] deg; its fitness
// is the fuzzy collision risk index (CRI, eq. 1-6, asv_core/risk/cri.h) recomputed for the candidate heading,
// with the safe encounter distance of eq. (7)-(12) and the COLREGs of section 2.1 as penalties.
//
// Sign convention. The paper reports every avoiding alteration as negative (head-on: -28.49 deg, although
// section 2.1 demands a turn to starboard), i.e. its angles are counter-clockwise positive. Ours are
// nautical: a positive alteration is to starboard (clockwise). So ours = -(paper's): the paper's
// -28.49 deg is our +28.49 deg.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "asv_core/common/param_map.h"
#include "asv_core/planning/planning.h"
#include "asv_core/risk/colregs.h"
#include "asv_core/risk/cri.h"

namespace asv {

// Every field: unit, meaning, default, source. Keys for fromParams() are the field names; the CRI and
// COLREGs fields take the prefixes "cri/" and "colregs/" (e.g. "cri/dlma_m", "colregs/max_range_m").
struct GaConfig {
  // --- GA parameters (section 3.1 and the simulation settings of section 4) ---
  int population_size = 150;  // [-] individuals per generation; paper section 4 (n = 150, 3.2 step 2)
  int generations = 150;      // [-] stop rule: number of generations; paper section 4 (150)
  double crossover_probability = 0.7;  // [-] Pc, per pair of parents; paper section 4 (0.7)
  double mutation_probability = 0.05;  // [-] Pm, per individual ("probability of individual mutation",
                                       // section 3.1 item 3): one gene (bit) position is flipped; paper 0.05
  // [-] bits of the binary chromosome that codes the alteration (section 3.2 step 1: "each code
  // corresponds to an angle"). 10 bits = 1024 codes, the smallest power of two above the paper's
  // "maximum number of genes ... 1,000" (section 4); resolution 2 max_alteration / (2^bits - 1) =
  // 0.176 deg at the defaults. Range [2, 16] (the fitness cache holds 2^bits entries).
  int chromosome_bits = 10;
  double max_alteration_deg =
      90.0;  // [deg] the feasible space is [-max, +max]; paper section 3.2 step 1 (90)
  // [-] the best individuals copied unchanged into the next generation. Not in the paper (0 = the
  // paper's plain GA). One elite keeps the best fitness monotone over the generations, so that mutation
  // and the roulette cannot lose the best heading found; the returned heading is in any case the best
  // ever seen (section 3.2 step 9, "output the optimal solution").
  int elite_count = 1;

  // --- Decision rule (section 2.2, Fig. 3; section 4) ---
  double cri_threshold = 0.61;  // [-] act when some target's CRI on the original course exceeds this (sec. 4)
  // [-] targets whose CRI (on the original course) lies within this of the largest CRI are "similar" and
  // their CRIs are summed in the objective; the others do not enter the sum (section 4, 2): "priority to
  // the largest CRI ... if the CRIs of multiple target ships are similar, the CRIs are added"). The paper
  // gives no number; 0.05 is about the spread of the paper's Fig. 9 curves that it treats together.
  double similar_cri_margin = 0.05;
  // Hold a decision (section 4.2: the ASV decides at 330 s, "then turns to the best collision avoidance
  // angle" and keeps it until the encounter ends; a new decision at 465 s when TS2's CRI passes the
  // threshold). true: the course decided for the targets above the threshold is kept until a target not
  // among them passes it, or none is above it (then the course to the goal). false: decide again at every
  // call, so that the plan follows the changing situation (sea mode; the shared rules check each plan).
  // Paper mode: true.
  bool hold_decision = false;

  // --- Penalties added to the objective (lower is better); our choices, not the paper's ---
  // [-] per target whose DCPA for the candidate falls short of the safe encounter distance SDA = d1 of
  // eq. (10) (eq. 7: DCPA >= SDA): penalty * (SDA - DCPA) / SDA. 1 = a full CRI unit at DCPA 0, so a
  // candidate that enters a domain ranks behind every candidate that does not.
  double safety_penalty = 1.0;
  // [-] per COLREGs violation (section 2.1: starboard turn and port-to-port passing head-on; pass astern
  // of crossing targets; plus Rule 17(c), no turn to port for a crossing target on the port side).
  double colregs_penalty = 1.0;
  // [-] per target outside the priority set: penalty * max(0, CRI - cri_threshold) for the candidate,
  // so that avoiding the priority target does not create a new risk with another.
  double new_risk_penalty = 1.0;
  // [-] per max_alteration_deg of |alteration|, linear: the least sufficient turn wins among candidates
  // of (nearly) equal risk. 0.05 is 0.0006 CRI per degree: far below the CRI's slope while the DCPA is
  // inside the safe encounter distances, so it only breaks ties once the risk has levelled off.
  double turn_penalty = 0.05;

  // --- Plan shape ---
  // [s] minimum duration of the evasive leg (the leg ends at the latest CPA of the priority targets on the
  // new heading, or after this time if that is sooner); then the plan returns to the goal.
  double min_leg_time_s = 30.0;

  CriConfig cri;          // CRI model (eq. 1-6, 10-12); scale its distances to the own ship
  ColregsConfig colregs;  // encounter classification (section 2.1)

  // Key mode (planning.h): sea, the defaults above; paper, Wu et al. (2022) alone: the CRI objective with
  // no elite and no penalty, decisions held (the extensions' keys still override when given).
  static GaConfig paper();
  void validate() const;  // throws std::invalid_argument naming the bad field
  // Reads the keys above (absent keys keep the defaults); rejects unknown keys.
  static GaConfig fromParams(const ParamMap& params);
};

// ---------------------------------------------------------------------------------------------------
// GA operators (section 3.2), separately testable.

// Deterministic generator for the GA (splitmix64): the same seed gives the same sequence on every
// platform and standard library (std:: distributions are implementation-defined).
class GaRng {
public:
  explicit GaRng(uint64_t seed) : state_(seed) {}
  uint64_t next() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  // Integer in [0, n), n > 0 (multiply-shift; bias < n / 2^64).
  uint32_t below(uint32_t n) {
    return static_cast<uint32_t>((static_cast<unsigned __int128>(next()) * n) >> 64);
  }

private:
  uint64_t state_;
};

// Section 3.2 step 1: code k in [0, 2^bits - 1] <-> alteration in [-max, max] [rad], equally spaced:
// decode(k) = -max + 2 max k / (2^bits - 1). encode rounds to the nearest code (clamped).
double decodeAlteration(uint32_t code, int bits, double max_alteration);
uint32_t encodeAlteration(double alteration, int bits, double max_alteration);
inline double alterationResolution(int bits, double max_alteration) {
  return 2.0 * max_alteration / static_cast<double>((1u << bits) - 1u);
}

// Roulette-wheel weights from costs (lower is better). The paper minimises the CRI, the wheel needs a
// larger-is-better fitness: f_i = (J_max - J_i) + 0.05 (J_max - J_min) (windowing, Goldberg 1989), so the
// worst individual keeps a small chance and the pressure does not depend on the CRI's offset. Equal
// costs give equal weights. Writes the running sums of f into `cumulative` (same size as `cost`).
void rouletteCumulative(const std::vector<double>& cost, std::vector<double>& cumulative);
// Section 3.2 step 4: index i with cumulative[i-1] <= u * total < cumulative[i], u in [0, 1).
size_t rouletteSelect(const std::vector<double>& cumulative, double u);
// Section 3.2 step 5: with probability pc, cut both chromosomes at one point in [1, bits - 1] and swap
// the low parts. Returns true when crossed.
bool singlePointCrossover(uint32_t& a, uint32_t& b, int bits, double pc, GaRng& rng);
// Section 3.2 step 6: with probability pm, flip one gene (bit) at a uniformly drawn position. Returns the
// position flipped, or -1.
int mutateGene(uint32_t& code, int bits, double pm, GaRng& rng);

// ---------------------------------------------------------------------------------------------------
// Objective.

struct GaTargetInfo {
  size_t index = 0;            // into PlanningProblem::targets
  EncounterGeometry geometry;  // on the original course (section 2.1)
  double cri = 0.0;            // CRI on the original course (eq. 1)
  bool priority = false;       // in the summed set (largest CRI and the similar ones)
  bool engaged = false;        // priority, or CRI above the threshold: COLREGs apply
};

struct GaCostTerms {
  double risk = 0.0;      // sum of the priority targets' CRI for the candidate (eq. 1)
  double new_risk = 0.0;  // new_risk_penalty * sum over the others of max(0, CRI - threshold)
  double safety = 0.0;    // safety_penalty * sum of (SDA - DCPA)/SDA shortfalls (eq. 7, 10)
  double colregs = 0.0;   // colregs_penalty * number of violations (section 2.1)
  double turn = 0.0;      // turn_penalty * |alteration| / max_alteration
  // Not in the paper (its port has no land model): kLandCost when the evasive leg, or the way from its
  // end back to the route, comes closer to land than the clearance; such a heading is taken only when
  // every heading would.
  double land = 0.0;
  double total = 0.0;  // the GA's objective J (lower is better); Plan::cost of the best
};

// The fitness of a candidate alteration, built once per planning problem. The original course is the
// course to the next route waypoint (or the goal); alterations are measured from it, so that a planner
// called again every cycle returns to it as soon as the risk on it has cleared.
class GaFitness {
public:
  GaFitness(const PlanningProblem& problem, const GaConfig& cfg);
  double sdaFloor() const { return sda_floor_; }  // [m] PlanningProblem::min_separation x margin
  double referenceCourse() const { return reference_course_; }  // [rad] nautical
  double maxCri() const { return max_cri_; }                    // on the original course
  bool triggered() const { return max_cri_ > cfg_.cri_threshold; }
  const std::vector<GaTargetInfo>& targets() const { return info_; }
  // J(alteration) [-]; alteration [rad], positive to starboard. Allocates nothing.
  double cost(double alteration) const { return terms(alteration).total; }
  GaCostTerms terms(double alteration) const;
  // CPA of target i (index into targets()) with the own ship on the candidate heading.
  Cpa cpa(size_t i, double alteration) const;
  // [s] how long the evasive leg lasts: until the last priority target's CPA on the candidate heading,
  // at least min_leg_time_s.
  double legTime(double alteration) const;
  static constexpr double kLandCost = 1e6;

private:
  double sda_floor_ = 0.0;
  double passing_cap_ = 0.0;  // [m] PlanningProblem::passing_cap (0: open water)
  struct Target {
    ShipState state;
    Eigen::Vector2d velocity;
    Eigen::Vector2d unit_velocity;  // zero when stopped
    double true_bearing = 0.0;      // [rad] from the own ship
    Encounter encounter = Encounter::None;
    bool priority = false, engaged = false;
  };
  GaConfig cfg_;
  CriConfig candidate_cri_;  // cfg_.cri without Fig. 3's zeroing of diverging pairs
  ShipState own_;
  double reference_course_ = 0.0;
  double max_cri_ = 0.0;
  std::vector<Target> targets_;
  std::vector<GaTargetInfo> info_;
  const std::vector<StaticObstacle>* land_ = nullptr;
  double land_required_ = 0.0;                      // [m] landRequirement of the problem; 0: no land
  double land_reach_ = 0.0;                         // [m] how far along the candidate's track land is judged
  Eigen::Vector2d next_ = Eigen::Vector2d::Zero();  // the route's next point (or the goal)
};

// Result of one GA run, for tests and tools.
struct GaRunResult {
  double alteration = 0.0;  // [rad] best alteration, positive to starboard
  uint32_t code = 0;        // its chromosome
  double cost = 0.0;        // J of the best
  int generations = 0;      // generations run
  size_t evaluations = 0;   // distinct codes evaluated (the rest came from the cache)
  bool deadline_hit = false;
};

// Runs the GA of section 3.2 on `fitness` with the seed; stops after cfg.generations or at the deadline.
GaRunResult runGa(const GaFitness& fitness, const GaConfig& cfg, uint64_t seed,
                  const Deadline* deadline = nullptr);

// ---------------------------------------------------------------------------------------------------

class GaPlanner : public PlannerAlgorithm {
public:
  explicit GaPlanner(const GaConfig& cfg = {});
  // Keys as GaConfig::fromParams.
  void configure(const ParamMap& params) override;
  // Below the threshold: hold the course to the goal (status Ok, cost 0). Above: run the GA and steer
  // the original course + the best alteration (or the held course, hold_decision); waypoints own
  // position, the end of the evasive leg, the remaining route and the goal.
  Plan plan(const PlanningProblem& problem) override;
  std::string name() const override { return "ga"; }
  // Paper mode (hold_decision): the CRI is checked against the threshold at every cycle (Sec. 4.2).
  bool ownTrigger() const override { return cfg_.hold_decision; }
  const GaConfig& config() const { return cfg_; }

private:
  // The decision in force (hold_decision): its course [rad] and the targets it was made for (none: no
  // decision; a decision has at least its priority target).
  struct Decision {
    double course = 0.0;
    double time = 0.0;  // [s] PlanningProblem::time of the decision
    std::vector<std::string> targets;
  };
  GaConfig cfg_;
  Decision held_;
  double last_time_ = -std::numeric_limits<double>::infinity();  // an earlier time: a new run
};

}  // namespace asv
