// sim_node's parameters (asv_sim/config/sim_node.yaml), ROS-free: one struct read by fromParams(), so
// that each key and its default is defined once. The global lockstep parameters (/lockstep,
// /lockstep_timeout) are the ROS layer's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "asv_core/charts/charts.h"
#include "asv_core/common/input_watch.h"
#include "asv_core/common/param_map.h"
#include "asv_core/sim/simulation.h"

namespace asv {

struct SimNodeConfig {
  std::string scenario;       // path of a scenario file (format 1); required
  ChartOptions charts;        // charts, chart_cache_dir: the land of the scenario's charts
  uint64_t seed = 1;          // NMEA noise and dropouts
  double rate = 1.0;          // real-time factor; 0 = as fast as possible
  bool publish_clock = true;  // drive /clock (the launch sets /use_sim_time)
  double odom_rate = 10.0;    // [Hz, sim time] odometry and tf
  double ships_rate = 2.0;    // [Hz, sim time] ground truth and markers
  bool emit_topic = true;     // publish NMEA on sim/nmea
  bool emit_udp = false;      // also send NMEA as UDP datagrams (one sentence each)
  std::string udp_host = "127.0.0.1";
  int udp_port = 10110;
  bool stop_on_collision = false;
  // watch/*: a ship's set-points (<ship>/cmd, 1 Hz from planner_node) missing for input_timeout after the
  // first: alarm (the ship holds her last set-point). The planner's plan may take 0.5 s of wall time,
  // and twice that before it is discarded: 3 s and a 1.5 s wall floor are our choice.
  InputWatchConfig watch{3.0, 10.0, 1.5};
  bool shutdown_at_end = true;  // shut the node down when the scenario ends (launch: required="true")
  // Before shutting down, wait (publishing the final clock) until this node has left the master, at
  // most linger_max seconds: the evaluator writes its result after the END event, and the launch ends
  // when sim_node (required) does. Empty: wait 1 s only.
  std::string linger_for;
  double linger_max = 60.0;   // [s, wall]
  double start_delay = 1.0;   // [s, wall] wait for subscribers before time starts
  double max_sim_time = 0.0;  // [s] end the run here if earlier than the scenario end (0: no limit)
  // rate 0 runs "as fast as the subscribers keep up": the simulation never gets more than keep_up_lead
  // simulated seconds ahead of the last risk assessment on keep_up_topic (the pipeline's output),
  // waiting at most keep_up_timeout wall seconds each time (then it goes on: a pipeline that is not
  // there does not stop the simulation). "" disables the wait.
  std::string keep_up_topic = "/risk";
  double keep_up_lead = 2.0;                       // [s, sim]
  double keep_up_timeout = 1.0;                    // [s, wall]
  std::vector<std::string> lockstep_participants;  // node names the first lockstep step waits for
  // A recorder stamps a message with its own clock at receipt, and replays by that time: a recorded
  // lockstep run needs the clock at every step (else only at steps with work, about 22 % faster).
  bool lockstep_clock_every_step = false;
  // Keys dt, collision_distance, wind_speed, wind_direction_deg, wave_direction_deg, wave_height,
  // wave_length, give_way_alteration_deg, give_way_tcpa, give_way_dcpa, late_give_way_tcpa,
  // late_give_way_alteration_deg, waypoint_acceptance.
  SimConfig sim;
  // Keys ais, radar, radar_range, radar_period, range_noise, bearing_noise_deg, speed_noise_kn,
  // course_noise_deg, radar_dropout, ais_dropout, static_interval.
  EmitterConfig emitter;

  void validate() const;  // std::invalid_argument naming the parameter
  static SimNodeConfig fromParams(const ParamMap& params);
};

}  // namespace asv
