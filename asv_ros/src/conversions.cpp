#include "asv_ros/conversions.h"

#include <algorithm>
#include <cmath>

#include <asv_core/common/geodesy.h>
#include <asv_core/common/units.h>

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/utils.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace asv_ros {

const char* toString(Reject r) {
  switch (r) {
    case Reject::None:
      return "accepted";
    case Reject::NonFinite:
      return "non_finite";
    case Reject::Impossible:
      return "impossible_value";
    case Reject::EmptyId:
      return "empty_id";
    case Reject::Duplicate:
      return "duplicate_id";
    case Reject::Stale:
      return "stale";
    case Reject::Future:
      return "future_stamp";
    case Reject::Frame:
      return "unknown_frame";
    case Reject::kCount:
      break;
  }
  return "unknown";
}

Reject targetToShipState(const asv_msgs::Target& msg, asv::ShipState& out) {
  if (msg.id.empty())
    return Reject::EmptyId;
  if (!asv::allFinite({msg.position.x, msg.position.y, msg.course_over_ground, msg.speed_over_ground}))
    return Reject::NonFinite;
  if (msg.has_heading && !std::isfinite(msg.heading))
    return Reject::NonFinite;
  if (!std::isfinite(msg.length))
    return Reject::NonFinite;
  if (msg.speed_over_ground < 0.0 || msg.speed_over_ground > kMaxSpeed)
    return Reject::Impossible;
  out.id = msg.id;
  out.position = {msg.position.x, msg.position.y};
  out.course = asv::wrapTwoPi(msg.course_over_ground);
  out.speed = msg.speed_over_ground;
  // COLREGs bearings are taken from the heading; without one, the course over ground stands in.
  out.heading = msg.has_heading ? asv::wrapTwoPi(msg.heading) : out.course;
  out.length = msg.length > 0.0f ? msg.length : 0.0;
  return Reject::None;
}

Reject odometryToShipState(const nav_msgs::Odometry& msg, const std::string& name, asv::ShipState& out) {
  const auto& p = msg.pose.pose.position;
  const auto& q = msg.pose.pose.orientation;
  const auto& v = msg.twist.twist.linear;
  if (!asv::allFinite({p.x, p.y, q.x, q.y, q.z, q.w, v.x, v.y}))
    return Reject::NonFinite;
  const double qn = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  if (qn < 0.5 || qn > 1.5)
    return Reject::Impossible;  // not a rotation
  const double yaw = tf2::getYaw(q);
  // Twist is expressed in the child (body) frame: rotate it into the working frame.
  const double ve = v.x * std::cos(yaw) - v.y * std::sin(yaw);
  const double vn = v.x * std::sin(yaw) + v.y * std::cos(yaw);
  const double speed = std::hypot(ve, vn);
  if (speed > kMaxSpeed)
    return Reject::Impossible;
  out.id = name;
  out.position = {p.x, p.y};
  out.heading = asv::yawToCourse(yaw);
  out.speed = speed;
  // Below 1 cm/s the course over ground is noise; the heading is the better course.
  out.course = speed > 0.01 ? asv::courseOf({ve, vn}) : out.heading;
  return Reject::None;
}

uint8_t encounterToMsg(asv::Encounter e) {
  using TR = asv_msgs::TargetRisk;
  switch (e) {
    case asv::Encounter::HeadOn:
      return TR::ENCOUNTER_HEAD_ON;
    case asv::Encounter::CrossingGiveWay:
    case asv::Encounter::CrossingStandOn:
      return TR::ENCOUNTER_CROSSING;
    case asv::Encounter::Overtaking:
      return TR::ENCOUNTER_OVERTAKING;
    case asv::Encounter::BeingOvertaken:
      return TR::ENCOUNTER_BEING_OVERTAKEN;
    case asv::Encounter::None:
      break;
  }
  return TR::ENCOUNTER_NONE;
}

uint8_t roleToMsg(asv::OwnRole r) {
  using TR = asv_msgs::TargetRisk;
  switch (r) {
    case asv::OwnRole::GiveWay:
    case asv::OwnRole::BothGiveWay:
      return TR::ROLE_GIVE_WAY;
    case asv::OwnRole::StandOn:
      return TR::ROLE_STAND_ON;
    case asv::OwnRole::None:
      break;
  }
  return TR::ROLE_NONE;
}

asv::Encounter encounterFromMsg(uint8_t encounter, uint8_t role) {
  using TR = asv_msgs::TargetRisk;
  switch (encounter) {
    case TR::ENCOUNTER_HEAD_ON:
      return asv::Encounter::HeadOn;
    case TR::ENCOUNTER_CROSSING:
      return role == TR::ROLE_STAND_ON ? asv::Encounter::CrossingStandOn : asv::Encounter::CrossingGiveWay;
    case TR::ENCOUNTER_OVERTAKING:
      return asv::Encounter::Overtaking;
    case TR::ENCOUNTER_BEING_OVERTAKEN:
      return asv::Encounter::BeingOvertaken;
    default:
      return asv::Encounter::None;
  }
}

asv_msgs::TargetRisk toMsg(const asv::TargetRisk& r, uint32_t mmsi) {
  asv_msgs::TargetRisk m;
  m.target_id = r.id;
  m.mmsi = mmsi;
  m.range = r.range;
  m.bearing = r.true_bearing;
  m.relative_bearing = r.geometry.relative_bearing;
  m.aspect = r.geometry.aspect;
  m.tcpa = r.cpa.tcpa;
  m.dcpa = r.cpa.dcpa;
  m.own_cpa_position.x = r.cpa.own_at_cpa.x();
  m.own_cpa_position.y = r.cpa.own_at_cpa.y();
  m.target_cpa_position.x = r.cpa.target_at_cpa.x();
  m.target_cpa_position.y = r.cpa.target_at_cpa.y();
  m.cri = r.cri.cri;
  m.safe_distance_d1 = r.cri.d1;
  m.safe_distance_d2 = r.cri.d2;
  m.risk_level = static_cast<uint8_t>(r.compliance.risk);
  m.encounter = encounterToMsg(r.geometry.encounter);
  m.own_role = roleToMsg(r.geometry.role);
  m.compliant = r.compliance.compliant;
  m.decision = static_cast<uint8_t>(r.compliance.decision);
  m.applicable_rule = static_cast<uint8_t>(r.rule);
  return m;
}

bool riskFromMsg(const asv_msgs::TargetRisk& m, asv::PlannerTarget& out) {
  out.risk = static_cast<asv::RiskLevel>(m.risk_level);
  out.compliant = m.compliant;
  out.encounter = encounterFromMsg(m.encounter, m.own_role);
  out.role = asv::ownRole(out.encounter);  // the role follows from the encounter (Rules 13-17)
  out.cri = m.cri;
  out.tcpa = m.tcpa;
  out.dcpa = m.dcpa;
  return m.encounter == asv_msgs::TargetRisk::ENCOUNTER_NONE || out.encounter != asv::Encounter::None;
}

geometry_msgs::Quaternion yawToQuaternion(double yaw) {
  tf2::Quaternion q;
  q.setRPY(0.0, 0.0, yaw);
  return tf2::toMsg(q);
}

bool resetOnClockJump(asv::ClockJumpDetector& clock, diagnostic_updater::Updater& updater,
                      const ros::Time& now, const std::function<std::string()>& reset) {
  if (!clock.jumpedBack(now.toSec()))
    return false;
  const std::string forgotten = reset();
  ROS_WARN("%s: time went back %.1f s (a looping bag or a restarted clock): %s",
           ros::this_node::getName().c_str(), clock.lastJump(), forgotten.c_str());
  updater.force_update();
  return true;
}

double pixelsToMetres(double px) {
  constexpr double kDefaultScale = 0.06;  // [px/m] asv.rviz's
  double scale = kDefaultScale;
  if (!ros::param::getCached("/view_scale", scale) || !(scale > 0.0) || !std::isfinite(scale))
    scale = kDefaultScale;
  return px / scale;
}

bool navSatToFix(const sensor_msgs::NavSatFix& msg, asv::gnss::Fix& fix, std::string& why) {
  if (msg.status.status < sensor_msgs::NavSatStatus::STATUS_FIX) {
    why = "NavSatFix: no fix (status " + std::to_string(msg.status.status) + ")";
    return false;
  }
  if (!asv::allFinite({msg.latitude, msg.longitude}) || !asv::validLatLon(msg.latitude, msg.longitude)) {
    why = "NavSatFix: no position";
    return false;
  }
  fix = asv::gnss::Fix{};
  fix.lat_deg = msg.latitude;
  fix.lon_deg = msg.longitude;
  fix.quality = msg.status.status == sensor_msgs::NavSatStatus::STATUS_FIX
                    ? asv::gnss::Quality::kGnss
                    : asv::gnss::Quality::kDifferential;
  if (msg.position_covariance_type != sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN) {
    const double var = std::max(msg.position_covariance[0], msg.position_covariance[4]);  // east, north
    if (!(std::isfinite(var) && var >= 0.0)) {
      why = "NavSatFix: covariance is no variance";
      return false;
    }
    fix.sigma = std::sqrt(var);
  }
  return true;
}

bool enuTwistToMotion(const geometry_msgs::TwistStamped& msg, asv::gnss::Motion& motion) {
  const Eigen::Vector2d v(msg.twist.linear.x, msg.twist.linear.y);
  if (!v.allFinite())
    return false;
  motion.course = asv::courseOf(v);
  motion.speed = v.norm();
  return true;
}

bool orientationToHeading(const geometry_msgs::QuaternionStamped& msg, bool yaw_is_bearing, double& heading) {
  const auto& q = msg.quaternion;
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!std::isfinite(norm) || std::fabs(norm - 1.0) > 1e-3)
    return false;
  const double yaw = tf2::getYaw(q);
  heading = yaw_is_bearing ? asv::wrapTwoPi(yaw) : asv::yawToCourse(yaw);
  return true;
}

}  // namespace asv_ros

// The message constants mirror the core enumerations: catch any drift at compile time.
namespace {
using TR = asv_msgs::TargetRisk;
static_assert(TR::RISK_URGENT == static_cast<uint8_t>(asv::RiskLevel::Urgent), "risk enum drift");
static_assert(TR::RISK_COLLISION == static_cast<uint8_t>(asv::RiskLevel::Collision), "risk enum drift");
static_assert(TR::DECISION_RULE_2 == static_cast<uint8_t>(asv::RuleDecision::Rule2), "decision drift");
static_assert(TR::DECISION_RULE_APPLIES == static_cast<uint8_t>(asv::RuleDecision::RuleApplies), "");
}  // namespace
