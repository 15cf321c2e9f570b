// sim_node: the whole scenario on asv_core's Simulation, driving ROS time.
//
// Publishes: /clock (when publish_clock), <ship>/odom (nav_msgs/Odometry) and tf map -> <ship>/base_link
//   for every ship, sim/nmea (asv_msgs/NmeaSentence: the traffic's AIVDM and the own radar's TTM),
//   sim/ships (asv_msgs/TargetArray: ground truth, for evaluation and rviz), sim/events
//   (asv_msgs/SimEvent), sim/markers, sim/land (visualization_msgs/MarkerArray; land latched), /diagnostics
// Subscribes: <ship>/cmd (asv_msgs/CourseSpeedSetpoint) for every ship that plans
// Parameters: config/sim_node.yaml (every key documented there).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <asv_core/planning/plan_follower.h>
#include <asv_core/sim/lockstep.h>
#include <asv_core/sim/run_summary.h>
#include <asv_core/sim/sim_node_config.h>
#include <asv_core/sim/simulation.h>
#include <asv_msgs/CourseSpeedSetpoint.h>
#include <asv_msgs/LockstepAck.h>
#include <asv_msgs/Target.h>
#include <asv_ros/alarm.h>
#include <asv_ros/map_origin.h>
#include <asv_ros/nmea_output.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/Point.h>
#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>
#include <visualization_msgs/MarkerArray.h>

namespace asv_sim {

// Stamps are sim time on a fixed epoch, so that two runs of the same scenario record the same stamps.
constexpr double kEpoch = 1.0e9;  // [s] ROS time of simulation time 0

// sim_node's parameters: its own (asv::SimNodeConfig, config/sim_node.yaml) and the global lockstep
// ones (/lockstep: the simulation advances a step only when every participant has done that step's
// work, asv_core/sim/lockstep.h; rate, start_delay and keep_up_* then do not apply).
struct SimNodeParams : asv::SimNodeConfig {
  bool lockstep = false;
  double lockstep_timeout = 30.0;  // [s, wall] global /lockstep_timeout
};

SimNodeParams loadParams(const ros::NodeHandle& pnh);

class SimNode {
public:
  SimNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  ~SimNode();
  // Runs the scenario to its end (or until ROS shuts down); returns the process exit code.
  int run();

private:
  int runFreely();
  int runLockstep();
  bool runOver() const;               // the scenario's end or max_sim_time
  int everySteps(double rate) const;  // [steps] between two publications at `rate` Hz of sim time
  struct Sentences {
    std::vector<std::string> ais, ttm;
  };
  Sentences emitSensors();  // the NMEA the own ship's receivers get at this time
  void publishSensors(const Sentences& s);
  void publishLand();
  void addClearanceZones(visualization_msgs::MarkerArray& arr) const;
  bool publishNewEvents();  // true: the run must stop (stop_on_collision)
  void lockstepStart();
  // The END event, then (shutdown_at_end) linger until the evaluator has written its result.
  int finishRun();
  void publishClock();
  ros::Publisher& stepPublisher(int phase);
  // Lockstep: admit the participants that asked to join, then the pipeline's phases that have work.
  void lockstepAdmit(uint64_t step);
  void lockstepPhases(uint64_t step, bool wait);
  bool lockstepRound(uint64_t step, int phase, const std::vector<std::string>& run, bool wait);
  void lockstepWaitForCmds();
  void lockstepAckCallback(const asv_msgs::LockstepAck::ConstPtr& msg);
  bool waitFor(const std::function<bool()>& done, const char* what);
  void publishState(bool odom, bool ships);
  // sim_node_markers.cpp: the rviz markers.
  void addShipMarkers(size_t i, const asv_msgs::Target& t, double yaw, const ros::Time& stamp,
                      visualization_msgs::MarkerArray& markers);
  void addTrail(size_t i, const visualization_msgs::Marker& ship, visualization_msgs::MarkerArray& arr);
  // sim/summary: each target's closest approach to the own ship so far, the own ship's manoeuvres, and
  // the simulated time and rate at the scene box's top-left corner (the recording's last frame).
  void publishSummary();
  void publishNmea(const std::vector<std::string>& lines, const ros::Time& stamp, const char* frame);
  void publishEvents(size_t from);
  void cmdCallback(const std::string& ship, const std::string& topic,
                   const asv_msgs::CourseSpeedSetpoint::ConstPtr& msg);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);

  ros::NodeHandle nh_, pnh_;
  SimNodeParams params_;
  std::unique_ptr<asv::Simulation> sim_;
  std::unique_ptr<asv_ros::MapOrigin> map_origin_;
  std::unique_ptr<asv::NmeaEmitter> emitter_;
  ros::Publisher clock_pub_, nmea_pub_, ships_pub_, events_pub_, markers_pub_, land_pub_, summary_pub_;
  asv::RunSummary summary_;
  asv::SceneBox scene_box_;  // sim/scene_box [xmin, ymin, xmax, ymax]: where the encounter takes place
  std::vector<ros::Publisher> odom_pubs_;
  std::vector<ros::Subscriber> cmd_subs_;
  asv::InputWatch cmd_watch_;  // each ship's cmd topic (free-running)
  std::unique_ptr<asv_ros::AlarmReporter> alarm_;
  // The set-points' watch: an alarm when a ship's planner has stopped sending (after her first).
  void watchCmds();
  tf2_ros::TransformBroadcaster tf_;
  diagnostic_updater::Updater updater_;
  std::unique_ptr<asv_ros::NmeaOutput> udp_out_;  // emit_udp: each sentence as a datagram
  uint64_t cmds_ok_ = 0, cmds_rejected_ = 0, nmea_sent_ = 0;
  double achieved_rtf_ = 0.0;
  ros::Subscriber keep_up_sub_;
  double keep_up_time_ = -1.0;  // [s, sim] stamp of the last message on keep_up_topic (-1: none yet)
  uint64_t keep_up_timeouts_ = 0;
  std::map<size_t, std::vector<geometry_msgs::Point>> trails_;  // markers: where each ship has been
  asv::LockstepCoordinator lockstep_;
  std::map<int, ros::Publisher> step_pubs_;  // per phase (asv_ros::lockstepStepTopic)
  uint64_t state_step_ = 0;                  // the lockstep step whose odometry went out
  ros::Time last_clock_;                     // the stamp of the latest /clock sent
  bool odom_due_ = false;                    // lockstep: this step's odometry is due (odom_rate)
  size_t events_done_ = 0;                   // events already published
  ros::Subscriber ack_sub_;
  std::set<std::string> lockstep_waiting_;  // participants that have not answered the current round
  uint64_t lockstep_round_step_ = 0;
  int lockstep_round_phase_ = -1;
  uint64_t lockstep_rounds_ = 0, lockstep_timeouts_ = 0;
  std::map<std::string, uint64_t> cmds_received_;    // per cmd topic
  std::map<std::string, ros::WallTime> last_hello_;  // lockstep start-up: when each participant last asked
  uint64_t lockstep_rejected_ = 0;                   // requests to join with no name or phase 0
};

}  // namespace asv_sim
