#include "asv_ros/lockstep.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "asv_ros/params.h"

#include <xmlrpcpp/XmlRpcValue.h>

namespace asv_ros {

namespace {
const char* const kAckTopic = "/lockstep/ack";

// Publishers of `topic` according to the master (0 when it cannot be asked).
int masterPublishers(const std::string& topic) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", args, result, payload, false) || payload.size() < 1)
    return 0;
  XmlRpc::XmlRpcValue& pubs = payload[0];
  for (int i = 0; i < pubs.size(); ++i)
    if (static_cast<std::string>(pubs[i][0]) == topic)
      return pubs[i][1].size();
  return 0;
}
}  // namespace

std::string lockstepStepTopic(int phase) {
  return "/lockstep/step/" + std::to_string(phase);
}

bool lockstepEnabled() {
  bool on = false;
  getParam(ros::NodeHandle(), "/lockstep", on);
  return on;
}

double lockstepTimeout() {
  double t = 30.0;
  getParam(ros::NodeHandle(), "/lockstep_timeout", t);
  if (!(t > 0.0 && std::isfinite(t)))
    throw std::invalid_argument(
        "parameter '/lockstep_timeout' must be a finite number of seconds > 0 (default 30)");
  return t;
}

Lockstep::Lockstep(ros::NodeHandle nh, LockstepPhase phase)
    : nh_(nh), phase_(phase), enabled_(lockstepEnabled()), name_(ros::this_node::getName()) {
  if (enabled_)
    timeout_ = lockstepTimeout();
}

void Lockstep::every(double period, const std::function<void()>& job, bool only_with_input) {
  Job j;
  j.period = ros::Duration(period);
  j.run = job;
  j.only_with_input = only_with_input;
  if (!enabled_)
    j.timer = nh_.createTimer(j.period, [job](const ros::TimerEvent&) { job(); });
  jobs_.push_back(std::move(j));
}

void Lockstep::start() {
  if (!enabled_)
    return;
  step_sub_ = nh_.subscribe(lockstepStepTopic(phase_), 100, &Lockstep::stepCallback, this,
                            ros::TransportHints().tcpNoDelay());
  ack_pub_ = nh_.advertise<asv_msgs::LockstepAck>(kAckTopic, 100);
  hello_timer_ = nh_.createWallTimer(ros::WallDuration(0.2), [this](const ros::WallTimerEvent&) { hello(); });
  retry_timer_ = nh_.createWallTimer(
      ros::WallDuration(0.0005), [this](const ros::WallTimerEvent&) { tryStep(); }, false, false);
  ROS_INFO("%s: lockstep participant, phase %d, %zu inputs, %zu periodic jobs", name_.c_str(), phase_,
           inputs_.size(), jobs_.size());
}

void Lockstep::hello() {
  if (admitted_) {
    hello_timer_.stop();
    return;
  }
  // /lockstep outlives a launch on its master: a node started later, with no simulator to step it,
  // would wait for ever. Say so.
  if (hello_since_.isZero())
    hello_since_ = ros::WallTime::now();
  if ((ros::WallTime::now() - hello_since_).toSec() > 10.0)
    ROS_WARN_THROTTLE(10.0,
                      "%s: /lockstep is true but no simulator has admitted this node after %.0f s: its input "
                      "is held until sim_node steps it (set /lockstep false for live or replayed data)",
                      name_.c_str(), (ros::WallTime::now() - hello_since_).toSec());
  // Ask only while every input is connected to every publisher the master knows: a message published
  // before would be lost to this node. (sim_node admits once every hello is fresh and settled.)
  for (const Input& in : inputs_)
    if (static_cast<int>(in.sub.getNumPublishers()) < masterPublishers(in.topic))
      return;
  if (step_sub_.getNumPublishers() == 0 || ack_pub_.getNumSubscribers() == 0)
    return;
  asv_msgs::LockstepAck a;
  a.header.stamp = ros::Time::now();
  a.node = name_;
  a.phase = phase_;
  a.hello = true;
  for (const Input& in : inputs_) {
    a.inputs.push_back(in.topic);
    a.triggers.push_back(in.trigger);
  }
  ack_pub_.publish(a);
}

void Lockstep::hold(std::size_t input, std::function<void()> deliver) {
  Input& in = inputs_[input];
  ++in.received;
  in.held.push_back(std::move(deliver));
  if (pending_)
    tryStep();
}

void Lockstep::stepCallback(const asv_msgs::LockstepStep::ConstPtr& msg) {
  if (std::find(msg->run.begin(), msg->run.end(), name_) == msg->run.end())
    return;
  if (msg->phase != 0 && !admitted_)
    return;
  if (pending_)
    ROS_WARN("%s: lockstep step %lu superseded by step %lu", name_.c_str(),
             static_cast<unsigned long>(pending_->step), static_cast<unsigned long>(msg->step));
  pending_ = msg;
  pending_since_ = ros::WallTime::now();
  tryStep();
}

bool Lockstep::inputsComplete(const asv_msgs::LockstepStep& s) const {
  for (std::size_t k = 0; k < s.topics.size() && k < s.counts.size(); ++k)
    for (const Input& in : inputs_)
      if (in.topic == s.topics[k] &&
          static_cast<int64_t>(in.received) + in.base < static_cast<int64_t>(s.counts[k]))
        return false;
  return true;
}

void Lockstep::tryStep() {
  if (!pending_) {
    retry_timer_.stop();
    return;
  }
  const asv_msgs::LockstepStep& s = *pending_;
  // /clock comes on its own connection, handled by roscpp's internal thread: the latest one sent is at
  // most a moment behind the step, so wait for it here (briefly) rather than through the callback queue.
  for (int i = 0; i < 2000 && s.phase != 0 && ros::Time::now() < s.clock && ros::ok(); ++i)
    ros::WallDuration(0.00005).sleep();
  // Phase 0 (admission) comes before any message of the step: nothing to wait for.
  bool ready = s.phase == 0 || (ros::Time::now() >= s.clock && inputsComplete(s));
  if (!ready && (ros::WallTime::now() - pending_since_).toSec() > timeout_) {
    ROS_ERROR("%s: lockstep step %lu: input or clock still missing after %.0f s; acting on what arrived",
              name_.c_str(), static_cast<unsigned long>(s.step), timeout_);
    ready = true;
  }
  if (!ready) {
    retry_timer_.start();
    return;
  }
  retry_timer_.stop();
  const asv_msgs::LockstepStep::ConstPtr step = pending_;
  pending_.reset();
  runStep(*step);
}

void Lockstep::runStep(const asv_msgs::LockstepStep& s) {
  if (s.phase == 0 || !inputsComplete(s)) {
    // Admission (or a late resynchronisation): from now on count from the publishers' totals.
    for (Input& in : inputs_)
      for (std::size_t k = 0; k < s.topics.size() && k < s.counts.size(); ++k)
        if (in.topic == s.topics[k])
          in.base = static_cast<int64_t>(s.counts[k]) - static_cast<int64_t>(in.received);
    if (s.phase == 0) {
      admitted_ = true;
      acknowledge(s, ros::Time());
      return;
    }
  }
  // The step's time is the node's time. sim_node sends /clock only once per simulated second (a /clock
  // at each step with work, to every node, was a third of a run's messages); every /clock sent before
  // this step has been taken (tryStep), so none can move the clock back.
  if (ros::Time::isSimTime() && ros::Time::now() < s.header.stamp)
    ros::Time::setNow(s.header.stamp);
  bool triggered = false;
  for (Input& in : inputs_) {
    std::vector<std::function<void()>> held;
    held.swap(in.held);
    triggered |= in.trigger && !held.empty();
    for (auto& deliver : held)
      deliver();
  }
  if (triggered)
    for (Job& j : jobs_)
      j.input = true;
  acknowledge(s, runJobs(s.header.stamp));
}

ros::Time Lockstep::runJobs(const ros::Time& t) {
  ros::Time next_due;
  for (Job& j : jobs_) {
    if (j.next.isZero())
      j.next = t;
    if (j.next <= t && (!j.only_with_input || j.input)) {
      j.run();
      j.input = false;
    }
    while (j.next <= t)
      j.next += j.period;
    if (j.only_with_input && !j.input)
      continue;  // nothing to do until new input
    if (next_due.isZero() || j.next < next_due)
      next_due = j.next;
  }
  return next_due;
}

void Lockstep::acknowledge(const asv_msgs::LockstepStep& s, const ros::Time& next_due) {
  asv_msgs::LockstepAck a;
  a.header.stamp = s.header.stamp;
  a.node = name_;
  a.step = s.step;
  a.phase = phase_;
  for (const auto& [topic, n] : published_) {
    a.topics.push_back(topic);
    a.counts.push_back(n);
  }
  a.next_due = next_due;
  ack_pub_.publish(a);
}

}  // namespace asv_ros
