#include "asv_core/sim/scenario_gen.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "asv_core/common/format.h"
#include "asv_core/common/units.h"
#include "asv_core/risk/colregs.h"
#include "asv_core/risk/cpa.h"
#include "asv_core/risk/risk_level.h"
#include "asv_core/sim/simulation.h"
#include "asv_core/world/scenario_write.h"

namespace asv {
namespace {

// The own ship of every generated scenario: a 3-DOF draw runs the wu_asv_40m preset at its steady speed.
constexpr const char* kThreeDofPreset = "wu_asv_40m";
constexpr double kThreeDofSpeedKn = 12.0;
// The open North Sea, as the scenario library: an origin for AIS positions in ROS runs.
const GeoPoint kOrigin{54.0, 3.0};

// Uniform draws from std::mt19937_64 seeded through std::seed_seq, both specified bit for bit by the
// standard (std::uniform_real_distribution is not), so a seed gives the same file on every platform.
class Draw {
public:
  Draw(uint64_t seed, uint64_t index) {
    std::seed_seq seq{uint32_t(seed), uint32_t(seed >> 32), uint32_t(index), uint32_t(index >> 32)};
    rng_.seed(seq);
  }
  double uniform(double a, double b) { return a + (b - a) * (double(rng_() >> 11) * 0x1.0p-53); }
  int integer(int a, int b) { return a + int(rng_() % uint64_t(b - a + 1)); }  // [a, b]
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  double sign() { return chance(0.5) ? 1.0 : -1.0; }

private:
  std::mt19937_64 rng_;
};

// What each target is drawn to be. The encounter as the own ship sees it.
enum class Kind : uint8_t { HeadOn, FromStarboard, FromPort, Overtaking, Overtaken };
constexpr Kind kKinds[] = {Kind::HeadOn, Kind::FromStarboard, Kind::FromPort, Kind::Overtaking,
                           Kind::Overtaken};

Encounter expectedEncounter(Kind k) {
  switch (k) {
    case Kind::HeadOn:
      return Encounter::HeadOn;
    case Kind::FromStarboard:
      return Encounter::CrossingGiveWay;
    case Kind::FromPort:
      return Encounter::CrossingStandOn;
    case Kind::Overtaking:
      return Encounter::Overtaking;
    case Kind::Overtaken:
      break;
  }
  return Encounter::BeingOvertaken;
}

const char* describe(Kind k) {
  switch (k) {
    case Kind::HeadOn:
      return "head-on (both give way)";
    case Kind::FromStarboard:
      return "crossing from starboard (the own ship gives way)";
    case Kind::FromPort:
      return "crossing from port (the target gives way)";
    case Kind::Overtaking:
      return "overtaken by the own ship (the own ship gives way)";
    case Kind::Overtaken:
      break;
  }
  return "overtaking the own ship (the target gives way)";
}

// The target is the give-way ship (alone or, head-on, with the own ship): she may break the rules.
bool targetGivesWay(Kind k) {
  return k == Kind::HeadOn || k == Kind::FromPort || k == Kind::Overtaken;
}

struct TargetDraw {
  Kind kind = Kind::HeadOn;
  double ratio = 1.0;       // target / own speed
  double rel_course = 0.0;  // [deg] target course - own course
  double tcpa = 0.0;        // [s]
  double dcpa = 0.0;        // [m] >= 0
  double side = 1.0;        // which side of the own ship the CPA lies
  double length = 0.0;      // [m]
  Behaviour behaviour = Behaviour::Constant;
  bool check_encounter = true;  // refuse the draw when the placed target classifies otherwise
  std::string what;             // the description's words for it ("" : describe(kind))
};

// Relative course and speed ratio of an encounter (the classification is checked after placement).
void drawMotion(Draw& d, const GeneratorConfig& cfg, TargetDraw& t) {
  switch (t.kind) {
    case Kind::HeadOn:
      t.rel_course = 180.0 + d.uniform(-6.0, 6.0);
      break;
    case Kind::FromStarboard:
      t.rel_course = d.uniform(205.0, 335.0);
      break;
    case Kind::FromPort:
      t.rel_course = d.uniform(25.0, 155.0);
      break;
    case Kind::Overtaking:
    case Kind::Overtaken:
      t.rel_course = d.uniform(-20.0, 20.0);
      break;
  }
  double lo = cfg.speed_ratio_min, hi = cfg.speed_ratio_max;
  if (t.kind == Kind::Overtaking)
    hi = cfg.overtaking_ratio_max;
  if (t.kind == Kind::Overtaken)
    lo = cfg.overtaken_ratio_min;
  t.ratio = d.uniform(lo, hi);
}

TargetDraw drawTarget(Draw& d, const GeneratorConfig& cfg, Kind kind, double tcpa, double breaker_share) {
  TargetDraw t;
  t.kind = kind;
  drawMotion(d, cfg, t);
  t.tcpa = tcpa;
  t.dcpa = d.uniform(0.0, cfg.dcpa_max_m);
  t.side = d.sign();
  t.length = std::round(d.uniform(30.0, 300.0));
  if (targetGivesWay(kind)) {
    const bool breaks = d.chance(breaker_share);
    t.behaviour = !breaks         ? Behaviour::GiveWay
                  : d.chance(0.5) ? Behaviour::NonCompliant
                                  : Behaviour::PortTurn;
  }
  return t;
}

Kind anyKind(Draw& d, bool channel) {
  if (channel) {
    constexpr Kind along[] = {Kind::HeadOn, Kind::Overtaking, Kind::Overtaken};
    return along[d.integer(0, 2)];
  }
  return kKinds[d.integer(0, 4)];
}

// The families that probe the referee (scenario_gen.h). Ranges: our choice, from issue-style examples
// (an offset head-on 0.3-0.8 nm, a boundary sweep 8-35 deg off the reciprocal, a remote duty 20-30 min).
std::vector<TargetDraw> drawProbe(Draw& d, const GeneratorConfig& cfg, SituationClass c, double tcpa) {
  const double nm = kMetresPerNauticalMile;
  TargetDraw t =
      drawTarget(d, cfg, c == SituationClass::StandOnRemoteDuty ? Kind::FromPort : Kind::HeadOn, tcpa, 0.0);
  if (c == SituationClass::OffsetHeadOn) {
    t.dcpa = d.uniform(0.3, 0.8) * nm;
    const double u = d.uniform(0.0, 1.0);  // gives way, never acts, or acts late and little: a third each
    t.behaviour = u < 1.0 / 3.0   ? Behaviour::GiveWay
                  : u < 2.0 / 3.0 ? Behaviour::NonCompliant
                                  : Behaviour::LateGiveWay;
    t.check_encounter = false;  // an offset this large may put her just off the head-on sector
    t.what = "met nearly head-on, offset";
    return {t};
  }
  if (c == SituationClass::HeadOnCrossingBoundary) {
    t.rel_course = 180.0 + d.sign() * d.uniform(8.0, 35.0);
    t.check_encounter = false;  // the point: either side of the head-on/crossing boundary
    t.what = strFormat("near the head-on/crossing boundary, %.0f deg off the reciprocal",
                       std::fabs(t.rel_course - 180.0));
    return {t};
  }
  TargetDraw o;  // the other ship: anchored or slow on the starboard side, or overtaken far ahead
  o.kind = Kind::Overtaking;
  o.length = std::round(d.uniform(30.0, 300.0));
  if (c == SituationClass::StandOnRemoteDuty) {
    o.ratio = d.uniform(0.2, 0.5);
    o.tcpa = d.uniform(1200.0, 1800.0);
    o.dcpa = d.uniform(0.5, 0.9) * nm;
    o.side = d.sign();
    o.what = "a slow ship the own ship overtakes (her remote give-way duty)";
    return {t, o};
  }
  const int obstruction = d.integer(0, 2);  // 0 anchored, 1 slow, 2 a coast (drawScenario)
  if (obstruction == 2)
    return {t};
  o.ratio = obstruction == 0 ? 0.0 : d.uniform(0.15, 0.35);
  o.tcpa = t.tcpa * d.uniform(0.5, 0.9);
  o.dcpa = d.uniform(0.3, 0.7) * nm;
  o.side = 1.0;  // on the own ship's starboard side
  o.check_encounter = false;
  o.what = obstruction == 0 ? "at anchor on the starboard bow" : "a slow ship on the starboard bow";
  return {t, o};
}

std::vector<TargetDraw> drawTargets(Draw& d, const GeneratorConfig& cfg, SituationClass c, bool channel) {
  const auto tcpa = [&] { return d.uniform(cfg.tcpa_min_s, cfg.tcpa_max_s); };
  switch (c) {
    case SituationClass::HeadOn:
      return {drawTarget(d, cfg, Kind::HeadOn, tcpa(), 0.0)};
    case SituationClass::CrossingGiveWay:
      return {drawTarget(d, cfg, Kind::FromStarboard, tcpa(), 0.0)};
    case SituationClass::CrossingStandOn:
      return {drawTarget(d, cfg, Kind::FromPort, tcpa(), 0.0)};
    case SituationClass::Overtaking:
      return {drawTarget(d, cfg, Kind::Overtaking, tcpa(), 0.0)};
    case SituationClass::BeingOvertaken:
      return {drawTarget(d, cfg, Kind::Overtaken, tcpa(), 0.0)};
    case SituationClass::RuleBreaker: {
      constexpr Kind give_way[] = {Kind::HeadOn, Kind::FromPort, Kind::Overtaken};
      return {drawTarget(d, cfg, give_way[d.integer(0, 2)], tcpa(), 1.0)};
    }
    case SituationClass::OffsetHeadOn:
    case SituationClass::HeadOnStarboardOccupied:
    case SituationClass::HeadOnCrossingBoundary:
    case SituationClass::StandOnRemoteDuty:
      return drawProbe(d, cfg, c, tcpa());
    case SituationClass::LateGiveWay: {
      constexpr Kind give_way[] = {Kind::HeadOn, Kind::FromPort, Kind::Overtaken};
      const Kind kind = give_way[d.integer(0, 2)];  // drawn before the TCPA: one order on every compiler
      TargetDraw t = drawTarget(d, cfg, kind, tcpa(), 0.0);
      t.behaviour = Behaviour::LateGiveWay;
      return {t};
    }
    case SituationClass::RouteBendCrossing: {
      const Kind kind = d.chance(0.5) ? Kind::FromStarboard : Kind::FromPort;
      TargetDraw t = drawTarget(d, cfg, kind, tcpa(), 0.0);
      t.check_encounter = false;  // drawn against the route's second leg, not the first
      t.what = std::string(describe(t.kind)) + " of the route's second leg";
      return {t};
    }
    default:
      break;
  }
  const bool several = c != SituationClass::Coastal;
  const int n = several ? d.integer(2, cfg.max_targets) : d.integer(1, 3);
  const double centre = d.uniform(cfg.tcpa_min_s + 0.5 * cfg.converging_window_s, cfg.tcpa_max_s);
  std::vector<TargetDraw> out;
  for (int i = 0; i < n; ++i) {
    const double t =
        c == SituationClass::Converging ? centre + d.uniform(-0.5, 0.5) * cfg.converging_window_s : tcpa();
    out.push_back(drawTarget(d, cfg, anyKind(d, channel), t, several ? cfg.rule_breaker_share : 0.0));
  }
  return out;
}

double roundTo(double x, double step) {
  return std::round(x / step) * step;
}

// The target that, with both ships holding course and speed, passes `dcpa` off the own ship after `tcpa`.
ScenarioShip placeTarget(const ScenarioShip& own, const TargetDraw& t, int number) {
  ScenarioShip s;
  s.name = "ts" + std::to_string(number);
  s.length = t.length;
  s.course = degToRad(wrapDeg360(roundTo(radToDeg(own.course) + t.rel_course, 0.1)));
  s.speed = knotsToMps(roundTo(mpsToKnots(own.speed) * t.ratio, 0.01));
  const Eigen::Vector2d vo = courseSpeedToVelocity(own.course, own.speed);
  const Eigen::Vector2d vt = courseSpeedToVelocity(s.course, s.speed);
  const Eigen::Vector2d vr = vt - vo;
  const Eigen::Vector2d normal = t.side * Eigen::Vector2d(-vr.y(), vr.x()) / vr.norm();
  s.position = own.position + vo * t.tcpa + t.dcpa * normal - vt * t.tcpa;
  s.behaviour = t.behaviour;
  return s;
}

ScenarioShip drawOwn(Draw& d, const GeneratorConfig& cfg) {
  ScenarioShip own;
  own.name = "own";
  own.course = degToRad(roundTo(d.uniform(0.0, 360.0), 0.1));
  if (d.chance(cfg.three_dof_share)) {
    own.model = kThreeDofPreset;
    own.speed = knotsToMps(kThreeDofSpeedKn);
  } else {
    own.length = std::round(d.uniform(50.0, 250.0));
    own.speed = knotsToMps(roundTo(d.uniform(cfg.own_speed_min_kn, cfg.own_speed_max_kn), 0.01));
  }
  return own;
}

// A shore along the own route on `side` (+1 starboard, -1 port), `offset` from it, 2 nm deep, from
// 3 nm behind the start to 3 nm past the goal, its edge wavering by up to 0.2 nm every mile.
StaticObstacle coast(Draw& d, const ScenarioShip& own, double route_length, double side, double offset,
                     const std::string& name) {
  const Eigen::Vector2d u = courseSpeedToVelocity(own.course, 1.0);
  const Eigen::Vector2d stbd(u.y(), -u.x());
  const double nm = kMetresPerNauticalMile;
  StaticObstacle o;
  o.name = name;
  const int miles = int(std::ceil(route_length / nm)) + 6;
  for (int i = 0; i <= miles; ++i)
    o.polygon.push_back(own.position + (i - 3) * nm * u + side * (offset + d.uniform(-0.2, 0.2) * nm) * stbd);
  for (int i : {miles, 0})
    o.polygon.push_back(own.position + (i - 3) * nm * u + side * (offset + 2.0 * nm) * stbd);
  for (auto& p : o.polygon)
    p = Eigen::Vector2d(roundTo(p.x(), 0.1), roundTo(p.y(), 0.1));
  return o;
}

const char* behaviourText(Behaviour b) {
  switch (b) {
    case Behaviour::GiveWay:
      return "gives way by the rules (40 deg or more to starboard, to pass 1 nm off)";
    case Behaviour::NonCompliant:
      return "breaks the rules: stands on although she should give way";
    case Behaviour::PortTurn:
      return "breaks the rules: turns 40 deg to port instead of starboard";
    case Behaviour::LateGiveWay:
      return "gives way late and little: 15 deg to starboard, 6 min before the CPA";
    default:
      break;
  }
  return "keeps course and speed";
}

std::string description(SituationClass c, uint64_t seed, uint64_t index, const ScenarioShip& own,
                        const std::vector<TargetDraw>& draws, const std::string& land) {
  std::string text = "Generated by asv_scenario_gen (seed " + std::to_string(seed) + ", situation " +
                     std::to_string(index) + ", class " + toString(c) + "). Own ship: " +
                     (own.model == "kinematic" ? strFormat("kinematic, %.0f m", own.length)
                                               : std::string(own.model) + " (3-DOF)") +
                     strFormat(", %.2f kn on %05.1f.", mpsToKnots(own.speed), radToDeg(own.course));
  for (size_t i = 0; i < draws.size(); ++i) {
    const TargetDraw& t = draws[i];
    text += " ts" + std::to_string(i + 1) + ": " + (t.what.empty() ? describe(t.kind) : t.what.c_str()) +
            ", " + behaviourText(t.behaviour) +
            strFormat("; speed ratio %.2f, CPA %.2f nm after %.1f min if both hold on.", t.ratio,
                      t.dcpa / kMetresPerNauticalMile, t.tcpa / 60.0);
  }
  return text + land;
}

// When the last rule-breaker's breach becomes apparent with the own ship holding on: a ship that stands
// on is clearly not acting once the encounter is urgent (Hu et al. 2017 eq. 2, t_safe, as the
// evaluator's Rule 17); a port turn starts when the simulator's give_way logic acts and shows within a
// minute. 0 without rule-breakers.
double breachTime(const std::vector<TargetDraw>& draws) {
  double t = 0.0;
  for (const auto& d : draws) {
    if (d.behaviour == Behaviour::NonCompliant || d.behaviour == Behaviour::LateGiveWay)
      t = std::max(t, d.tcpa - HuRiskConfig{}.t_safe_s);
    else if (d.behaviour == Behaviour::PortTurn)
      t = std::max(t, d.tcpa - TrafficConfig{}.give_way_tcpa + 60.0);
  }
  return t;
}

struct Draft {
  Scenario scenario;
  std::vector<TargetDraw> draws;
  double act_time = 0.0;
};

// RouteBendCrossing: the own route turns 30-60 deg to either side after 5-15 min, and the target meets
// her 5-15 min after the bend. Returns the ship the targets are placed against: the own ship as if she
// had sailed the second leg from the start (where she is on it after the bend), and sets the bend's time.
ScenarioShip bendRoute(Draw& d, ScenarioShip& own, TargetDraw& target, double& bend_time, std::string& text) {
  bend_time = roundTo(d.uniform(300.0, 900.0), 1.0);
  const double turn = d.sign() * roundTo(d.uniform(30.0, 60.0), 1.0);
  const Eigen::Vector2d bend = own.position + courseSpeedToVelocity(own.course, own.speed * bend_time);
  ScenarioShip frame = own;
  frame.course = degToRad(wrapDeg360(radToDeg(own.course) + turn));
  frame.position = bend - courseSpeedToVelocity(frame.course, own.speed * bend_time);
  target.tcpa = bend_time + d.uniform(300.0, 900.0);
  RouteWaypoint w;
  w.position = Eigen::Vector2d(roundTo(bend.x(), 0.1), roundTo(bend.y(), 0.1));
  own.route = {w};
  text = strFormat(" The own route bends %.0f deg to %s after %.0f min.", std::fabs(turn),
                   turn > 0.0 ? "starboard" : "port", bend_time / 60.0);
  return frame;
}

Draft drawScenario(Draw& d, const GeneratorConfig& cfg, SituationClass c, uint64_t seed, uint64_t index) {
  Draft out;
  Scenario& s = out.scenario;
  s.name = std::string("gen_") + toString(c) + "_s" + std::to_string(seed) + "_" + std::to_string(index);
  s.origin = kOrigin;
  s.has_origin = true;
  s.min_separation = cfg.min_separation_m;
  s.own = drawOwn(d, cfg);
  const bool channel = c == SituationClass::Coastal && d.chance(0.5);
  out.draws = drawTargets(d, cfg, c, channel);
  ScenarioShip frame = s.own;  // the ship the targets are placed against
  double bend_time = 0.0;
  std::string bend;
  if (c == SituationClass::RouteBendCrossing)
    frame = bendRoute(d, s.own, out.draws[0], bend_time, bend);
  double last_cpa = 0.0;
  for (size_t i = 0; i < out.draws.size(); ++i) {
    s.targets.push_back(placeTarget(frame, out.draws[i], int(i) + 1));
    last_cpa = std::max(last_cpa, out.draws[i].tcpa);
  }
  const double route = roundTo(s.own.speed * (last_cpa + 1200.0), 10.0);
  s.own.goal = frame.position + courseSpeedToVelocity(frame.course, route);
  if (!s.own.route.empty()) {
    RouteWaypoint end;
    end.position = *s.own.goal;
    s.own.route.push_back(end);
  }
  s.duration = 60.0 * std::ceil((1.4 * route / s.own.speed + 300.0) / 60.0);
  std::string land;
  if (c == SituationClass::HeadOnStarboardOccupied && out.draws.size() == 1) {
    s.min_obstacle_clearance = cfg.obstacle_clearance_m;
    const double offset = d.uniform(0.6, 1.2) * kMetresPerNauticalMile;
    s.obstacles.push_back(coast(d, s.own, route, 1.0, offset, "coast"));
    land = strFormat(" A coast %.1f nm to starboard of the route (clearance %.0f m).",
                     offset / kMetresPerNauticalMile, cfg.obstacle_clearance_m);
  }
  if (c == SituationClass::Coastal) {
    s.min_obstacle_clearance = cfg.obstacle_clearance_m;
    const double nm = kMetresPerNauticalMile;
    const double side = d.sign(), offset = d.uniform(1.0, channel ? 2.0 : 2.5) * nm;
    s.obstacles.push_back(coast(d, s.own, route, side, offset, channel ? "bank 1" : "coast"));
    land = std::string(channel ? " A channel: banks " : " A coast ") + strFormat("%.1f nm to ", offset / nm) +
           (side > 0 ? "starboard" : "port");
    if (channel) {
      const double other = d.uniform(1.0, 2.0) * nm;
      s.obstacles.push_back(coast(d, s.own, route, -side, other, "bank 2"));
      land += strFormat(" and %.1f nm to ", other / nm) + (side > 0 ? "port" : "starboard");
    }
    land += strFormat(" of the route (clearance %.0f m).", cfg.obstacle_clearance_m);
  }
  s.description = description(c, seed, index, s.own, out.draws, bend + land);
  // After the bend the crossing is the one drawn: a manoeuvre for it is sought a minute later.
  out.act_time = c == SituationClass::RouteBendCrossing ? bend_time + 60.0 : breachTime(out.draws);
  return out;
}

}  // namespace

namespace {

ShipState stateOf(const ScenarioShip& s) {
  ShipState st;
  st.position = s.position;
  st.course = st.heading = s.course;
  st.speed = s.speed;
  st.length = s.length;
  return st;
}

// Whether a risk of collision with a target forms while the own ship sails her route's first leg: the
// velocities are constant, so the CPA's distance is the same at every instant and its time falls by the
// time sailed; risk when that distance is below first_leg_clear_m and the time, at some instant before the
// bend, lies in (0, first_leg_window_s].
bool meetsFirstLeg(const GeneratorConfig& cfg, const Scenario& s) {
  const ShipState own = stateOf(s.own);
  const double bend_time = (s.own.route.front().position - own.position).norm() / std::max(own.speed, 1e-6);
  for (const auto& target : s.targets) {
    const Cpa cpa = computeCpa(own, stateOf(target));
    if (cpa.dcpa < cfg.first_leg_clear_m && cpa.tcpa > 0.0 && cpa.tcpa - bend_time <= cfg.first_leg_window_s)
      return true;
  }
  return false;
}

// Start ranges and encounters; "" when the draw is as intended, else the reason it is refused.
std::string checkGeometry(const GeneratorConfig& cfg, const Scenario& s,
                          const std::vector<TargetDraw>& draws) {
  const double min_start = cfg.start_range_min_factor * cfg.min_separation_m;
  const ShipState own = stateOf(s.own);
  for (size_t i = 0; i < s.targets.size(); ++i) {
    const ShipState t = stateOf(s.targets[i]);
    const double range = (t.position - own.position).norm();
    if (range < min_start)
      return "target starts inside the safety distance";
    if (range > cfg.start_range_max_m)
      return "target starts beyond the classification horizon";
    for (size_t j = 0; j < i; ++j)
      if ((s.targets[j].position - t.position).norm() < min_start)
        return "two targets start too close";
    if (draws[i].check_encounter &&
        classifyEncounter(own, t, computeCpa(own, t), ColregsConfig{}).encounter !=
            expectedEncounter(draws[i].kind))
      return "encounter classified otherwise";
  }
  for (const auto& o : s.obstacles)
    if (s.own.goal && obstacleDistance(o, *s.own.goal, *s.own.goal) < cfg.obstacle_clearance_m)
      return "goal inside an obstacle's clearance";
  if (s.own.route.size() >= 2 && meetsFirstLeg(cfg, s))
    return "target meets the route's first leg";
  return "";
}

// The traffic with the own ship holding course and speed to the end: targets must not collide with
// each other or run aground on their own.
std::string checkTraffic(const GeneratorConfig& cfg, const Scenario& s) {
  SimConfig sc;
  sc.dt = cfg.check_dt;
  Simulation sim(s, sc);
  if (s.own.route.empty())  // else she sails her route
    sim.setSetpoint(s.own.name, s.own.course, s.own.speed);
  while (!sim.finished())
    sim.step();
  for (const auto& e : sim.events()) {
    if (e.type == SimEvent::Collision && e.a != s.own.name && e.b != s.own.name)
      return "targets collide with each other";
    if (e.type == SimEvent::Grounding && e.a != s.own.name)
      return "a target runs aground";
  }
  return "";
}

bool allPast(const Simulation& sim, double min_separation) {
  const ShipState own = sim.own().shipState();
  for (size_t i = 1; i < sim.vessels().size(); ++i) {
    const SimVessel& v = sim.vessels()[i];
    if (v.arrived)
      continue;
    const Cpa cpa = computeCpa(own, v.shipState());
    if (cpa.range < min_separation || cpa.tcpa > 0.0)
      return false;
  }
  return true;
}

bool manoeuvreKeepsClear(const Scenario& s, double act_time, double course_change, double speed_factor,
                         double min_separation, double clearance, double dt) {
  SimConfig sc;
  sc.dt = dt;
  Simulation sim(s, sc);
  if (s.own.route.empty())  // else she sails her route until she acts
    sim.setSetpoint(s.own.name, s.own.course, s.own.speed);
  bool acted = false;
  while (!sim.finished()) {
    if (!acted && sim.time() >= act_time - 1e-9) {
      const double course = s.own.route.empty() ? s.own.course : sim.own().cog();
      sim.setSetpoint(s.own.name, wrapTwoPi(course + course_change), s.own.speed * speed_factor);
      acted = true;
    }
    sim.step();
    if (sim.minSeparationOwn() < min_separation || sim.grounded() || sim.minObstacleDistanceOwn() < clearance)
      return false;
    if (acted && allPast(sim, min_separation))
      return true;
  }
  return true;
}

}  // namespace

bool manoeuvreExists(const Scenario& s, double act_time, double min_separation, double clearance, double dt,
                     bool port_too) {
  // Smallest alterations first, starboard before port, speed kept before reduced: the first success ends it.
  for (int step = 0; step <= 12; ++step)
    for (double side : {1.0, -1.0}) {
      if ((step == 0 || !port_too) && side < 0.0)
        continue;
      for (double speed_factor : {1.0, 0.5, 0.0})
        if (manoeuvreKeepsClear(s, act_time, side * degToRad(10.0 * step), speed_factor, min_separation,
                                clearance, dt))
          return true;
    }
  return false;
}

GeneratedScenario generateScenario(const GeneratorConfig& cfg, SituationClass situation, uint64_t seed,
                                   uint64_t index) {
  cfg.validate();
  Draw d(seed, index);
  GeneratedScenario g;
  g.situation = situation;
  for (int attempt = 0; attempt <= cfg.max_redraws; ++attempt) {
    Draft draft = drawScenario(d, cfg, situation, seed, index);
    g.yaml = scenarioToYaml(draft.scenario);
    std::string reason;
    try {
      g.scenario = parseScenario(g.yaml, draft.scenario.name + ".yaml");
    } catch (const ScenarioError& e) {
      reason = std::string("the loader refuses it: ") + e.what();
    }
    if (reason.empty())
      reason = checkGeometry(cfg, g.scenario, draft.draws);
    if (reason.empty())
      reason = checkTraffic(cfg, g.scenario);
    const double clearance = g.scenario.obstacles.empty() ? 0.0 : cfg.obstacle_clearance_m;
    if (reason.empty() &&
        !manoeuvreExists(g.scenario, draft.act_time, cfg.min_separation_m, clearance, cfg.check_dt))
      reason = "no manoeuvre keeps the minimum separation";
    // The starboard side is occupied, not closed: a turn to starboard or a speed reduction still works.
    if (reason.empty() && situation == SituationClass::HeadOnStarboardOccupied &&
        !manoeuvreExists(g.scenario, draft.act_time, cfg.min_separation_m, clearance, cfg.check_dt, false))
      reason = "no starboard manoeuvre keeps the minimum separation";
    if (reason.empty())
      return g;
    ++g.refused[reason];
  }
  throw std::runtime_error(std::string("asv_scenario_gen: no acceptable draw for class ") +
                           toString(situation) + " after " + std::to_string(cfg.max_redraws) + " redraws");
}

const std::vector<SituationClass>& allSituationClasses() {
  static const std::vector<SituationClass> all{SituationClass::HeadOn,
                                               SituationClass::CrossingGiveWay,
                                               SituationClass::CrossingStandOn,
                                               SituationClass::Overtaking,
                                               SituationClass::BeingOvertaken,
                                               SituationClass::RuleBreaker,
                                               SituationClass::Multi,
                                               SituationClass::Converging,
                                               SituationClass::Coastal,
                                               SituationClass::OffsetHeadOn,
                                               SituationClass::HeadOnStarboardOccupied,
                                               SituationClass::HeadOnCrossingBoundary,
                                               SituationClass::StandOnRemoteDuty,
                                               SituationClass::LateGiveWay,
                                               SituationClass::RouteBendCrossing};
  return all;
}

const char* toString(SituationClass c) {
  switch (c) {
    case SituationClass::HeadOn:
      return "head_on";
    case SituationClass::CrossingGiveWay:
      return "crossing_give_way";
    case SituationClass::CrossingStandOn:
      return "crossing_stand_on";
    case SituationClass::Overtaking:
      return "overtaking";
    case SituationClass::BeingOvertaken:
      return "being_overtaken";
    case SituationClass::RuleBreaker:
      return "rule_breaker";
    case SituationClass::Multi:
      return "multi";
    case SituationClass::Converging:
      return "converging";
    case SituationClass::Coastal:
      return "coastal";
    case SituationClass::OffsetHeadOn:
      return "offset_head_on";
    case SituationClass::HeadOnStarboardOccupied:
      return "head_on_starboard_occupied";
    case SituationClass::HeadOnCrossingBoundary:
      return "head_on_crossing_boundary";
    case SituationClass::StandOnRemoteDuty:
      return "stand_on_remote_duty";
    case SituationClass::LateGiveWay:
      return "late_give_way";
    case SituationClass::RouteBendCrossing:
      break;
  }
  return "route_bend_crossing";
}

std::optional<SituationClass> situationClassFromString(const std::string& name) {
  for (SituationClass c : allSituationClasses())
    if (name == toString(c))
      return c;
  return std::nullopt;
}

void GeneratorConfig::validate() const {
  auto require = [](bool ok, const char* what) {
    if (!ok)
      throw std::invalid_argument(std::string("GeneratorConfig: ") + what);
  };
  require(own_speed_min_kn > 0.0 && own_speed_min_kn <= own_speed_max_kn && own_speed_max_kn <= 40.0,
          "own_speed_min_kn/own_speed_max_kn must satisfy 0 < min <= max <= 40");
  require(speed_ratio_min > 0.0 && speed_ratio_min < speed_ratio_max,
          "speed_ratio_min must be > 0 and < speed_ratio_max");
  require(overtaking_ratio_max > 0.0 && overtaking_ratio_max < 1.0, "overtaking_ratio_max must be in (0, 1)");
  require(overtaken_ratio_min > 1.0, "overtaken_ratio_min must be > 1");
  require(tcpa_min_s > 0.0 && tcpa_min_s < tcpa_max_s, "tcpa_min_s must be > 0 and < tcpa_max_s");
  require(dcpa_max_m >= 0.0, "dcpa_max_m must be >= 0");
  require(max_targets >= 2, "max_targets must be >= 2");
  require(converging_window_s >= 0.0 && converging_window_s < tcpa_max_s - tcpa_min_s,
          "converging_window_s must be in [0, tcpa_max_s - tcpa_min_s)");
  require(rule_breaker_share >= 0.0 && rule_breaker_share <= 1.0, "rule_breaker_share must be in [0, 1]");
  require(three_dof_share >= 0.0 && three_dof_share <= 1.0, "three_dof_share must be in [0, 1]");
  require(min_separation_m > 0.0 && obstacle_clearance_m > 0.0,
          "min_separation_m and obstacle_clearance_m must be > 0");
  require(start_range_min_factor >= 1.0, "start_range_min_factor must be >= 1");
  require(first_leg_clear_m >= 0.0 && first_leg_window_s >= 0.0,
          "first_leg_clear_m and first_leg_window_s must be >= 0");
  require(start_range_max_m > start_range_min_factor * min_separation_m,
          "start_range_max_m must exceed start_range_min_factor x min_separation_m");
  require(check_dt > 0.0 && check_dt <= 5.0, "check_dt must be in (0, 5] s");
  require(max_redraws >= 0, "max_redraws must be >= 0");
}

}  // namespace asv
