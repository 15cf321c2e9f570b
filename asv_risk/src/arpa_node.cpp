#include "asv_risk/arpa_node.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <asv_core/common/units.h>
#include <asv_core/tracking/radar_fix.h>
#include <asv_ros/conversions.h>

#include "asv_risk/params.h"
#include "asv_risk/target_quality.h"

namespace asv_risk {

namespace {

std::set<std::string> knownKeys() {
  std::set<std::string> k = ingestionKeys();
  k.insert({"odom_timeout", "range_sigma", "range_sigma_fraction", "bearing_sigma_deg", "tll_sigma",
            "max_distance", "max_speed"});
  return k;
}

constexpr int kMaxTargetNumber = 65535;  // Target.arpa_number is a uint16

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
  checkUnknownParams(pnh, knownKeys(), "config/arpa_node.yaml");
  ArpaNodeParams p;
  loadIngestionParams(pnh, p);
  getParam(pnh, "odom_timeout", p.odom_timeout);
  getParam(pnh, "range_sigma", p.range_sigma);
  getParam(pnh, "range_sigma_fraction", p.range_sigma_fraction);
  getParam(pnh, "bearing_sigma_deg", p.bearing_sigma_deg);
  getParam(pnh, "tll_sigma", p.tll_sigma);
  getParam(pnh, "max_distance", p.arpa.max_distance);
  getParam(pnh, "max_speed", p.arpa.max_speed);
  p.arpa.validate();
  if (!(p.odom_timeout > 0.0))
    throw std::invalid_argument("odom_timeout must be > 0 s");
  if (!(p.range_sigma > 0.0 && p.range_sigma_fraction >= 0.0 && p.bearing_sigma_deg > 0.0 &&
        p.tll_sigma > 0.0))
    throw std::invalid_argument(
        "range_sigma, bearing_sigma_deg, tll_sigma must be > 0, range_sigma_fraction >= 0");
  return p;
}

ArpaNode::ArpaNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh),
      pnh_(pnh),
      params_(loadArpaParams(pnh)),
      frame_(params_.origin_lat_deg, params_.origin_lon_deg),
      framer_([this] {
        asv::nmea::FramerConfig c;
        c.max_length = params_.max_sentence_length;
        return c;
      }()) {
  targets_pub_ = nh_.advertise<asv_msgs::TargetArray>("arpa/targets", 10);
  odom_sub_ = lockstep_.subscribe("odom", 20, &ArpaNode::odomCallback, this, false);
  // Each array holds what was reported since the last: nothing new, nothing to publish.
  lockstep_.every(
      1.0 / params_.publish_rate, [this] { publish(); }, true);
  updater_.setHardwareID("radar");
  updater_.add("arpa input", this, &ArpaNode::diagnose);
  diag_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  last_sentence_ = diag_time_ = ros::WallTime::now();
  input_ = std::make_unique<NmeaInput>(
      nh_, params_.input, [this](const std::string& l, const ros::Time& t) { handleLine(l, t); }, &lockstep_);
  lockstep_.start();
  ROS_INFO("arpa_node: input %s, origin %.6f %.6f, own ship from %s, targets on %s", input_->source().c_str(),
           params_.origin_lat_deg, params_.origin_lon_deg, odom_sub_.getTopic().c_str(),
           targets_pub_.getTopic().c_str());
}

void ArpaNode::checkClock() {
  asv_ros::resetOnClockJump(clock_, updater_, ros::Time::now(), [this] {
    std::string what = std::to_string(radars_.size()) + " radar targets and the own ship forgotten";
    radars_.clear();
    has_odom_ = has_osd_heading_ = false;
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

ArpaNode::Radar* ArpaNode::radar(int number, const ros::Time& stamp) {
  auto it = radars_.find(number);
  if (it != radars_.end())
    return &it->second;
  if (radars_.size() >= params_.max_targets) {
    auto oldest = std::min_element(radars_.begin(), radars_.end(), [](const auto& a, const auto& b) {
      return a.second.target.stamp < b.second.target.stamp;
    });
    radars_.erase(oldest);
  }
  Radar& r = radars_[number];
  r.target.id = "arpa:" + std::to_string(number);
  r.target.source = asv_msgs::Target::SOURCE_ARPA;
  r.target.arpa_number = static_cast<uint16_t>(number);
  r.target.nav_status = 15;
  r.target.stamp = stamp;
  return &r;
}

bool ArpaNode::ownHeading(const ros::Time& stamp, double& heading) const {
  if (has_odom_ && std::abs((stamp - odom_stamp_).toSec()) <= params_.odom_timeout) {
    heading = own_heading_;
    return true;
  }
  if (has_osd_heading_ && std::abs((stamp - osd_stamp_).toSec()) <= params_.odom_timeout) {
    heading = osd_heading_;
    return true;
  }
  return false;
}

void ArpaNode::setVelocity(Radar& r, const asv::arpa::TrackedTarget& tt) {
  asv_msgs::Target& t = r.target;
  double course = 0.0, speed = 0.0;
  if (tt.has_speed && tt.has_course) {
    course = tt.course;
    speed = tt.speed;
  } else if (tt.has_speed && tt.speed == 0.0) {
    speed = 0.0;
  } else {
    r.has_velocity = false;
    t.course_over_ground = t.speed_over_ground = 0.0;
    t.velocity.x = t.velocity.y = 0.0;
    return;
  }
  r.has_velocity = true;
  t.course_over_ground = asv::wrapTwoPi(course);
  t.speed_over_ground = speed;
  const Eigen::Vector2d v = asv::courseSpeedToVelocity(course, speed);
  t.velocity.x = v.x();
  t.velocity.y = v.y();
}

void ArpaNode::handleTtm(const asv::nmea::Sentence& s, const ros::Time& stamp) {
  ++ttm_;
  asv::arpa::TrackedTarget tt;
  const asv::arpa::Error e = asv::arpa::parseTtm(s, tt, params_.arpa);
  if (e != asv::arpa::Error::kNone) {
    parseError(e, "TTM");
    return;
  }
  if (tt.number < 0 || tt.number > kMaxTargetNumber) {
    reject(ArpaReject::kNoNumber, tt.number);
    return;
  }
  if (tt.status == asv::arpa::TargetStatus::kLost) {
    lost_ += radars_.erase(tt.number);
    return;
  }
  double heading = asv::arpa::kNaN;
  ownHeading(stamp, heading);
  if (!asv::arpa::toTrue(tt, heading)) {
    reject(ArpaReject::kNoOwnHeading, tt.number);
    return;
  }
  if (!tt.has_distance || !tt.has_bearing) {
    reject(ArpaReject::kNoPosition, tt.number);
    return;
  }
  if (!has_odom_ || std::abs((stamp - odom_stamp_).toSec()) > params_.odom_timeout) {
    reject(ArpaReject::kNoOwnPosition, tt.number);
    return;
  }
  const asv::RadarFix fix =
      asv::radarFix(own_position_, tt.distance, tt.bearing,
                    {params_.range_sigma, params_.range_sigma_fraction, params_.bearing_sigma_deg});
  const Eigen::Vector2d& p = fix.position;
  Radar& r = *radar(tt.number, stamp);
  asv_msgs::Target& t = r.target;
  t.position.x = p.x();
  t.position.y = p.y();
  t.has_geodetic = false;
  const asv::GeoPoint g = frame_.toGeodetic(p);
  if (std::isfinite(g.lat_deg) && std::isfinite(g.lon_deg)) {
    t.has_geodetic = true;
    t.latitude = g.lat_deg;
    t.longitude = g.lon_deg;
  }
  setVelocity(r, tt);
  if (!tt.name.empty())
    t.name = tt.name;
  const Eigen::Matrix2d& cov = fix.covariance;
  t.position_covariance = {cov(0, 0), cov(0, 1), cov(1, 0), cov(1, 1)};
  t.quality = !r.has_velocity                                ? kQualityNoVelocity
              : tt.status == asv::arpa::TargetStatus::kQuery ? kQualityAcquiring
                                                             : kQualityArpa;
  t.stamp = stamp;
  r.dirty = true;
}

void ArpaNode::handleTll(const asv::nmea::Sentence& s, const ros::Time& stamp) {
  ++tll_;
  asv::arpa::TargetPosition tp;
  const asv::arpa::Error e = asv::arpa::parseTll(s, tp, params_.arpa);
  if (e != asv::arpa::Error::kNone) {
    parseError(e, "TLL");
    return;
  }
  if (tp.number < 0 || tp.number > kMaxTargetNumber) {
    reject(ArpaReject::kNoNumber, tp.number);
    return;
  }
  if (tp.status == asv::arpa::TargetStatus::kLost) {
    lost_ += radars_.erase(tp.number);
    return;
  }
  if (!tp.has_position || !asv::validLatLon(tp.lat_deg, tp.lon_deg)) {
    reject(ArpaReject::kNoPosition, tp.number);
    return;
  }
  const Eigen::Vector2d p = frame_.toLocal(tp.lat_deg, tp.lon_deg);
  if (!(p.allFinite() && p.norm() <= params_.max_range)) {
    reject(ArpaReject::kOutOfRange, tp.number);
    return;
  }
  Radar& r = *radar(tp.number, stamp);
  asv_msgs::Target& t = r.target;
  t.position.x = p.x();
  t.position.y = p.y();
  t.has_geodetic = true;
  t.latitude = tp.lat_deg;
  t.longitude = tp.lon_deg;
  if (!tp.name.empty())
    t.name = tp.name;
  const double v = params_.tll_sigma * params_.tll_sigma;
  t.position_covariance = {v, 0.0, 0.0, v};
  if (!r.has_velocity)
    t.quality = kQualityNoVelocity;
  else if (t.quality == 0)
    t.quality = kQualityArpa;
  t.stamp = stamp;
  r.dirty = true;
}

void ArpaNode::handleOsd(const asv::nmea::Sentence& s, const ros::Time& stamp) {
  ++osd_;
  asv::arpa::OwnShipData o;
  const asv::arpa::Error e = asv::arpa::parseOsd(s, o, params_.arpa);
  if (e != asv::arpa::Error::kNone) {
    parseError(e, "OSD");
    return;
  }
  if (o.has_heading && o.heading_valid) {
    has_osd_heading_ = true;
    osd_heading_ = o.heading;
    osd_stamp_ = stamp;
  }
}

void ArpaNode::odomCallback(const nav_msgs::Odometry::ConstPtr& msg) {
  checkClock();
  const auto& q = msg->pose.pose.orientation;
  const auto& x = msg->pose.pose.position;
  std::string frame = msg->header.frame_id;
  if (!frame.empty() && frame[0] == '/')
    frame.erase(0, 1);
  const double n = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
  if (frame != params_.frame_id || !asv::allFinite({x.x, x.y, q.x, q.y, q.z, q.w}) || !(n > 0.5 && n < 1.5)) {
    reject(ArpaReject::kOdom, -1);
    return;
  }
  const double yaw = std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
  has_odom_ = true;
  own_position_ = {x.x, x.y};
  own_heading_ = asv::yawToCourse(yaw);
  odom_stamp_ = msg->header.stamp.isZero() ? ros::Time::now() : msg->header.stamp;
}

void ArpaNode::publish() {
  checkClock();
  const ros::Time now = ros::Time::now();
  asv_msgs::TargetArray arr;
  arr.header.stamp = now;
  arr.header.frame_id = params_.frame_id;
  for (auto it = radars_.begin(); it != radars_.end();) {
    Radar& r = it->second;
    const double age = (now - r.target.stamp).toSec();
    if (age > params_.forget_after) {
      it = radars_.erase(it);
      continue;
    }
    if (r.dirty) {
      r.target.age = std::max(0.0, age);
      arr.targets.push_back(r.target);
      r.dirty = false;
    }
    ++it;
  }
  if (arr.targets.empty())
    return;
  lockstep_.publish(targets_pub_, arr);
  ++published_;
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
  framer_.diagnose(stat);
  stat.add("TTM", ttm_);
  stat.add("TLL", tll_);
  stat.add("OSD", osd_);
  stat.add("other sentences", other_);
  stat.add("targets lost (status L)", lost_);
  stat.add("targets known", radars_.size());
  stat.add("own position known", has_odom_);
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
  else if (!has_odom_)
    stat.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no own-ship odometry: TTM cannot be placed");
  else
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::OK, "%zu radar targets", radars_.size());
  diag_time_ = now;
  diag_sentences_ = framer_.sentences();
  diag_rejected_ = rejected;
  diag_drops_ = in.drops();
}

}  // namespace asv_risk
