// Lockstep participation for a pipeline node.
//
// When the global parameter /lockstep is true (scenario.launch lockstep:=true, with /use_sim_time),
// sim_node advances the simulation one step only when every participant has done that step's work
// (asv_core/sim/lockstep.h has the rule and asv_msgs/LockstepStep the protocol). A node takes part through
// this class, which replaces three ROS calls:
//  - subscribe(): in lockstep a message is held, and handed to the callback at the node's step, once
//    every message published so far on each input has arrived: inputs in the order they were
//    subscribed, each input in arrival order. So a node with two inputs (odometry and targets, say)
//    sees them in the same order on every run, whatever the operating system's scheduling;
//  - every(): a periodic job, a ros::Timer in ROS time when free-running; in lockstep run at the steps
//    at which it is due, after the step's input;
//  - publish(): publishes and counts, so that the subscribers know how many messages to wait for.
// With /lockstep false (the default, and on a real boat) the three are the plain ROS calls.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <asv_msgs/LockstepAck.h>
#include <asv_msgs/LockstepStep.h>
#include <ros/ros.h>

namespace asv_ros {

// The pipeline's phases, in the order they act within a step (asv_msgs/LockstepStep.phase). Phase 1
// holds every node that takes only what the simulator and earlier steps published: the ingestion nodes
// and the evaluator (which reads the planner's output of earlier steps).
enum LockstepPhase : uint8_t { kIngestion = 1, kEvaluation = 1, kTracking = 2, kRisk = 3, kPlanning = 4 };
// Each phase has its own step topic, so that a step wakes only the nodes of its phase.
std::string lockstepStepTopic(int phase);

// The global parameters: /lockstep (default false) and /lockstep_timeout ([s, wall], default 30: the
// longest wait for a step's input or a participant's answer; then the run goes on, with an error).
// Each asks the master: read them once. A value of the wrong type, or a timeout not > 0, is
// std::invalid_argument.
bool lockstepEnabled();
double lockstepTimeout();

class Lockstep {
public:
  Lockstep(ros::NodeHandle nh, LockstepPhase phase);
  Lockstep(const Lockstep&) = delete;
  Lockstep& operator=(const Lockstep&) = delete;
  bool enabled() const { return enabled_; }

  // As NodeHandle::subscribe. trigger: a message gives the node work (false: it only updates what
  // the node reads at its next step, like odometry for the risk node).
  template <class M>
  ros::Subscriber subscribe(const std::string& topic, uint32_t queue,
                            const std::function<void(const boost::shared_ptr<M const>&)>& cb,
                            bool trigger = true) {
    if (!enabled_)
      return nh_.subscribe<M>(topic, queue, cb);
    const std::size_t i = inputs_.size();
    inputs_.emplace_back();
    inputs_[i].trigger = trigger;
    // TCP_NODELAY: a step waits for these messages, so none may sit in Nagle's buffer.
    inputs_[i].sub = nh_.subscribe<M>(
        topic, std::max<uint32_t>(queue, 1000),
        boost::function<void(const boost::shared_ptr<M const>&)>(
            [this, i, cb](const boost::shared_ptr<M const>& m) { hold(i, [cb, m] { cb(m); }); }),
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
    inputs_[i].topic = inputs_[i].sub.getTopic();
    return inputs_[i].sub;
  }
  template <class M, class T>
  ros::Subscriber subscribe(const std::string& topic, uint32_t queue,
                            void (T::*fp)(const boost::shared_ptr<M const>&), T* obj, bool trigger = true) {
    return subscribe<M>(
        topic, queue, [fp, obj](const boost::shared_ptr<M const>& m) { (obj->*fp)(m); }, trigger);
  }

  // A job every `period` seconds of ROS time. only_with_input: in lockstep it runs only at a due step
  // after new trigger input (a job that publishes what arrived since its last run has nothing to do
  // otherwise), so the node is not woken for nothing.
  void every(double period, const std::function<void()>& job, bool only_with_input = false);

  template <class M>
  void publish(const ros::Publisher& pub, const M& msg) {
    pub.publish(msg);
    if (enabled_)
      ++published_[pub.getTopic()];
  }

  // Declares the node ready: it asks to join once each input has a publisher. Call it once, after
  // every subscribe() and every().
  void start();

private:
  struct Input {
    std::string topic;
    bool trigger = true;
    ros::Subscriber sub;
    uint64_t received = 0;
    int64_t base = 0;  // received + base = the publishers' count (set at admission)
    std::vector<std::function<void()>> held;
  };
  struct Job {
    ros::Duration period;
    std::function<void()> run;
    bool only_with_input = false;
    bool input = false;  // trigger input delivered since the job last ran
    ros::Time next;      // zero: at the first step
    ros::Timer timer;    // free-running only
  };

  void hold(std::size_t input, std::function<void()> deliver);
  void stepCallback(const asv_msgs::LockstepStep::ConstPtr& msg);
  void tryStep();
  bool inputsComplete(const asv_msgs::LockstepStep& s) const;
  void runStep(const asv_msgs::LockstepStep& s);
  ros::Time runJobs(const ros::Time& t);
  void acknowledge(const asv_msgs::LockstepStep& s, const ros::Time& next_due);
  void hello();

  ros::NodeHandle nh_;
  LockstepPhase phase_;
  bool enabled_ = false;
  double timeout_ = 30.0;  // [s, wall] /lockstep_timeout
  bool admitted_ = false;
  std::string name_;
  std::vector<Input> inputs_;
  std::vector<Job> jobs_;
  std::map<std::string, uint64_t> published_;
  ros::Subscriber step_sub_;
  ros::Publisher ack_pub_;
  ros::WallTimer hello_timer_, retry_timer_;
  asv_msgs::LockstepStep::ConstPtr pending_;
  ros::WallTime pending_since_;
  ros::WallTime hello_since_;  // first attempt to join
};

}  // namespace asv_ros
