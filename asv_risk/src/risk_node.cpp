#include "asv_risk/risk_node.h"

#include <algorithm>
#include <set>
#include <sstream>
#include <unordered_set>

#include <asv_ros/conversions.h>
#include <asv_ros/params.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace asv_risk {

using asv_ros::odometryToShipState;
using asv_ros::targetToShipState;
using asv_ros::toMsg;

namespace {

// Every private parameter the node understands; anything else under ~ is a typo and an error.
float riskColour(uint8_t level, int channel) {
  // green (none), amber (collision risk), red (urgent)
  static const float rgb[3][3] = {{0.1f, 0.8f, 0.2f}, {1.0f, 0.65f, 0.0f}, {0.9f, 0.1f, 0.1f}};
  return rgb[std::min<uint8_t>(level, 2)][channel];
}

}  // namespace

asv::RiskNodeConfig loadParams(const ros::NodeHandle& pnh) {
  return asv_ros::loadConfig<asv::RiskNodeConfig>(pnh, "asv_risk/config/risk_node.yaml");
}

RiskNode::RiskNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh),
      pnh_(pnh),
      params_(loadParams(pnh)),
      assessor_(params_.risk),
      frames_(params_.frame_id),
      diag_min_rate_(params_.min_rate),
      diag_max_rate_(params_.max_rate) {
  risk_pub_ = nh_.advertise<asv_msgs::RiskAssessment>("risk", 10);
  if (params_.publish_markers)
    marker_pub_ = nh_.advertise<visualization_msgs::MarkerArray>("risk_markers", 2);
  // Lockstep: the odometry of the step first, then the tracks it is assessed with.
  odom_sub_ = lockstep_.subscribe("odom", 20, &RiskNode::odomCallback, this, false);
  targets_sub_ = lockstep_.subscribe("targets", 20, &RiskNode::targetsCallback, this);
  watch_.add(targets_sub_.getTopic());
  watch_.add(odom_sub_.getTopic());
  // Free-running only: in lockstep a node that stops stops the simulation (lockstep_timeout, ERROR).
  if (!lockstep_.enabled())
    lockstep_.every(asv_ros::kWatchPeriod, [this] { watchInputs(); });

  updater_.setHardwareID(params_.own_ship);
  risk_diag_ = std::make_unique<diagnostic_updater::TopicDiagnostic>(
      "risk", updater_, diagnostic_updater::FrequencyStatusParam(&diag_min_rate_, &diag_max_rate_, 0.1, 10),
      diagnostic_updater::TimeStampStatusParam(-1.0, 5.0));
  updater_.add("inputs", this, &RiskNode::diagnose);
  diag_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  lockstep_.start();
  ROS_INFO("risk_node: own ship '%s', frame '%s', t_max %.0f s, d_min %.0f m, t_safe %.0f s, d_safe %.0f m",
           params_.own_ship.c_str(), params_.frame_id.c_str(), params_.risk.level.t_max_s,
           params_.risk.level.d_min_m, params_.risk.level.t_safe_s, params_.risk.level.d_safe_m);
}

void RiskNode::reject(Reject why, const std::string& what) {
  ++rejected_[static_cast<size_t>(why)];
  ROS_WARN_THROTTLE(5.0, "risk_node: rejected %s (%s); further rejections are counted in diagnostics",
                    what.c_str(), toString(why));
}

void RiskNode::checkClock() {
  asv_ros::resetOnClockJump(clock_, updater_, ros::Time::now(), [this] {
    own_.reset();
    assessor_.reset();
    watch_.reset();
    return std::string("own ship and compliance histories reset");
  });
}

void RiskNode::odomCallback(const nav_msgs::Odometry::ConstPtr& msg) {
  checkClock();
  asv::ShipState s;
  tf2::Transform t;
  if (!frames_.get(msg->header.frame_id, msg->header.stamp, t)) {
    ++odom_rejected_;
    reject(Reject::Frame, "own odometry in frame '" + msg->header.frame_id + "'");
    return;
  }
  nav_msgs::Odometry o = *msg;
  o.pose.pose = asv_ros::transformPose(t, msg->pose.pose);  // the twist stays in the body frame (REP 105)
  const Reject r = odometryToShipState(o, params_.own_ship, s);
  if (r != Reject::None) {
    ++odom_rejected_;
    reject(r, "own odometry");
    return;
  }
  own_ = s;
  watch_.received(odom_sub_.getTopic(), asv_ros::rosNow(), asv_ros::wallNow());
  own_stamp_ = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
}

void RiskNode::targetsCallback(const asv_msgs::TargetArray::ConstPtr& msg) {
  checkClock();
  const ros::Time now = ros::Time::now();
  targets_seen_ += msg->targets.size();
  watch_.received(targets_sub_.getTopic(), now.toSec(), asv_ros::wallNow());
  if (!own_) {
    ROS_WARN_THROTTLE(10.0, "risk_node: no own-ship odometry yet on '%s'; targets not assessed",
                      odom_sub_.getTopic().c_str());
    return;
  }
  if ((now - own_stamp_).toSec() > params_.odom_timeout) {
    ROS_WARN_THROTTLE(10.0, "risk_node: own-ship odometry is %.1f s old (odom_timeout %.1f s); not assessing",
                      (now - own_stamp_).toSec(), params_.odom_timeout);
    return;
  }
  tf2::Transform t;
  uint32_t rejected = 0;
  if (!frames_.get(msg->header.frame_id, msg->header.stamp, t)) {
    for (const auto& tg : msg->targets)
      reject(Reject::Frame, "target '" + tg.id + "' in frame '" + msg->header.frame_id + "'");
    rejected = msg->targets.size();
  }
  const double yaw = tf2::getYaw(t.getRotation());
  std::vector<asv::ShipState> states;
  std::vector<uint32_t> mmsis;
  std::unordered_set<std::string> ids;
  states.reserve(msg->targets.size());
  if (rejected == 0) {
    for (const asv_msgs::Target& tg : msg->targets) {
      asv::ShipState s;
      Reject r = targetToShipState(tg, s);
      if (r == Reject::None && !ids.insert(tg.id).second)
        r = Reject::Duplicate;
      if (r == Reject::None && !tg.stamp.isZero()) {
        const double age = (now - tg.stamp).toSec();
        if (age > params_.stale_after)
          r = Reject::Stale;
        if (-age > params_.future_tolerance)
          r = Reject::Future;
      }
      if (r != Reject::None) {
        reject(r, "target '" + tg.id + "'");
        ++rejected;
        continue;
      }
      if (msg->header.frame_id != params_.frame_id) {
        const tf2::Vector3 p = t * tf2::Vector3(s.position.x(), s.position.y(), 0.0);
        s.position = {p.x(), p.y()};
        s.course = asv::wrapTwoPi(s.course - yaw);  // a counter-clockwise frame rotation lowers courses
        s.heading = asv::wrapTwoPi(s.heading - yaw);
      }
      states.push_back(std::move(s));
      mmsis.push_back(tg.mmsi);
    }
  }

  const std::vector<asv::TargetRisk> risks = assessor_.assessAll(*own_, states);
  asv_msgs::RiskAssessment ra;
  ra.header.stamp = msg->header.stamp.isZero() ? now : msg->header.stamp;
  ra.header.frame_id = params_.frame_id;
  ra.own_ship = params_.own_ship;
  ra.own_position.x = own_->position.x();
  ra.own_position.y = own_->position.y();
  ra.own_course = own_->course;
  ra.own_speed = own_->speed;
  ra.rejected_targets = rejected;
  for (size_t i = 0; i < risks.size(); ++i) {
    ra.targets.push_back(toMsg(risks[i], mmsis[i]));
    ra.max_cri = std::max(ra.max_cri, risks[i].cri.cri);
    ra.max_risk_level = std::max(ra.max_risk_level, ra.targets.back().risk_level);
  }
  fillDataState(ra, now.toSec());
  last_ = ra;
  lockstep_.publish(risk_pub_, ra);
  risk_diag_->tick(ra.header.stamp);
  ++assessments_;
  if (params_.publish_markers)
    marker_pub_.publish(makeMarkers(ra));
}

void RiskNode::fillDataState(asv_msgs::RiskAssessment& ra, double now) {
  const std::vector<asv::StaleInput> stale =
      lockstep_.enabled() ? std::vector<asv::StaleInput>() : watch_.stale(now, asv_ros::wallNow());
  ra.data_ok = stale.empty();
  ra.data_fault.clear();
  for (const asv::StaleInput& s : stale)
    ra.data_fault += (ra.data_fault.empty() ? "" : "; ") + s.text;
  ra.targets_age =
      watch_.everReceived(targets_sub_.getTopic()) ? watch_.age(targets_sub_.getTopic(), now) : -1.0;
  ra.odom_age = watch_.everReceived(odom_sub_.getTopic()) ? watch_.age(odom_sub_.getTopic(), now) : -1.0;
}

void RiskNode::watchInputs() {
  checkClock();
  const ros::Time now = ros::Time::now();
  if (now.isZero())
    return;  // no clock yet (a simulation not started)
  const std::vector<asv::StaleInput> stale = watch_.stale(now.toSec(), asv_ros::wallNow());
  alarm_.update(stale, "risk sent with data_ok false and the last assessment");
  if (stale.empty())
    return;
  asv_msgs::RiskAssessment ra = last_;
  ra.header.stamp = now;
  ra.header.frame_id = params_.frame_id;
  ra.own_ship = params_.own_ship;
  fillDataState(ra, now.toSec());
  lockstep_.publish(risk_pub_, ra);
}

visualization_msgs::MarkerArray RiskNode::makeMarkers(const asv_msgs::RiskAssessment& ra) const {
  visualization_msgs::MarkerArray arr;
  visualization_msgs::Marker clear;
  clear.action = visualization_msgs::Marker::DELETEALL;
  arr.markers.push_back(clear);
  int id = 0;
  for (const asv_msgs::TargetRisk& t : ra.targets) {
    visualization_msgs::Marker m;
    m.header = ra.header;
    m.pose.orientation.w = 1.0;
    m.color.a = 1.0;
    m.color.r = riskColour(t.risk_level, 0);
    m.color.g = riskColour(t.risk_level, 1);
    m.color.b = riskColour(t.risk_level, 2);
    if (t.tcpa > 0.0) {
      m.ns = "cpa_line";
      m.id = id++;
      m.type = visualization_msgs::Marker::LINE_LIST;
      m.scale.x = asv_ros::pixelsToMetres(2.0);
      m.points = {t.own_cpa_position, t.target_cpa_position};
      arr.markers.push_back(m);
      m.points.clear();
      m.ns = "cpa_point";
      m.id = id++;
      m.type = visualization_msgs::Marker::SPHERE;
      m.pose.position = t.target_cpa_position;
      m.scale.x = m.scale.y = m.scale.z = asv_ros::pixelsToMetres(9.0);
      arr.markers.push_back(m);
    }
    m.ns = "label";
    m.id = id++;
    m.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
    m.pose.position.x = ra.own_position.x + t.range * std::sin(t.bearing);
    m.pose.position.y =
        ra.own_position.y + t.range * std::cos(t.bearing) - asv_ros::pixelsToMetres(42.0);  // below the ship
    m.scale.z = asv_ros::pixelsToMetres(12.0);
    const asv::Encounter encounter = asv_ros::encounterFromMsg(t.encounter, t.own_role);
    std::ostringstream s;
    s.precision(2);
    s << std::fixed << t.target_id << " CRI " << t.cri << "\nTCPA " << t.tcpa / 60.0 << " min DCPA "
      << t.dcpa / 1852.0 << " nm\n"
      << asv::toString(encounter) << " " << asv::toString(asv::ownRole(encounter))
      << (t.compliant ? "" : " NON-COMPLIANT");
    m.text = s.str();
    arr.markers.push_back(m);
  }
  arr.markers.push_back(ownRiskLabel(ra, id));
  return arr;
}

// The own ship's risk state above her: the most dangerous target's risk, or no data (never "no risk"
// when the picture is not there).
visualization_msgs::Marker RiskNode::ownRiskLabel(const asv_msgs::RiskAssessment& ra, int id) const {
  const asv_msgs::TargetRisk* worst = nullptr;
  for (const asv_msgs::TargetRisk& t : ra.targets)
    if (!worst || t.risk_level > worst->risk_level ||
        (t.risk_level == worst->risk_level && t.cri > worst->cri))
      worst = &t;
  visualization_msgs::Marker m;
  m.header = ra.header;
  m.ns = "own_risk";
  m.id = id;
  m.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
  m.pose.orientation.w = 1.0;
  m.pose.position = ra.own_position;
  m.pose.position.y += asv_ros::pixelsToMetres(54.0);  // above her name
  m.scale.z = asv_ros::pixelsToMetres(15.0);
  const uint8_t level = ra.data_ok ? (worst ? worst->risk_level : 0) : 3;
  m.color.a = 1.0;
  m.color.r = riskColour(level, 0);
  m.color.g = riskColour(level, 1);
  m.color.b = riskColour(level, 2);
  std::ostringstream s;
  s.precision(2);
  if (!ra.data_ok)
    s << "RISK UNKNOWN: " << ra.data_fault;
  else if (!worst)
    s << "risk: none (no targets)";
  else
    s << std::fixed << "risk: " << asv::toString(static_cast<asv::RiskLevel>(worst->risk_level)) << ", "
      << worst->target_id << " CRI " << worst->cri << " TCPA " << worst->tcpa / 60.0 << " min";
  m.text = s.str();
  return m;
}

void RiskNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  uint64_t total = 0;
  for (size_t i = 1; i < rejected_.size(); ++i) {
    stat.add(std::string("rejected ") + toString(static_cast<Reject>(i)), rejected_[i]);
    total += rejected_[i];
  }
  stat.add("assessments", assessments_);
  stat.add("clock jumps back (state reset)", clock_.jumps());
  stat.add("targets received", targets_seen_);
  stat.add("own odometry rejected", odom_rejected_);
  stat.add("own ship known", own_.has_value());
  if (total > rejected_at_last_diag_)
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::WARN, "%lu inputs rejected since the last report",
                  static_cast<unsigned long>(total - rejected_at_last_diag_));
  else if (!own_)
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no own-ship odometry");
  else
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "inputs ok");
  alarm_.diagnose(stat);
  rejected_at_last_diag_ = total;
}

}  // namespace asv_risk
