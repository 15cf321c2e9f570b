#include "asv_core/papers/lazarowska_scenarios.h"

#include <string>

#include "asv_core/risk/colregs.h"
#include "asv_core/risk/cpa.h"

namespace asv {

PlanningProblem lazarowskaProblem(const LazarowskaShip& own, const std::vector<LazarowskaShip>& targets,
                                  double goal_range_nm) {
  PlanningProblem p;
  p.own.id = "own";
  p.own.position = Eigen::Vector2d::Zero();
  p.own.course = p.own.heading = wrapTwoPi(degToRad(own.course_deg));
  p.own.speed = knotsToMps(own.speed_kn);
  p.limits.max_speed = p.own.speed;
  p.limits.turn_rate = kLazarowskaTurnRate;
  p.goal = courseSpeedToVelocity(p.own.course, nmToMetres(goal_range_nm));  // on the initial course line
  const ColregsConfig colregs;
  int n = 0;
  for (const auto& t : targets) {
    PlannerTarget pt;
    pt.state.id = "ts" + std::to_string(++n);
    // True bearing and range -> ENU: x = r sin(bearing), y = r cos(bearing).
    pt.state.position = courseSpeedToVelocity(degToRad(t.bearing_deg), nmToMetres(t.range_nm));
    pt.state.course = pt.state.heading = wrapTwoPi(degToRad(t.course_deg));
    pt.state.speed = knotsToMps(t.speed_kn);
    const Cpa cpa = computeCpa(p.own, pt.state);
    const EncounterGeometry g = classifyEncounter(p.own, pt.state, cpa, colregs);
    pt.tcpa = cpa.tcpa;
    pt.dcpa = cpa.dcpa;
    pt.encounter = g.encounter;
    pt.role = g.role;
    p.targets.push_back(pt);
  }
  p.seed = 1;
  p.time_budget = 60.0;
  return p;
}

std::vector<LazarowskaShip> lazarowskaScenario1Ships() {
  // Table 3: course [deg], speed [kn], bearing [deg], range [nm].
  return {
      {66, 10.4, 0, 0}, {294, 10.4, 90, 7.9}, {67, 12.2, 64, 5.9}, {74, 15.8, 65, 8.3}, {249, 18.4, 25, 5.5}};
}

std::vector<LazarowskaShip> lazarowskaScenario2Ships() {
  // Table 4.
  return {{61, 15.4, 0, 0},      {171, 8.9, 103, 6.5}, {347, 8.7, 93, 7.4},  {169, 15.4, 66, 5.8},
          {336, 11.7, 62, 10.5}, {162, 12.1, 29, 7.7}, {161, 13.9, 36, 7.8}, {337, 7.9, 37, 9.0}};
}

namespace {
PlanningProblem fromShips(const std::vector<LazarowskaShip>& ships, double goal_range_nm) {
  return lazarowskaProblem(ships.front(), std::vector<LazarowskaShip>(ships.begin() + 1, ships.end()),
                           goal_range_nm);
}
}  // namespace

PlanningProblem lazarowskaScenario1(double goal_range_nm) {
  return fromShips(lazarowskaScenario1Ships(), goal_range_nm);
}

PlanningProblem lazarowskaScenario2(double goal_range_nm) {
  return fromShips(lazarowskaScenario2Ships(), goal_range_nm);
}

std::vector<double> lazarowskaScenario1CoursesDeg() {
  return {66, 77, 52};
}

std::vector<double> lazarowskaScenario2CoursesDeg() {
  return {61, 50, 79, 61};
}

}  // namespace asv
