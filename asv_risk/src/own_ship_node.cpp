#include "asv_risk/own_ship_node.h"

#include <cmath>

#include <asv_core/common/units.h>
#include <asv_ros/conversions.h>

namespace asv_risk {

using asv_ros::enuTwistToMotion;
using asv_ros::navSatToFix;
using asv_ros::orientationToHeading;

namespace {

constexpr const char* kYaml = "asv_risk/config/own_ship_node.yaml";

OwnShipNodeParams loadOwnShipParams(const ros::NodeHandle& pnh) {
  NmeaInputParams input;
  input.udp_port = 10112;  // its own port: a GNSS feed apart from AIS (10110) and radar (10111)
  input.serial_baud = 4800;
  input.frame_id = "gnss";
  return loadIngestionParams<asv::OwnShipConfig>(pnh, input, kYaml);
}

}  // namespace

nav_msgs::Odometry toOdometry(const asv::OwnShipState& s, const std::string& frame_id,
                              const std::string& child, const ros::Time& stamp) {
  nav_msgs::Odometry o;
  o.header.stamp = stamp;
  o.header.frame_id = frame_id;
  o.child_frame_id = child;
  o.pose.pose.position.x = s.position.x();
  o.pose.pose.position.y = s.position.y();
  const double yaw = asv::courseToYaw(s.heading);
  o.pose.pose.orientation = asv_ros::yawToQuaternion(yaw);
  const double var = s.position_sigma * s.position_sigma;
  o.pose.covariance[0] = o.pose.covariance[7] = var;
  o.pose.covariance[14] = o.pose.covariance[21] = o.pose.covariance[28] =
      1e6;  // z, roll, pitch: not estimated
  o.pose.covariance[35] = s.heading_sigma * s.heading_sigma;
  // REP 105: the twist in the body frame (x forward, y to port).
  const Eigen::Vector2d v = asv::courseSpeedToVelocity(s.course, s.speed);
  o.twist.twist.linear.x = v.x() * std::cos(yaw) + v.y() * std::sin(yaw);
  o.twist.twist.linear.y = -v.x() * std::sin(yaw) + v.y() * std::cos(yaw);
  o.twist.twist.angular.z = -s.yaw_rate;  // a turn to starboard is clockwise: negative about z up
  return o;
}

OwnShipNode::OwnShipNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh),
      pnh_(pnh),
      params_(loadOwnShipParams(pnh)),
      map_origin_(nh, givenOrigin(params_)),
      frame_(map_origin_.get().lat_deg, map_origin_.get().lon_deg),
      estimator_(params_, frame_),
      framer_([this] {
        asv::nmea::FramerConfig c;
        c.max_length = params_.max_sentence_length;
        return c;
      }()) {
  odom_pub_ = nh_.advertise<nav_msgs::Odometry>("odom", 20);
  timer_ = nh_.createTimer(ros::Duration(1.0 / params_.publish_rate),
                           [this](const ros::TimerEvent&) { publish(); });
  updater_.setHardwareID("own ship " + params_.ship);
  updater_.add("own ship sensors", this, &OwnShipNode::diagnose);
  diag_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  if (params_.navsat)
    subscribeNavSat();
  input_ = std::make_unique<NmeaInput>(
      nh_, params_.input, [this](const std::string& l, const ros::Time& t) { handleLine(l, t); });
  ROS_INFO("own_ship_node: input %s, origin %.6f %.6f, %s -> %s/base_link at %.1f Hz, own MMSI %u",
           input_->source().c_str(), map_origin_.get().lat_deg, map_origin_.get().lon_deg,
           params_.frame_id.c_str(), params_.ship.c_str(), params_.publish_rate, params_.own_mmsi);
}

void OwnShipNode::handleLine(const std::string& line, const ros::Time& stamp) {
  const double wall = asv_ros::wallNow();
  framer_.frame(line, [&](const asv::nmea::Sentence& s) {
    if (s.is("VDO") || s.is("VDM")) {
      asv::ais::Kinematics k;
      if (decoder_.feed(s, stamp.toSec(), message_) == asv::ais::Status::kMessage &&
          (message_.own_ship || (params_.own_mmsi != 0 && message_.mmsi == params_.own_mmsi)) &&
          asv::ais::toKinematics(message_, k) && k.has_position) {
        const auto* a = std::get_if<asv::ais::PositionReportA>(&message_.body);
        estimator_.aisReport(k.lat_deg, k.lon_deg, a && a->accuracy,
                             k.has_course ? std::optional<double>(k.course) : std::nullopt,
                             k.has_speed ? std::optional<double>(k.speed) : std::nullopt,
                             k.has_heading ? std::optional<double>(k.heading) : std::nullopt, stamp.toSec());
        ++ais_reports_;
      }
      return;
    }
    std::string why;
    const asv::OwnShipEstimator::Use u = estimator_.feed(s, stamp.toSec(), wall, why);
    if (u == asv::OwnShipEstimator::Use::kUsed) {
      ++used_[std::string(s.type)];
    } else if (u == asv::OwnShipEstimator::Use::kRejected) {
      last_rejection_ = why;
      ROS_WARN_THROTTLE(10.0, "own_ship_node: rejected %s; counted in diagnostics", why.c_str());
    }
  });
}

void OwnShipNode::subscribeNavSat() {
  fix_sub_ = nh_.subscribe("fix", 20, &OwnShipNode::fixCallback, this);
  vel_sub_ = nh_.subscribe("vel", 20, &OwnShipNode::velCallback, this);
  heading_sub_ = nh_.subscribe("heading", 20, &OwnShipNode::headingCallback, this);
  ROS_INFO("own_ship_node: also reading %s, %s and %s", fix_sub_.getTopic().c_str(),
           vel_sub_.getTopic().c_str(), heading_sub_.getTopic().c_str());
}

void OwnShipNode::reject(const std::string& why) {
  last_rejection_ = why;
  ROS_WARN_THROTTLE(10.0, "own_ship_node: rejected %s; counted in diagnostics", why.c_str());
}

// The receiver's own stamps are its clock, not ours: what it says is taken when it arrives, as a
// sentence is.
void OwnShipNode::fixCallback(const sensor_msgs::NavSatFix& msg) {
  asv::gnss::Fix fix;
  std::string why;
  if (!navSatToFix(msg, fix, why)) {
    ++navsat_rejected_;
    reject(why);
  } else if (estimator_.position(fix, "NavSatFix", ros::Time::now().toSec(), asv_ros::wallNow(), why) !=
             asv::OwnShipEstimator::Use::kUsed) {
    reject(why);  // a jump: counted by the estimator
  } else {
    ++used_["NavSatFix"];
  }
}

void OwnShipNode::velCallback(const geometry_msgs::TwistStamped& msg) {
  asv::gnss::Motion m;
  if (!enuTwistToMotion(msg, m)) {
    ++navsat_rejected_;
    reject("vel: a velocity that is no number");
    return;
  }
  estimator_.motion(m, ros::Time::now().toSec());
  ++used_["vel"];
}

void OwnShipNode::headingCallback(const geometry_msgs::QuaternionStamped& msg) {
  double h = 0.0;
  if (!orientationToHeading(msg, params_.navsat_heading_is_bearing, h)) {
    ++navsat_rejected_;
    reject("heading: a quaternion that is no rotation");
    return;
  }
  estimator_.heading(h, ros::Time::now().toSec(), asv_ros::wallNow());
  ++used_["heading"];
}

void OwnShipNode::publish() {
  const ros::Time now = ros::Time::now();
  if (now.isZero())
    return;
  const std::vector<asv::StaleInput> lost = estimator_.stale(now.toSec(), asv_ros::wallNow());
  const bool no_fix = !lost.empty() && lost.front().name == "fix";
  alarm_.update(lost, no_fix ? "no odometry: the position is unknown"
                             : "heading from the course over ground (or the last heading)");
  const std::optional<asv::OwnShipState> s = estimator_.state(now.toSec());
  if (!s || no_fix)
    return;  // a stale fix is not published as the ship's position: the stages below see it stop
  const std::string child = params_.ship + "/base_link";
  const nav_msgs::Odometry o = toOdometry(*s, params_.frame_id, child, now);
  odom_pub_.publish(o);
  geometry_msgs::TransformStamped t;
  t.header = o.header;
  t.child_frame_id = child;
  t.transform.translation.x = o.pose.pose.position.x;
  t.transform.translation.y = o.pose.pose.position.y;
  t.transform.rotation = o.pose.pose.orientation;
  if (!params_.odom_frame.empty()) {  // REP 105: map -> odom (the fixes' corrections) -> base_link
    odom_.update(now.toSec(), s->position, asv::courseSpeedToVelocity(s->course, s->speed));
    geometry_msgs::TransformStamped m;
    m.header = o.header;
    m.child_frame_id = params_.odom_frame;
    m.transform.translation.x = odom_.mapToOdom().x();
    m.transform.translation.y = odom_.mapToOdom().y();
    m.transform.rotation.w = 1.0;
    t.header.frame_id = params_.odom_frame;
    t.transform.translation.x = odom_.inOdom().x();
    t.transform.translation.y = odom_.inOdom().y();
    tf_.sendTransform(std::vector<geometry_msgs::TransformStamped>{m, t});
  } else {
    tf_.sendTransform(t);
  }
  ++published_;
}

void OwnShipNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  for (const auto& [type, n] : used_)
    stat.add("used " + type, n);
  stat.add("own AIS reports", ais_reports_);
  stat.add("rejected (invalid, no fix, jumps)", estimator_.rejected());
  if (params_.navsat)
    stat.add("rejected ROS inputs (fix, vel, heading)", navsat_rejected_);
  stat.add("position jumps", estimator_.jumps());
  stat.add("last rejection", last_rejection_);
  stat.add("odometry published", published_);
  const std::optional<asv::OwnShipState> s = estimator_.state(ros::Time::now().toSec());
  if (s) {
    stat.add("position source", s->position_source);
    stat.add("fix quality", static_cast<int>(s->quality));
    stat.add("position sigma [m]", s->position_sigma);
    stat.add("heading from course over ground", s->heading_from_cog);
  }
  input_->diagnose(stat);
  if (!s)
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no position, velocity or heading yet");
  else if (s->heading_from_cog)
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no heading sensor: course over ground stands in");
  else
    stat.summary(diagnostic_msgs::DiagnosticStatus::OK, "fix " + s->position_source);
  alarm_.diagnose(stat);
}

}  // namespace asv_risk
