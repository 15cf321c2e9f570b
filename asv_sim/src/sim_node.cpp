#include "asv_sim/sim_node.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <asv_msgs/LockstepStep.h>
#include <asv_msgs/NmeaSentence.h>
#include <asv_msgs/RiskAssessment.h>
#include <asv_msgs/SimEvent.h>
#include <asv_msgs/TargetArray.h>
#include <asv_ros/conversions.h>
#include <asv_ros/lockstep.h>
#include <asv_ros/params.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <rosgraph_msgs/Clock.h>
#include <visualization_msgs/MarkerArray.h>

namespace asv_sim {

namespace {

uint8_t toMsgType(asv::SimEvent::Type t) {
  switch (t) {
    case asv::SimEvent::Collision:
      return asv_msgs::SimEvent::COLLISION;
    case asv::SimEvent::NearMiss:
      return asv_msgs::SimEvent::NEAR_MISS;
    case asv::SimEvent::Grounding:
      return asv_msgs::SimEvent::GROUNDING;
    case asv::SimEvent::Arrival:
      break;
  }
  return asv_msgs::SimEvent::ARRIVAL;
}

}  // namespace

SimNodeParams loadParams(const ros::NodeHandle& pnh) {
  SimNodeParams p;
  static_cast<asv::SimNodeConfig&>(p) =
      asv_ros::loadConfig<asv::SimNodeConfig>(pnh, "asv_sim/config/sim_node.yaml");
  p.lockstep = asv_ros::lockstepEnabled();
  p.lockstep_timeout = asv_ros::lockstepTimeout();
  return p;
}

SimNode::SimNode(ros::NodeHandle nh, ros::NodeHandle pnh) : nh_(nh), pnh_(pnh), params_(loadParams(pnh)) {
  sim_ = std::make_unique<asv::Simulation>(asv::loadScenario(params_.scenario, params_.charts), params_.sim);
  // The scenario's origin is the simulator's own: a run's /map_origin that differs stops it.
  map_origin_ = std::make_unique<asv_ros::MapOrigin>(nh_, sim_->frame().origin());
  emitter_ = std::make_unique<asv::NmeaEmitter>(params_.emitter, params_.seed);
  if (params_.publish_clock)
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  nmea_pub_ = nh_.advertise<asv_msgs::NmeaSentence>("sim/nmea", 1000);
  ships_pub_ = nh_.advertise<asv_msgs::TargetArray>("sim/ships", 10);
  events_pub_ = nh_.advertise<asv_msgs::SimEvent>("sim/events", 100, true);
  markers_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("sim/markers", 2);
  land_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("sim/land", 1, true);
  summary_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("sim/summary", 2, true);
  publishLand();
  scene_box_ = asv::sceneBox(sim_->scenario());
  // Not under ~: the node's own parameters are only those of sim_node.yaml (a respawn checks them).
  nh_.setParam("sim/scene_box", std::vector<double>{scene_box_.min.x(), scene_box_.min.y(),
                                                    scene_box_.max.x(), scene_box_.max.y()});
  cmd_watch_ = asv::InputWatch(params_.watch);
  alarm_ = std::make_unique<asv_ros::AlarmReporter>(nh_);
  for (const auto& v : sim_->vessels()) {
    odom_pubs_.push_back(nh_.advertise<nav_msgs::Odometry>(v.name + "/odom", 50));
    if (v.own || v.behaviour == asv::Behaviour::Planner) {
      const std::string ship = v.name, topic = nh_.resolveName(ship + "/cmd");
      cmd_watch_.add(topic);
      cmd_subs_.push_back(nh_.subscribe<asv_msgs::CourseSpeedSetpoint>(
          topic, 10,
          [this, ship, topic](const asv_msgs::CourseSpeedSetpoint::ConstPtr& m) {
            cmdCallback(ship, topic, m);
          },
          ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay()));
    }
  }
  if (params_.emit_udp) {
    asv_ros::NmeaOutputConfig out;
    out.udp_host = params_.udp_host;
    out.udp_port = params_.udp_port;
    udp_out_ = std::make_unique<asv_ros::NmeaOutput>(out);
  }
  if (params_.rate == 0.0 && !params_.keep_up_topic.empty())
    keep_up_sub_ = nh_.subscribe<asv_msgs::RiskAssessment>(
        params_.keep_up_topic, 10, [this](const asv_msgs::RiskAssessment::ConstPtr& m) {
          const double t = m->header.stamp.toSec() - kEpoch;
          if (std::isfinite(t))
            keep_up_time_ = std::max(keep_up_time_, t);
        });
  if (params_.lockstep) {
    for (int phase : {asv_ros::kIngestion, asv_ros::kTracking, asv_ros::kRisk, asv_ros::kPlanning})
      stepPublisher(phase);
    ack_sub_ = nh_.subscribe("/lockstep/ack", 1000, &SimNode::lockstepAckCallback, this,
                             ros::TransportHints().tcpNoDelay());
  }
  updater_.setHardwareID("asv_sim");
  updater_.add("simulation", this, &SimNode::diagnose);
  ROS_INFO("sim_node: scenario '%s' (%zu ships, %.0f s), %s, seed %lu", sim_->scenario().name.c_str(),
           sim_->vessels().size(), sim_->scenario().duration,
           params_.lockstep   ? "lockstep"
           : params_.rate > 0 ? ("rate " + std::to_string(params_.rate)).c_str()
                              : "as fast as possible",
           static_cast<unsigned long>(params_.seed));
}

SimNode::~SimNode() = default;

void SimNode::cmdCallback(const std::string& ship, const std::string& topic,
                          const asv_msgs::CourseSpeedSetpoint::ConstPtr& msg) {
  ++cmds_received_[topic];
  cmd_watch_.received(topic, ros::Time::now().toSec(), asv_ros::wallNow());
  if (sim_->setSetpoint(ship, msg->course, msg->speed)) {
    ++cmds_ok_;
  } else {
    ++cmds_rejected_;
    ROS_WARN_THROTTLE(5.0, "sim_node: rejected set-point for '%s' (course %f rad, speed %f m/s)",
                      ship.c_str(), msg->course, msg->speed);
  }
}

void SimNode::watchCmds() {
  std::vector<asv::StaleInput> lost;
  for (const asv::StaleInput& s : cmd_watch_.stale(ros::Time::now().toSec(), asv_ros::wallNow()))
    if (cmd_watch_.everReceived(s.name))
      lost.push_back(s);
  alarm_->update(lost, "the ship holds her last set-point");
}

void SimNode::publishNmea(const std::vector<std::string>& lines, const ros::Time& stamp, const char* frame) {
  for (const auto& l : lines) {
    if (params_.emit_topic) {
      asv_msgs::NmeaSentence m;
      m.header.stamp = stamp;
      m.header.frame_id = frame;
      m.sentence = l;
      m.source = "sim";
      nmea_pub_.publish(m);
      lockstep_.published(nmea_pub_.getTopic());
    }
    if (udp_out_)
      udp_out_->send(l);
    ++nmea_sent_;
  }
}

void SimNode::publishState(bool odom, bool ships) {
  const ros::Time stamp(kEpoch + sim_->time());
  const auto& vs = sim_->vessels();
  asv_msgs::TargetArray arr;
  visualization_msgs::MarkerArray markers;
  arr.header.stamp = stamp;
  arr.header.frame_id = "map";
  for (size_t i = 0; i < vs.size(); ++i) {
    const asv::SimVessel& v = vs[i];
    const asv::VesselState& s = v.state();
    const double yaw = asv::courseToYaw(s.psi);
    if (odom) {
      nav_msgs::Odometry o;
      o.header.stamp = stamp;
      o.header.frame_id = "map";
      o.child_frame_id = v.name + "/base_link";
      o.pose.pose.position.x = s.x;
      o.pose.pose.position.y = s.y;
      o.pose.pose.orientation = asv_ros::yawToQuaternion(yaw);
      // REP 103 body frame: x forward, y left, z up; the core's sway is positive to starboard and its
      // yaw rate positive clockwise.
      o.twist.twist.linear.x = s.u;
      o.twist.twist.linear.y = -s.v;
      o.twist.twist.angular.z = -s.r;
      odom_pubs_[i].publish(o);
      lockstep_.published(odom_pubs_[i].getTopic());
      geometry_msgs::TransformStamped t;
      t.header = o.header;
      t.child_frame_id = o.child_frame_id;
      t.transform.translation.x = s.x;
      t.transform.translation.y = s.y;
      t.transform.rotation = o.pose.pose.orientation;
      tf_.sendTransform(t);
    }
    if (ships) {
      asv_msgs::Target t;
      t.id = v.name;
      t.mmsi = v.mmsi;
      t.name = v.name;
      t.position.x = s.x;
      t.position.y = s.y;
      const asv::GeoPoint g = sim_->frame().toGeodetic(v.position());
      t.has_geodetic = true;
      t.latitude = g.lat_deg;
      t.longitude = g.lon_deg;
      t.course_over_ground = v.cog();
      t.speed_over_ground = v.sog();
      const Eigen::Vector2d vel = s.velocity();
      t.velocity.x = vel.x();
      t.velocity.y = vel.y();
      t.has_heading = true;
      t.heading = s.psi;
      t.has_rate_of_turn = true;
      t.rate_of_turn = s.r;
      t.length = static_cast<float>(v.length);
      t.beam = static_cast<float>(v.beam);
      t.stamp = stamp;
      t.quality = 100;
      arr.targets.push_back(t);
      addShipMarkers(i, t, yaw, stamp, markers);
    }
  }
  if (ships) {
    ships_pub_.publish(arr);
    lockstep_.published(ships_pub_.getTopic());
    markers_pub_.publish(markers);
    publishSummary();
  }
}

void SimNode::publishEvents(size_t from) {
  const auto& ev = sim_->events();
  for (size_t i = from; i < ev.size(); ++i) {
    asv_msgs::SimEvent m;
    m.header.stamp = ros::Time(kEpoch + ev[i].time);
    m.header.frame_id = "map";
    m.type = toMsgType(ev[i].type);
    m.ship_a = ev[i].a;
    m.ship_b = ev[i].b;
    m.distance = ev[i].distance;
    events_pub_.publish(m);
    lockstep_.published(events_pub_.getTopic());
    if (ev[i].type == asv::SimEvent::Collision)
      ROS_ERROR("sim_node: COLLISION between %s and %s at t = %.1f s", ev[i].a.c_str(), ev[i].b.c_str(),
                ev[i].time);
    else if (ev[i].type == asv::SimEvent::Grounding)
      ROS_ERROR("sim_node: GROUNDING of %s on %s at t = %.1f s", ev[i].a.c_str(), ev[i].b.c_str(),
                ev[i].time);
    else
      ROS_INFO("sim_node: %s %s %s at t = %.1f s (%.0f m)", asv::toString(ev[i].type), ev[i].a.c_str(),
               ev[i].b.c_str(), ev[i].time, ev[i].distance);
  }
}

void SimNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  stat.add("sim time [s]", sim_->time());
  stat.add("real-time factor achieved", achieved_rtf_);
  stat.add("real-time factor requested", params_.rate);
  stat.add("keep-up waits timed out", keep_up_timeouts_);
  stat.add("lockstep", params_.lockstep);
  if (params_.lockstep) {
    stat.add("lockstep participants", lockstep_.participants());
    stat.add("lockstep rounds", lockstep_rounds_);
    stat.add("lockstep waits timed out", lockstep_timeouts_);
    stat.add("lockstep requests to join refused", lockstep_rejected_);
  }
  stat.add("set-points accepted", cmds_ok_);
  stat.add("set-points rejected", cmds_rejected_);
  stat.add("NMEA sentences sent", nmea_sent_);
  stat.add("min separation own [m]", sim_->minSeparationOwn());
  if (sim_->collided())
    stat.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "collision");
  else if (sim_->grounded())
    stat.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "grounding");
  else if (lockstep_timeouts_ > 0)
    stat.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "a lockstep participant did not answer in time");
  else if (lockstep_rejected_ > 0)
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "refused a lockstep request to join");
  else if (!params_.lockstep && params_.rate > 0.0 && achieved_rtf_ < 0.8 * params_.rate)
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "slower than the requested real-time factor");
  else
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "running");
  alarm_->diagnose(stat);
}

void SimNode::publishClock() {
  if (!params_.publish_clock)
    return;
  rosgraph_msgs::Clock c;
  c.clock = ros::Time(kEpoch + sim_->time());
  clock_pub_.publish(c);
  last_clock_ = c.clock;
}

int SimNode::run() {
  return params_.lockstep ? runLockstep() : runFreely();
}

bool SimNode::runOver() const {
  return sim_->finished() || (params_.max_sim_time > 0.0 && sim_->time() >= params_.max_sim_time);
}

int SimNode::everySteps(double rate) const {
  return std::max(1, static_cast<int>(std::lround(1.0 / (rate * params_.sim.dt))));
}

SimNode::Sentences SimNode::emitSensors() {
  Sentences s;
  emitter_->update(*sim_, s.ais, s.ttm);
  return s;
}

void SimNode::publishSensors(const Sentences& s) {
  const ros::Time stamp(kEpoch + sim_->time());
  publishNmea(s.ais, stamp, "ais");
  publishNmea(s.ttm, stamp, "radar");
}

bool SimNode::publishNewEvents() {
  if (sim_->events().size() <= events_done_)
    return false;
  publishEvents(events_done_);
  events_done_ = sim_->events().size();
  return params_.stop_on_collision && (sim_->collided() || sim_->grounded());
}

int SimNode::runFreely() {
  const ros::WallTime wait_until = ros::WallTime::now() + ros::WallDuration(params_.start_delay);
  while (ros::ok() && ros::WallTime::now() < wait_until) {
    publishClock();
    publishState(true, true);
    ros::spinOnce();
    ros::WallDuration(0.05).sleep();
  }
  const int odom_every = everySteps(params_.odom_rate), ships_every = everySteps(params_.ships_rate);
  const ros::WallTime wall_start = ros::WallTime::now();
  ros::WallTime last_diag = wall_start;
  long k = 0;
  while (ros::ok() && !runOver()) {
    publishSensors(emitSensors());
    sim_->step();
    ++k;
    publishClock();
    publishState(k % odom_every == 0, k % ships_every == 0);
    if (publishNewEvents())
      break;
    ros::spinOnce();
    watchCmds();
    const double wall = (ros::WallTime::now() - wall_start).toSec();
    achieved_rtf_ = wall > 0.0 ? sim_->time() / wall : 0.0;
    if (params_.rate > 0.0) {
      const double ahead = sim_->time() / params_.rate - wall;
      if (ahead > 0.0)
        ros::WallDuration(ahead).sleep();
    } else if (keep_up_sub_ && keep_up_time_ >= 0.0 && sim_->time() - keep_up_time_ > params_.keep_up_lead) {
      // As fast as the subscribers keep up: wait for the pipeline's output to catch up.
      const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(params_.keep_up_timeout);
      while (ros::ok() && sim_->time() - keep_up_time_ > params_.keep_up_lead) {
        if (ros::WallTime::now() > give_up) {
          ++keep_up_timeouts_;
          break;
        }
        ros::WallDuration(0.0005).sleep();
        ros::spinOnce();
      }
    }
    if ((ros::WallTime::now() - last_diag).toSec() >= 1.0) {
      updater_.force_update();
      last_diag = ros::WallTime::now();
    }
  }
  return finishRun();
}

// ---- lockstep ----

bool SimNode::waitFor(const std::function<bool()>& done, const char* what) {
  const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(params_.lockstep_timeout);
  while (ros::ok() && !done()) {
    if (ros::WallTime::now() > give_up) {
      ++lockstep_timeouts_;
      ROS_ERROR(
          "sim_node: lockstep at t = %.1f s: still waiting for %s after %.0f s; the run goes on without",
          sim_->time(), what, params_.lockstep_timeout);
      return false;
    }
    ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.01));
  }
  return true;
}

ros::Publisher& SimNode::stepPublisher(int phase) {
  auto it = step_pubs_.find(phase);
  if (it == step_pubs_.end())
    it = step_pubs_
             .emplace(phase, nh_.advertise<asv_msgs::LockstepStep>(asv_ros::lockstepStepTopic(phase), 100))
             .first;
  return it->second;
}

void SimNode::lockstepAckCallback(const asv_msgs::LockstepAck::ConstPtr& msg) {
  if (msg->hello) {
    std::vector<asv::LockstepInput> inputs;
    for (size_t i = 0; i < msg->inputs.size(); ++i)
      inputs.push_back({msg->inputs[i], i < msg->triggers.size() && msg->triggers[i]});
    if (!lockstep_.hello(msg->node, msg->phase, inputs)) {
      ++lockstep_rejected_;
      ROS_ERROR_THROTTLE(5.0,
                         "sim_node: lockstep: refused '%s' asking to join phase %d (a participant "
                         "has a name and a phase of 1 or more; phase 0 is admission)",
                         msg->node.c_str(), static_cast<int>(msg->phase));
      return;
    }
    ROS_INFO_ONCE("sim_node: lockstep participants are asking to join");
    stepPublisher(msg->phase);  // a participant of a phase the stack does not know: it asks again
    last_hello_[msg->node] = ros::WallTime::now();
    return;
  }
  if (msg->step != lockstep_round_step_ || !lockstep_waiting_.count(msg->node))
    return;  // a late answer to a round that timed out
  if (lockstep_round_phase_ == 0) {
    lockstep_.admit(msg->node);
  } else {
    std::map<std::string, uint64_t> outputs;
    for (size_t i = 0; i < msg->topics.size() && i < msg->counts.size(); ++i)
      outputs[msg->topics[i]] = msg->counts[i];
    lockstep_.acked(msg->node, outputs, static_cast<int64_t>(msg->next_due.toNSec()));
  }
  lockstep_waiting_.erase(msg->node);
}

bool SimNode::lockstepRound(uint64_t step, int phase, const std::vector<std::string>& run, bool wait) {
  if (state_step_ != step) {  // the participants act on the step's odometry
    state_step_ = step;
    if (odom_due_)
      publishState(true, false);
  }
  asv_msgs::LockstepStep m;
  m.header.stamp = ros::Time(kEpoch + sim_->time());
  m.clock = last_clock_;
  m.step = step;
  m.phase = static_cast<uint8_t>(phase);
  if (phase > 0)
    lockstep_.started(run);
  for (const auto& [topic, n] : lockstep_.totals()) {
    m.topics.push_back(topic);
    m.counts.push_back(n);
  }
  lockstep_round_step_ = step;
  lockstep_round_phase_ = phase;
  lockstep_waiting_ = std::set<std::string>(run.begin(), run.end());
  // Each participant hears its step on its own phase's topic (admissions included).
  std::map<int, std::vector<std::string>> by_phase;
  for (const auto& n : run)
    by_phase[lockstep_.phaseOf(n)].push_back(n);
  for (auto& [p, names] : by_phase) {
    m.run = names;
    stepPublisher(p).publish(m);
  }
  ++lockstep_rounds_;
  if (!wait)
    return true;
  const std::string what = "phase " + std::to_string(phase) + " of step " + std::to_string(step);
  return waitFor([this] { return lockstep_waiting_.empty(); }, what.c_str());
}

void SimNode::lockstepAdmit(uint64_t step) {
  const std::vector<std::string> newcomers = lockstep_.pendingAdmissions();
  if (newcomers.empty())
    return;
  for (const auto& n : newcomers)
    ROS_INFO("sim_node: lockstep participant %s joins at t = %.1f s", n.c_str(), sim_->time());
  lockstepRound(step, 0, newcomers, true);
}

void SimNode::lockstepPhases(uint64_t step, bool wait) {
  const int64_t t_ns = static_cast<int64_t>(ros::Time(kEpoch + sim_->time()).toNSec());
  for (int phase : lockstep_.phases()) {
    const std::vector<std::string> run = lockstep_.runners(phase, t_ns);
    if (!run.empty())
      lockstepRound(step, phase, run, wait);
  }
}

void SimNode::lockstepWaitForCmds() {
  // The set-points the planners published in this step are applied before the simulation moves on.
  waitFor(
      [this] {
        for (const auto& s : cmd_subs_)
          if (cmds_received_[s.getTopic()] < lockstep_.total(s.getTopic()))
            return false;
        return true;
      },
      "the planners' set-points");
}

void SimNode::lockstepStart() {
  std::vector<std::string> expected;
  for (const auto& n : params_.lockstep_participants)
    expected.push_back(ros::names::resolve(nh_.getNamespace(), n));
  ROS_INFO("sim_node: lockstep: waiting for %zu participants", expected.size());
  // A participant repeats its hello (every 0.2 s) while its inputs are connected to every publisher:
  // the first step waits until everyone has asked, then 0.5 s more with every hello still fresh, so
  // that no message of the run is lost to a node still connecting.
  ros::WallTime all_seen;
  waitFor(
      [&] {
        publishClock();
        const ros::WallTime now = ros::WallTime::now();
        for (const auto& n : expected)
          if (!last_hello_.count(n)) {
            all_seen = ros::WallTime();
            return false;
          }
        if (all_seen.isZero())
          all_seen = now;
        for (const auto& [n, t] : last_hello_)
          if ((now - t).toSec() > 0.5)
            return false;
        return (now - all_seen).toSec() > 0.5;
      },
      "the lockstep participants to start");
}

int SimNode::runLockstep() {
  lockstepStart();
  const int odom_every = everySteps(params_.odom_rate), ships_every = everySteps(params_.ships_rate);
  const int clock_every = params_.lockstep_clock_every_step ? 1 : everySteps(1.0);
  const ros::WallTime wall_start = ros::WallTime::now();
  ros::WallTime last_diag = wall_start;
  uint64_t k = 0;
  while (ros::ok() && !runOver()) {
    ++k;
    // Step k: the state and the sensors at t_k, then every stage's work, then the dynamics. /clock goes
    // out every simulated second (every step when recording), for the nodes' diagnostics timers, rviz
    // and rosbag; a participant takes its step's time from the step itself. Odometry and tf go out at
    // a step with work (and with /clock): a participant only reads the latest odometry at its step (it
    // wakes nobody), so at a step without work it would be read by none, and at every step it was most
    // of a run's messages. (lockstepRound sends it too, should this guess have missed a round.)
    const Sentences sentences = emitSensors();
    const int64_t t_ns = static_cast<int64_t>(ros::Time(kEpoch + sim_->time()).toNSec());
    odom_due_ = (k - 1) % odom_every == 0;
    const bool clock_due = (k - 1) % clock_every == 0;
    if (clock_due)
      publishClock();
    if (clock_due || !sentences.ais.empty() || !sentences.ttm.empty() || lockstep_.anyRunner(t_ns))
      state_step_ = k;
    lockstepAdmit(k);
    publishState(odom_due_ && state_step_ == k, (k - 1) % ships_every == 0);
    publishSensors(sentences);
    lockstepPhases(k, true);
    lockstepWaitForCmds();
    sim_->step();
    if (publishNewEvents())
      break;
    const double wall = (ros::WallTime::now() - wall_start).toSec();
    achieved_rtf_ = wall > 0.0 ? sim_->time() / wall : 0.0;
    if ((ros::WallTime::now() - last_diag).toSec() >= 1.0) {
      updater_.force_update();
      last_diag = ros::WallTime::now();
    }
  }
  // The final state and the events of the last step reach the evaluator in a last step.
  publishClock();
  publishState(true, true);
  odom_due_ = false;  // sent just now
  lockstepPhases(++k, true);
  ROS_INFO("sim_node: lockstep: %lu steps, %lu rounds, %lu timeouts", static_cast<unsigned long>(k),
           static_cast<unsigned long>(lockstep_rounds_), static_cast<unsigned long>(lockstep_timeouts_));
  return finishRun();
}

int SimNode::finishRun() {
  asv_msgs::SimEvent end;
  end.header.stamp = ros::Time(kEpoch + sim_->time());
  end.header.frame_id = "map";
  end.type = asv_msgs::SimEvent::END;
  end.distance = sim_->minSeparationOwn();
  events_pub_.publish(end);
  lockstep_.published(events_pub_.getTopic());
  ROS_INFO("sim_node: scenario '%s' ended at t = %.1f s: %s%s, min separation %.0f m, real-time factor %.1f",
           sim_->scenario().name.c_str(), sim_->time(), sim_->collided() ? "COLLISION" : "no collision",
           sim_->grounded() ? ", GROUNDING" : "", sim_->minSeparationOwn(), achieved_rtf_);
  // The evaluator takes the END event in one more step; it writes its result and leaves (below) without
  // answering.
  if (params_.lockstep)
    lockstepPhases(lockstep_round_step_ + 1, false);
  if (params_.shutdown_at_end) {
    // Let the last messages (END event, final state) reach the subscribers before leaving, and the node
    // named by linger_for (the evaluator) finish its work and leave. In lockstep every participant has
    // taken the final state, and the evaluator's leaving says it took the END event: a short floor (for
    // a recorder's buffers) is enough; free-running, nothing confirms delivery, so 1 s.
    const ros::WallTime start = ros::WallTime::now();
    const bool confirmed = params_.lockstep && !params_.linger_for.empty();
    const ros::WallTime linger = start + ros::WallDuration(confirmed ? 0.2 : 1.0);
    const ros::WallTime latest = start + ros::WallDuration(std::max(1.0, params_.linger_max));
    auto waiting = [&]() {
      const ros::WallTime now = ros::WallTime::now();
      if (now < linger)
        return true;
      if (params_.linger_for.empty() || now >= latest)
        return false;
      std::vector<std::string> nodes;
      if (!ros::master::getNodes(nodes))
        return false;
      return std::find(nodes.begin(), nodes.end(), params_.linger_for) != nodes.end();
    };
    while (ros::ok() && waiting()) {
      publishClock();
      ros::spinOnce();
      ros::WallDuration(0.05).sleep();
    }
    return 0;
  }
  ros::spin();
  return 0;
}

}  // namespace asv_sim
