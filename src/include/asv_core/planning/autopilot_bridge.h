// The autopilot bridge's logic, free of ROS (asv_planning's autopilot_bridge node wraps it): the
// planner's course/speed set-points become what an NMEA 0183 autopilot steers by (APB, RMB, XTE, HSC;
// codec/autopilot.h), at a fixed rate, only while armed, with a watchdog:
//  - disarmed (the default at start): nothing is sent; the autopilot stays in whatever mode its
//    operator left it;
//  - the set-points stop (planner down, or stamps older than watch/input_timeout): an alarm, and the
//    configured safe action: hold_course (keep sending the last course, so the autopilot holds it) or
//    invalidate (APB, RMB and XTE with status V / mode N: an autopilot in track mode drops out of it and
//    alarms at its console; HSC, which has no status field, is no longer sent);
//  - the own position stops (odometry stale): the route sentences cannot be computed: status V on APB,
//    RMB and XTE, HSC keeps the last course;
// and a twist (forward speed and yaw rate towards the heading to steer) for a vehicle driven by
// geometry_msgs/TwistStamped.
// With a voyage plan in force (route()), the leg sent while the stack steers along the route is the
// route's active leg: origin and destination its waypoints (WP001 its first waypoint, ..., as
// plotter_node names them for the chart plotter; WP000 where the ship was given the route), the
// cross-track error from that leg, the range and bearing to its real waypoint. While the stack steers
// off the route (an avoiding manoeuvre), the leg of the set-point is sent, as without a route.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/codec/autopilot.h"
#include "asv_core/common/input_watch.h"
#include "asv_core/common/param_map.h"
#include "asv_core/planning/plan_follower.h"
#include "asv_core/world/route.h"

namespace asv {

// asv_planning/config/autopilot_bridge.yaml documents every key.
struct AutopilotBridgeConfig {
  // The map frame's origin, for RMB's waypoint position: origin_scenario (a scenario file's origin) or
  // origin_lat_deg/origin_lon_deg (both; the stack's other nodes use the same keys); neither: the
  // run's /map_origin
  std::string origin_scenario;
  std::optional<double> origin_lat_deg, origin_lon_deg;
  std::string talker = "EC";  // NMEA talker of the sentences (EC: electronic chart system)
  std::vector<std::string> sentences{"APB", "RMB", "XTE", "HSC"};
  double rate = 1.0;  // [Hz] sentences out (what autopilots expect); faster set-points wait for it
  std::string safe_action = "hold_course";  // hold_course | invalidate
  bool armed_at_start = false;
  std::optional<double>
      variation;               // [rad] magnetic variation, east positive (key variation_deg; unset: none)
  double twist_gain = 0.5;     // [1/s] yaw rate per radian of heading error
  double max_yaw_rate = 0.05;  // [rad/s] (about 3 deg/s)
  autopilot::LegConfig leg;    // lookahead, leg_change_deg
  // [m] key route_acceptance: a route waypoint this close is passed, as is one at its wheel-over point
  // (route_turn_rate_deg_s) or abeam; the default is planner_node's waypoint_acceptance, so that with
  // the ship's turn rate the bridge and the follower pass a waypoint at the same place.
  double route_acceptance = PlanFollowerConfig().waypoint_acceptance;
  // [rad/s] key route_turn_rate_deg_s: the ship's rate of turn, for the wheel-over point. Default 1
  // deg/s, OwnShipLimits' (planner_node's limits/turn_rate_deg_s where it is set).
  double route_turn_rate = OwnShipLimits().turn_rate;
  // [rad] key route_tolerance_deg: the set-point follows the route while it is within this of the
  // course to the follower's line-of-sight point on the active leg (kLineOfSightLookahead x
  // route_acceptance ahead of the ship's abeam point: where planner_node steers her back onto it);
  // farther off, the stack is manoeuvring and the set-point's leg is sent. Default 10 deg.
  double route_tolerance = degToRad(10.0);
  // watch/*: set-points (1 Hz from planner_node) and odometry stale after watch/input_timeout (3 s: a plan
  // may hold the set-point job up by a second)
  InputWatchConfig watch{3.0, 10.0, 0.5};

  void validate() const;  // std::invalid_argument naming the key
  static AutopilotBridgeConfig fromParams(const ParamMap& params);
};

class AutopilotBridge {
public:
  explicit AutopilotBridge(const AutopilotBridgeConfig& config);

  // Inputs, each with the node's clock (ROS time) and wall time [s].
  void setpoint(double course, double speed, double stamp, double now, double wall);
  void own(const Eigen::Vector2d& position, double course_over_ground, double speed, double heading,
           double now, double wall);
  // The voyage plan in force (map positions; empty: none), from where the ship is when it comes (at the
  // first position after it, when none is known yet). Non-finite waypoints are dropped.
  void route(const std::vector<Eigen::Vector2d>& waypoints);
  // Arming starts a new leg from where the ship is (she may have been steered by hand meanwhile).
  void arm(bool armed);
  bool armed() const { return armed_; }

  struct Output {
    std::vector<std::string> sentences;    // empty while disarmed or before the first set-point
    bool valid = false;                    // the route sentences carry status A
    double speed = 0.0;                    // [m/s] twist forward speed (0 when invalidated or disarmed)
    double yaw_rate = 0.0;                 // [rad/s] ENU (counter-clockwise positive)
    std::vector<StaleInput> lost;          // the watchdog's findings (alarm causes)
    std::string action;                    // what is being done about them ("" when nothing is lost)
    std::optional<size_t> route_waypoint;  // the route waypoint steered for when the route's leg was sent
  };
  // What to send now; `to_latlon` converts the map position of the leg's destination for RMB.
  Output tick(double now, double wall,
              const std::function<void(const Eigen::Vector2d&, double&, double&)>& to_latlon);

private:
  // The route's active leg for the set-point course, or nullopt when the set-point leaves the route.
  std::optional<autopilot::Steering> routeSteering(double setpoint_course);
  // The leg to send and its destination (map) for the set-point course.
  autopilot::Steering steering(bool setpoint_lost, Eigen::Vector2d* destination,
                               std::optional<size_t>* route_waypoint);

  AutopilotBridgeConfig cfg_;
  InputWatch watch_;
  autopilot::SetpointLeg leg_;
  bool armed_ = false;
  bool was_lost_ = false;  // an input was lost at the last tick: a new leg when it is back
  std::optional<double> course_, speed_;
  std::optional<Eigen::Vector2d> position_;
  double cog_ = 0.0, sog_ = 0.0, heading_ = 0.0;
  Route pending_route_;     // a route given before any position
  RouteProgress progress_;  // the route in force (empty: none)
};

}  // namespace asv
