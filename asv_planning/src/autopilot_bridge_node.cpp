#include "asv_planning/autopilot_bridge_node.h"

#include <cmath>

#include <asv_core/common/units.h>
#include <asv_core/world/scenario.h>
#include <asv_ros/conversions.h>
#include <asv_ros/params.h>
#include <geometry_msgs/TwistStamped.h>

namespace asv_planning {

namespace {

constexpr const char* kYaml = "asv_planning/config/autopilot_bridge.yaml";

// The node's own map origin: the scenario's when origin_scenario is set, else the two keys; neither:
// none (the run's /map_origin is used).
std::optional<asv::GeoPoint> givenOrigin(const asv::AutopilotBridgeConfig& c) {
  if (!c.origin_scenario.empty()) {
    const asv::Scenario s = asv::loadScenario(c.origin_scenario, asv::ChartOptions{"", "", false});
    if (!s.has_origin)
      throw std::invalid_argument("origin_scenario '" + c.origin_scenario + "' has no origin");
    return s.origin;
  }
  if (c.origin_lat_deg)
    return asv::GeoPoint{*c.origin_lat_deg, *c.origin_lon_deg};
  return std::nullopt;
}

}  // namespace

AutopilotBridgeNode::AutopilotBridgeNode(ros::NodeHandle nh, ros::NodeHandle pnh) : nh_(nh), pnh_(pnh) {
  const asv::ParamMap params = asv_ros::readParams(pnh_);
  try {
    config_ = asv::AutopilotBridgeConfig::fromParams(params);
    output_config_ = asv_ros::NmeaOutputConfig::fromParams(params);
    publish_twist_ = params.getBool("publish_twist", false);
    asv_ros::rejectUnknown(params, kYaml);
  } catch (const std::invalid_argument&) {
    asv_ros::rejectTypoBehindError(params, kYaml);
    throw;
  }
  map_origin_ = std::make_unique<asv_ros::MapOrigin>(nh_, givenOrigin(config_));
  frame_.emplace(map_origin_->get().lat_deg, map_origin_->get().lon_deg);
  bridge_ = std::make_unique<asv::AutopilotBridge>(config_);
  output_ = std::make_unique<asv_ros::NmeaOutput>(output_config_);  // throws naming the device
  // An NMEA sentence is at most 82 characters: what a tick sends must fit the line between ticks.
  const double needed = 82.0 * static_cast<double>(config_.sentences.size()) * config_.rate;
  if (needed > output_->capacity())
    throw std::invalid_argument("rate " + std::to_string(config_.rate) + " Hz x " +
                                std::to_string(config_.sentences.size()) + " sentences needs up to " +
                                std::to_string(static_cast<int>(needed * 10.0)) +
                                " Bd; output/serial/baud is " + std::to_string(output_config_.serial_baud));
  alarm_ = std::make_unique<asv_ros::AlarmReporter>(nh_);
  cmd_sub_ = nh_.subscribe("cmd", 10, &AutopilotBridgeNode::cmdCallback, this);
  odom_sub_ = nh_.subscribe("odom", 20, &AutopilotBridgeNode::odomCallback, this);
  route_sub_ = nh_.subscribe("active_route", 1, &AutopilotBridgeNode::routeCallback, this);
  if (publish_twist_)
    twist_pub_ = nh_.advertise<geometry_msgs::TwistStamped>("cmd_vel", 5);
  arm_srv_ = pnh_.advertiseService("arm", &AutopilotBridgeNode::armService, this);
  timer_ = nh_.createTimer(ros::Duration(1.0 / config_.rate), [this](const ros::TimerEvent&) { tick(); });
  updater_.setHardwareID("autopilot");
  updater_.add("autopilot bridge", this, &AutopilotBridgeNode::diagnose);
  diag_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  ROS_INFO("autopilot_bridge: %s -> %s at %.1f Hz, %s; safe action %s", cmd_sub_.getTopic().c_str(),
           output_->describe().c_str(), config_.rate, bridge_->armed() ? "ARMED" : "disarmed (call ~arm)",
           config_.safe_action.c_str());
}

void AutopilotBridgeNode::cmdCallback(const asv_msgs::CourseSpeedSetpoint::ConstPtr& msg) {
  const ros::Time now = ros::Time::now();
  const ros::Time stamp = msg->header.stamp.isZero() ? now : msg->header.stamp;
  bridge_->setpoint(msg->course, msg->speed, stamp.toSec(), now.toSec(), asv_ros::wallNow());
}

void AutopilotBridgeNode::odomCallback(const nav_msgs::Odometry::ConstPtr& msg) {
  asv::ShipState s;
  const asv_ros::Reject why = asv_ros::odometryToShipState(*msg, "own", s);
  if (why != asv_ros::Reject::None) {
    ROS_WARN_THROTTLE(5.0, "autopilot_bridge: odometry ignored (%s)", asv_ros::toString(why));
    return;
  }
  bridge_->own(s.position, s.course, s.speed, s.heading, ros::Time::now().toSec(), asv_ros::wallNow());
}

// The route in force (planner_node's active_route, latched), in map only: another frame is refused,
// not misplaced, and the route sentences stay with the set-point's leg.
void AutopilotBridgeNode::routeCallback(const nav_msgs::Path::ConstPtr& msg) {
  const std::string& frame = msg->header.frame_id;
  if (!frame.empty() && frame != "map" && frame != "/map") {
    ROS_WARN("autopilot_bridge: route in frame '%s', not map: ignored", frame.c_str());
    return;
  }
  std::vector<Eigen::Vector2d> route;
  for (const auto& p : msg->poses)
    if (std::isfinite(p.pose.position.x) && std::isfinite(p.pose.position.y))
      route.emplace_back(p.pose.position.x, p.pose.position.y);
  if (route.size() != msg->poses.size())
    ROS_WARN("autopilot_bridge: %zu route waypoint(s) not finite: dropped", msg->poses.size() - route.size());
  bridge_->route(route);
  route_waypoints_ = route.size();
  if (route.empty())
    ROS_INFO("autopilot_bridge: no route in force: the set-point's leg is sent");
  else
    ROS_INFO("autopilot_bridge: route of %zu waypoint(s): its active leg is sent while the ship follows it",
             route.size());
}

bool AutopilotBridgeNode::armService(std_srvs::SetBool::Request& req, std_srvs::SetBool::Response& res) {
  bridge_->arm(req.data);
  res.success = true;
  res.message =
      req.data ? "armed: steering sentences go out on " + output_->describe() : "disarmed: nothing goes out";
  ROS_WARN("autopilot_bridge: %s", res.message.c_str());
  return true;
}

void AutopilotBridgeNode::tick() {
  const ros::Time now = ros::Time::now();
  if (now.isZero())
    return;
  last_ = bridge_->tick(now.toSec(), asv_ros::wallNow(),
                        [this](const Eigen::Vector2d& p, double& lat, double& lon) {
                          const asv::GeoPoint g = frame_->toGeodetic(p);
                          lat = g.lat_deg;
                          lon = g.lon_deg;
                        });
  alarm_->update(last_.lost, last_.action);
  for (const std::string& s : last_.sentences)
    if (!output_->send(s))
      ROS_WARN_THROTTLE(10.0, "autopilot_bridge: write to %s failed; counted in diagnostics",
                        output_->describe().c_str());
  ticks_sent_ += !last_.sentences.empty();
  if (publish_twist_ && bridge_->armed()) {
    geometry_msgs::TwistStamped t;
    t.header.stamp = now;
    t.header.frame_id = "base_link";
    t.twist.linear.x = last_.speed;
    t.twist.angular.z = last_.yaw_rate;
    twist_pub_.publish(t);
  }
}

void AutopilotBridgeNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  stat.add("armed", bridge_->armed());
  stat.add("output", output_->describe());
  stat.add("sentences sent", output_->sent());
  stat.add("writes failed", output_->failed());
  stat.add("route sentences valid", last_.valid);
  stat.add("route waypoints", route_waypoints_);
  stat.add("leg sent", last_.route_waypoint ? "route, to WP" + std::to_string(*last_.route_waypoint + 1)
                                            : std::string("set-point"));
  if (!bridge_->armed())
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "disarmed: nothing sent (call ~arm)");
  else if (output_->failed() > 0)
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "writes failed");
  else
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK,
                 last_.sentences.empty() ? "waiting for a set-point" : "steering");
  alarm_->diagnose(stat);
}

}  // namespace asv_planning
