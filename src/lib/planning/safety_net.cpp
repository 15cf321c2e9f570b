#include "asv_core/planning/safety_net.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <utility>

#include "asv_core/common/format.h"
#include "asv_core/common/units.h"
#include "asv_core/planning/land_route.h"
#include "asv_core/risk/cpa.h"

namespace asv {

double routeClearance(const PredictedRoute& route, const std::vector<PlannerTarget>& targets, double horizon,
                      double dt) {
  double best = std::numeric_limits<double>::infinity();
  if (route.points.empty() || targets.empty())
    return best;
  size_t leg = 1;
  Eigen::Vector2d p = route.points[0];
  for (double t = 0.0; t <= horizon; t += dt) {
    for (const auto& tg : targets)
      best = std::min(best, (tg.state.position + tg.state.velocity() * t - p).norm());
    if (route.ends_at_goal && leg >= route.points.size())
      break;
    double time_left = dt;
    while (time_left > 0.0 && leg < route.points.size()) {
      const double speed = route.speeds[leg - 1];
      if (!(speed > 0.0))
        break;  // stopped on this leg: stays
      const Eigen::Vector2d d = route.points[leg] - p;
      const double step = speed * time_left;
      if (d.norm() <= step) {
        time_left -= d.norm() / speed;
        p = route.points[leg++];
      } else {
        p += d.normalized() * step;
        time_left = 0.0;
      }
    }
  }
  return best;
}

PredictedRoute planRoute(const Plan& plan, const PlanningProblem& pr) {
  const Eigen::Vector2d from = pr.own.position;
  const double reach = std::max(pr.own.speed, 0.5) * pr.prediction_horizon;
  const double after =
      plan.speed_setpoint > 0.0 || plan.status == PlanStatus::Fallback ? plan.speed_setpoint : keptSpeed(pr);
  if (plan.waypoints.size() < 2)
    return {{from, from + courseSpeedToVelocity(plan.course_setpoint, reach)}, {after}};
  PredictedRoute r{{from}, {}};
  for (size_t i = 1; i < plan.waypoints.size(); ++i) {
    r.points.push_back(plan.waypoints[i].position);
    r.speeds.push_back(plan.waypoints[i].speed > 0.0 ? plan.waypoints[i].speed : after);
  }
  size_t next = pr.route.size();
  double nearest = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < pr.route.size(); ++k) {
    const double d = (pr.route[k] - r.points.back()).norm();
    if (d < nearest) {
      nearest = d;
      next = d < 1.0 ? k + 1 : k;
    }
  }
  for (size_t k = next; k < pr.route.size(); ++k) {
    r.points.push_back(pr.route[k]);
    r.speeds.push_back(after);
  }
  r.points.push_back(pr.goal);
  r.speeds.push_back(after);
  r.ends_at_goal = true;
  return r;
}

std::vector<Eigen::Vector2d> flownTrack(const PredictedRoute& route, double heading,
                                        const OwnShipLimits& limits, double reach, double acceptance,
                                        double dt) {
  std::vector<Eigen::Vector2d> track;
  if (route.points.empty())
    return track;
  Eigen::Vector2d p = route.points[0];
  track.push_back(p);
  size_t next = 1;
  double flown = 0.0;
  while (next < route.points.size() && flown < reach) {
    if ((route.points[next] - p).norm() < acceptance && next + 1 < route.points.size()) {
      ++next;
      continue;
    }
    const Eigen::Vector2d d = route.points[next] - p;
    if (d.norm() < 1.0)
      break;
    const double turn = std::remainder(courseOf(d) - heading, kTwoPi);
    heading = wrapTwoPi(heading + std::clamp(turn, -limits.turn_rate * dt, limits.turn_rate * dt));
    const double speed = std::max(route.speeds[next - 1], 0.5);
    const double step = std::min(speed * dt, d.norm());
    p += courseSpeedToVelocity(heading, step);
    flown += step;
    track.push_back(p);
  }
  return track;
}

bool routeKeepsOffLand(const PredictedRoute& route, const PlanningProblem& pr, double required) {
  if (!(required > 0.0))
    return true;
  const double reach = std::max(pr.own.speed, 0.5) * pr.prediction_horizon;
  // As flown the track cuts corners (waypoint acceptance) and swings out of sharp turns: half the
  // clearance is kept there, the whole on the planned legs.
  return trackObstacleDistance(truncateTrack(route.points, reach), pr.obstacles) >= required &&
         trackObstacleDistance(flownTrack(route, pr.own.heading, pr.limits, reach), pr.obstacles) >=
             0.5 * required;
}

namespace {

// [s] the shortest leg: long enough to be flown (longer than the follower's waypoint acceptance at any
// sensible speed) and, at 30 deg or more, readily apparent (Rule 8(b)).
constexpr double kShortestHold = 180.0;

struct Candidate {
  double turn = 0.0;          // [rad] course change, + starboard
  double speed_factor = 1.0;  // of the own speed
};

// The candidates in order of preference (see separationManoeuvre).
std::vector<Candidate> candidates(bool starboard_at_full_speed) {
  std::vector<Candidate> c;
  for (int deg = 30; deg <= 90; deg += 10)
    c.push_back({degToRad(deg), 1.0});
  if (starboard_at_full_speed)
    return c;
  for (int deg = 30; deg <= 90; deg += 10)
    c.push_back({degToRad(deg), 0.5});
  c.push_back({0.0, 0.5});
  for (int deg = 30; deg <= 90; deg += 10)
    c.push_back({-degToRad(deg), 1.0});
  return c;
}

// How long the new course is held before the ship steers for the goal again: until every target is past
// her CPA with the ship on it and the range has opened to kSeparationMargin x the minimum separation,
// plus a minute (at least kShortestHold), at most the prediction horizon.
double holdUntilPast(const PlanningProblem& pr, const Eigen::Vector2d& velocity,
                     const std::vector<PlannerTarget>& targets) {
  const double open = kSeparationMargin * pr.min_separation;
  double hold = kShortestHold;
  for (const auto& t : targets) {
    const Cpa cpa = computeCpa(pr.own.position, velocity, t.state.position, t.state.velocity());
    if (!cpa.relative_motion)
      continue;
    const double opening = std::sqrt(std::max(0.0, open * open - cpa.dcpa * cpa.dcpa)) / cpa.relative_speed;
    hold = std::max(hold, cpa.tcpa + opening + 60.0);
  }
  return std::min(hold, pr.prediction_horizon);
}

// What the net's alterations are measured from: the course to the next point of the way (the land
// route's, else the goal). Measured from the ship's heading instead, a manoeuvre renewed at every
// replan adds its turn again each time, and in crowded waters the ship turned full circles.
double wayCourse(const PlanningProblem& pr) {
  const Eigen::Vector2d next = nextWayPoint(pr);
  const Eigen::Vector2d to = next - pr.own.position;
  return to.norm() > 1.0 ? courseOf(to) : pr.own.course;
}

// The candidate flown: `base` + its turn at its speed for `hold` seconds, then (the follower's way past
// a plan) straight for the goal at the cruising speed. A stop is a Fallback: the follower holds still
// and keeps asking the planner.
Plan manoeuvrePlan(const PlanningProblem& pr, double base, const Candidate& c, double hold) {
  Plan p;
  p.status = c.speed_factor > 0.0 ? PlanStatus::Ok : PlanStatus::Fallback;
  p.course_setpoint = wrapTwoPi(base + c.turn);
  p.speed_setpoint = c.speed_factor > 0.0 ? keptSpeed(pr) : 0.0;  // past the leg: cruising speed again
  PlannedWaypoint start, leg;
  start.position = pr.own.position;
  leg.time = hold;
  leg.course = p.course_setpoint;
  leg.speed = keptSpeed(pr) * c.speed_factor;
  leg.position = pr.own.position + courseSpeedToVelocity(leg.course, leg.speed) * hold;
  p.waypoints = {start};
  if (c.speed_factor > 0.0)
    p.waypoints.push_back(leg);
  return p;
}

// The own ship overtakes one of the targets (Rule 13).
bool overtakes(const PlanningProblem& pr) {
  return std::any_of(pr.targets.begin(), pr.targets.end(),
                     [](const PlannerTarget& t) { return t.encounter == Encounter::Overtaking; });
}

// The candidate's hold times, shortest first: a short leg that gains enough room is the smaller
// deviation; then the hold until every target is past; with `until_clear` (the preferred distance),
// longer ones when she overtakes.
std::vector<double> holdTimes(const PlanningProblem& pr, double base, const Candidate& c, bool until_clear) {
  const double past =
      holdUntilPast(pr, courseSpeedToVelocity(base + c.turn, keptSpeed(pr) * c.speed_factor), pr.targets);
  std::vector<double> out;
  // The preferred distance is not worth a swing longer than kLongestHold.
  auto add = [&](double h) {
    if (!until_clear || h <= kLongestHold)
      out.push_back(h);
  };
  for (double h : {kShortestHold, 2.0 * kShortestHold, 600.0})
    if (h < past)
      add(h);
  add(past);
  // Rule 13(d): the overtaking ship keeps clear until finally past and clear. Past with the ship on the
  // new course is not yet past on her way back when the tracks converge slowly: longer holds, while the
  // horizon lasts. Not for the other encounters: there the pass is quick, and a long swing only ends
  // in a late turn back.
  if (until_clear && overtakes(pr))
    for (double h : {1.5 * past, 2.0 * past})
      if (h < pr.prediction_horizon)
        add(h);
  return out;
}

// Rule 13(d), the way a seaman overtakes: turn `turn` off the way course until `offset` metres to that
// side of the way, run parallel to it for `stretch` x the time until every target is past
// (holdUntilPast, from there; at most until the next point of the way is `offset` ahead, so that she
// does not sail past her goal), then steer for the goal. Overtaking, a turn held and then undone towards
// the goal comes back across the overtaken ship's bow before she is clear; the parallel leg keeps the
// offset for the whole pass, and the stretch lets her draw ahead before she comes back.
Plan offsetPlan(const PlanningProblem& pr, double base, double turn, double offset, double stretch) {
  const double v = keptSpeed(pr);
  const double out_time = offset / (v * std::abs(std::sin(turn)));
  const Eigen::Vector2d out_end = pr.own.position + courseSpeedToVelocity(base + turn, v) * out_time;
  PlanningProblem there = pr;
  there.own.position = out_end;
  for (auto& t : there.targets)
    t.state.position += t.state.velocity() * out_time;
  // Never beyond the next point of the way (the goal or the land route's): abeam of it she turns in.
  const Eigen::Vector2d next = nextWayPoint(pr);
  const double ahead = (next - out_end).dot(courseSpeedToVelocity(base, 1.0)) - offset;
  const double parallel =
      std::min(stretch * holdUntilPast(there, courseSpeedToVelocity(base, v), there.targets),
               std::max(0.0, ahead) / v);
  Plan p;
  p.status = PlanStatus::Ok;
  p.course_setpoint = wrapTwoPi(base + turn);
  p.speed_setpoint = v;
  PlannedWaypoint start, out, along;
  start.position = pr.own.position;
  out = {out_end, out_time, p.course_setpoint, v};
  along = {out_end + courseSpeedToVelocity(base, v) * parallel, out_time + parallel, wrapTwoPi(base), v};
  p.waypoints = {start, out, along};
  return p;
}

// The offset manoeuvres in order of preference, handed to `visit` until it returns true: the
// smaller offset first (1.1 or 1.5 x the margin on the minimum separation, so that the parallel leg
// passes with room to spare), then the side away from the overtaken ships (either is allowed, Rule 13),
// the smaller turn (at least 30 deg, Rule 8(b)) and the shorter parallel leg.
void visitOffsetPlans(const PlanningProblem& pr, double base, const std::function<bool(const Plan&)>& visit) {
  double abeam = 0.0;  // the overtaken ships' side of the way: + starboard
  for (const auto& t : pr.targets)
    if (t.encounter == Encounter::Overtaking)
      abeam += std::sin(courseOf(t.state.position - pr.own.position) - base);
  const double away = abeam > 0.0 ? -1.0 : 1.0;
  const double wanted = kSeparationMargin * pr.min_separation;
  for (double k : {1.1, 1.5})
    for (double side : {away, -away})
      for (int deg : {30, 45, 60})
        for (double stretch : {1.0, 1.5, 2.0})
          if (visit(offsetPlan(pr, base, side * degToRad(deg), k * wanted, stretch)))
            return;
}

// Every manoeuvre the net may fly, in its order of preference (see separationManoeuvre), handed to
// `visit` until it returns true. Built one at a time: the search mostly ends at the first few.
void visitManoeuvres(const PlanningProblem& pr, double base, const NetOptions& options,
                     const std::function<bool(const Plan&)>& visit) {
  for (const Candidate& c : candidates(options.starboard_at_full_speed))
    for (double hold : holdTimes(pr, base, c, options.until_clear))
      if (visit(manoeuvrePlan(pr, base, c, hold)))
        return;
  if (options.until_clear && overtakes(pr))
    visitOffsetPlans(pr, base, visit);
}

// [s] The step in which the stand-on ship's hold is lengthened (holdUntilClearBack): our choice, half a
// minute, a fraction of a crossing's passing time.
constexpr double kHoldStep = 30.0;

// The stand-on ship's hold, from `past` (holdUntilPast) on, lengthened in steps of kHoldStep until her
// way back to the next point of her way passes each ship of `until_past` at the preferred distance
// with the margin (kSeparationMargin x kPreferredSeparation x min_separation: the turn back is flown,
// not drawn), or as wide as holding on would. Turned back sooner (a route bend she held through), she
// crosses the track of the ship she stood on for and re-creates the risk with her, a close-quarters
// situation of her own making (Rule 2(a)), and then alters as her stand-on ship (Rule 17(a)). At most
// the prediction horizon; when no hold within it is clear, the one that passes widest.
double holdUntilClearBack(const PlanningProblem& pr, const std::vector<PlannerTarget>& until_past,
                          double past) {
  if (until_past.empty() || !(pr.min_separation > 0.0))
    return past;
  PlanningProblem watched = pr;
  watched.targets = until_past;
  watched.prediction_horizon = 2.0 * pr.prediction_horizon;  // the way back after the longest hold too
  auto separation = [&](double hold) {
    return planSeparation(manoeuvrePlan(pr, pr.own.course, {0.0, 1.0}, hold), watched);
  };
  const double wanted = std::min(kSeparationMargin * kPreferredSeparation * pr.min_separation,
                                 separation(watched.prediction_horizon)) -
                        1.0;
  double best = past, widest = -1.0;
  for (double hold = past; hold <= pr.prediction_horizon; hold += kHoldStep) {
    const double s = separation(hold);
    if (s >= wanted)
      return hold;
    if (s > widest) {
      widest = s;
      best = hold;
    }
  }
  return best;
}

}  // namespace

Plan holdCoursePlan(const PlanningProblem& pr, const std::vector<PlannerTarget>& until_past) {
  const double past = holdUntilPast(pr, pr.own.velocity(), until_past);
  Plan p = manoeuvrePlan(pr, pr.own.course, {0.0, 1.0}, holdUntilClearBack(pr, until_past, past));
  p.message = "hold course and speed";
  return p;
}

double passingHorizon(const PlanningProblem& pr) {
  if (!overtakes(pr))
    return pr.prediction_horizon;
  PlanningProblem longest = pr;
  longest.prediction_horizon = std::max(pr.prediction_horizon, kLongestPass);
  const double past = holdUntilPast(longest, courseSpeedToVelocity(wayCourse(pr), keptSpeed(pr)), pr.targets);
  return std::max(past, pr.prediction_horizon);
}

double planSeparation(const Plan& plan, const PlanningProblem& pr) {
  return routeClearance(planRoute(plan, pr), pr.targets, pr.prediction_horizon);
}

namespace {

Plan described(Plan p, const PlanningProblem& pr, double clearance, const std::string& why) {
  const double turn = radToDeg(wrapPi(p.course_setpoint - pr.own.course));
  const double speed = p.waypoints.size() >= 2 ? p.waypoints[1].speed : 0.0;
  const double hold = p.waypoints.size() >= 2 ? p.waypoints[1].time : 0.0;
  p.message = "separation manoeuvre (" + why + ")" +
              strFormat(": %+.0f deg at %.1f m/s for %.0f s, predicted %.0f m", turn, speed, hold, clearance);
  return p;
}

}  // namespace

Plan separationManoeuvre(const PlanningProblem& pr, double land_clearance, const std::string& why,
                         const NetOptions& options, double* predicted) {
  const double wanted = kSeparationMargin * pr.min_separation;
  // The first manoeuvre that keeps the margin, in the order of preference; else the first that keeps
  // the minimum; else the one that keeps farthest, or stopping when that keeps farther still.
  std::optional<std::pair<Plan, double>> margin, first_minimum, farthest;
  visitManoeuvres(pr, wayCourse(pr), options, [&](const Plan& p) {
    if (!routeKeepsOffLand(planRoute(p, pr), pr, land_clearance))
      return false;
    const double clearance = planSeparation(p, pr);
    if (clearance >= wanted)
      margin.emplace(p, clearance);
    else if (clearance >= pr.min_separation && !first_minimum)
      first_minimum.emplace(p, clearance);
    if (!farthest || clearance > farthest->second)
      farthest.emplace(p, clearance);
    return margin.has_value();
  });
  auto chosen = [&](const Plan& p, double clearance) {
    if (predicted)
      *predicted = clearance;
    return described(p, pr, clearance, why);
  };
  if (margin)
    return chosen(margin->first, margin->second);
  if (first_minimum)
    return chosen(first_minimum->first, first_minimum->second);
  const double stop_clearance = routeClearance({{pr.own.position}, {}}, pr.targets, pr.prediction_horizon);
  if (!farthest || stop_clearance > farthest->second)
    return chosen(manoeuvrePlan(pr, wayCourse(pr), {0.0, 0.0}, 0.0), stop_clearance);
  return chosen(farthest->first, farthest->second);
}

}  // namespace asv
