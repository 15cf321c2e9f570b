// The simulated world: every ship of a scenario on its vessel model, the traffic behaviours, the
// referee, and the NMEA the traffic emits (AIS types 1/5 and 18/24 at ITU-R M.1371 intervals, radar TTM).
// ROS-free: sim_node and the batch runner drive the same class.
#pragma once

#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "asv_core/codec/nmea_encode.h"
#include "asv_core/common/geodesy.h"
#include "asv_core/common/geometry.h"
#include "asv_core/risk/risk_level.h"
#include "asv_core/sim/autopilot.h"
#include "asv_core/sim/vessel_model.h"
#include "asv_core/world/scenario.h"

namespace asv {

struct TrafficConfig {
  // give_way behaviour: a COLREGs-compliant target that, when it is the give-way vessel (Rules 14-16)
  // and a risk of collision exists (Hu eq. 1 with these thresholds), alters to starboard in good time,
  // enough to pass at give_way_dcpa or more (Simulation::giveWayAlteration).
  double give_way_alteration_deg = 40.0;  // [deg] the smallest alteration, >= 30 so that it is readily
                                          // apparent (Rule 8(b)); a port_turn ship's whole alteration
  double give_way_tcpa = 900.0;           // [s] act when the CPA is this close in time (15 min) ...
  double give_way_dcpa = 1852.0;          // [m] ... and closer than this (1 nm)
  // late_give_way behaviour: a give-way ship that acts late and little: when the CPA is this close in
  // time (and closer than give_way_dcpa) she turns this much to starboard, whatever it passes. 6 min is
  // inside the stand-on ship's urgent level (10 min, Hu et al. 2017), so her action is clearly lacking
  // first; 15 deg is half a readily apparent turn (our choices).
  double late_give_way_tcpa = 360.0;           // [s]
  double late_give_way_alteration_deg = 15.0;  // [deg]
  double waypoint_acceptance = 200.0;          // [m] kinematic waypoint following: switch within this radius
  void validate() const;
};

struct SimConfig {
  double dt = 0.1;  // [s] integration step
  // A collision is two hull outlines (length x beam rectangles round each ship's reference point)
  // touching; with collision_distance > 0, any two ships closer than that instead.
  double collision_distance = 0.0;        // [m]
  double default_beam_ratio = 1.0 / 6.0;  // beam = length x this when the scenario gives no beam
  Environment environment;                // wind and waves for the 3-DOF models
  TrafficConfig traffic;
  void validate() const;
};

struct SimVessel {
  std::string name;
  uint32_t mmsi = 0;
  char ais_class = 'A';
  bool own = false;
  Behaviour behaviour = Behaviour::Constant;
  std::string planner;  // plugin name for the own ship or a planner target
  std::string model_name;
  std::unique_ptr<VesselModel> model;
  std::unique_ptr<Autopilot> autopilot;            // 3-DOF models only
  double length = 0.0, beam = 0.0;                 // [m]
  double course_sp = 0.0, speed_sp = 0.0;          // [rad], [m/s] current set-points
  double cruise_course = 0.0, cruise_speed = 0.0;  // what the ship does when nothing disturbs it
  std::optional<Eigen::Vector2d> goal;
  double goal_radius = 0.0;  // [m] arrival radius; 0: max(traffic.waypoint_acceptance, 2 L)
  std::vector<Eigen::Vector2d> waypoints;
  size_t wp_index = 0;
  Route route;  // the own ship's voyage plan (its last waypoint is `goal`); empty: none
  std::optional<RouteProgress> route_progress;            // sailed while no planner steers her
  std::vector<TrackPoint> track;                          // Behaviour::Track
  Eigen::Vector2d track_start = Eigen::Vector2d::Zero();  // [m] where the track starts (t = 0)
  Eigen::Vector2d step_from = Eigen::Vector2d::Zero();    // [m] position at the start of the last step
  bool arrived = false;
  bool stays_at_goal = false;  // ScenarioShip::stays_at_goal: once arrived she stops and stays present
  double arrival_time = -1.0;
  bool giving_way = false;  // give_way behaviour: alteration in progress
  std::string giving_way_to;
  bool external_setpoint = false;  // a planner has sent a set-point
  double path_length = 0.0;        // [m] travelled so far

  const VesselState& state() const { return model->state(); }
  Eigen::Vector2d position() const { return model->state().position(); }
  double cog() const { return model->courseOverGround(); }
  double sog() const { return model->speedOverGround(); }
  // Still in the scenario (seen, refereed, an obstacle to the others): under way, or arrived and staying.
  bool present() const { return !arrived || stays_at_goal; }
  ShipState shipState() const;
};

// Where a ship replaying a recorded track is at time t [s]: on the straight leg that spans t (from
// `start` at t = 0 to the first point, then point to point), at that leg's course and constant speed.
// A leg of no length keeps the course before it (`start_course` on the first). Past the last point:
// there, speed 0, ended.
struct TrackSample {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // [m] ENU
  double course = 0.0;                                 // [rad] nautical
  double speed = 0.0;                                  // [m/s]
  bool ended = false;
};
TrackSample sampleTrack(const Eigen::Vector2d& start, double start_course,
                        const std::vector<TrackPoint>& track, double t);

struct SimEvent {
  // Grounding: ship a's hull outline touched static obstacle b (land); distance 0.
  enum Type { Collision, NearMiss, Arrival, Grounding } type;
  double time = 0.0;
  std::string a, b;
  double distance = 0.0;  // [m]
};
const char* toString(SimEvent::Type t);

class Simulation {
public:
  // Throws std::invalid_argument / std::runtime_error on a bad config or an unknown vessel preset.
  Simulation(const Scenario& scenario, const SimConfig& config = {});

  void step();  // advances config.dt
  double time() const { return time_; }
  bool finished() const { return time_ >= scenario_.duration - 1e-9; }

  // Course/speed set-point from a planner (or a test) for a ship: the ship follows it from now on.
  // Returns false for an unknown ship or non-finite values (nothing changes).
  bool setSetpoint(const std::string& ship, double course, double speed);
  // Waypoints for a ship to follow (3-DOF by LOS, kinematic by pure pursuit), at `speed`.
  bool setWaypoints(const std::string& ship, const std::vector<Eigen::Vector2d>& wps, double speed);

  const std::vector<SimVessel>& vessels() const { return vessels_; }
  const SimVessel* find(const std::string& name) const;
  const SimVessel& own() const { return vessels_[0]; }
  const Scenario& scenario() const { return scenario_; }
  const LocalFrame& frame() const { return frame_; }
  const SimConfig& config() const { return cfg_; }

  // Referee.
  const std::vector<SimEvent>& events() const { return events_; }
  bool collided() const { return collided_; }
  double minSeparationOwn() const { return min_sep_own_; }  // [m] own ship to any other, whole run
  double minDistanceTo(size_t vessel_index) const { return min_dist_[vessel_index]; }  // own to vessel i
  // The own ship's hull touched a static obstacle at some time of the run.
  bool grounded() const { return grounded_own_; }
  // [m] own hull to the nearest static obstacle, whole run; infinity without obstacles.
  double minObstacleDistanceOwn() const { return min_obstacle_own_; }
  // Hull outlines of two ships touch (separating axis test on their rectangles).
  static bool hullsTouch(const SimVessel& a, const SimVessel& b);
  // A ship's hull outline now (hullOutline of its position, heading, length and beam).
  static Polygon hull(const SimVessel& v);

private:
  void steer(SimVessel& v);
  void replayTrack(SimVessel& v, double t);
  void giveWayLogic(SimVessel& v, size_t index);
  double giveWayAlteration(const SimVessel& v, const ShipState& other) const;
  void referee();
  void refereeLand();

  Scenario scenario_;
  SimConfig cfg_;
  LocalFrame frame_;
  std::vector<SimVessel> vessels_;
  double time_ = 0.0;
  std::vector<SimEvent> events_;
  bool collided_ = false;
  double min_sep_own_ = 1e12;
  std::vector<double> min_dist_;
  std::vector<std::vector<char>> in_contact_, in_near_miss_;
  std::vector<std::vector<char>> aground_;  // [vessel][obstacle]: hull touching it now
  std::vector<Eigen::AlignedBox2d> obstacle_boxes_;
  bool grounded_own_ = false;
  double min_obstacle_own_ = std::numeric_limits<double>::infinity();
};

// NMEA the traffic emits, as an AIS receiver and a radar on the own ship would receive it.
struct EmitterConfig {
  bool ais = true;
  bool radar = true;
  double radar_range = 12.0 * 1852.0;  // [m] targets beyond are not tracked
  double radar_period = 2.5;           // [s] one antenna revolution (24 rpm)
  double range_noise = 10.0;           // [m] 1-sigma range noise of a TTM
  double bearing_noise_deg = 0.5;      // [deg] 1-sigma bearing noise
  double speed_noise_kn = 0.2;         // [kn] 1-sigma speed noise
  double course_noise_deg = 1.0;       // [deg] 1-sigma course noise
  double radar_dropout = 0.02;         // probability that a scan misses a target
  double ais_dropout = 0.0;            // probability that an AIS report is lost
  double static_interval = 360.0;      // [s] types 5 / 24 (ITU-R M.1371: 6 min)
  void validate() const;
};

class NmeaEmitter {
public:
  NmeaEmitter(const EmitterConfig& cfg, uint64_t seed);
  // Sentences due since the last call (at simulation time sim.time()), in emission order. The own
  // ship (vessel 0) is the receiver and is never reported. The scenario's sensor_faults are played:
  // an AIS silence sends nothing of the ship, a radar loss sends one TTM with status L and then none,
  // a radar swap reports each of the two ships under the other's target number.
  void update(const Simulation& sim, std::vector<std::string>& ais, std::vector<std::string>& ttm);
  // ITU-R M.1371-5 Table 1 reporting interval [s] for a vessel.
  static double reportingInterval(char ais_class, double sog, double rate_of_turn, uint8_t nav_status = 0);
  uint64_t aisSent() const { return ais_sent_; }
  uint64_t ttmSent() const { return ttm_sent_; }

private:
  void schedule(const Simulation& sim);  // the first call: staggered first reports
  void send(const ais::BitWriter& w, std::vector<std::string>& out);
  void emitAis(const Simulation& sim, std::vector<std::string>& out);
  void sendStatic(const Simulation& sim, size_t i, std::vector<std::string>& out);
  void sendPosition(const Simulation& sim, size_t i, std::vector<std::string>& out);
  void emitRadar(const Simulation& sim, std::vector<std::string>& out);
  bool radarLost(const Simulation& sim, size_t i, std::vector<std::string>& out);

  EmitterConfig cfg_;
  std::mt19937_64 rng_;
  std::vector<double> next_pos_, next_static_;
  double next_scan_ = 0.0;
  std::vector<char> loss_announced_;  // per scenario sensor fault: the status-L TTM went out
  int seq_ = 0;
  bool channel_b_ = false;
  uint64_t ais_sent_ = 0, ttm_sent_ = 0;
};

}  // namespace asv
