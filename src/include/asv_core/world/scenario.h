// Scenario files, format 1 (asv_bringup/scenarios/README.md): one YAML scenario per file. Unknown keys,
// missing fields, ambiguous position forms, unit mistakes and ships that start overlapping are errors
// naming the file, line and key.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/charts/charts.h"
#include "asv_core/common/geodesy.h"
#include "asv_core/common/param_map.h"
#include "asv_core/world/obstacles.h"
#include "asv_core/world/route.h"

namespace asv {

class ScenarioError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// NonCompliant: a give-way ship that stands on; PortTurn: a give-way ship that alters to port (the
// classic error of Rules 14/15). Both are the rule-breakers of generated traffic. LateGiveWay: a
// give-way ship that acts late and little (a small turn to starboard when the CPA is minutes away), not
// the substantial early action of Rule 16. Track: a recorded track replayed in time (real traffic from
// an AIS log), whatever happens round the ship.
enum class Behaviour : uint8_t {
  Constant,
  Waypoints,
  GiveWay,
  NonCompliant,
  PortTurn,
  LateGiveWay,
  Planner,
  Track
};
const char* toString(Behaviour b);

// One point of a recorded track: where the ship was at time t of the scenario.
struct TrackPoint {
  double t = 0.0;                                      // [s] since the scenario's start, > 0
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] ENU
};

struct ScenarioShip {
  std::string name;
  uint32_t mmsi = 0;                // 0: the simulator assigns one
  std::string model = "kinematic";  // vessel preset: kinematic | point | <3-DOF preset name>
  char ais_class = 'A';             // 'A' (types 1/5) or 'B' (types 18/24) for NMEA emission
  double length = 0.0;              // [m] overall length (0: the model's)
  double beam = 0.0;                // [m]
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] ENU at t = 0
  double course = 0.0;                                 // [rad] nautical
  double speed = 0.0;                                  // [m/s]
  std::optional<Eigen::Vector2d> goal;                 // [m] ENU
  double goal_radius = 0.0;  // [m] arrival radius round the goal; 0: the simulator's (max(200 m, 2 L))
  // Key stays_at_goal. false: on arrival the ship leaves the scenario (no longer seen or refereed);
  // true: she stops there and stays, seen and refereed, a stationary obstacle (Hirayama et al. 2019's
  // experiments, Fig. 1: only a ship "who does not reach her goal" moves).
  bool stays_at_goal = false;
  std::string planner;                        // plugin short name; empty: none
  Behaviour behaviour = Behaviour::Constant;  // targets only; the own ship plans (or steers for its goal)
  std::vector<Eigen::Vector2d> waypoints;     // [m] ENU, for Behaviour::Waypoints
  // Behaviour::Track: times strictly increasing; the ship sails in a straight line from `position`
  // (t = 0) to each point in turn, arriving at its time, and leaves the scenario after the last.
  std::vector<TrackPoint> track;
  // The own ship's voyage plan (key route): she sails it leg by leg from `position`; its last waypoint is
  // `goal`. Empty: straight for the goal.
  Route route;
  std::vector<int> route_lines;  // the file's line of each route point (errors found after parsing)
  std::string route_source;      // the route file it came from (key route_file); empty: the scenario
};

// What the master who sailed the window did, from the same log (key human; real-traffic scenarios):
// the yardstick a run in her place is judged against.
struct HumanRecord {
  double min_separation_m = 0.0;  // her closest approach to any other vessel of the log
  double time_s = 0.0;            // her time from the start to the goal
  double path_m = 0.0;            // the length of her track
};

// A sensor fault the simulator's NMEA emitter plays (sim_node; asv_batch uses ground truth and ignores
// them), for fault tests: scenario key sensor_faults.
struct SensorFault {
  enum class Type : uint8_t {
    AisSilence,  // the ship's transponder sends nothing (position and static reports)
    RadarLoss,   // the radar loses the ship: one TTM with status L, then none
    RadarSwap,   // the radar swaps the target numbers of `ship` and `with` (two echoes passing close)
  };
  Type type = Type::AisSilence;
  std::string ship, with;  // target names; `with` for RadarSwap only
  double start = 0.0;      // [s] simulation time
  double duration = 0.0;   // [s] > 0
  bool active(double t) const { return t >= start && t < start + duration; }
};
const char* toString(SensorFault::Type t);

struct Scenario {
  int format = 1;
  std::string name;
  std::string description;
  std::string source;             // file it was read from
  double duration = 0.0;          // [s]
  GeoPoint origin;                // geodetic origin of the local frame
  bool has_origin = false;        // false: origin defaults to 0 N 0 E (documented)
  double min_separation = 926.0;  // [m] evaluation threshold (default 0.5 nm)
  // [m] safety.min_obstacle_clearance_m: how far from land every plan keeps in these waters (a port's
  // is smaller than the open sea's); 0: not given, the planner node's min_obstacle_clearance_m.
  double min_obstacle_clearance = 0.0;
  ScenarioShip own;
  std::vector<ScenarioShip> targets;
  std::vector<StaticObstacle> obstacles;  // static_obstacles, then chart land (after loadCharts)
  // The charts key: land from GSHHG or a chart file round the origin (relative file paths resolved
  // against the scenario's folder). Its polygons join `obstacles` as "land 1", "land 2", ...
  std::optional<ChartSpec> charts;
  std::vector<SensorFault> sensor_faults;
  std::optional<HumanRecord> human;
  ParamMap planner_params;  // flattened: nested maps become "a/b" keys

  LocalFrame frame() const { return LocalFrame(origin.lat_deg, origin.lon_deg); }
  // Every ship that runs a planner: the own ship if it has one, and targets with behaviour planner.
  std::vector<const ScenarioShip*> planningShips() const;
};

// A planner's name as scenarios, launch files and asv_batch give it: a short name of asv_planning's
// (aco, dssa, dssa_plus, mopso, ga) or any plugin's pluginlib name, package/class (lower case, digits
// and underscores, a letter first). Which exist is pluginlib's to say, when the planner is loaded.
bool validPlannerName(const std::string& name);

// Parses a scenario; `source` names the file in error messages. Throws ScenarioError. The charts key
// is read, not loaded: see loadCharts.
Scenario parseScenario(const std::string& yaml_text, const std::string& source = "<string>");
// Throws ScenarioError naming the file, line and leg when a leg of the own ship's route crosses a static
// obstacle (the scenario's or its charts' land).
void checkRouteOffLand(const Scenario& s);
// Adds the land of the scenario's charts (with the options' override) to its obstacles. Throws
// ScenarioError naming the file when the chart cannot be read, the own ship starts on land or her
// route crosses it.
void loadCharts(Scenario& s, const ChartOptions& options);
// Reads a scenario file and loads its charts (scenario_load.cpp).
Scenario loadScenario(const std::string& path, const ChartOptions& options = {});

}  // namespace asv
