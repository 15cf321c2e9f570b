#include "asv_risk/arpa_node.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <asv_core/common/units.h>
#include <asv_ros/conversions.h>

#include "asv_risk/heartbeat.h"
#include "asv_risk/params.h"
#include "asv_risk/target_quality.h"

namespace asv_risk {

namespace {

std::int64_t nanoseconds(const ros::Time& t) {
  return static_cast<std::int64_t>(t.toNSec());
}

ArpaReject toReject(asv::ArpaOutcome o) {
  switch (o) {
    case asv::ArpaOutcome::NoNumber:
      return ArpaReject::kNoNumber;
    case asv::ArpaOutcome::NoPosition:
      return ArpaReject::kNoPosition;
    case asv::ArpaOutcome::NoOwnPosition:
      return ArpaReject::kNoOwnPosition;
    case asv::ArpaOutcome::NoOwnHeading:
      return ArpaReject::kNoOwnHeading;
    case asv::ArpaOutcome::OutOfRange:
      return ArpaReject::kOutOfRange;
    default:
      return ArpaReject::kNone;
  }
}

std::uint8_t toQuality(asv::ArpaQuality q) {
  switch (q) {
    case asv::ArpaQuality::Tracking:
      return kQualityArpa;
    case asv::ArpaQuality::Acquiring:
      return kQualityAcquiring;
    default:
      return kQualityNoVelocity;
  }
}

// The message a target is published as.
asv_msgs::Target toMsg(const asv::ArpaTarget& r, double age) {
  asv_msgs::Target t;
  t.id = "arpa:" + std::to_string(r.number);
  t.source = asv_msgs::Target::SOURCE_ARPA;
  t.arpa_number = static_cast<uint16_t>(r.number);
  t.nav_status = 15;  // not defined: a radar does not know it
  t.name = r.name;
  t.position.x = r.position.x();
  t.position.y = r.position.y();
  t.has_geodetic = r.has_geodetic;
  t.latitude = r.lat_deg;
  t.longitude = r.lon_deg;
  t.course_over_ground = r.course;
  t.speed_over_ground = r.speed;
  t.velocity.x = r.velocity.x();
  t.velocity.y = r.velocity.y();
  const Eigen::Matrix2d& c = r.covariance;
  t.position_covariance = {c(0, 0), c(0, 1), c(1, 0), c(1, 1)};
  t.quality = toQuality(r.quality());
  t.stamp.fromNSec(static_cast<std::uint64_t>(r.stamp_ns));
  t.age = std::max(0.0, age);
  return t;
}

}  // namespace

const char* toString(ArpaReject r) {
  switch (r) {
    case ArpaReject::kNoNumber:
      return "no usable target number";
    case ArpaReject::kNoPosition:
      return "no range/bearing or position";
    case ArpaReject::kNoOwnPosition:
      return "no recent own position (odom)";
    case ArpaReject::kNoOwnHeading:
      return "relative bearing/course without a recent own heading";
    case ArpaReject::kOutOfRange:
      return "beyond max_range";
    case ArpaReject::kOdom:
      return "odometry unusable (frame or values)";
    default:
      return "none";
  }
}

ArpaNodeParams loadArpaParams(const ros::NodeHandle& pnh) {
  NmeaInputParams input;
  input.frame_id = "radar";
  input.udp_port = 10111;
  input.tcp_port = 10111;
  input.serial_baud = 4800;
  return loadIngestionParams<asv::ArpaNodeConfig>(pnh, input, "config/arpa_node.yaml");
}

ArpaNode::ArpaNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh),
      pnh_(pnh),
      params_(loadArpaParams(pnh)),
      map_origin_(nh, givenOrigin(params_)),
      frame_(map_origin_.get().lat_deg, map_origin_.get().lon_deg),
      framer_([this] {
        asv::nmea::FramerConfig c;
        c.max_length = params_.max_sentence_length;
        return c;
      }()),
      table_(params_.targets, frame_) {
  targets_pub_ = nh_.advertise<asv_msgs::TargetArray>("arpa/targets", 10);
  odom_sub_ = lockstep_.subscribe("odom", 20, &ArpaNode::odomCallback, this, false);
  // Each array holds what was reported since the last: nothing new, nothing to publish.
  lockstep_.every(
      1.0 / params_.publish_rate, [this] { publish(); }, true);
  // Free-running only: in lockstep a node that stops stops the simulation (lockstep_timeout).
  if (!lockstep_.enabled())
    lockstep_.every(params_.heartbeat_period, [this] { heartbeat(); });
  updater_.setHardwareID("radar");
  updater_.add("arpa input", this, &ArpaNode::diagnose);
  diag_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  last_sentence_ = diag_time_ = ros::WallTime::now();
  input_ = std::make_unique<NmeaInput>(
      nh_, params_.input, [this](const std::string& l, const ros::Time& t) { handleLine(l, t); }, &lockstep_);
  lockstep_.start();
  ROS_INFO("arpa_node: input %s, origin %.6f %.6f, own ship from %s, targets on %s", input_->source().c_str(),
           map_origin_.get().lat_deg, map_origin_.get().lon_deg, odom_sub_.getTopic().c_str(),
           targets_pub_.getTopic().c_str());
}

void ArpaNode::checkClock() {
  asv_ros::resetOnClockJump(clock_, updater_, ros::Time::now(), [this] {
    std::string what = std::to_string(table_.size()) + " radar targets and the own ship forgotten";
    table_.clear();
    return what;
  });
}

void ArpaNode::handleLine(const std::string& line, const ros::Time& stamp) {
  checkClock();
  framer_.frame(line, [&](const asv::nmea::Sentence& s) {
    last_sentence_ = ros::WallTime::now();
    handleSentence(s, stamp);
  });
}

void ArpaNode::handleSentence(const asv::nmea::Sentence& s, const ros::Time& stamp) {
  if (s.is("TTM"))
    handleTtm(s, stamp);
  else if (s.is("TLL"))
    handleTll(s, stamp);
  else if (s.is("OSD"))
    handleOsd(s, stamp);
  else
    ++other_;
}

void ArpaNode::reject(ArpaReject why, int number) {
  ++rejected_[static_cast<std::size_t>(why)];
  ROS_WARN_THROTTLE(10.0, "arpa_node: radar target %d rejected (%s); counted in diagnostics", number,
                    toString(why));
}

void ArpaNode::parseError(asv::arpa::Error e, const char* type) {
  ++parse_errors_[static_cast<std::size_t>(e)];
  ROS_WARN_THROTTLE(10.0, "arpa_node: %s rejected (%s); counted in diagnostics", type,
                    asv::arpa::errorText(e));
}

void ArpaNode::handleTtm(const asv::nmea::Sentence& s, const ros::Time& stamp) {
  ++ttm_;
  asv::arpa::TrackedTarget tt;
  const asv::arpa::Error e = asv::arpa::parseTtm(s, tt, params_.arpa);
  if (e != asv::arpa::Error::kNone) {
    parseError(e, "TTM");
    return;
  }
  const ArpaReject r = toReject(table_.ttm(tt, nanoseconds(stamp)));
  if (r != ArpaReject::kNone)
    reject(r, tt.number);
}

void ArpaNode::handleTll(const asv::nmea::Sentence& s, const ros::Time& stamp) {
  ++tll_;
  asv::arpa::TargetPosition tp;
  const asv::arpa::Error e = asv::arpa::parseTll(s, tp, params_.arpa);
  if (e != asv::arpa::Error::kNone) {
    parseError(e, "TLL");
    return;
  }
  const ArpaReject r = toReject(table_.tll(tp, nanoseconds(stamp)));
  if (r != ArpaReject::kNone)
    reject(r, tp.number);
}

void ArpaNode::handleOsd(const asv::nmea::Sentence& s, const ros::Time& stamp) {
  ++osd_;
  asv::arpa::OwnShipData o;
  const asv::arpa::Error e = asv::arpa::parseOsd(s, o, params_.arpa);
  if (e != asv::arpa::Error::kNone) {
    parseError(e, "OSD");
    return;
  }
  if (o.has_heading && o.heading_valid)
    table_.osdHeading(o.heading, nanoseconds(stamp));
}

void ArpaNode::odomCallback(const nav_msgs::Odometry::ConstPtr& msg) {
  checkClock();
  std::string frame = msg->header.frame_id;
  if (!frame.empty() && frame[0] == '/')
    frame.erase(0, 1);
  // The one odometry converter every node uses (its checks: finite values, a rotation, a ship's speed).
  asv::ShipState own;
  if (frame != params_.frame_id || asv_ros::odometryToShipState(*msg, "own", own) != asv_ros::Reject::None) {
    reject(ArpaReject::kOdom, -1);
    return;
  }
  const ros::Time stamp = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
  table_.ownShip(own.position, own.heading, nanoseconds(stamp));
}

void ArpaNode::publish() {
  checkClock();
  const ros::Time now = ros::Time::now();
  asv_msgs::TargetArray arr;
  arr.header.stamp = now;
  arr.header.frame_id = params_.frame_id;
  table_.due(nanoseconds(now),
             [&](const asv::ArpaTarget& t, double age) { arr.targets.push_back(toMsg(t, age)); });
  if (arr.targets.empty())
    return;
  lockstep_.publish(targets_pub_, arr);
  last_publish_ = now;
  ++published_;
}

void ArpaNode::heartbeat() {
  if (!input_ || !input_->linkUp())
    return;  // a link that is down is silence the tracker must see
  if (auto arr = heartbeatArray(ros::Time::now(), last_publish_, params_.heartbeat_period, params_.frame_id))
    lockstep_.publish(targets_pub_, *arr);
}

void ArpaNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  const ros::WallTime now = ros::WallTime::now();
  const double dt = std::max(1e-3, (now - diag_time_).toSec());
  std::uint64_t rejected = framer_.totalRejected();
  for (std::size_t i = 1; i < static_cast<std::size_t>(ArpaReject::kCount); ++i) {
    stat.add(std::string("rejected: ") + toString(static_cast<ArpaReject>(i)), rejected_[i]);
    rejected += rejected_[i];
  }
  for (std::size_t i = 1; i < static_cast<std::size_t>(asv::arpa::Error::kCount); ++i) {
    stat.add(std::string("parse errors: ") + asv::arpa::errorText(static_cast<asv::arpa::Error>(i)),
             parse_errors_[i]);
    rejected += parse_errors_[i];
  }
  stat.add("sentences per second", (framer_.sentences() - diag_sentences_) / dt);
  addFramerStats(framer_, stat);
  stat.add("TTM", ttm_);
  stat.add("TLL", tll_);
  stat.add("OSD", osd_);
  stat.add("other sentences", other_);
  stat.add("targets lost (status L)", table_.lost());
  stat.add("targets forgotten (table full)", table_.evicted());
  stat.add("targets known", table_.size());
  stat.add("own position known", table_.hasOwnShip());
  stat.add("target arrays published", published_);
  stat.add("clock jumps back (state reset)", clock_.jumps());
  input_->diagnose(stat);
  const NmeaInputStats in = input_->stats();
  const double silent = (now - last_sentence_).toSec();
  if (!in.connected && !in.finished && params_.input.type != "topic")
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::ERROR, "input %s not connected",
                  input_->source().c_str());
  else if (silent > params_.silence_warning)
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::WARN, "no sentence for %.0f s", silent);
  else if (in.drops() > diag_drops_)
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::WARN,
                  "%lu input lines dropped since the last report (overload)",
                  static_cast<unsigned long>(in.drops() - diag_drops_));
  else if (rejected > diag_rejected_)
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::WARN, "%lu inputs rejected since the last report",
                  static_cast<unsigned long>(rejected - diag_rejected_));
  else if (!table_.hasOwnShip())
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no own-ship odometry: TTM cannot be placed");
  else
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::OK, "%zu radar targets", table_.size());
  diag_time_ = now;
  diag_sentences_ = framer_.sentences();
  diag_rejected_ = rejected;
  diag_drops_ = in.drops();
}

}  // namespace asv_risk
