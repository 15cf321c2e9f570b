#include "asv_risk/plotter_node.h"

#include <asv_core/common/units.h>
#include <asv_ros/params.h>

#include <asv_ros/conversions.h>

namespace asv_risk {

using asv_ros::odometryToShipState;
using asv_ros::Reject;
using asv_ros::targetToShipState;

namespace {

constexpr const char* kYaml = "asv_risk/config/plotter_node.yaml";

}  // namespace

PlotterNode::PlotterNode(ros::NodeHandle nh, ros::NodeHandle pnh) : nh_(nh), pnh_(pnh) {
  const asv::ParamMap params = asv_ros::readParams(pnh_);
  std::optional<asv::GeoPoint> given;
  try {
    config_ = asv::PlotterConfig::fromParams(params);
    output_config_ = asv_ros::NmeaOutputConfig::fromParams(params);
    given = asv::originFromParams(params);
    asv_ros::rejectUnknown(params, kYaml);
  } catch (const std::invalid_argument&) {
    asv_ros::rejectTypoBehindError(params, kYaml);
    throw;
  }
  map_origin_ = std::make_unique<asv_ros::MapOrigin>(nh_, given);
  plotter_ = std::make_unique<asv::PlotterOutput>(
      config_, asv::LocalFrame(map_origin_->get().lat_deg, map_origin_->get().lon_deg));
  output_ = std::make_unique<asv_ros::NmeaOutput>(output_config_);  // throws naming the device
  odom_sub_ = nh_.subscribe<nav_msgs::Odometry>("odom", 10, [this](const nav_msgs::Odometry::ConstPtr& m) {
    if (!inMap(m->header.frame_id, "odometry"))
      return;
    odom_ = m;
    odom_time_ = ros::Time::now();
  });
  targets_sub_ =
      nh_.subscribe<asv_msgs::TargetArray>("targets", 10, [this](const asv_msgs::TargetArray::ConstPtr& m) {
        if (!inMap(m->header.frame_id, "targets"))
          return;
        targets_ = m;
        targets_time_ = ros::Time::now();
      });
  risk_sub_ = nh_.subscribe<asv_msgs::RiskAssessment>("risk", 10,
                                                      [this](const asv_msgs::RiskAssessment::ConstPtr& m) {
                                                        cpa_.clear();
                                                        for (const auto& t : m->targets)
                                                          cpa_[t.target_id] = {t.dcpa, t.tcpa};
                                                      });
  route_sub_ = nh_.subscribe<nav_msgs::Path>("active_route", 1, [this](const nav_msgs::Path::ConstPtr& m) {
    if (!inMap(m->header.frame_id, "route"))
      return;
    std::vector<Eigen::Vector2d> route;
    for (const auto& p : m->poses)
      if (std::isfinite(p.pose.position.x) && std::isfinite(p.pose.position.y))
        route.emplace_back(p.pose.position.x, p.pose.position.y);
    plotter_->setRoute(route);
  });
  if (config_.forward_ais)
    nmea_sub_ = nh_.subscribe("nmea_in", 1000, &PlotterNode::forward, this);
  timer_ = nh_.createTimer(ros::Duration(1.0 / config_.rate), [this](const ros::TimerEvent&) { tick(); });
  updater_.setHardwareID("chart plotter");
  updater_.add("plotter output", this, &PlotterNode::diagnose);
  diag_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  ROS_INFO("plotter_node: %s, %s and %s -> %s at %.1f Hz", odom_sub_.getTopic().c_str(),
           targets_sub_.getTopic().c_str(), risk_sub_.getTopic().c_str(), output_->describe().c_str(),
           config_.rate);
}

// Positions are read in map only (what the pipeline publishes): another frame is refused, not misplaced.
bool PlotterNode::inMap(const std::string& frame, const char* what) const {
  if (frame.empty() || frame == "map" || frame == "/map")
    return true;
  ROS_WARN_THROTTLE(10.0, "plotter_node: %s in frame '%s', not map: ignored", what, frame.c_str());
  return false;
}

void PlotterNode::forward(const asv_msgs::NmeaSentence& msg) {
  const std::string& s = msg.sentence;
  if (s.size() > 6 && s[0] == '!' && (s.compare(3, 3, "VDM") == 0 || s.compare(3, 3, "VDO") == 0) &&
      output_->send(s))
    ++forwarded_;
}

std::optional<asv::PlotterOwn> PlotterNode::own(const ros::Time& now) const {
  if (!odom_ || (now - odom_time_).toSec() > config_.stale_after)
    return std::nullopt;  // a stale position is not sent as the ship's: the plotter shows the loss
  asv::ShipState s;
  if (odometryToShipState(*odom_, "own", s) != Reject::None)
    return std::nullopt;
  asv::PlotterOwn o;
  o.position = s.position;
  o.course = s.course;
  o.speed = s.speed;
  o.heading = s.heading;
  return o;
}

std::vector<asv::PlotterTarget> PlotterNode::targets(const ros::Time& now) const {
  std::vector<asv::PlotterTarget> out;
  if (!targets_ || (now - targets_time_).toSec() > config_.stale_after)
    return out;
  for (const asv_msgs::Target& m : targets_->targets) {
    asv::ShipState s;
    if (targetToShipState(m, s) != Reject::None)
      continue;
    asv::PlotterTarget t;
    t.id = m.id;
    t.name = m.name;
    t.position = s.position;
    t.course = s.course;
    t.speed = s.speed;
    t.reported = m.source == asv_msgs::Target::SOURCE_AIS;
    const auto c = cpa_.find(m.id);
    if (c != cpa_.end() && c->second.second >= 0.0) {  // a CPA already past is none
      t.dcpa = c->second.first;
      t.tcpa = c->second.second;
    }
    out.push_back(t);
  }
  return out;
}

void PlotterNode::tick() {
  const ros::Time now = ros::Time::now();
  if (now.isZero())
    return;
  const std::optional<asv::PlotterOwn> o = own(now);
  void_periods_ += !o;
  for (const std::string& s : plotter_->sentences(o, targets(now), now.toSec()))
    if (!output_->send(s))
      ROS_WARN_THROTTLE(10.0, "plotter_node: write to %s failed; counted in diagnostics",
                        output_->describe().c_str());
  ++periods_;
}

void PlotterNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  stat.add("output", output_->describe());
  stat.add("periods sent", periods_);
  stat.add("periods without own position (RMC V)", void_periods_);
  stat.add("AIS sentences forwarded", forwarded_);
  stat.add("sentences sent", output_->sent());
  stat.add("writes failed", output_->failed());
  if (output_->failed() > 0)
    stat.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "writes to " + output_->describe() + " fail");
  else if (void_periods_ > 0 && !own(ros::Time::now()))
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no own position: RMC sent void");
  else
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "sending to " + output_->describe());
}

}  // namespace asv_risk
