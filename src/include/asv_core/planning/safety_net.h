// The separation rule every planner's plan must keep at sea, whatever the algorithm (a sea-mode rule of
// ours, not any paper's): a plan predicted to pass a target closer than the situation's minimum
// separation is refused, and when no plan of the planner keeps it, a simple manoeuvre that does is
// flown instead (planUnderSharedRules, plan_follower.h). Predictions are kinematic: the own ship flies
// the plan's route at the plan's speed, every target holds its course and speed.
#pragma once

#include <string>
#include <vector>

#include "asv_core/planning/planning.h"

namespace asv {

// A way the own ship is predicted to go: from points[0] through the others, leg i (points[i] to
// points[i + 1]) at speeds[i] [m/s].
struct PredictedRoute {
  std::vector<Eigen::Vector2d> points;
  std::vector<double> speeds;
  bool ends_at_goal = false;  // the last point is the goal: there the ship has arrived and left the scene
};

// The smallest distance between the own ship flying `route` and any target over `horizon` seconds,
// sampled every `dt`; the own ship stays at the route's end once there, unless that end is the goal
// (an arrived ship is out of every encounter). Infinity without targets.
double routeClearance(const PredictedRoute& route, const std::vector<PlannerTarget>& targets, double horizon,
                      double dt = 5.0);

// The way the plan follower flies a plan (PlanFollower::setpoint): from the own position through its
// waypoints at their speeds; then, as later plans will, through the rest of the problem's land route
// (from the route point nearest the plan's end) and to the goal, at the plan's speed set-point (the
// own speed when it has none). A plan without waypoints: its course and speed set-points over the
// reach of the prediction horizon.
PredictedRoute planRoute(const Plan& plan, const PlanningProblem& problem);

// The track a ship with `limits` (turn rate, turn delay ignored) flies along `route` from `heading`:
// she turns at most turn_rate towards the next point, which she passes within `acceptance`, every
// `dt` seconds, for `reach` metres or until the last point. A sharp turn at a waypoint swings her out
// by about her turning radius (speed / turn rate), which the straight legs leave out.
std::vector<Eigen::Vector2d> flownTrack(const PredictedRoute& route, double heading,
                                        const OwnShipLimits& limits, double reach, double acceptance = 150.0,
                                        double dt = 2.0);

// Whether the route keeps `required` off the problem's obstacles as planned, and half of it as flown
// (flownTrack from the own heading: corners cut, sharp turns swung out), over the reach of the
// prediction horizon. True when nothing is required.
bool routeKeepsOffLand(const PredictedRoute& route, const PlanningProblem& problem, double required);

// The predicted smallest distance of a plan to the problem's targets (infinity without targets).
double planSeparation(const Plan& plan, const PlanningProblem& problem);

// When the own ship overtakes a target (Rule 13), how long she takes, sailing for the next point of her
// way at her speed, until every target is past and the range has opened to kSeparationMargin x
// min_separation (plus a minute): at least the problem's prediction horizon, at most kLongestPass. A slow
// overtaking lasts longer than the prediction horizon, and a plan judged over the horizon alone then
// passes close after it. Without an overtaking, the prediction horizon.
double passingHorizon(const PlanningProblem& problem);

// Hold course and speed until every ship of `until_past` has passed her CPA (plus a minute) and the way
// back to the next point passes them at 1.1 x the preferred distance (kSeparationMargin x
// kPreferredSeparation x min_separation), or as wide as holding on would (the widest hold found when
// none does), then steer for the goal: the stand-on ship's plan (Rule 17(a)(i)).
Plan holdCoursePlan(const PlanningProblem& problem, const std::vector<PlannerTarget>& until_past);

// How the separation net searches (separationManoeuvre). The defaults: every candidate, for the minimum.
struct NetOptions {
  // The turns to starboard at full speed only: the preferred passing distance is worth neither the
  // ship's way nor a turn to port.
  bool starboard_at_full_speed = false;
  // Rule 13(d), when she overtakes: the overtaken ship clear on her way back too. Holds up to twice as
  // long as until past (none longer than kLongestHold), and, when no turn keeps the margin, an offset:
  // 30-60 deg to either side (away from the overtaken ships first) until 1.1 or 1.5 x the margin off the
  // way, then parallel to the way until they are past, then the goal.
  bool until_clear = false;
  // How planUnderSharedRules seeks the preferred passing distance: both.
  static NetOptions preferredDistance() { return {true, true}; }
};

// The separation net's manoeuvre: the first of these that keeps every target of the problem at least
// kSeparationMargin x min_separation away and the track `land_clearance` off land (0: no land check),
// in this order (COLREGs preference: Rules 8, 14-17): 30 to 90 deg to starboard at full speed, the
// same at half speed, half speed on the way, 30 to 90 deg to port, stop (as `options` narrow or widen
// the list); the turns are measured from the course to the next point of the way (land route or goal),
// so a renewed manoeuvre does not add its turn to the last one's. The ship holds the new course until
// every target is past and then steers for the goal. When none keeps the margin, the first that keeps
// the minimum; when none does, the one that keeps the ship farthest from every target, or stopping when
// that keeps farther still. Status Ok (Fallback when it stops); `why` goes into the message. Speeds are
// the kept speed (keptSpeed, planning.h). `predicted`, when given, gets the returned plan's
// planSeparation, so that a caller need not fly it again.
Plan separationManoeuvre(const PlanningProblem& problem, double land_clearance, const std::string& why,
                         const NetOptions& options = {}, double* predicted = nullptr);

}  // namespace asv
