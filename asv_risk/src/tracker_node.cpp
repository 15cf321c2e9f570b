#include "asv_risk/tracker_node.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <asv_core/common/units.h>
#include <asv_ros/conversions.h>
#include <asv_ros/params.h>

#include "asv_risk/target_quality.h"

namespace asv_risk {

const char* toString(TrackReject r) {
  switch (r) {
    case TrackReject::kFrame:
      return "wrong frame";
    case TrackReject::kSource:
      return "source not AIS/ARPA or no MMSI";
    case TrackReject::kNonFinite:
      return "non-finite value";
    case TrackReject::kFuture:
      return "stamped in the future";
    default:
      return "none";
  }
}

asv::TrackerNodeConfig loadTrackerParams(const ros::NodeHandle& pnh) {
  return asv_ros::loadConfig<asv::TrackerNodeConfig>(pnh, "config/tracker.yaml");
}

TrackReject targetToReport(const asv_msgs::Target& t, const ros::Time& array_stamp,
                           const asv::TrackerNodeConfig& p, asv::TrackReport& r) {
  r = asv::TrackReport();
  if (t.source == asv_msgs::Target::SOURCE_AIS) {
    if (t.mmsi == 0)
      return TrackReject::kSource;
    r.source = asv::TrackSource::kAis;
    r.mmsi = t.mmsi;
    r.ais_class = t.ais_class == asv_msgs::Target::AIS_CLASS_B   ? asv::AisClass::kB
                  : t.ais_class == asv_msgs::Target::AIS_CLASS_A ? asv::AisClass::kA
                                                                 : asv::AisClass::kNone;
    r.velocity_variance = p.ais_velocity_sigma * p.ais_velocity_sigma;
  } else if (t.source == asv_msgs::Target::SOURCE_ARPA) {
    r.source = asv::TrackSource::kArpa;
    r.arpa_number = t.arpa_number;
    r.velocity_variance = p.arpa_velocity_sigma * p.arpa_velocity_sigma;
  } else {
    return TrackReject::kSource;
  }
  const ros::Time stamp = t.stamp.isZero() ? array_stamp : t.stamp;
  r.time = stamp.toSec();
  r.position = {t.position.x, t.position.y};
  r.has_velocity = hasVelocity(t.quality);
  r.velocity = {t.velocity.x, t.velocity.y};
  const auto& c = t.position_covariance;
  if (!asv::allFinite({r.position.x(), r.position.y(), c[0], c[1], c[2], c[3]}) ||
      (r.has_velocity && !r.velocity.allFinite()))
    return TrackReject::kNonFinite;
  const double var = 0.5 * (c[0] + c[3]);
  r.position_variance = var > 0.0 ? var : p.default_position_sigma * p.default_position_sigma;
  r.quality = std::min<double>(t.quality, 100.0);
  return TrackReject::kNone;
}

TrackerNode::TrackerNode(ros::NodeHandle nh, ros::NodeHandle pnh)
    : nh_(nh), pnh_(pnh), params_(loadTrackerParams(pnh)), tracker_(params_.tracker) {
  targets_pub_ = nh_.advertise<asv_msgs::TargetArray>("targets", 10);
  // Each input counts for the watch (an empty array is the ingestion node's heartbeat).
  auto watched = [this](const ros::Subscriber* sub) {
    return [this, sub](const asv_msgs::TargetArray::ConstPtr& msg) {
      watch_.received(sub->getTopic(), asv_ros::rosNow(), asv_ros::wallNow());
      targetsCallback(msg);
    };
  };
  ais_sub_ = lockstep_.subscribe<asv_msgs::TargetArray>("ais/targets", 50, watched(&ais_sub_));
  arpa_sub_ = lockstep_.subscribe<asv_msgs::TargetArray>("arpa/targets", 50, watched(&arpa_sub_));
  watch_.add(ais_sub_.getTopic());
  watch_.add(arpa_sub_.getTopic());
  // Free-running only: in lockstep a node that stops stops the simulation (lockstep_timeout, ERROR).
  if (!lockstep_.enabled())
    lockstep_.every(asv_ros::kWatchPeriod, [this] { watchInputs(ros::Time::now()); });
  lockstep_.every(1.0 / params_.publish_rate, [this] { publish(); });
  lockstep_.start();
  updater_.setHardwareID("tracker");
  updater_.add("tracks", this, &TrackerNode::diagnose);
  diag_timer_ = nh_.createTimer(ros::Duration(1.0), [this](const ros::TimerEvent&) { updater_.update(); });
  diag_time_ = ros::WallTime::now();
  ROS_INFO("tracker: %s + %s -> %s at %.1f Hz, gate max(%.0f m, %.1f sigma), velocity gate %.1f m/s",
           ais_sub_.getTopic().c_str(), arpa_sub_.getTopic().c_str(), targets_pub_.getTopic().c_str(),
           params_.publish_rate, params_.tracker.gate_min, params_.tracker.gate_sigmas,
           params_.tracker.velocity_gate);
}

void TrackerNode::reject(TrackReject why, const std::string& id) {
  ++rejected_[static_cast<std::size_t>(why)];
  ROS_WARN_THROTTLE(10.0, "tracker: report '%s' rejected (%s); counted in diagnostics", id.c_str(),
                    toString(why));
}

void TrackerNode::targetsCallback(const asv_msgs::TargetArray::ConstPtr& msg) {
  std::string frame = msg->header.frame_id;
  if (!frame.empty() && frame[0] == '/')
    frame.erase(0, 1);
  const ros::Time now = ros::Time::now();
  checkClock(now);
  for (const asv_msgs::Target& t : msg->targets) {
    if (frame != params_.frame_id) {
      reject(TrackReject::kFrame, t.id);
      continue;
    }
    asv::TrackReport r;
    TrackReject why = targetToReport(t, msg->header.stamp, params_, r);
    if (why == TrackReject::kNone && r.time - now.toSec() > params_.future_tolerance)
      why = TrackReject::kFuture;
    if (why != TrackReject::kNone) {
      reject(why, t.id);
      continue;
    }
    const asv::UpdateResult u = tracker_.update(r);
    if (u == asv::UpdateResult::kInvalid || u == asv::UpdateResult::kFull) {
      ROS_WARN_THROTTLE(10.0, "tracker: report '%s' not tracked (%s)", t.id.c_str(),
                        asv::updateResultText(u));
      continue;
    }
    if (u == asv::UpdateResult::kOld)
      continue;
    if (r.source == asv::TrackSource::kAis)
      ais_meta_[r.mmsi] = t;
    else
      arpa_meta_[r.arpa_number] = t;
  }
}

asv_msgs::Target TrackerNode::toMsg(const asv::TrackEstimate& e) const {
  asv_msgs::Target t;
  const asv_msgs::Target* ais = nullptr;
  if (e.mmsi != 0) {
    auto it = ais_meta_.find(e.mmsi);
    if (it != ais_meta_.end())
      ais = &it->second;
  }
  const asv_msgs::Target* arpa = nullptr;
  if (e.arpa_number >= 0) {
    auto it = arpa_meta_.find(e.arpa_number);
    if (it != arpa_meta_.end())
      arpa = &it->second;
  }
  if (ais) {  // static data, status and heading from the last AIS report
    t = *ais;
  } else if (arpa) {
    t.name = arpa->name;
    t.nav_status = 15;
  } else {
    t.nav_status = 15;
  }
  t.has_geodetic = false;  // the track moved since that report; map positions only
  t.latitude = t.longitude = 0.0;
  t.id = "track:" + std::to_string(e.id);
  t.source = static_cast<uint8_t>(e.source);
  t.ais_class = static_cast<uint8_t>(e.ais_class);
  t.mmsi = e.mmsi;
  t.arpa_number = e.arpa_number >= 0 ? static_cast<uint16_t>(e.arpa_number) : 0;
  t.position.x = e.position.x();
  t.position.y = e.position.y();
  t.position.z = 0.0;
  t.velocity.x = e.velocity.x();
  t.velocity.y = e.velocity.y();
  t.velocity.z = 0.0;
  t.speed_over_ground = e.velocity.norm();
  t.course_over_ground = e.has_velocity && t.speed_over_ground > 0.0 ? asv::courseOf(e.velocity) : 0.0;
  if (ais && e.source == asv::TrackSource::kArpa) {
    t.has_heading = t.has_rate_of_turn = false;  // the AIS part is gone: its heading is stale
    t.heading = t.rate_of_turn = 0.0;
  }
  t.stamp = ros::Time(std::max(0.0, e.last_report));
  t.age = e.age;
  t.position_covariance = {e.position_variance, 0.0, 0.0, e.position_variance};
  double q = std::clamp(e.quality, 0.0, 100.0);
  if (!e.has_velocity)
    q = std::min<double>(q, kQualityNoVelocity);
  t.quality = static_cast<uint8_t>(std::lround(q));
  return t;
}

bool TrackerNode::checkClock(const ros::Time& now) {
  return asv_ros::resetOnClockJump(clock_, updater_, now, [this] {
    std::string what = std::to_string(tracker_.tracks().size()) + " tracks dropped";
    tracker_.clear();
    watch_.reset();
    ais_meta_.clear();
    arpa_meta_.clear();
    return what;
  });
}

void TrackerNode::watchInputs(const ros::Time& now) {
  if (!now.isZero())
    alarm_.update(watch_.stale(now.toSec(), asv_ros::wallNow()), "tracks coast on their last reports");
}

void TrackerNode::publish() {
  const ros::Time now = ros::Time::now();
  checkClock(now);
  tracker_.maintain(now.toSec());
  asv_msgs::TargetArray arr;
  arr.header.stamp = now;
  arr.header.frame_id = params_.frame_id;
  alive_ = coasting_ = fused_ = 0;
  std::set<std::uint32_t> mmsis;
  std::set<int> numbers;
  for (const asv::TrackEstimate& e : tracker_.estimates(now.toSec())) {
    arr.targets.push_back(toMsg(e));
    ++alive_;
    coasting_ += e.coasting;
    fused_ += e.source == asv::TrackSource::kFused;
    mmsis.insert(e.mmsi);
    numbers.insert(e.arpa_number);
  }
  // Metadata of ships no track refers to any more (bounded memory).
  for (auto it = ais_meta_.begin(); it != ais_meta_.end();)
    it = mmsis.count(it->first) ? std::next(it) : ais_meta_.erase(it);
  for (auto it = arpa_meta_.begin(); it != arpa_meta_.end();)
    it = numbers.count(it->first) ? std::next(it) : arpa_meta_.erase(it);
  lockstep_.publish(targets_pub_, arr);
}

void TrackerNode::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) {
  const ros::WallTime now = ros::WallTime::now();
  const double dt = std::max(1e-3, (now - diag_time_).toSec());
  const asv::TrackerCounters& c = tracker_.counters();
  std::uint64_t rejected = 0;
  for (std::size_t i = 1; i < static_cast<std::size_t>(TrackReject::kCount); ++i) {
    stat.add(std::string("rejected: ") + toString(static_cast<TrackReject>(i)), rejected_[i]);
    rejected += rejected_[i];
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(asv::UpdateResult::kCount); ++i)
    stat.add(std::string("reports ") + asv::updateResultText(static_cast<asv::UpdateResult>(i)),
             c.results[i]);
  rejected += c.results[static_cast<std::size_t>(asv::UpdateResult::kInvalid)] +
              c.results[static_cast<std::size_t>(asv::UpdateResult::kFull)];
  stat.add("reports per second", (c.reports - diag_reports_) / dt);
  stat.add("tracks alive", alive_);
  stat.add("tracks coasting", coasting_);
  stat.add("tracks fused", fused_);
  stat.add("track-to-track merges", c.merged);
  stat.add("radar pairings split", c.split);
  stat.add("tracks dropped", c.dropped);
  stat.add("clock jumps back (state reset)", clock_.jumps());
  if (rejected > diag_rejected_)
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::WARN, "%lu reports rejected since the last report",
                  static_cast<unsigned long>(rejected - diag_rejected_));
  else
    stat.summaryf(diagnostic_msgs::DiagnosticStatus::OK, "%zu tracks (%zu fused, %zu coasting)", alive_,
                  fused_, coasting_);
  diag_time_ = now;
  diag_reports_ = c.reports;
  diag_rejected_ = rejected;
  alarm_.diagnose(stat);
}

}  // namespace asv_risk
