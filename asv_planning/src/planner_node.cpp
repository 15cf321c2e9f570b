#include "asv_planning/planner_node.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include <asv_core/world/scenario.h>
#include <asv_msgs/CourseSpeedSetpoint.h>
#include <asv_msgs/Plan.h>
#include <asv_ros/conversions.h>
#include <asv_ros/params.h>
#include <nav_msgs/Path.h>
#include <tf2/utils.h>
#include <visualization_msgs/MarkerArray.h>

namespace asv_planning {

namespace {

constexpr const char* kYaml = "asv_planning/config/planner_node.yaml";

// The subtrees under ~ that are not the node's keys: every declared planner's own ~<planner>/ (a live
// switch may load any of them) and DssaRosAgent's exchange/.
std::vector<std::string> otherSubtrees() {
  std::vector<std::string> skip{"exchange/"};
  for (const std::string& p : PluginLoader().parameterNames())
    skip.push_back(p + "/");
  return skip;
}

// PlannerNodeConfig::fromParams, naming a typo first when it fails with every key read.
asv::PlannerNodeConfig plannerConfig(const asv::ParamMap& params) {
  try {
    return asv::PlannerNodeConfig::fromParams(params);
  } catch (const std::invalid_argument&) {
    asv_ros::rejectTypoBehindError(params, kYaml, otherSubtrees());
    throw;
  }
}

// The plan follower's settings. In lockstep a plan costs no simulated time: the budget only guards
// against a plugin that never returns, and plugins that stop at their budget give the same plan on
// any machine. Paper mode switches the follower's sea extensions off, and the replanning on rising risk of
// a method that plans once (applyPlannerMode).
asv::PlanFollowerConfig followerConfig(const asv::PlannerNodeConfig& p, bool lockstep,
                                       const std::string& mode, const asv::PlannerAlgorithm& plugin) {
  asv::PlanFollowerConfig fc = p.follower;
  if (lockstep)
    fc.time_budget = p.lockstep_time_budget;
  asv::applyPlannerMode(fc, asv::parsePlannerMode(mode, p.planner), plugin.plansOnce(), plugin.ownTrigger());
  return fc;
}

// The tracks as the planners see them, through the checks every node applies to a target (the tracker
// has checked its values; one that fails now is dropped and logged).
std::vector<asv::ShipState> trackStates(const asv_msgs::TargetArray& targets) {
  std::vector<asv::ShipState> tracks;
  for (const auto& t : targets.targets) {
    asv::ShipState s;
    const asv_ros::Reject why = asv_ros::targetToShipState(t, s);
    if (why == asv_ros::Reject::None)
      tracks.push_back(s);
    else
      ROS_WARN_THROTTLE(5.0, "planner_node: track '%s' ignored (%s)", t.id.c_str(), asv_ros::toString(why));
  }
  return tracks;
}

using AssessedTargets = std::map<std::string, asv::PlannerTarget>;

// The risk fields of each assessed target, by id (selectPlannerTargets adds the tracks).
AssessedTargets assessedBy(const asv_msgs::RiskAssessment& risk) {
  AssessedTargets assessed;
  for (const auto& r : risk.targets)
    if (!asv_ros::riskFromMsg(r, assessed[r.target_id]))
      ROS_WARN_THROTTLE(5.0,
                        "planner_node: target '%s': unknown encounter %u in the risk picture, taken as none",
                        r.target_id.c_str(), static_cast<unsigned>(r.encounter));
  return assessed;
}

}  // namespace

PlannerNode::PlannerNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : PlannerNode(nh, pnh, asv_ros::readParams(pnh)) {}

// The node's private parameters (config/planner_node.yaml) and the plugin's: the plugin's own subtree
// ~<planner>/ over the scenario's planner_params (the plugin checks its keys); ~exchange/ is
// DssaRosAgent's.
PlannerNode::PlannerNode(ros::NodeHandle nh, ros::NodeHandle pnh, const asv::ParamMap& params)
    : nh_(nh), pnh_(pnh), params_(plannerConfig(params)), node_params_(params) {
  asv::PlannerNodeConfig& p = params_;
  applyScenario();
  asv_ros::rejectUnknown(params, kYaml, otherSubtrees());
  if (p.planner.empty() || p.planner == "none") {
    ROS_INFO("planner_node: no planner for ship '%s': it steers straight for its goal", p.ship.c_str());
    lockstep_.start();  // nothing to do at any step, but the simulation waits for every participant
    return;
  }
  asv::OwnShipLimits& limits = p.follower.limits;
  if (p.follower.cruise_speed > limits.max_speed) {
    ROS_WARN("planner_node: cruise speed %.1f m/s above max_speed %.1f m/s: max_speed raised to it",
             p.follower.cruise_speed, limits.max_speed);
    limits.max_speed = p.follower.cruise_speed;
  }
  mode_ = pluginParams(p.planner).getString("mode", mode_);
  plugin_ = loader_.load(p.planner, pluginParams(p.planner));
  if (DssaRosAgent::wanted(p.planner, p.distributed)) {  // distributed DSSA: the agent drives cmd
    const asv::PlanFollowerConfig& f = p.follower;
    dssa_ = std::make_unique<DssaRosAgent>(
        nh_, pnh_, DssaRosAgent::configOf(*plugin_),
        DssaRosOptions{p.ship, p.frame_id, p.has_goal, p.goal, f.cruise_speed, f.limits.min_speed,
                       f.limits.max_speed, f.seed, scenario_goal_radius_, scenario_stays_at_goal_});
    lockstep_.start();  // the distributed agents keep their own timing (agents.launch, not lockstep)
    return;
  }
  follower_config_ = followerConfig(p, lockstep_.enabled(), mode_, *plugin_);
  follower_ = std::make_unique<asv::PlanFollower>(follower_config_);  // validates: throws on a bad value
  if (!scenario_route_.empty())
    route_ = scenario_route_;
  if (!route_.empty())
    follower_->setRoute(route_);
  else if (p.has_goal)
    follower_->setGoal(p.goal);
  follower_->setObstacles(allObstacles());
  start();
}

// The scenario's part, when one is given: the obstacles, this ship's goal, cruise speed and minimum
// separation where the parameters leave them open, the planner when none is given (the scenario's
// choice for this ship), and the scenario's parameters of that planner.
void PlannerNode::applyScenario() {
  asv::PlannerNodeConfig& p = params_;
  if (p.scenario.empty())
    return;
  const asv::Scenario sc = asv::loadScenario(p.scenario, p.charts);
  obstacles_ = sc.obstacles;
  scenario_planners_ = sc.planner_params;
  scenario_min_separation_ = sc.min_separation;
  const asv::ScenarioShip* ship = sc.own.name == p.ship ? &sc.own : nullptr;
  for (const auto& t : sc.targets)
    if (t.name == p.ship)
      ship = &t;
  if (!ship)
    throw std::invalid_argument("ship '" + p.ship + "' is not in scenario " + p.scenario);
  if (!p.has_goal && ship->goal) {
    p.goal = *ship->goal;
    p.has_goal = true;
    scenario_route_ = ship->route;  // the voyage plan, unless goal_x/goal_y name another goal
  }
  if (p.follower.cruise_speed <= 0.0)
    p.follower.cruise_speed = ship->speed;
  if (p.follower.min_separation <= 0.0)
    p.follower.min_separation = sc.min_separation;  // the scenario's safety.min_separation_m
  if (sc.min_obstacle_clearance > 0.0)
    p.follower.min_obstacle_clearance_m = sc.min_obstacle_clearance;  // the waters' own (a port)
  scenario_planner_ = ship->planner;
  scenario_goal_radius_ = ship->goal_radius;
  scenario_stays_at_goal_ = ship->stays_at_goal;
  if (p.planner.empty())
    p.planner = ship->planner;
}

// A plugin's parameters: the node's ~<planner>/ over the scenario's planner_params (the plugin checks
// its keys).
asv::ParamMap PlannerNode::pluginParams(const std::string& planner) const {
  const std::string key = PluginLoader::parameterName(planner);
  asv::ParamMap m = scenario_planners_.sub(key);
  m.merge(node_params_.sub(key));
  if (!params_.mode.empty())
    m.set("mode", params_.mode);  // the node's ~mode over the plugin's own
  return m;
}

// The inputs are read at the set-point job (lockstep: the step's odometry, risk and tracks first).
void PlannerNode::start() {
  odom_sub_ = lockstep_.subscribe("odom", 10, &PlannerNode::odomCallback, this, false);
  risk_sub_ = lockstep_.subscribe("risk", 10, &PlannerNode::riskCallback, this, false);
  targets_sub_ = lockstep_.subscribe("targets", 10, &PlannerNode::targetsCallback, this, false);
  goal_sub_ = nh_.subscribe("goal", 1, &PlannerNode::goalCallback, this);
  route_sub_ = nh_.subscribe("route", 1, &PlannerNode::routeCallback, this);
  alarms_sub_ = nh_.subscribe("alarms", 50, &PlannerNode::alarmCallback, this);
  if (params_.use_aids)
    aids_sub_ = nh_.subscribe("aids_to_navigation", 1, &PlannerNode::aidsCallback, this);
  watch_ = asv::InputWatch(params_.watch);
  for (const ros::Subscriber* s : {&odom_sub_, &risk_sub_, &targets_sub_})
    watch_.add(s->getTopic());
  alarm_ = std::make_unique<asv_ros::AlarmReporter>(nh_);
  plan_pub_ = nh_.advertise<asv_msgs::Plan>("plan", 5, true);
  path_pub_ = nh_.advertise<nav_msgs::Path>("path", 5, true);
  cmd_pub_ = nh_.advertise<asv_msgs::CourseSpeedSetpoint>("cmd", 5);
  markers_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("plan_markers", 2, true);
  domains_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("domains", 2);
  route_markers_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("route_markers", 1, true);
  route_status_pub_ = nh_.advertise<asv_msgs::RouteStatus>("route_status", 5);
  active_route_pub_ = nh_.advertise<nav_msgs::Path>("active_route", 1, true);
  publishRoute();
  lockstep_.every(1.0 / params_.setpoint_rate, [this] { timerCallback(); });
  if (!lockstep_.enabled())  // a lost input is acted on between set-points too
    lockstep_.every(asv_ros::kWatchPeriod, [this] { watchJob(); });
  lockstep_.start();
  updater_.setHardwareID(params_.ship);
  updater_.add("planner", this, &PlannerNode::diagnose);
  live_ = std::make_unique<dynamic_reconfigure::Server<PlannerConfig>>(pnh_);
  live_->setCallback([this](PlannerConfig& c, uint32_t level) { reconfigure(c, level); });
  ROS_INFO("planner_node: ship '%s', planner '%s', goal %s, budget %.2f s", params_.ship.c_str(),
           params_.planner.c_str(), params_.has_goal ? "set" : "none", follower_config_.time_budget);
}

std::vector<asv::StaticObstacle> PlannerNode::allObstacles() const {
  std::vector<asv::StaticObstacle> all = obstacles_;
  all.insert(all.end(), aid_obstacles_.begin(), aid_obstacles_.end());
  return all;
}

void PlannerNode::aidsCallback(const asv_msgs::AidToNavigationArray::ConstPtr& msg) {
  if (msg->header.frame_id != params_.frame_id) {
    ROS_WARN_THROTTLE(10.0, "planner_node: aids_to_navigation in frame '%s', not '%s': ignored",
                      msg->header.frame_id.c_str(), params_.frame_id.c_str());
    return;
  }
  const double radius =
      asv::pointHazardRadius(params_.aid_clearance, follower_config_.min_obstacle_clearance_m);
  std::vector<asv::StaticObstacle> hazards;
  for (const auto& a : msg->aids) {
    const Eigen::Vector2d p(a.position.x, a.position.y);
    if (p.allFinite())
      hazards.push_back(asv::pointHazard("aid:" + std::to_string(a.mmsi), p, radius));
  }
  auto same = [](const asv::StaticObstacle& x, const asv::StaticObstacle& y) {
    return x.name == y.name && x.polygon == y.polygon;
  };
  if (std::equal(hazards.begin(), hazards.end(), aid_obstacles_.begin(), aid_obstacles_.end(), same))
    return;  // republished unchanged (every aids/publish_period)
  ROS_INFO("planner_node: %zu aids to navigation kept clear of by %.0f m", hazards.size(),
           std::max(params_.aid_clearance, follower_config_.min_obstacle_clearance_m));
  aid_obstacles_ = std::move(hazards);
  follower_->setObstacles(allObstacles());
}

void PlannerNode::checkClock() {
  asv_ros::resetOnClockJump(clock_, updater_, ros::Time::now(), [this] {
    own_.reset();
    watch_.reset();
    upstream_alarms_.clear();
    first_input_ = -1.0;
    risk_.reset();
    targets_.reset();
    follower_ = std::make_unique<asv::PlanFollower>(follower_config_);
    if (!route_.empty())
      follower_->setRoute(route_);  // sailed again from the leg nearest to her
    else if (params_.has_goal)
      follower_->setGoal(params_.goal);
    follower_->setObstacles(allObstacles());
    return std::string("own ship, targets, risk and plan dropped");
  });
}

void PlannerNode::odomCallback(const nav_msgs::Odometry::ConstPtr& msg) {
  checkClock();
  // Odometry in another frame (a GNSS/INS driver's odom or utm) is moved into map; no frame is map.
  tf2::Transform t;
  if (!msg->header.frame_id.empty() && !frames_.get(msg->header.frame_id, msg->header.stamp, t)) {
    ROS_WARN_THROTTLE(5.0,
                      "planner_node: odometry in frame '%s', which tf2 does not connect to '%s': ignored",
                      msg->header.frame_id.c_str(), params_.frame_id.c_str());
    return;
  }
  nav_msgs::Odometry o = *msg;
  if (!msg->header.frame_id.empty())
    o.pose.pose = asv_ros::transformPose(t, msg->pose.pose);  // the twist stays in the body frame (REP 105)
  asv::ShipState s;
  const asv_ros::Reject why = asv_ros::odometryToShipState(o, params_.ship, s);
  if (why != asv_ros::Reject::None) {
    ROS_WARN_THROTTLE(5.0, "planner_node: odometry ignored (%s)", asv_ros::toString(why));
    return;
  }
  follower_->updateOwn(s);
  own_ = s;
  watch_.received(odom_sub_.getTopic(), asv_ros::rosNow(), asv_ros::wallNow());
  if (first_input_ < 0.0)
    first_input_ = ros::Time::now().toSec();
}

void PlannerNode::riskCallback(const asv_msgs::RiskAssessment::ConstPtr& msg) {
  checkClock();
  risk_ = msg;
  watch_.received(risk_sub_.getTopic(), asv_ros::rosNow(), asv_ros::wallNow());
}
void PlannerNode::targetsCallback(const asv_msgs::TargetArray::ConstPtr& msg) {
  checkClock();
  targets_ = msg;
  watch_.received(targets_sub_.getTopic(), asv_ros::rosNow(), asv_ros::wallNow());
}

void PlannerNode::alarmCallback(const asv_msgs::Alarm::ConstPtr& msg) {
  const std::string& src = msg->source;
  const std::string base = src.substr(src.rfind('/') + 1);
  if (std::find(params_.upstream_nodes.begin(), params_.upstream_nodes.end(), base) !=
      params_.upstream_nodes.end())
    upstream_alarms_[src] = msg;
}

void PlannerNode::routeCallback(const nav_msgs::Path::ConstPtr& msg) {
  tf2::Transform t;
  const std::string& frame = msg->header.frame_id;
  if (!frame.empty() && !frames_.get(frame, msg->header.stamp, t, true)) {
    ROS_WARN("planner_node: route in frame '%s', which tf2 does not connect to '%s': ignored", frame.c_str(),
             params_.frame_id.c_str());
    return;
  }
  asv::Route route;
  for (size_t k = 0; k < msg->poses.size(); ++k) {
    const geometry_msgs::Pose p =
        frame.empty() ? msg->poses[k].pose : asv_ros::transformPose(t, msg->poses[k].pose);
    if (!std::isfinite(p.position.x) || !std::isfinite(p.position.y)) {
      ROS_WARN("planner_node: route pose %zu is not finite: route ignored", k);
      return;
    }
    asv::RouteWaypoint w;
    w.position = {p.position.x, p.position.y};
    route.push_back(w);
  }
  if (route.empty()) {
    ROS_WARN("planner_node: an empty route: ignored (send a goal to steer for one point)");
    return;
  }
  const auto on_land = asv::legOnLand(route, own_ ? own_->position : route.front().position, allObstacles());
  if (on_land) {
    ROS_ERROR("planner_node: route refused: leg %d (to waypoint %d) crosses land '%s'", on_land->leg + 1,
              on_land->leg, on_land->land.c_str());
    return;
  }
  setRoute(route, "topic " + route_sub_.getTopic());
}

void PlannerNode::setRoute(const asv::Route& route, const std::string& from) {
  route_ = route;
  follower_->setRoute(route_);
  ROS_INFO("planner_node: route of %zu waypoint(s) from %s", route_.size(), from.c_str());
  publishRoute();
}

void PlannerNode::publishRoute() {
  nav_msgs::Path path;
  path.header.frame_id = params_.frame_id;
  path.header.stamp = ros::Time::now();
  for (const asv::RouteWaypoint& w : route_) {
    geometry_msgs::PoseStamped ps;
    ps.header = path.header;
    ps.pose.position.x = w.position.x();
    ps.pose.position.y = w.position.y();
    ps.pose.orientation.w = 1.0;
    path.poses.push_back(ps);
  }
  active_route_pub_.publish(path);
  visualization_msgs::MarkerArray arr;
  visualization_msgs::Marker line, corridor, points;
  line.header.frame_id = params_.frame_id;
  line.ns = params_.ship + "/route";
  line.action = route_.empty() ? visualization_msgs::Marker::DELETEALL : visualization_msgs::Marker::ADD;
  line.type = visualization_msgs::Marker::LINE_STRIP;
  line.pose.orientation.w = 1.0;
  line.scale.x = asv_ros::pixelsToMetres(2.0);
  line.color.r = line.color.g = 1.0f;  // yellow, as a chart plotter draws the active route
  line.color.a = 0.9f;
  if (route_.empty()) {
    arr.markers.push_back(line);
    route_markers_pub_.publish(arr);
    return;
  }
  corridor = points = line;
  corridor.id = 1;
  corridor.type = visualization_msgs::Marker::LINE_LIST;
  corridor.color.a = 0.4f;
  points.id = 2;
  points.type = visualization_msgs::Marker::SPHERE_LIST;
  points.scale.x = points.scale.y = points.scale.z = asv_ros::pixelsToMetres(8.0);
  auto point = [](const Eigen::Vector2d& p) {
    geometry_msgs::Point q;
    q.x = p.x();
    q.y = p.y();
    return q;
  };
  for (size_t k = 0; k < route_.size(); ++k) {
    line.points.push_back(point(route_[k].position));
    points.points.push_back(point(route_[k].position));
    if (k == 0)
      continue;
    // The corridor's two edges along leg k (port to the left of its direction, starboard to the right).
    const Eigen::Vector2d a = route_[k - 1].position, b = route_[k].position, d = (b - a).normalized();
    const Eigen::Vector2d right(d.y(), -d.x());
    for (const double off : {-route_[k].port_xtd, route_[k].starboard_xtd})
      if (off != 0.0 && (b - a).norm() > 0.0) {
        corridor.points.push_back(point(a + right * off));
        corridor.points.push_back(point(b + right * off));
      }
  }
  arr.markers.push_back(line);
  arr.markers.push_back(points);
  if (!corridor.points.empty())
    arr.markers.push_back(corridor);
  route_markers_pub_.publish(arr);
}

void PlannerNode::publishRouteStatus() {
  const auto& progress = follower_->routeProgress();
  if (!progress || !own_)
    return;
  asv_msgs::RouteStatus s;
  s.header.stamp = ros::Time::now();
  s.header.frame_id = params_.frame_id;
  s.ship = params_.ship;
  s.waypoints = static_cast<uint32_t>(progress->route().size());
  s.active_waypoint = static_cast<uint32_t>(progress->active());
  s.cross_track_error = progress->crossTrackError(own_->position);
  s.distance_to_waypoint = (progress->target().position - own_->position).norm();
  s.leg_speed = progress->target().speed;
  s.port_xtd = progress->target().port_xtd;
  s.starboard_xtd = progress->target().starboard_xtd;
  route_status_pub_.publish(s);  // for displays and logs: no lockstep stage waits for it
}

void PlannerNode::goalCallback(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  // A goal in another frame (rviz's goal tool in its fixed frame, a chart's `utm`) is moved into map;
  // no frame at all is taken as map, as rostopic pub writes it.
  tf2::Transform t;
  if (!msg->header.frame_id.empty() && !frames_.get(msg->header.frame_id, msg->header.stamp, t, true)) {
    ROS_WARN("planner_node: goal in frame '%s', which tf2 does not connect to '%s': ignored",
             msg->header.frame_id.c_str(), params_.frame_id.c_str());
    return;
  }
  const geometry_msgs::Pose g =
      msg->header.frame_id.empty() ? msg->pose : asv_ros::transformPose(t, msg->pose);
  if (!std::isfinite(g.position.x) || !std::isfinite(g.position.y))
    return;
  ROS_INFO("planner_node: new goal (%.0f, %.0f) m in %s", g.position.x, g.position.y,
           params_.frame_id.c_str());
  params_.goal = {g.position.x, g.position.y};
  params_.has_goal = true;
  route_.clear();  // a goal replaces the route
  if (follower_)
    follower_->setGoal(params_.goal);  // replans towards the new goal
  publishRoute();
}

std::vector<asv::PlannerTarget> PlannerNode::targetsNow() const {
  // The tracked targets with their risk picture; stale messages give nothing (the plan is then made
  // on what the ship knows: no targets).
  const ros::Time now = ros::Time::now();
  // A message stamped far in the future is as unusable as an old one. Not any stamp ahead of our clock:
  // faster than real time, /clock reaches the nodes milliseconds apart, which is seconds of simulated
  // time at 150x (a real jump back is handled by checkClock()).
  auto fresh = [&](const ros::Time& stamp) {
    const double age = (now - stamp).toSec();
    return age < params_.stale_after && age > -params_.stale_after;
  };
  if (!targets_ || !fresh(targets_->header.stamp))
    return {};
  const bool risk_fresh = risk_ && fresh(risk_->header.stamp);
  return withRisk(trackStates(*targets_), risk_fresh);
}

std::vector<asv::PlannerTarget> PlannerNode::lastPicture(const ros::Time& now) const {
  if (!targets_)
    return {};
  const std::vector<asv::ShipState> tracks = trackStates(*targets_);
  // Every last track counts, assessed or not (with its last assessment, however old): in degraded
  // operation a ship is a danger until shown not.
  return asv::PlanFollower::deadReckon(
      asv::selectPlannerTargets(params_.ship, tracks, risk_ ? assessedBy(*risk_) : AssessedTargets(), false),
      targets_->header.stamp.toSec(), now.toSec());
}

std::vector<asv::PlannerTarget> PlannerNode::withRisk(const std::vector<asv::ShipState>& tracks,
                                                      bool risk_fresh) const {
  const ros::Time now = ros::Time::now();
  const AssessedTargets assessed = risk_fresh ? assessedBy(*risk_) : AssessedTargets();
  const bool risk_alive = !asv::riskBlindPlanning(risk_fresh, now.toSec(), first_input_, params_.stale_after);
  return asv::selectPlannerTargets(params_.ship, tracks, assessed, risk_alive);
}

asv::CycleResult PlannerNode::plan(const std::vector<asv::PlannerTarget>& targets) {
  asv::CycleOptions options;
  // Free-running, a plan made for a picture overrun_factor budgets old is not flown: the fallback keeps
  // the ship safe until the next plan comes in time (diagnostics WARN). In lockstep planning costs no
  // simulated time.
  if (!lockstep_.enabled())
    options.overrun_factor = params_.overrun_factor;
  if (params_.fault_plan_delay > 0.0)  // fault injection: a plugin that overruns
    options.after_plan = [this] { ros::WallDuration(params_.fault_plan_delay).sleep(); };
  const double now = ros::Time::now().toSec();
  asv::CycleResult r = asv::planningCycle(*follower_, *plugin_, asv::parsePlannerMode(mode_, params_.planner),
                                          now, targets, options);
  if (!r.replanned)
    return r;
  if (!r.error.empty())
    ROS_ERROR_THROTTLE(5.0, "planner_node: plugin '%s' failed: %s", params_.planner.c_str(), r.error.c_str());
  if (r.overran) {
    ++overruns_;
    ROS_WARN_THROTTLE(5.0, "planner_node: '%s' %s; fallback in force", params_.planner.c_str(),
                      r.proposed.message.c_str());
  }
  last_compute_ = r.proposed.compute_time;
  max_compute_ = std::max(max_compute_, last_compute_);
  plan_stamp_ = ros::Time::now();
  watch_.busy(plan_stamp_.toSec(), asv_ros::wallNow());  // what came meanwhile is still queued
  last_reason_ = r.why;
  const asv::Plan& in_force = follower_->plan();
  ROS_INFO("planner_node: %s plan (%s) in %.1f ms: course %.1f deg, speed %.1f kn, %zu waypoints: %s",
           asv::toString(in_force.status), r.why.c_str(), last_compute_ * 1e3,
           asv::radToDeg(in_force.course_setpoint), asv::mpsToKnots(in_force.speed_setpoint),
           in_force.waypoints.size(), in_force.message.c_str());
  publishPlan();
  return r;
}

void PlannerNode::publishPlan() {
  const asv::Plan& plan = follower_->plan();
  asv_msgs::Plan m;
  m.header.stamp = plan_stamp_;
  m.header.frame_id = params_.frame_id;
  m.ship = params_.ship;
  m.planner = params_.planner;
  m.status = static_cast<uint8_t>(plan.status);
  nav_msgs::Path path;
  path.header = m.header;
  visualization_msgs::MarkerArray markers;
  visualization_msgs::Marker line;
  line.header = m.header;
  line.ns = params_.ship + "/plan";
  line.type = visualization_msgs::Marker::LINE_STRIP;
  line.pose.orientation.w = 1.0;
  line.scale.x = asv_ros::pixelsToMetres(2.5);
  line.color.a = 0.6;  // the ship's own track (sim/markers) shows through where she followed it
  line.color.g = plan.status == asv::PlanStatus::Ok ? 1.0f : 0.3f;
  line.color.r = plan.status == asv::PlanStatus::Ok ? 0.2f : 1.0f;
  for (const auto& w : plan.waypoints) {
    asv_msgs::PlanWaypoint pw;
    pw.position.x = w.position.x();
    pw.position.y = w.position.y();
    pw.time = w.time;
    pw.course = w.course;
    pw.speed = w.speed;
    m.waypoints.push_back(pw);
    geometry_msgs::PoseStamped ps;
    ps.header = m.header;
    ps.header.stamp = plan_stamp_ + ros::Duration(std::max(0.0, w.time));
    ps.pose.position = pw.position;
    ps.pose.orientation = asv_ros::yawToQuaternion(asv::courseToYaw(w.course));
    path.poses.push_back(ps);
    line.points.push_back(pw.position);
  }
  m.course_setpoint = plan.course_setpoint;
  m.speed_setpoint = plan.speed_setpoint;
  m.cost = std::isfinite(plan.cost) ? plan.cost : 0.0;
  m.compute_time = plan.compute_time;
  m.passing_distance = plan.passing_distance;
  m.message = plan.message;
  lockstep_.publish(plan_pub_, m);
  path_pub_.publish(path);
  if (line.points.size() >= 2)
    markers.markers.push_back(line);
  markers_pub_.publish(markers);
}

// The domain the plugin plans with round each target of the problem now (a compliant give-way target
// the own ship stands on for is not in it), as closed outlines.
void PlannerNode::publishDomains(const std::vector<asv::PlannerTarget>& targets) {
  visualization_msgs::MarkerArray arr;
  visualization_msgs::Marker clear;
  clear.action = visualization_msgs::Marker::DELETEALL;
  arr.markers.push_back(clear);
  const ros::Time now = ros::Time::now();
  int id = 0;
  for (const asv::TargetDomain& d : plugin_->domains(follower_->buildProblem(now.toSec(), targets))) {
    if (d.polygon.size() < 3)
      continue;
    visualization_msgs::Marker m;
    m.header.stamp = now;
    m.header.frame_id = params_.frame_id;
    m.ns = params_.ship + "/domains";
    m.id = id++;
    m.type = visualization_msgs::Marker::LINE_STRIP;
    m.pose.orientation.w = 1.0;
    m.scale.x = asv_ros::pixelsToMetres(1.5);
    m.color.r = 0.3f;
    m.color.g = 0.8f;
    m.color.b = 1.0f;
    m.color.a = 0.8f;
    for (size_t k = 0; k <= d.polygon.size(); ++k) {
      geometry_msgs::Point p;
      p.x = d.polygon[k % d.polygon.size()].x();
      p.y = d.polygon[k % d.polygon.size()].y();
      m.points.push_back(p);
    }
    arr.markers.push_back(m);
  }
  domains_pub_.publish(arr);
}

PlannerConfig PlannerNode::liveConfig() const {
  PlannerConfig c;
  c.planner = params_.planner;
  c.mode = mode_;
  c.min_separation = params_.follower.min_separation;
  c.replan_period = params_.follower.replan_period;
  c.min_replan_interval = params_.follower.min_replan_interval;
  c.time_budget = params_.follower.time_budget;
  c.stand_on_policy = params_.follower.stand_on_policy;
  return c;
}

void PlannerNode::reconfigure(PlannerConfig& c, uint32_t /*level*/) {
  if (!live_started_) {  // setCallback's first call: the values in force (the scenario's where resolved)
    live_started_ = true;
    c = liveConfig();
    return;
  }
  asv::PlannerNodeConfig next = params_;
  next.follower.min_separation = c.min_separation > 0.0 ? c.min_separation : scenario_min_separation_;
  next.follower.replan_period = c.replan_period;
  next.follower.min_replan_interval = c.min_replan_interval;
  next.follower.time_budget = c.time_budget;
  next.follower.stand_on_policy = c.stand_on_policy;
  next.planner = c.planner.empty() ? scenario_planner_ : c.planner;
  next.mode = c.mode;
  asv::PlanFollowerConfig fc;
  pluginlib::UniquePtr<asv::PlannerAlgorithm> plugin;
  try {  // nothing changes unless the plugin loads and the whole set is valid
    if (next.planner != params_.planner || next.mode != mode_)
      plugin = loadPlugin(next.planner, next.mode);
    fc = followerConfig(next, lockstep_.enabled(), next.mode, plugin ? *plugin : *plugin_);
    fc.cruise_speed = follower_->cruiseSpeed();
    fc.validate();
  } catch (const std::exception& e) {
    ROS_ERROR("planner_node: live parameters refused (%s); the values in force are kept", e.what());
    c = liveConfig();
    return;
  }
  follower_->reconfigure(fc);  // validated above: cannot throw
  if (plugin) {
    ROS_INFO("planner_node: planner '%s' (%s) replaces '%s' (%s)", next.planner.c_str(), next.mode.c_str(),
             params_.planner.c_str(), mode_.c_str());
    plugin_ = std::move(plugin);
    mode_ = next.mode;
  }
  params_ = next;
  follower_config_ = follower_->config();
  c = liveConfig();
  ROS_INFO(
      "planner_node: live parameters: planner %s (%s), min separation %.0f m, replan period %.0f s, "
      "min replan interval %.1f s, time budget %.2f s, stand-on policy %s",
      params_.planner.c_str(), mode_.c_str(), params_.follower.min_separation, params_.follower.replan_period,
      params_.follower.min_replan_interval, params_.follower.time_budget,
      params_.follower.stand_on_policy ? "on" : "off");
}

// `planner` in `mode`, its parameters read from ~ again (the user may have set ~<planner>/ since the
// start); throws when it cannot load.
pluginlib::UniquePtr<asv::PlannerAlgorithm> PlannerNode::loadPlugin(const std::string& planner,
                                                                    const std::string& mode) {
  if (planner.empty() || planner == "none")
    throw std::invalid_argument("planner '" + planner + "': a running planner_node needs a planner");
  node_params_ = asv_ros::readParams(pnh_);
  asv::ParamMap params = pluginParams(planner);
  params.set("mode", mode);
  return loader_.load(planner, params);
}

void PlannerNode::publishSetpoint() {
  double course = 0.0, speed = 0.0;
  if (follower_->setpoint(course, speed))
    publishSetpoint(course, speed);
}

void PlannerNode::publishSetpoint(double course, double speed) {
  asv_msgs::CourseSpeedSetpoint sp;
  sp.header.stamp = ros::Time::now();
  sp.header.frame_id = params_.frame_id;
  sp.course = course;
  sp.speed = speed;
  lockstep_.publish(cmd_pub_, sp);
}

void PlannerNode::timerCallback() {
  checkClock();
  if (!own_) {
    ROS_WARN_THROTTLE(10.0, "planner_node: waiting for odometry on %s", odom_sub_.getTopic().c_str());
    if (!ros::Time::now().isZero())
      alarm_->update(lostInputs(), "no set-point: own position unknown");
    return;
  }
  const std::vector<asv::StaleInput> lost = lostInputs();
  if (!lost.empty()) {
    degrade(lost);
    publishSetpoint();
  } else {
    alarm_->update({}, "");
    follower_->recover();
    const std::vector<asv::PlannerTarget> targets = targetsNow();
    const asv::CycleResult r = plan(targets);
    publishDomains(targets);
    if (r.has_setpoint)
      publishSetpoint(r.course, r.speed);
  }
  publishRouteStatus();
  updater_.update();
}

void PlannerNode::watchJob() {
  checkClock();
  const std::vector<asv::StaleInput> lost = lostInputs();
  if (!own_ || lost.empty())
    return;  // the set-point job does the rest (waiting for odometry, recovery)
  const uint64_t replans = follower_->replans();
  degrade(lost);
  if (follower_->replans() != replans)
    publishSetpoint();
}

std::vector<asv::StaleInput> PlannerNode::lostInputs() {
  const ros::Time now = ros::Time::now();
  if (lockstep_.enabled() || now.isZero())
    return {};  // in lockstep a node that stops stops the simulation (lockstep_timeout, ERROR)
  std::vector<asv::StaleInput> lost = watch_.stale(now.toSec(), asv_ros::wallNow());
  if (risk_ && !risk_->data_ok && !risk_->data_fault.empty())
    lost.push_back({risk_sub_.getTopic(), risk_sub_.getTopic() + " says data not ok: " + risk_->data_fault});
  for (const auto& [source, a] : upstream_alarms_)
    if (a->level == asv_msgs::Alarm::ERROR) {
      std::string why = source + " alarm:";
      for (const std::string& c : a->causes)
        why += " " + c;
      lost.push_back({source, why});
    }
  return lost;
}

void PlannerNode::degrade(const std::vector<asv::StaleInput>& lost) {
  const ros::Time now = ros::Time::now();
  std::string cause;
  for (const asv::StaleInput& l : lost)
    cause += (cause.empty() ? "" : "; ") + l.text;
  const uint64_t replans = follower_->replans();
  const asv::Plan& plan = follower_->degrade(now.toSec(), lastPicture(now), cause);
  alarm_->update(lost, plan.status == asv::PlanStatus::Ok
                           ? "degraded: plan in force kept while it passes the last known targets"
                           : plan.message);
  if (follower_->replans() == replans)
    return;
  plan_stamp_ = now;
  last_reason_ = "degraded";
  ROS_WARN("planner_node: %s", plan.message.c_str());
  publishPlan();
}

void PlannerNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  stat.add("planner", params_.planner);
  stat.add("mode", mode_);
  stat.add("min separation [m]", follower_->config().min_separation);
  stat.add("replans", follower_->replans());
  stat.add("fallbacks", follower_->fallbacks());
  stat.add("budget overruns", overruns_);
  stat.add("clock jumps back (state reset)", clock_.jumps());
  stat.add("last compute time [s]", last_compute_);
  stat.add("max compute time [s]", max_compute_);
  stat.add("last replan reason", last_reason_);
  if (const auto& progress = follower_->routeProgress(); progress && own_) {
    stat.add("route waypoint",
             std::to_string(progress->active()) + " of " + std::to_string(progress->route().size()));
    stat.add("cross-track error [m]", progress->crossTrackError(own_->position));
  }
  const asv::Plan& plan = follower_->plan();
  if (follower_->havePlan() && plan.status == asv::PlanStatus::Fallback)
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "fallback: " + plan.message);
  else if (overruns_ > 0)
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "plugin overran its time budget");
  else
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, follower_->havePlan() ? "planning" : "waiting");
  alarm_->diagnose(stat);
}

}  // namespace asv_planning
