// DssaRosAgent: distributed DSSA / DSSA+ (Hirayama et al. 2019, Fig. 1 and Fig. 2) for one ship over ROS.
//
// Every ship that runs DSSA runs its own planner_node with one of these (README.md, Distributed DSSA); the
// ships exchange intentions on the shared topic /intentions (asv_msgs/Intention), as they would over AIS.
// The search itself is asv::DssaAgent, the same code the in-process asv::DssaExchange runs; this class
// only moves its intentions over ROS and keeps the round protocol:
//
//   Every control step (time_step of the plugin's DssaConfig, ROS time: all agents share the clock, so
//   phase k = floor(t / time_step) begins at the same time everywhere), a search phase:
//     round 0: setOwn() from the latest odometry, publish the initial intention (current course/speed);
//     round r >= 1: decide(r), publish the intention of round r;
//     after each publication the round is collected: it completes when every awaited neighbour's
//     intention of (phase, round) has arrived, or after ~exchange/round_timeout (wall clock). Awaited
//     are the neighbours in the detection range that are responsive (heard since they last missed a
//     round), have not ended this phase's search (search_done) and are not already in a later phase.
//     A missing intention is taken as the last known one (DssaAgent keeps it, carried forward along its
//     intended velocity), and the neighbour is not awaited again until it is heard from: a lost message
//     or a dead node slows one round, never blocks the search.
//     Quiescence: self and every neighbour whose round-r intention arrived reported satisfied in round r
//     (a neighbour that did not answer holds a fixed intention, like a ship that does not search). The
//     search also ends at max_rounds, at max_search_time (wall, when > 0) or when the next step begins.
//     It ends by publishing the final intention again with search_done, so a neighbour that has not
//     seen quiescence yet stops waiting for this ship.
//   Then the ship steers by its intention (cmd: course and speed) until the next step.
//   A ship with no neighbour completes each round at once (nothing to wait for).
//   Within ~exchange/arrival_radius of its goal (the scenario's goal radius when that is not set) the
//   ship leaves the exchange (publishes `leaving`, which makes the others forget it) and steers straight
//   for the goal.
//
// Threads: the intention and odometry callbacks run on the agent's own callback queue (one
// AsyncSpinner thread) and the search runs on a worker thread, so waiting for a round never blocks a
// callback of the agent or of the hosting node.
//
// Subscribes: odom (nav_msgs/Odometry), /intentions (asv_msgs/Intention, ~exchange/topic)
// Publishes: /intentions, cmd (asv_msgs/CourseSpeedSetpoint), plan (asv_msgs/Plan), path
//   (nav_msgs/Path), /diagnostics (rounds per search, round timeouts, neighbours, messages)
// Parameters (~exchange/, every key in asv_planning/config/dssa.yaml): topic, round_timeout,
//   forget_after, arrival_radius, drop_outgoing_from, drop_outgoing_until. The algorithm's own are the
//   plugin's (~dssa/ or ~dssa_plus/, config/dssa.yaml).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <utility>

#include <asv_core/planning/dssa/dssa.h>
#include <asv_msgs/CourseSpeedSetpoint.h>
#include <asv_msgs/Intention.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <asv_core/planning/planning.h>

namespace asv_planning {

// What the hosting planner_node knows of its ship.
struct DssaRosOptions {
  std::string ship = "own";  // own ship name: Intention.ship_id
  std::string frame_id = "map";
  bool has_goal = false;
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();  // [m] map
  double cruise_speed = 0.0;                       // [m/s] RefSPD unless the config's ref_speed > 0
  double min_speed = 0.0;                          // [m/s] MinSPD
  double max_speed = 10.0;                         // [m/s] MaxSPD
  int seed = 1;                                    // the agent draws from dssaAgentSeed(seed, id)
  // [m] the scenario's arrival radius round the goal (goal_radius_m; 0: none given): where the ship
  // leaves the exchange unless ~exchange/arrival_radius is set, as the simulator counts her arrived there.
  double goal_radius = 0.0;
  // The scenario's stays_at_goal: once arrived the ship stays in the exchange as a stopped ship (the others
  // avoid her) instead of leaving it.
  bool stays_at_goal = false;
};

// ~exchange/ parameters (config/dssa.yaml).
struct DssaExchangeParams {
  std::string topic = "/intentions";  // shared topic of every ship's intentions
  double round_timeout = 0.3;         // [s, wall] a round completes at the latest this long after it began
  double forget_after = 120.0;        // [s, ROS time] a ship not heard from this long is forgotten
  double arrival_radius = 250.0;      // [m] within this of the goal the ship leaves the exchange
  double drop_outgoing_from = 0.0;    // [s, ROS time] tests: own intentions are not sent from ...
  double drop_outgoing_until = 0.0;   // [s, ROS time] ... until this time (until <= from: never dropped)

  // The keys above from a map of the exchange/ subtree; std::invalid_argument on a value out of range.
  static DssaExchangeParams fromParams(const asv::ParamMap& exchange);
  // Reads ~exchange/*; throws std::invalid_argument on an unknown key or a value out of range.
  static DssaExchangeParams load(const ros::NodeHandle& pnh);
};

class DssaRosAgent {
public:
  // `config`: the algorithm's parameters (configOf() of the loaded plugin). Starts the threads.
  DssaRosAgent(const ros::NodeHandle& nh, const ros::NodeHandle& pnh, const asv::DssaConfig& config,
               const DssaRosOptions& options);
  ~DssaRosAgent();
  DssaRosAgent(const DssaRosAgent&) = delete;
  DssaRosAgent& operator=(const DssaRosAgent&) = delete;

  // True when `planner` is dssa or dssa_plus and ~distributed is set.
  static bool wanted(const std::string& planner, bool distributed);
  // The DssaConfig of a loaded dssa / dssa_plus plugin: its sea-scale defaults, the scenario's
  // planner_params and ~<planner>/ merged and validated. Throws std::invalid_argument for other plugins.
  static asv::DssaConfig configOf(const asv::PlannerAlgorithm& plugin);
  // DssaIntention.id of a ship name: 31-bit FNV-1a, the same on every machine.
  static int shipId(const std::string& name);

private:
  struct Peer {
    std::string name;
    asv::DssaIntention last;  // last intention heard
    uint32_t last_phase = 0;  // its phase and round
    uint32_t last_round = 0;
    ros::Time heard;                     // ROS time it was heard
    bool responsive = true;              // false after it missed a round, until heard from again
    bool leaving = false;                // it left the exchange
    std::optional<uint32_t> done_phase;  // phase whose search it has ended
    std::map<std::pair<uint32_t, uint32_t>, asv::DssaIntention> inbox;  // (phase, round) -> intention
  };
  struct Round {
    bool all_satisfied = true;  // every answering neighbour reported satisfied
    int answered = 0, awaited = 0, timeouts = 0;
  };

  void odomCallback(const nav_msgs::Odometry::ConstPtr& msg);
  void intentionCallback(const asv_msgs::Intention::ConstPtr& msg);
  void run();
  void searchPhase(uint32_t phase, double step_end);
  Round collect(uint32_t phase, uint32_t round, const Eigen::Vector2d& own_position, double now);
  void forgetStale(double now);
  void publishIntention(const asv::DssaIntention& in, uint32_t phase, bool done, bool leaving);
  void publishCommand(double course, double speed, double search_time, int rounds, bool quiescent);
  // The last set-point again (1 Hz, spinner thread): a control step lasts time_step (10 s), and an
  // autopilot's watchdog would take a silence that long for a planner that has stopped.
  void resendCommand();
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);

  ros::CallbackQueue queue_;
  ros::NodeHandle nh_;  // on queue_
  asv::DssaConfig config_;
  DssaRosOptions opt_;
  DssaExchangeParams ex_;
  int id_;
  asv::DssaAgent agent_;  // worker thread only
  std::mt19937_64 rng_;   // worker thread only
  ros::Subscriber odom_sub_, intention_sub_;
  ros::Publisher intention_pub_, cmd_pub_, plan_pub_, path_pub_;
  diagnostic_updater::Updater updater_;

  std::mutex mu_;
  std::condition_variable cv_;
  std::map<int, Peer> peers_;                             // by DssaIntention.id; under mu_
  std::optional<std::pair<asv::ShipState, double>> own_;  // state and its ROS time; under mu_
  uint64_t received_ = 0;                                 // under mu_

  // Worker-thread statistics (read by diagnose() on the worker thread).
  uint64_t phases_ = 0, rounds_total_ = 0, quiescent_ = 0, round_timeouts_ = 0, sent_ = 0, dropped_ = 0;
  int last_rounds_ = 0, max_rounds_seen_ = 0, neighbours_ = 0;
  double last_search_time_ = 0.0, max_search_time_ = 0.0;
  double course_sp_ = 0.0, speed_sp_ = 0.0;
  std::mutex cmd_mu_;                                      // the last set-point sent, for resendCommand()
  std::optional<asv_msgs::CourseSpeedSetpoint> last_cmd_;  // under cmd_mu_
  ros::Timer resend_timer_;
  double own_course_ = 0.0;  // [rad] course over ground when the search phase began
  bool left_ = false;

  std::atomic<bool> stop_{false};
  ros::AsyncSpinner spinner_;
  std::thread worker_;
};

}  // namespace asv_planning
