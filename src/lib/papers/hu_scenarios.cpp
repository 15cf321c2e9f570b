#include "asv_core/papers/hu_scenarios.h"

#include <cmath>

namespace asv {

namespace {

ShipState ship(const std::string& id, double x_nm, double y_nm, double course_deg, double speed_kn) {
  ShipState s;
  s.id = id;
  s.position = {nmToMetres(x_nm), nmToMetres(y_nm)};
  s.course = s.heading = degToRad(course_deg);
  s.speed = knotsToMps(speed_kn);
  return s;
}

PlanningProblem baseProblem(double goal_east_nm) {
  PlanningProblem p;
  p.own = ship("own", 0.0, 0.0, 90.0, mpsToKnots(kHuOwnSpeed));
  p.limits.max_speed = kHuOwnSpeed;
  p.goal = {nmToMetres(goal_east_nm), 0.0};
  p.seed = 1;
  // Planned to completion: no wall-clock deadline may change a published or tested plan (a test may
  // run starved of CPU, e.g. beside make test's rostests).
  p.time_budget = 60.0;
  return p;
}

void addTarget(PlanningProblem& p, const ShipState& s) {
  PlannerTarget t;
  t.state = s;
  p.targets.push_back(t);
}

}  // namespace

void assessTargets(PlanningProblem& problem, RiskAssessor& assessor) {
  for (PlannerTarget& t : problem.targets) {
    t = toPlannerTarget(t.state, assessor.assess(problem.own, t.state));
    if (t.state.speed < 0.1) {
      t.encounter = Encounter::None;
      t.role = OwnRole::None;
    }
  }
}

PlanningProblem huOvertakingOpenWater() {
  PlanningProblem p = baseProblem(10.0);
  addTarget(p, ship("TG", 1.5, 0.0, 90.0, 6.0));
  RiskAssessor assessor;
  assessTargets(p, assessor);
  return p;
}

PlanningProblem huOvertakingRestrictedWater() {
  PlanningProblem p = huOvertakingOpenWater();
  StaticObstacle land;
  land.name = "land";
  land.polygon = {{nmToMetres(-2.0), nmToMetres(-0.6)},
                  {nmToMetres(12.0), nmToMetres(-0.6)},
                  {nmToMetres(12.0), nmToMetres(-5.6)},
                  {nmToMetres(-2.0), nmToMetres(-5.6)}};
  p.obstacles.push_back(land);
  return p;
}

PlanningProblem huMultiTarget() {
  PlanningProblem p = baseProblem(12.0);
  addTarget(p, ship("A", 6.0, -5.0, 0.0, 10.0));
  addTarget(p, ship("B", 1.5, 0.0, 90.0, 6.0));
  addTarget(p, ship("C", 14.0, -1.5, 270.0, 8.0));
  addTarget(p, ship("D", 9.0, 0.0, 0.0, 0.0));
  RiskAssessor assessor;
  assessTargets(p, assessor);
  return p;
}

PlanningProblem huNonCompliantTarget(double elapsed_s) {
  PlanningProblem p = baseProblem(10.0);
  addTarget(p, ship("A", 3.0, 3.0, 180.0, 12.0));
  RiskAssessor assessor;
  const ShipState own0 = p.own;
  const ShipState tgt0 = p.targets[0].state;
  constexpr double kStep = 10.0;  // [s] assessment period of Algorithm 1
  const int steps = static_cast<int>(std::floor(std::max(0.0, elapsed_s) / kStep));
  for (int k = 0; k <= steps; ++k) {
    const double t = k == steps ? std::max(0.0, elapsed_s) : k * kStep;
    p.own.position = own0.position + own0.velocity() * t;
    p.targets[0].state.position = tgt0.position + tgt0.velocity() * t;
    assessTargets(p, assessor);
  }
  p.time = std::max(0.0, elapsed_s);
  return p;
}

}  // namespace asv
