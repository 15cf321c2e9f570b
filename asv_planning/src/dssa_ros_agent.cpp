#include "asv_planning/dssa_ros_agent.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <asv_core/common/units.h>
#include <asv_msgs/CourseSpeedSetpoint.h>
#include <asv_msgs/Plan.h>
#include <asv_ros/conversions.h>
#include <asv_ros/params.h>
#include <nav_msgs/Path.h>
#include <tf2/utils.h>

namespace asv_planning {

DssaExchangeParams DssaExchangeParams::fromParams(const asv::ParamMap& ex) {
  DssaExchangeParams p;
  p.topic = ex.getString("topic", p.topic);
  p.round_timeout = ex.getDouble("round_timeout", p.round_timeout);
  p.forget_after = ex.getDouble("forget_after", p.forget_after);
  p.arrival_radius = ex.getDouble("arrival_radius", p.arrival_radius);
  p.drop_outgoing_from = ex.getDouble("drop_outgoing_from", p.drop_outgoing_from);
  p.drop_outgoing_until = ex.getDouble("drop_outgoing_until", p.drop_outgoing_until);
  if (p.topic.empty())
    throw std::invalid_argument("~exchange/topic must not be empty");
  if (!(p.round_timeout > 0.0) || !(p.forget_after > 0.0) || !(p.arrival_radius >= 0.0))
    throw std::invalid_argument(
        "~exchange/: round_timeout and forget_after must be > 0, arrival_radius >= 0");
  return p;
}

DssaExchangeParams DssaExchangeParams::load(const ros::NodeHandle& pnh) {
  return asv_ros::loadConfig<DssaExchangeParams>(ros::NodeHandle(pnh, "exchange"),
                                                 "asv_planning/config/dssa.yaml");
}

namespace {

// ~exchange/, with the scenario's goal radius as the arrival radius when none is set: a ship that left
// the exchange farther out (a paper's scale) would no longer avoid anyone before she has arrived.
DssaExchangeParams exchangeParams(const ros::NodeHandle& pnh, const DssaRosOptions& options) {
  DssaExchangeParams p = DssaExchangeParams::load(pnh);
  if (options.goal_radius > 0.0 && !pnh.hasParam("exchange/arrival_radius"))
    p.arrival_radius = options.goal_radius;
  return p;
}

}  // namespace

bool DssaRosAgent::wanted(const std::string& planner, bool distributed) {
  // Off by default: an agent sees only ships that exchange intentions, so against ordinary traffic
  // (AIS/radar targets) the single-ship plugin is the safe choice. agents.launch turns it on.
  return distributed && (planner == "dssa" || planner == "dssa_plus");
}

asv::DssaConfig DssaRosAgent::configOf(const asv::PlannerAlgorithm& plugin) {
  // The loaded plugin's parameters (its sea-scale defaults and the node's keys), read as the plugin's
  // DssaPlanner reads them: the agents plan exactly as the plugin would.
  const std::string name = plugin.name();
  if (name != "dssa" && name != "dssa_plus")
    throw std::invalid_argument("distributed DSSA needs the dssa or dssa_plus plugin, not '" + name + "'");
  return asv::DssaConfig::fromParams(plugin.parameters(), name);
}

int DssaRosAgent::shipId(const std::string& name) {
  uint32_t h = 2166136261u;
  for (unsigned char c : name) {
    h ^= c;
    h *= 16777619u;
  }
  return static_cast<int>(h & 0x7fffffffu);
}

namespace {
asv::DssaShipSpeeds shipSpeeds(const asv::DssaConfig& c, const DssaRosOptions& o) {
  return asv::dssaShipSpeeds(c, o.cruise_speed, o.min_speed, o.max_speed);
}
}  // namespace

DssaRosAgent::DssaRosAgent(const ros::NodeHandle& nh, const ros::NodeHandle& pnh,
                           const asv::DssaConfig& config, const DssaRosOptions& options)
    : nh_(nh),
      config_(config),
      opt_(options),
      ex_(exchangeParams(pnh, options)),
      id_(shipId(options.ship)),
      agent_(id_, config, shipSpeeds(config, options)),
      rng_(asv::dssaAgentSeed(static_cast<uint64_t>(options.seed), id_)),
      updater_(nh, pnh),
      spinner_(1, &queue_) {
  nh_.setCallbackQueue(&queue_);
  const auto hints = ros::TransportHints().tcpNoDelay();
  odom_sub_ = nh_.subscribe("odom", 10, &DssaRosAgent::odomCallback, this, hints);
  intention_sub_ = nh_.subscribe(ex_.topic, 200, &DssaRosAgent::intentionCallback, this, hints);
  intention_pub_ = nh_.advertise<asv_msgs::Intention>(ex_.topic, 200);
  cmd_pub_ = nh_.advertise<asv_msgs::CourseSpeedSetpoint>("cmd", 5);
  resend_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { resendCommand(); });
  plan_pub_ = nh_.advertise<asv_msgs::Plan>("plan", 5, true);
  path_pub_ = nh_.advertise<nav_msgs::Path>("path", 5, true);
  updater_.setHardwareID(opt_.ship);
  updater_.add("dssa exchange", this, &DssaRosAgent::diagnose);
  spinner_.start();
  worker_ = std::thread([this] { run(); });
  ROS_INFO(
      "planner_node: ship '%s' (id %d) runs distributed %s on %s: step %.1f s, detection range %.0f m, "
      "round timeout %.2f s, goal %s",
      opt_.ship.c_str(), id_, config_.speed_changes ? "DSSA+" : "DSSA", intention_sub_.getTopic().c_str(),
      config_.time_step, config_.detection_range, ex_.round_timeout, opt_.has_goal ? "set" : "none");
}

DssaRosAgent::~DssaRosAgent() {
  stop_ = true;
  cv_.notify_all();
  if (worker_.joinable())
    worker_.join();
  spinner_.stop();
}

void DssaRosAgent::odomCallback(const nav_msgs::Odometry::ConstPtr& msg) {
  asv::ShipState s;
  const asv_ros::Reject why = asv_ros::odometryToShipState(*msg, opt_.ship, s);
  if (why != asv_ros::Reject::None) {
    ROS_WARN_THROTTLE(5.0, "planner_node: odometry ignored (%s)", asv_ros::toString(why));
    return;
  }
  const double t = msg->header.stamp.isZero() ? ros::Time::now().toSec() : msg->header.stamp.toSec();
  std::lock_guard<std::mutex> lock(mu_);
  own_ = std::make_pair(s, t);
}

void DssaRosAgent::intentionCallback(const asv_msgs::Intention::ConstPtr& msg) {
  if (msg->ship_id == opt_.ship || msg->ship_id.empty())
    return;
  if (!asv::allFinite({msg->course, msg->speed, msg->speed_change, msg->position.x, msg->position.y,
                       msg->velocity.x, msg->velocity.y})) {
    ROS_WARN_THROTTLE(5.0, "planner_node: non-finite intention of '%s' ignored", msg->ship_id.c_str());
    return;
  }
  asv::DssaIntention in;
  in.id = shipId(msg->ship_id);
  in.round = static_cast<int>(msg->round);
  in.stamp = msg->header.stamp.toSec();
  in.course = msg->course;
  in.speed_change = msg->speed_change;
  in.speed = msg->speed;
  in.position = {msg->position.x, msg->position.y};
  in.velocity = {msg->velocity.x, msg->velocity.y};
  in.satisfied = msg->satisfied;
  {
    std::lock_guard<std::mutex> lock(mu_);
    if (msg->leaving && !peers_.count(in.id))
      return;  // gone already (a leaving ship repeats it every step)
    Peer& p = peers_[in.id];
    p.name = msg->ship_id;
    p.heard = ros::Time::now();
    p.responsive = true;
    p.leaving = msg->leaving;
    ++received_;
    if (!msg->leaving) {
      p.last = in;
      p.last_phase = msg->phase;
      p.last_round = msg->round;
      p.inbox[{msg->phase, msg->round}] = in;
      if (msg->search_done)
        p.done_phase = msg->phase;
    }
  }
  cv_.notify_all();
}

void DssaRosAgent::run() {
  const double step = config_.time_step;
  int64_t last_phase = -1;
  while (!stop_ && ros::ok()) {
    const double now = ros::Time::now().toSec();
    const int64_t phase = static_cast<int64_t>(std::floor(now / step));
    if (now <= 0.0 || phase == last_phase) {
      // Wait for the next control step (ROS time, which follows /clock in a simulation).
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      continue;
    }
    last_phase = phase;
    searchPhase(static_cast<uint32_t>(phase), (phase + 1) * step);
    updater_.update();
  }
}

void DssaRosAgent::forgetStale(double now) {
  std::lock_guard<std::mutex> lock(mu_);
  for (auto it = peers_.begin(); it != peers_.end();) {
    if (it->second.leaving || now - it->second.heard.toSec() > ex_.forget_after) {
      ROS_INFO("planner_node: '%s' forgets '%s' (%s)", opt_.ship.c_str(), it->second.name.c_str(),
               it->second.leaving ? "it left the exchange" : "not heard from");
      agent_.forget(it->first);
      it = peers_.erase(it);
    } else {
      ++it;
    }
  }
}

void DssaRosAgent::searchPhase(uint32_t phase, double step_end) {
  std::optional<std::pair<asv::ShipState, double>> own;
  {
    std::lock_guard<std::mutex> lock(mu_);
    own = own_;
  }
  if (!own) {
    ROS_WARN_THROTTLE(10.0, "planner_node: waiting for odometry on %s", odom_sub_.getTopic().c_str());
    return;
  }
  const asv::ShipState& s = own->first;
  const double t_state = own->second;
  const Eigen::Vector2d goal =
      opt_.has_goal ? opt_.goal : Eigen::Vector2d(s.position + asv::courseSpeedToVelocity(s.course, 20000.0));
  own_course_ = s.course;
  forgetStale(ros::Time::now().toSec());

  agent_.setOwn(s, goal, t_state);
  if (opt_.has_goal && (goal - s.position).norm() <= ex_.arrival_radius) {
    // Arrived: leave the exchange (the others forget this ship), or stay in it as a stopped ship, and steer
    // straight for the goal (the simulator stops her there).
    if (opt_.stays_at_goal)
      publishIntention(asv::dssaStationaryShip(agent_.id(), s.position, s.course, t_state), phase, true,
                       false);
    else
      publishIntention(agent_.intention(), phase, true, true);
    if (!left_)
      ROS_INFO("planner_node: '%s' is within %.0f m of its goal: %s", opt_.ship.c_str(), ex_.arrival_radius,
               opt_.stays_at_goal ? "stays there, a stopped ship to the others" : "leaves the exchange");
    left_ = true;
    publishCommand(asv::courseOf(goal - s.position), opt_.cruise_speed > 0.0 ? opt_.cruise_speed : s.speed,
                   0.0, 0, true);
    return;
  }
  left_ = false;

  const auto wall_start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  };
  // Fig. 2, first box: the current course and speed are the intention of round 0.
  publishIntention(agent_.intention(), phase, false, false);
  Round rd = collect(phase, 0, s.position, t_state);
  int rounds = 0, awaited = rd.awaited;
  bool quiescent = false;
  for (int r = 1; r <= config_.max_rounds && !stop_ && ros::ok(); ++r) {
    const asv::DssaIntention in = agent_.decide(r, rng_);
    publishIntention(in, phase, false, false);
    rd = collect(phase, static_cast<uint32_t>(r), s.position, t_state);
    rounds = r;
    awaited = std::max(awaited, rd.awaited);
    if (agent_.satisfied() && rd.all_satisfied) {
      quiescent = true;
      break;
    }
    if ((config_.max_search_time > 0.0 && elapsed() >= config_.max_search_time) ||
        ros::Time::now().toSec() >= step_end)
      break;
  }
  // The search is over for this ship: a neighbour still waiting for a later round stops waiting.
  publishIntention(agent_.intention(), phase, true, false);
  neighbours_ = agent_.neighbourCount();
  const double t = elapsed();
  ++phases_;
  rounds_total_ += static_cast<uint64_t>(rounds);
  quiescent_ += quiescent ? 1 : 0;
  last_rounds_ = rounds;
  max_rounds_seen_ = std::max(max_rounds_seen_, rounds);
  last_search_time_ = t;
  max_search_time_ = std::max(max_search_time_, t);
  const asv::DssaIntention& in = agent_.intention();
  ROS_DEBUG(
      "planner_node: '%s' phase %u: %d round(s)%s, %d neighbour(s) (%d awaited), course %.1f deg, speed "
      "%.2f m/s, %.1f ms",
      opt_.ship.c_str(), phase, rounds, quiescent ? " to quiescence" : "", neighbours_, awaited,
      asv::radToDeg(in.course), in.speed, t * 1e3);
  publishCommand(in.course, in.speed, t, rounds, quiescent);
}

DssaRosAgent::Round DssaRosAgent::collect(uint32_t phase, uint32_t round, const Eigen::Vector2d& own_position,
                                          double now) {
  Round rd;
  const auto key = std::make_pair(phase, round);
  std::unique_lock<std::mutex> lock(mu_);
  // Whom to wait for: neighbours in the detection range (last known intention carried forward to now),
  // responsive, still searching in this phase and not already in a later one.
  auto inRange = [&](const Peer& p) {
    const Eigen::Vector2d pos = p.last.position + p.last.intendedVelocity() * (now - p.last.stamp);
    return !p.leaving && (pos - own_position).norm() <= config_.detection_range;
  };
  auto awaited = [&](const Peer& p) {
    return inRange(p) && p.responsive && !(p.done_phase && *p.done_phase == phase) && p.last_phase <= phase;
  };
  auto complete = [&] {
    if (stop_)
      return true;
    for (const auto& kv : peers_)
      if (awaited(kv.second) && !kv.second.inbox.count(key))
        return false;
    return true;
  };
  for (const auto& kv : peers_)
    rd.awaited += awaited(kv.second) ? 1 : 0;
  cv_.wait_for(lock, std::chrono::duration<double>(ex_.round_timeout), complete);
  for (auto& kv : peers_) {
    Peer& p = kv.second;
    auto it = p.inbox.find(key);
    if (it != p.inbox.end()) {
      agent_.receive(it->second);
      if (inRange(p)) {  // a ship out of range is no neighbour: its satisfaction does not matter here
        rd.all_satisfied = rd.all_satisfied && it->second.satisfied;
        ++rd.answered;
      }
    } else if (awaited(p)) {
      // Missed the round: its last known intention stands, and it is not awaited until heard again.
      p.responsive = false;
      ++rd.timeouts;
      ++round_timeouts_;
      ROS_WARN_THROTTLE(2.0, "planner_node: '%s': no intention of '%s' for phase %u round %u within %.2f s",
                        opt_.ship.c_str(), p.name.c_str(), phase, round, ex_.round_timeout);
    } else if (p.done_phase && *p.done_phase == phase) {
      agent_.receive(p.last);  // its final intention of this phase
    }
    // Rounds up to this one are consumed; later ones wait for their round.
    p.inbox.erase(p.inbox.begin(), p.inbox.upper_bound(key));
  }
  return rd;
}

void DssaRosAgent::publishIntention(const asv::DssaIntention& in, uint32_t phase, bool done, bool leaving) {
  const double now = ros::Time::now().toSec();
  if (ex_.drop_outgoing_until > ex_.drop_outgoing_from && now >= ex_.drop_outgoing_from &&
      now < ex_.drop_outgoing_until) {
    ++dropped_;
    return;
  }
  asv_msgs::Intention m;
  m.header.stamp = ros::Time(in.stamp);
  m.header.frame_id = opt_.frame_id;
  m.ship_id = opt_.ship;
  m.round = static_cast<uint32_t>(std::max(in.round, 0));
  m.phase = phase;
  m.course = in.course;
  m.course_change = asv::wrapPi(in.course - own_course_);
  m.speed_change = in.speed_change;
  m.speed = in.speed;
  m.position.x = in.position.x();
  m.position.y = in.position.y();
  const Eigen::Vector2d v = in.intendedVelocity();
  m.velocity.x = v.x();
  m.velocity.y = v.y();
  m.satisfied = in.satisfied;
  m.search_done = done;
  m.leaving = leaving;
  intention_pub_.publish(m);
  ++sent_;
}

void DssaRosAgent::resendCommand() {
  std::lock_guard<std::mutex> lock(cmd_mu_);
  if (!last_cmd_)
    return;
  last_cmd_->header.stamp = ros::Time::now();
  cmd_pub_.publish(*last_cmd_);
}

void DssaRosAgent::publishCommand(double course, double speed, double search_time, int rounds,
                                  bool quiescent) {
  if (!std::isfinite(course) || !std::isfinite(speed))
    return;
  course_sp_ = asv::wrapTwoPi(course);
  speed_sp_ = std::clamp(speed, 0.0, opt_.max_speed);
  const ros::Time now = ros::Time::now();
  asv_msgs::CourseSpeedSetpoint sp;
  sp.header.stamp = now;
  sp.header.frame_id = opt_.frame_id;
  sp.course = course_sp_;
  sp.speed = speed_sp_;
  cmd_pub_.publish(sp);
  {
    std::lock_guard<std::mutex> lock(cmd_mu_);
    last_cmd_ = sp;
  }

  // The intention as a plan: where the ship will be after one TimeWindow on it.
  asv_msgs::Plan plan;
  plan.header = sp.header;
  plan.ship = opt_.ship;
  plan.planner = config_.speed_changes ? "dssa_plus" : "dssa";
  plan.status = asv_msgs::Plan::STATUS_OK;
  nav_msgs::Path path;
  path.header = sp.header;
  const Eigen::Vector2d p0 = agent_.position();
  const Eigen::Vector2d p1 = p0 + asv::courseSpeedToVelocity(course_sp_, speed_sp_) * config_.time_window;
  for (int i = 0; i < 2; ++i) {
    asv_msgs::PlanWaypoint w;
    const Eigen::Vector2d& p = i == 0 ? p0 : p1;
    w.position.x = p.x();
    w.position.y = p.y();
    w.time = i == 0 ? 0.0 : config_.time_window;
    w.course = course_sp_;
    w.speed = speed_sp_;
    plan.waypoints.push_back(w);
    geometry_msgs::PoseStamped ps;
    ps.header = sp.header;
    ps.header.stamp = now + ros::Duration(w.time);
    ps.pose.position = w.position;
    ps.pose.orientation = asv_ros::yawToQuaternion(asv::courseToYaw(course_sp_));
    path.poses.push_back(ps);
  }
  plan.course_setpoint = course_sp_;
  plan.speed_setpoint = speed_sp_;
  plan.cost = left_ ? 0.0
                    : agent_.cost(asv::wrapPi(agent_.intention().course - own_course_),
                                  agent_.intention().speed_change);
  if (!std::isfinite(plan.cost))
    plan.cost = 0.0;
  plan.compute_time = search_time;
  plan.message = left_ ? "arrived: left the exchange, straight for the goal"
                       : std::to_string(rounds) + " round(s)" + (quiescent ? " to quiescence" : " (limit)") +
                             ", " + std::to_string(neighbours_) + " neighbour(s)";
  plan_pub_.publish(plan);
  path_pub_.publish(path);
}

void DssaRosAgent::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  uint64_t received = 0;
  size_t peers = 0;
  {
    std::lock_guard<std::mutex> lock(mu_);
    received = received_;
    peers = peers_.size();
  }
  stat.add("ship id", id_);
  stat.add("search phases", phases_);
  stat.add("rounds per search (mean)", phases_ ? static_cast<double>(rounds_total_) / phases_ : 0.0);
  stat.add("rounds in the last search", last_rounds_);
  stat.add("most rounds in a search", max_rounds_seen_);
  stat.add("searches ended by quiescence", quiescent_);
  stat.add("round timeouts", round_timeouts_);
  stat.add("neighbours in range", neighbours_);
  stat.add("ships heard", peers);
  stat.add("intentions sent", sent_);
  stat.add("intentions received", received);
  stat.add("intentions dropped (test window)", dropped_);
  stat.add("last search wall time [s]", last_search_time_);
  stat.add("max search wall time [s]", max_search_time_);
  stat.add("course set-point [deg]", asv::radToDeg(course_sp_));
  stat.add("speed set-point [m/s]", speed_sp_);
  if (left_)
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "arrived: left the exchange");
  else if (round_timeouts_ > 0)
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                 "rounds timed out (lost intentions or silent ships)");
  else
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, phases_ ? "searching" : "waiting");
}

}  // namespace asv_planning
