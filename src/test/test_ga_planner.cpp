// GA planner of Wu et al. (2022): operators, objective, decision rule, determinism and the paper's
// section 4 situation (reconstructed in wu_scenarios).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "asv_core/papers/wu_scenarios.h"
#include "asv_core/planning/ga/ga_planner.h"

using namespace asv;

namespace {

ShipState ship(const std::string& id, double x, double y, double course_deg, double speed) {
  ShipState s;
  s.id = id;
  s.position = {x, y};
  s.course = s.heading = degToRad(course_deg);
  s.speed = speed;
  return s;
}

PlanningProblem oneTarget(const ShipState& t) {
  PlanningProblem p;
  p.own = ship("own", 0.0, 0.0, 0.0, kWuAsvSpeed);
  p.goal = {0.0, 3000.0};
  p.time_budget = 60.0;  // planned to completion, however slow the machine (the tests run under ASan)
  PlannerTarget pt;
  pt.state = t;
  p.targets.push_back(pt);
  return p;
}

double alterationOf(const Plan& plan, const PlanningProblem& p) {
  return wrapPi(plan.course_setpoint - trueBearing(p.own.position, p.goal));
}

// Two-sided bound on a binomial count: |k - n p| <= 5 sigma (false alarm < 1e-6).
void expectBinomial(long k, long n, double p) {
  const double sigma = std::sqrt(n * p * (1.0 - p));
  EXPECT_NEAR(static_cast<double>(k), n * p, 5.0 * sigma) << "k " << k << " n " << n << " p " << p;
}

}  // namespace

TEST(GaOperators, EncodeDecodeRoundTripWithinResolution) {
  const int bits = 10;
  const double max = degToRad(90.0);
  const double res = alterationResolution(bits, max);
  EXPECT_NEAR(radToDeg(res), 180.0 / 1023.0, 1e-12);
  EXPECT_NEAR(decodeAlteration(0, bits, max), -max, 1e-15);
  EXPECT_NEAR(decodeAlteration(1023, bits, max), max, 1e-15);
  EXPECT_EQ(encodeAlteration(-max, bits, max), 0u);
  EXPECT_EQ(encodeAlteration(max, bits, max), 1023u);
  EXPECT_EQ(encodeAlteration(degToRad(-200.0), bits, max), 0u);  // clamped
  EXPECT_EQ(encodeAlteration(degToRad(200.0), bits, max), 1023u);
  for (double d = -90.0; d <= 90.0; d += 0.37) {
    const double a = degToRad(d);
    EXPECT_LE(std::fabs(decodeAlteration(encodeAlteration(a, bits, max), bits, max) - a), 0.5 * res + 1e-12)
        << d;
  }
  for (uint32_t k = 0; k < 1024; ++k)  // every code is its own nearest code
    EXPECT_EQ(encodeAlteration(decodeAlteration(k, bits, max), bits, max), k);
}

TEST(GaOperators, RouletteWindowingWeights) {
  std::vector<double> cum;
  rouletteCumulative({0.0, 1.0, 0.5}, cum);  // f = (1 - J) + 0.05
  ASSERT_EQ(cum.size(), 3u);
  EXPECT_NEAR(cum[0], 1.05, 1e-12);
  EXPECT_NEAR(cum[1], 1.10, 1e-12);
  EXPECT_NEAR(cum[2], 1.65, 1e-12);
  rouletteCumulative({0.3, 0.3}, cum);  // equal costs: uniform wheel
  EXPECT_DOUBLE_EQ(cum[0], 1.0);
  EXPECT_DOUBLE_EQ(cum[1], 2.0);
  // Boundaries: u * total falls in [cum[i-1], cum[i]).
  const std::vector<double> c = {1.0, 3.0, 6.0};
  EXPECT_EQ(rouletteSelect(c, 0.0), 0u);
  EXPECT_EQ(rouletteSelect(c, 0.99 / 6.0), 0u);
  EXPECT_EQ(rouletteSelect(c, 1.0 / 6.0), 1u);
  EXPECT_EQ(rouletteSelect(c, 5.99 / 6.0), 2u);
}

TEST(GaOperators, RouletteFrequenciesProportionalToFitness) {
  const std::vector<double> w = {1.0, 2.0, 3.0, 4.0, 0.5};
  std::vector<double> cum;
  cum.reserve(w.size());
  double s = 0.0;
  for (double x : w)
    cum.push_back(s += x);
  GaRng rng(12345);
  const int n = 200000;
  std::vector<long> count(w.size(), 0);
  for (int i = 0; i < n; ++i)
    ++count[rouletteSelect(cum, rng.uniform())];
  double chi2 = 0.0;
  for (size_t i = 0; i < w.size(); ++i) {
    const double e = n * w[i] / s;
    chi2 += (count[i] - e) * (count[i] - e) / e;
  }
  EXPECT_LT(chi2, 18.47);  // chi-square, 4 degrees of freedom, p = 0.001
}

TEST(GaOperators, CrossoverRateAndCutPoints) {
  const int bits = 10, n = 100000;
  GaRng rng(7);
  long crossed = 0;
  std::vector<long> cut_count(bits, 0);
  for (int i = 0; i < n; ++i) {
    uint32_t a = 0u, b = 0x3FFu;
    const bool c = singlePointCrossover(a, b, bits, 0.7, rng);
    EXPECT_EQ(a ^ b, 0x3FFu);  // genes are exchanged, never lost
    if (!c) {
      EXPECT_EQ(a, 0u);
      continue;
    }
    ++crossed;
    // a took b's genes below the cut: a = 2^cut - 1 with the cut in [1, bits - 1].
    int cut = 0;
    while (cut < bits && (a >> cut & 1u))
      ++cut;
    ASSERT_EQ(a, (1u << cut) - 1u);
    ASSERT_GE(cut, 1);
    ASSERT_LE(cut, bits - 1);
    ++cut_count[cut];
  }
  expectBinomial(crossed, n, 0.7);
  for (int cut = 1; cut < bits; ++cut)
    expectBinomial(cut_count[cut], crossed, 1.0 / (bits - 1));
}

TEST(GaOperators, MutationRateAndPositions) {
  const int bits = 10, n = 200000;
  GaRng rng(99);
  long mutated = 0;
  std::vector<long> pos_count(bits, 0);
  for (int i = 0; i < n; ++i) {
    uint32_t g = 0x155u;
    const int pos = mutateGene(g, bits, 0.05, rng);
    if (pos < 0) {
      EXPECT_EQ(g, 0x155u);
      continue;
    }
    ++mutated;
    EXPECT_EQ(g ^ 0x155u, 1u << pos);  // exactly one gene flipped
    ++pos_count[pos];
  }
  expectBinomial(mutated, n, 0.05);
  for (int p = 0; p < bits; ++p)
    expectBinomial(pos_count[p], mutated, 1.0 / bits);
}

TEST(GaConfigTest, ParamsAndValidation) {
  ParamMap m;
  m.set("population_size", 60.0);
  m.set("generations", 40.0);
  m.set("cri/dlma_m", 300.0);
  m.set("cri/domain_unit_m", 50.0);
  m.set("colregs/max_range_m", 5000.0);
  const GaConfig c = GaConfig::fromParams(m);
  EXPECT_EQ(c.population_size, 60);
  EXPECT_EQ(c.generations, 40);
  EXPECT_DOUBLE_EQ(c.cri.dlma_m, 300.0);
  EXPECT_DOUBLE_EQ(c.cri.safe_encounter.domain_unit_m, 50.0);
  EXPECT_DOUBLE_EQ(c.colregs.max_range_m, 5000.0);
  EXPECT_DOUBLE_EQ(c.crossover_probability, 0.7);  // paper defaults kept
  EXPECT_DOUBLE_EQ(c.mutation_probability, 0.05);
  EXPECT_DOUBLE_EQ(c.cri_threshold, 0.61);

  ParamMap typo;
  typo.set("mutation_prob", 0.1);
  EXPECT_THROW(GaConfig::fromParams(typo), std::invalid_argument);
  ParamMap bad;
  bad.set("crossover_probability", 1.5);
  EXPECT_THROW(GaConfig::fromParams(bad), std::invalid_argument);
  GaConfig g;
  g.chromosome_bits = 20;
  EXPECT_THROW(g.validate(), std::invalid_argument);
  g = GaConfig();
  g.elite_count = g.population_size;
  EXPECT_THROW(g.validate(), std::invalid_argument);

  GaPlanner planner;
  EXPECT_EQ(planner.name(), "ga");
  ParamMap unknown;
  unknown.set("ants", 10.0);
  EXPECT_THROW(planner.configure(unknown), std::invalid_argument);
}

TEST(GaFitnessTest, CostFallsAsTheHeadingClearsTheTarget) {
  const PlanningProblem p = wuHeadOn();
  const GaFitness f(p, wuAsvGaConfig());
  ASSERT_EQ(f.targets().size(), 1u);
  EXPECT_NEAR(f.referenceCourse(), 0.0, 1e-12);
  // DCPA by hand: own at the origin on delta at V, TS1 at (0, 400) on 180 at v:
  // w = (-V sin d, -v - V cos d), DCPA = |p x w| / |w| = 400 V sin d / |w|.
  const double V = kWuAsvSpeed, v = p.targets[0].state.speed;
  double prev = 1e9;
  for (double d : {0.0, 10.0, 20.0, 30.0, 40.0}) {
    const double a = degToRad(d);
    const double dcpa = 400.0 * V * std::sin(a) / std::hypot(V * std::sin(a), v + V * std::cos(a));
    EXPECT_NEAR(f.cpa(0, a).dcpa, dcpa, 1e-6);
    const double c = f.cost(a);
    EXPECT_LT(c, prev) << d;
    prev = c;
  }
  // Eq. (7): inside the safe encounter distance (d1 = 1.5 rho(0) L = 66.5 m) there is a safety penalty,
  // clear of it none.
  EXPECT_GT(f.terms(degToRad(10.0)).safety, 0.0);  // DCPA ~ 48 m
  EXPECT_DOUBLE_EQ(f.terms(degToRad(30.0)).safety, 0.0);
  // Port turns in a head-on break section 2.1 (turn right, pass port to port).
  EXPECT_GE(f.terms(degToRad(-30.0)).colregs, 2.0);
  EXPECT_DOUBLE_EQ(f.terms(degToRad(30.0)).colregs, 0.0);
  EXPECT_GT(f.cost(degToRad(-30.0)), f.cost(degToRad(30.0)) + 1.0);
  // The turn penalty is linear in |alteration|.
  EXPECT_NEAR(f.terms(degToRad(45.0)).turn, 0.5 * wuAsvGaConfig().turn_penalty, 1e-12);
}

// Wu et al. (2022), section 4.2: the ASV decides when TS1, 400 m dead ahead, has a CRI of 0.62. By hand,
// eq. (1)-(6) with the ASV's scaling (D1 = DLMA = 241.8 m, D2 = 2 DLMA = attention range = 483.6 m),
// own ship 6.1738 m/s, TS1 3 kn on 180: V_r = 7.7171 m/s, DCPA 0 (U_DCPA 1); TCPA = D / V_r,
// t1 = 241.8 / V_r = 31.33 s, t2 = 483.6 / V_r = 62.67 s; U_B(0) = 0.5 (cos 19 + sqrt(440/289 + cos^2 19))
// - 5/17 = 0.9559; U_K (K = 0.25, sin C = 0) = 1 / (1 + 2 / (0.25 sqrt(1.0625))) = 0.1141.
//   400 m: U_TCPA = U_D = 0.3457, CRI = 0.40 + 0.367 x 0.3457 + 0.033 x 0.9559 + 0.167 x 0.3457 + 0.033 x
//   0.1141 = 0.6199, above the threshold 0.61;
//   420 m: U_TCPA = U_D = 0.2630, CRI = 0.5758, below it.
TEST(GaFitnessTest, Ts1PassesTheThresholdAt400mAsInThePaper) {
  PlanningProblem p = wuHeadOn();
  ASSERT_NEAR(p.targets.at(0).state.position.y() - p.own.position.y(), 400.0, 1e-9);
  const GaFitness at400(p, wuAsvGaConfig());
  EXPECT_NEAR(at400.maxCri(), 0.6199, 5e-4);
  EXPECT_TRUE(at400.triggered());
  p.targets[0].state.position.y() = p.own.position.y() + 420.0;
  const GaFitness at420(p, wuAsvGaConfig());
  EXPECT_NEAR(at420.maxCri(), 0.5758, 5e-4);
  EXPECT_FALSE(at420.triggered());
}

TEST(GaFitnessTest, GaFindsTheBestCodeOfTheExhaustiveSearch) {
  for (const PlanningProblem& p : {wuHeadOn(), wuCrossing(), wuOvertaking(), wuFourTargets()}) {
    const GaConfig cfg = wuAsvGaConfig();
    const GaFitness f(p, cfg);
    double best = 1e9;
    for (uint32_t k = 0; k < 1024; ++k)
      best =
          std::min(best, f.cost(decodeAlteration(k, cfg.chromosome_bits, degToRad(cfg.max_alteration_deg))));
    const GaRunResult r = runGa(f, cfg, 3);
    EXPECT_EQ(r.generations, 150);
    EXPECT_LE(r.cost, best + 0.005);
    EXPECT_NEAR(r.cost, f.cost(r.alteration), 1e-12);
    EXPECT_LT(r.evaluations, 1025u);  // the cache: at most one evaluation per code
  }
}

TEST(GaPlannerTest, DeterministicBySeed) {
  GaPlanner a(wuAsvGaConfig()), b(wuAsvGaConfig());
  PlanningProblem p = wuFourTargets();
  p.seed = 42;
  const Plan pa = a.plan(p), pb = b.plan(p), pa2 = a.plan(p);
  EXPECT_EQ(pa.course_setpoint, pb.course_setpoint);
  EXPECT_EQ(pa.cost, pb.cost);
  EXPECT_EQ(pa.course_setpoint, pa2.course_setpoint);
  EXPECT_EQ(pa.message, pb.message);
  ASSERT_EQ(pa.waypoints.size(), pb.waypoints.size());
  for (size_t i = 0; i < pa.waypoints.size(); ++i)
    EXPECT_EQ(pa.waypoints[i].position, pb.waypoints[i].position);
  // The run really depends on the seed: a GA with a tiny population stops in different places.
  GaConfig tiny = wuAsvGaConfig();
  tiny.population_size = 4;
  tiny.generations = 1;
  tiny.elite_count = 0;
  const GaFitness f(p, tiny);
  bool differs = false;
  const GaRunResult r0 = runGa(f, tiny, 1);
  for (uint64_t s = 2; s < 20 && !differs; ++s)
    differs = runGa(f, tiny, s).code != r0.code;
  EXPECT_TRUE(differs);
}

TEST(GaPlannerTest, HeadOnTurnsToStarboardAndPassesPortToPort) {
  const PlanningProblem p = wuHeadOn();
  GaPlanner planner(wuAsvGaConfig());
  const Plan plan = planner.plan(p);
  EXPECT_EQ(plan.status, PlanStatus::Ok);
  const double alt = alterationOf(plan, p);
  EXPECT_GT(alt, degToRad(5.0));
  EXPECT_LE(alt, degToRad(90.0) + 1e-9);
  // On the new heading the target passes down the port side, clear of d1 = 66.5 m.
  const Cpa c = computeCpa(p.own.position, courseSpeedToVelocity(plan.course_setpoint, p.own.speed),
                           p.targets[0].state.position, p.targets[0].state.velocity());
  const Eigen::Vector2d stbd(std::cos(plan.course_setpoint), -std::sin(plan.course_setpoint));
  EXPECT_LT((c.target_at_cpa - c.own_at_cpa).dot(stbd), 0.0);
  EXPECT_GT(c.dcpa, 1.5 * wuRhoNm(0.0) * kWuAsvLength);
  // Plan shape: own position, end of the evasive leg on the new heading, goal.
  ASSERT_EQ(plan.waypoints.size(), 3u);
  EXPECT_EQ(plan.waypoints[0].position, p.own.position);
  EXPECT_NEAR(trueBearing(p.own.position, plan.waypoints[1].position), plan.course_setpoint, 1e-9);
  EXPECT_EQ(plan.waypoints[2].position, p.goal);
  EXPECT_GT(plan.waypoints[2].time, plan.waypoints[1].time);
  EXPECT_DOUBLE_EQ(plan.speed_setpoint, p.own.speed);
  EXPECT_GT(plan.cost, 0.0);
}

// Section 4.2: the ASV decides once per encounter (330 s for TS1; 465 s again when TS2's CRI passes
// the threshold) and holds the angle until the encounter ends. Paper mode's hold_decision does so.
TEST(GaPlannerTest, PaperModeHoldsItsDecisionUntilANewTargetPassesTheThreshold) {
  GaConfig cfg = wuAsvGaConfig();
  cfg.hold_decision = true;
  GaPlanner held(cfg), fresh(wuAsvGaConfig());
  ASSERT_TRUE(GaConfig::paper().hold_decision);
  ASSERT_FALSE(GaConfig{}.hold_decision);
  const PlanningProblem p0 = wuHeadOn();
  const Plan first = held.plan(p0);
  ASSERT_TRUE(GaFitness(p0, cfg).triggered());
  EXPECT_NE(first.message.find("generations"), std::string::npos) << first.message;

  // 30 s later, the own ship on the decided course, TS1 46 m nearer: still above the threshold.
  PlanningProblem p30 = p0;
  p30.time = 30.0;
  p30.own.course = p30.own.heading = first.course_setpoint;
  p30.own.position += courseSpeedToVelocity(first.course_setpoint, p0.own.speed) * 30.0;
  p30.targets[0].state.position += p0.targets[0].state.velocity() * 30.0;
  ASSERT_TRUE(GaFitness(p30, cfg).triggered());
  const Plan kept = held.plan(p30);
  EXPECT_NEAR(kept.course_setpoint, first.course_setpoint, 1e-12) << kept.message;
  EXPECT_NE(kept.message.find("held"), std::string::npos) << kept.message;
  // Deciding again (sea mode) would steer another course from there.
  EXPECT_GT(std::fabs(wrapPi(fresh.plan(p30).course_setpoint - first.course_setpoint)), degToRad(1.0));

  // A second ship passes the threshold (crossing from starboard, 60 s from a collision): a new decision.
  PlanningProblem p31 = p30;
  p31.time = 31.0;
  const double v = knotsToMps(5.0);
  PlannerTarget ts2;
  ts2.state = ship("ts2", 0, 0, 270.0, v);
  const double to_goal = trueBearing(p31.own.position, p31.goal);  // the original course the CRI is judged on
  ts2.state.position = p31.own.position + courseSpeedToVelocity(to_goal, p31.own.speed) * 60.0 -
                       courseSpeedToVelocity(degToRad(270.0), v) * 60.0;
  p31.targets.push_back(ts2);
  ASSERT_GT(GaFitness(p31, cfg).targets().at(1).cri, cfg.cri_threshold);
  const Plan again = held.plan(p31);
  EXPECT_NE(again.message.find("generations"), std::string::npos) << again.message;

  // Below the threshold the decision ends; the same situation again is decided afresh.
  PlanningProblem clear = p0;
  clear.time = 40.0;
  clear.targets[0].state.position = {0.0, -300.0};  // passed, astern
  EXPECT_NEAR(held.plan(clear).course_setpoint, 0.0, 1e-12);
  PlanningProblem p50 = p0;
  p50.time = 50.0;
  EXPECT_NE(held.plan(p50).message.find("generations"), std::string::npos);
  // An earlier time is a new run: nothing is held from the last one.
  held.plan(p30);
  EXPECT_NE(held.plan(p0).message.find("generations"), std::string::npos);
}

// The decision is the heading only (section 4.2): the speed asked for is the cruise speed, not the
// speed the ship has after a turn (fed back, that drifts upward under an integrating speed control).
TEST(GaPlannerTest, KeepsTheCruiseSpeed) {
  GaPlanner planner(wuAsvGaConfig());
  PlanningProblem p = wuHeadOn();
  p.cruise_speed = 5.5;
  const Plan evade = planner.plan(p);
  ASSERT_GT(std::fabs(alterationOf(evade, p)), degToRad(5.0));
  EXPECT_DOUBLE_EQ(evade.speed_setpoint, 5.5);
  for (const PlannedWaypoint& w : evade.waypoints)
    EXPECT_DOUBLE_EQ(w.speed, 5.5);
  p.targets.clear();
  EXPECT_DOUBLE_EQ(planner.plan(p).speed_setpoint, 5.5);
  p.cruise_speed = 0.0;  // unknown: the own speed
  EXPECT_DOUBLE_EQ(planner.plan(p).speed_setpoint, kWuAsvSpeed);
}

TEST(GaPlannerTest, CrossingFromStarboardPassesAstern) {
  // Target from 050 deg relative heading 270 at 5 kn, on a collision course 60 s away.
  const double v = knotsToMps(5.0), T = 60.0;
  const Eigen::Vector2d start =
      courseSpeedToVelocity(0.0, kWuAsvSpeed) * T - courseSpeedToVelocity(degToRad(270.0), v) * T;
  const PlanningProblem p = oneTarget(ship("x", start.x(), start.y(), 270.0, v));
  GaPlanner planner(wuAsvGaConfig());
  const GaFitness f(p, planner.config());
  ASSERT_EQ(f.targets()[0].geometry.encounter, Encounter::CrossingGiveWay);
  ASSERT_TRUE(f.triggered());
  const Plan plan = planner.plan(p);
  EXPECT_GT(alterationOf(plan, p), 0.0);  // starboard, behind a target heading west
  const Cpa c = computeCpa(p.own.position, courseSpeedToVelocity(plan.course_setpoint, p.own.speed),
                           p.targets[0].state.position, p.targets[0].state.velocity());
  const Eigen::Vector2d tgt_dir = courseSpeedToVelocity(degToRad(270.0), 1.0);
  EXPECT_LT((c.own_at_cpa - c.target_at_cpa).dot(tgt_dir), 0.0);  // own astern of the target at CPA
  EXPECT_GT(c.dcpa, 1.5 * wuRhoNm(radToDeg(relativeBearing(p.own, start))) * kWuAsvLength);
}

TEST(GaPlannerTest, NoActionBelowThreshold) {
  GaPlanner planner(wuAsvGaConfig());
  // A target passing 1 km abeam: U_DCPA = 0, so CRI <= 0.367 + 0.167 + 0.033 + 0.033 < 0.61.
  PlanningProblem p = oneTarget(ship("wide", 1000.0, 1500.0, 180.0, 3.0));
  p.own.course = p.own.heading = degToRad(30.0);  // currently off the goal course, e.g. after a manoeuvre
  const GaFitness f(p, planner.config());
  EXPECT_LT(f.maxCri(), 0.61);
  const Plan plan = planner.plan(p);
  EXPECT_EQ(plan.status, PlanStatus::Ok);
  EXPECT_NEAR(plan.course_setpoint, 0.0, 1e-12);  // back to the course to the goal
  EXPECT_DOUBLE_EQ(plan.cost, 0.0);
  ASSERT_EQ(plan.waypoints.size(), 2u);
  EXPECT_EQ(plan.waypoints[1].position, p.goal);
  // A target already passed (diverging, Fig. 3): no action even though it is close.
  const Plan passed = planner.plan(oneTarget(ship("astern", 0.0, -60.0, 180.0, 3.0)));
  EXPECT_NEAR(passed.course_setpoint, 0.0, 1e-12);
  // No targets at all.
  PlanningProblem empty = oneTarget(ship("x", 0, 0, 0, 0));
  empty.targets.clear();
  EXPECT_NEAR(planner.plan(empty).course_setpoint, 0.0, 1e-12);
}

TEST(GaPlannerTest, SeveralTargetsPriorityAndSum) {
  const PlanningProblem p = wuFourTargets();
  GaConfig cfg = wuAsvGaConfig();
  const GaFitness f(p, cfg);
  ASSERT_EQ(f.targets().size(), 4u);
  // Independent CRIs on the course to the goal.
  ShipState ref = p.own;
  ref.course = ref.heading = 0.0;
  double max_cri = 0.0;
  std::vector<double> cri;
  for (const auto& t : p.targets) {
    cri.push_back(computeCri(ref, t.state, computeCpa(ref, t.state), cfg.cri).cri);
    max_cri = std::max(max_cri, cri.back());
  }
  EXPECT_NEAR(f.maxCri(), max_cri, 1e-12);
  int n_priority = 0;
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(f.targets()[k].cri, cri[k], 1e-12);
    EXPECT_EQ(f.targets()[k].priority, cri[k] >= max_cri - cfg.similar_cri_margin) << k;
    n_priority += f.targets()[k].priority;
  }
  EXPECT_GE(n_priority, 1);
  // The risk term is the sum of the priority targets' CRIs for the candidate.
  const double a = degToRad(20.0);
  ShipState cand = ref;
  cand.course = cand.heading = a;
  double sum = 0.0;
  CriConfig cand_cri = cfg.cri;
  cand_cri.zero_when_diverging = false;
  for (size_t k = 0; k < 4; ++k)
    if (f.targets()[k].priority)
      sum += computeCri(cand, p.targets[k].state, computeCpa(cand, p.targets[k].state), cand_cri).cri;
  EXPECT_NEAR(f.terms(a).risk, sum, 1e-12);
  // "Similar" is a parameter: margin 0 keeps only the largest, margin 1 sums them all.
  cfg.similar_cri_margin = 0.0;
  int only = 0;
  const GaFitness f_only(p, cfg);
  for (const auto& t : f_only.targets())
    only += t.priority;
  EXPECT_EQ(only, 1);
  cfg.similar_cri_margin = 1.0;
  int all = 0;
  const GaFitness f_all(p, cfg);
  for (const auto& t : f_all.targets())
    all += t.priority;
  EXPECT_EQ(all, 4);
  // Closed loop: every target stays clear of its safe encounter distance (d1 >= 60 m abeam for L = 40.3).
  GaPlanner planner(wuAsvGaConfig());
  const RolloutResult r = rolloutKinematic(p, planner, 1.0, 200.0);
  for (const auto& t : r.targets)
    EXPECT_GT(t.min_distance, 1.5 * 0.9 * kWuAsvLength) << t.id;
}

TEST(GaPlannerTest, ReturnsToTheOriginalCourseOnceClear) {
  GaPlanner planner(wuAsvGaConfig());
  const RolloutResult r = rolloutKinematic(wuHeadOn(), planner, 1.0, 200.0);
  EXPECT_GT(r.first_alteration, 0.0);
  EXPECT_GT(r.first_cri, 0.61);
  EXPECT_LT(r.cri_after, r.first_cri);
  EXPECT_NEAR(r.final_course_error, 0.0, 1e-12);
  // Action first, then the course to the goal for the rest of the run.
  ASSERT_FALSE(r.alterations.empty());
  EXPECT_GT(std::fabs(r.alterations.front()), 0.0);
  size_t last_action = 0;
  for (size_t i = 0; i < r.alterations.size(); ++i)
    if (std::fabs(r.alterations[i]) > 1e-9)
      last_action = i;
  EXPECT_LT(last_action, r.alterations.size() / 2);
}

// Prints the figures of docs/results/ga.md (kinematic rollout; the 3-DOF closed loop comes later).
TEST(GaPlannerTest, WuSituationReport) {
  struct Case {
    const char* name;
    PlanningProblem p;
  };
  for (const Case& c : {Case{"head-on", wuHeadOn()}, Case{"crossing", wuCrossing()},
                        Case{"overtaking", wuOvertaking()}, Case{"four targets", wuFourTargets()}}) {
    GaPlanner planner(wuAsvGaConfig());
    const Plan first = planner.plan(c.p);
    const RolloutResult r = rolloutKinematic(c.p, planner, 1.0, 200.0);
    std::printf("[%s] %s\n  first alteration %+.2f deg (paper sign %+.2f), CRI %.3f -> %.3f\n", c.name,
                first.message.c_str(), radToDeg(r.first_alteration), -radToDeg(r.first_alteration),
                r.first_cri, r.cri_after);
    for (const auto& t : r.targets)
      std::printf("  %s closest %.2f m at t = %.0f s\n", t.id.c_str(), t.min_distance, t.min_time);
    for (const auto& t : r.targets)
      EXPECT_GT(t.min_distance, 1.5 * 0.9 * kWuAsvLength) << c.name << " " << t.id;
  }
}
