#include "asv_core/tracking/arpa_targets.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "asv_core/common/units.h"

namespace asv {

namespace {

constexpr int kMaxTargetNumber = 65535;  // target numbers travel as uint16 on the targets topic

}  // namespace

void ArpaTargetConfig::validate() const {
  if (!(max_range > 0.0) || !(forget_after > 0.0) || max_targets < 1)
    throw std::invalid_argument("max_range and forget_after must be > 0, max_targets >= 1");
  if (!(odom_timeout > 0.0))
    throw std::invalid_argument("odom_timeout must be > 0 s");
  if (!(sigmas.range > 0.0 && sigmas.range_fraction >= 0.0 && sigmas.bearing_deg > 0.0 && tll_sigma > 0.0))
    throw std::invalid_argument(
        "range_sigma, bearing_sigma_deg, tll_sigma must be > 0, range_sigma_fraction >= 0");
}

ArpaQuality ArpaTarget::quality() const {
  if (!has_velocity)
    return ArpaQuality::NoVelocity;
  return acquiring ? ArpaQuality::Acquiring : ArpaQuality::Tracking;
}

ArpaTargetTable::ArpaTargetTable(const ArpaTargetConfig& cfg, const LocalFrame& frame)
    : cfg_(cfg), frame_(frame) {
  cfg_.validate();
}

void ArpaTargetTable::ownShip(const Eigen::Vector2d& position, double heading, std::int64_t stamp_ns) {
  has_own_ = true;
  own_position_ = position;
  own_heading_ = heading;
  own_stamp_ns_ = stamp_ns;
}

void ArpaTargetTable::osdHeading(double heading, std::int64_t stamp_ns) {
  has_osd_heading_ = true;
  osd_heading_ = heading;
  osd_stamp_ns_ = stamp_ns;
}

void ArpaTargetTable::clear() {
  targets_.clear();
  has_own_ = has_osd_heading_ = false;
}

bool ArpaTargetTable::fresh(std::int64_t stamp_ns, std::int64_t now_ns) const {
  return std::abs(spanSeconds(now_ns - stamp_ns)) <= cfg_.odom_timeout;
}

ArpaTarget& ArpaTargetTable::target(int number, std::int64_t stamp_ns) {
  auto it = targets_.find(number);
  if (it != targets_.end())
    return it->second;
  if (targets_.size() >= cfg_.max_targets) {
    auto oldest = std::min_element(targets_.begin(), targets_.end(), [](const auto& a, const auto& b) {
      return a.second.stamp_ns < b.second.stamp_ns;
    });
    targets_.erase(oldest);
    ++evicted_;
  }
  ArpaTarget& t = targets_[number];
  t.number = number;
  t.stamp_ns = stamp_ns;
  return t;
}

// A velocity needs course and speed, or a speed of 0 (a stopped target has no course).
void ArpaTargetTable::setVelocity(ArpaTarget& t, const arpa::TrackedTarget& tt) {
  t.has_velocity = tt.has_speed && (tt.has_course || tt.speed == 0.0);
  t.course = t.has_velocity && tt.has_course ? wrapTwoPi(tt.course) : 0.0;
  t.speed = t.has_velocity ? tt.speed : 0.0;
  t.velocity = t.has_velocity ? courseSpeedToVelocity(tt.has_course ? tt.course : 0.0, tt.speed)
                              : Eigen::Vector2d::Zero();
}

ArpaOutcome ArpaTargetTable::checkNumber(int number, arpa::TargetStatus status) {
  if (number < 0 || number > kMaxTargetNumber)
    return ArpaOutcome::NoNumber;
  if (status == arpa::TargetStatus::kLost) {
    lost_ += targets_.erase(number);
    return ArpaOutcome::Lost;
  }
  return ArpaOutcome::Target;
}

ArpaOutcome ArpaTargetTable::ttm(const arpa::TrackedTarget& reported, std::int64_t stamp_ns) {
  const ArpaOutcome n = checkNumber(reported.number, reported.status);
  if (n != ArpaOutcome::Target)
    return n;
  // A relative bearing or course needs the own heading: the navigation sensors', else the radar's OSD.
  const double heading = has_own_ && fresh(own_stamp_ns_, stamp_ns)           ? own_heading_
                         : has_osd_heading_ && fresh(osd_stamp_ns_, stamp_ns) ? osd_heading_
                                                                              : arpa::kNaN;
  arpa::TrackedTarget tt = reported;
  if (!arpa::toTrue(tt, heading))
    return ArpaOutcome::NoOwnHeading;
  if (!tt.has_distance || !tt.has_bearing)
    return ArpaOutcome::NoPosition;
  if (!has_own_ || !fresh(own_stamp_ns_, stamp_ns))
    return ArpaOutcome::NoOwnPosition;
  const RadarFix fix = radarFix(own_position_, tt.distance, tt.bearing, cfg_.sigmas);
  ArpaTarget& t = target(tt.number, stamp_ns);
  t.position = fix.position;
  t.covariance = fix.covariance;
  const GeoPoint g = frame_.toGeodetic(fix.position);
  t.has_geodetic = std::isfinite(g.lat_deg) && std::isfinite(g.lon_deg);
  t.lat_deg = t.has_geodetic ? g.lat_deg : 0.0;
  t.lon_deg = t.has_geodetic ? g.lon_deg : 0.0;
  setVelocity(t, tt);
  if (!tt.name.empty())
    t.name = tt.name;
  t.acquiring = tt.status == arpa::TargetStatus::kQuery;
  t.stamp_ns = stamp_ns;
  t.updated = true;
  return ArpaOutcome::Target;
}

ArpaOutcome ArpaTargetTable::tll(const arpa::TargetPosition& tp, std::int64_t stamp_ns) {
  const ArpaOutcome n = checkNumber(tp.number, tp.status);
  if (n != ArpaOutcome::Target)
    return n;
  if (!tp.has_position || !validLatLon(tp.lat_deg, tp.lon_deg))
    return ArpaOutcome::NoPosition;
  const Eigen::Vector2d p = frame_.toLocal(tp.lat_deg, tp.lon_deg);
  if (!(p.allFinite() && p.norm() <= cfg_.max_range))
    return ArpaOutcome::OutOfRange;
  ArpaTarget& t = target(tp.number, stamp_ns);
  t.position = p;
  t.covariance = Eigen::Matrix2d::Identity() * (cfg_.tll_sigma * cfg_.tll_sigma);
  t.has_geodetic = true;
  t.lat_deg = tp.lat_deg;
  t.lon_deg = tp.lon_deg;
  if (!tp.name.empty())
    t.name = tp.name;
  t.stamp_ns = stamp_ns;
  t.updated = true;
  return ArpaOutcome::Target;
}

}  // namespace asv
