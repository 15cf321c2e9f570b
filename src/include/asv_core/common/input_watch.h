// Watches the age of a stage's inputs, so that a stage upstream that stops is noticed downstream: no
// data is a fault to report, never "no danger".
//
// An input is stale once nothing came for longer than its timeout, both in the node's clock (ROS or
// simulation time) and in wall time (wall_floor). The wall floor keeps a simulation run faster than
// real time from raising alarms for scheduling delays: at 10x, 2 s of simulated time are 0.2 s of the
// operating system's. On a boat (1x) and in lockstep (where nothing arrives late in simulated time) it
// changes nothing. An input never received is stale once the watch has run for its timeout plus
// `startup_grace` (nodes start in any order).
//
// A node that was busy (a plan computed in the same thread) has not yet read what arrived meanwhile:
// busy(t) counts every input as seen at t, so that the queue is read before an alarm is raised.
#pragma once

#include <map>

#include <string>
#include <vector>
#include "asv_core/common/param_map.h"

namespace asv {

struct StaleInput {
  std::string name;  // as added
  std::string text;  // "targets: none for 3.2 s (timeout 1.5 s)"
};

// A node's keys watch/input_timeout, watch/startup_grace, watch/wall_floor (its YAML documents them).
struct InputWatchConfig {
  // [s] an input that publishes at least every 0.5 s (the tracker's 2 Hz, the ingestion nodes'
  // heartbeat) is stale after three missed messages; our choice, so that a stage that stops is seen
  // downstream within 2 s
  double input_timeout = 1.5;
  double startup_grace = 10.0;  // [s] extra time for a first message after the watch starts
  double wall_floor = 0.5;      // [s, wall] an input is stale only after this much wall time too
  void validate() const;        // throws std::invalid_argument on a value not > 0 (timeout) or < 0
  // The keys over `defaults` (a node whose inputs come slower has its own).
  static InputWatchConfig fromParams(const ParamMap& params, const InputWatchConfig& defaults);
  static InputWatchConfig fromParams(const ParamMap& params) {
    return fromParams(params, InputWatchConfig());
  }
};

class InputWatch {
public:
  explicit InputWatch(const InputWatchConfig& config = {});

  // Adds an input (name as shown in alarms, e.g. the topic) that must arrive at least every `timeout`
  // seconds; throws std::invalid_argument on a timeout not > 0 or a duplicate name.
  void add(const std::string& name, double timeout);
  void add(const std::string& name) { add(name, cfg_.input_timeout); }
  // A message on `name` at node time `now` and wall time `wall` (unknown names throw).
  void received(const std::string& name, double now, double wall);
  // The node was busy until now: every input counts as seen at this time.
  void busy(double now, double wall);

  // Starts the clocks (the first check does it when not called). Call when the node's clock is valid.
  void start(double now, double wall);

  // The stale inputs, in the order added.
  std::vector<StaleInput> stale(double now, double wall);
  // Seconds since the input last arrived (or since the start when never); < 0 before start.
  double age(const std::string& name, double now) const;
  bool everReceived(const std::string& name) const;
  // Forgets every reception (a clock jump back).
  void reset();

private:
  struct Input {
    double timeout = 0.0;
    double last = 0.0, last_wall = 0.0;
    bool seen = false;
  };
  Input& find(const std::string& name);

  InputWatchConfig cfg_;
  std::vector<std::string> order_;
  std::map<std::string, Input> inputs_;
  bool started_ = false;
  double start_ = 0.0, start_wall_ = 0.0;
  double busy_ = -1e300, busy_wall_ = -1e300;
};

}  // namespace asv
