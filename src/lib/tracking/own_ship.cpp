#include "asv_core/tracking/own_ship.h"

#include <cmath>
#include <stdexcept>

#include "asv_core/common/units.h"

namespace asv {

namespace {

constexpr const char* kFix = "fix";
constexpr const char* kHeading = "heading";
constexpr double kDefaultHdop = 1.5;  // a sentence without HDOP (RMC): a fair sky

// [m] range error of a fix type (own_ship.h gives the sources of these choices).
double rangeError(gnss::Quality q) {
  switch (q) {
    case gnss::Quality::kDifferential:
      return 1.0;
    case gnss::Quality::kPps:
      return 2.0;
    case gnss::Quality::kRtkFixed:
      return 0.02;
    case gnss::Quality::kRtkFloat:
      return 0.3;
    case gnss::Quality::kDeadReckoning:
      return 50.0;
    case gnss::Quality::kManual:
    case gnss::Quality::kSimulator:
      return 10.0;
    default:
      return 4.0;
  }
}

}  // namespace

void OwnShipConfig::validate() const {
  validateShared();
  if (ship.empty())
    throw std::invalid_argument("ship must not be empty");
  if (odom_frame == frame_id || odom_frame == ship + "/base_link")
    throw std::invalid_argument("odom_frame must differ from frame_id and from <ship>/base_link");
  if (own_mmsi > 999999999u)
    throw std::invalid_argument("own_mmsi must have at most 9 digits");
  if (!(ais_timeout > 0.0))
    throw std::invalid_argument("ais_timeout must be > 0 s");
  if (!(max_speed > 0.0) || jump_accept < 1)
    throw std::invalid_argument("max_speed must be > 0 m/s and jump_accept >= 1");
  if (!(min_speed_for_cog >= 0.0) || !(heading_sigma > 0.0) || !(cog_heading_sigma > 0.0))
    throw std::invalid_argument(
        "min_speed_for_cog must be >= 0, heading_sigma_deg and cog_heading_sigma_deg > 0");
  watch.validate();
}

OwnShipConfig OwnShipConfig::fromParams(const ParamMap& p) {
  OwnShipConfig c;
  c.readShared(p);
  c.ship = p.getString("ship", c.ship);
  c.own_mmsi = static_cast<std::uint32_t>(p.getSize("own_mmsi", c.own_mmsi));
  c.ais_timeout = p.getDouble("ais_timeout", c.ais_timeout);
  c.max_speed = p.getDouble("max_speed", c.max_speed);
  c.jump_accept = p.getInt("jump_accept", c.jump_accept);
  c.min_speed_for_cog = p.getDouble("min_speed_for_cog", c.min_speed_for_cog);
  c.variation = gnss::variationFromParams(p);
  c.heading_sigma = degToRad(p.getDouble("heading_sigma_deg", radToDeg(c.heading_sigma)));
  c.cog_heading_sigma = degToRad(p.getDouble("cog_heading_sigma_deg", radToDeg(c.cog_heading_sigma)));
  c.watch = InputWatchConfig::fromParams(p, c.watch);
  c.navsat = p.getBool("navsat", c.navsat);
  c.navsat_heading_is_bearing = p.getBool("navsat_heading_is_bearing", c.navsat_heading_is_bearing);
  c.odom_frame = p.getString("odom_frame", c.odom_frame);
  c.validate();
  return c;
}

OwnShipEstimator::OwnShipEstimator(const OwnShipConfig& config, const LocalFrame& frame)
    : cfg_(config), frame_(frame), watch_(config.watch) {
  cfg_.validate();
  watch_.add(kFix);
  watch_.add(kHeading);
}

double OwnShipEstimator::sigmaOf(const gnss::Fix& fix) const {
  if (fix.sigma)
    return *fix.sigma;
  return fix.hdop.value_or(kDefaultHdop) * rangeError(fix.quality);
}

OwnShipEstimator::Use OwnShipEstimator::position(const gnss::Fix& fix, const char* source, double t,
                                                 double wall, std::string& why) {
  if (!validLatLon(fix.lat_deg, fix.lon_deg) || fix.quality == gnss::Quality::kNone ||
      (fix.sigma && !(*fix.sigma >= 0.0 && std::isfinite(*fix.sigma)))) {
    why = std::string(source) + ": no fix";
    ++rejected_;
    return Use::kRejected;
  }
  return takeFix(fix, source, t, wall, why);
}

void OwnShipEstimator::motion(const gnss::Motion& m, double t) {
  course_ = m.course;
  speed_ = m.speed;
  motion_time_ = t;
}

void OwnShipEstimator::heading(double value, double t, double wall) {
  heading_ = value;
  heading_time_ = t;
  watch_.received(kHeading, t, wall);
}

OwnShipEstimator::Use OwnShipEstimator::takeFix(const gnss::Fix& fix, const char* source, double t,
                                                double wall, std::string& why) {
  const Eigen::Vector2d p = frame_.toLocal(fix.lat_deg, fix.lon_deg);
  if (fix_) {
    const double dt = std::max(t - fix_->fix_time, 0.1);  // two sentences of one epoch: 0 s apart
    const Eigen::Vector2d predicted =
        fix_->position + courseSpeedToVelocity(course_.value_or(0.0), speed_.value_or(0.0)) *
                             std::max(t - fix_->fix_time, 0.0);
    const double move = (p - predicted).norm();
    if (move > cfg_.max_speed * dt + 3.0 * (sigmaOf(fix) + fix_->position_sigma)) {
      // Jumps that agree with each other (within max_speed of the previous jump) become the position.
      const bool agrees = jumps_in_row_ > 0 &&
                          (p - jump_candidate_).norm() <=
                              cfg_.max_speed * std::max(t - jump_candidate_time_, 0.1) + 3.0 * sigmaOf(fix);
      jumps_in_row_ = agrees ? jumps_in_row_ + 1 : 1;
      jump_candidate_ = p;
      jump_candidate_time_ = t;
      ++jumps_;
      if (jumps_in_row_ < cfg_.jump_accept) {
        why = std::string(source) + " jumped " + std::to_string(static_cast<int>(move)) + " m in " +
              std::to_string(dt).substr(0, 4) + " s";
        ++rejected_;
        return Use::kRejected;
      }
    }
  }
  jumps_in_row_ = 0;
  OwnShipState s;
  s.position = p;
  s.position_sigma = sigmaOf(fix);
  s.position_source = source;
  s.quality = fix.quality;
  s.fix_time = t;
  fix_ = s;
  watch_.received(kFix, t, wall);
  return Use::kUsed;
}

OwnShipEstimator::Use OwnShipEstimator::feed(const nmea::Sentence& s, double t, double wall,
                                             std::string& why) {
  gnss::Fix fix;
  gnss::Motion motion;
  double value = 0.0;
  gnss::Error e = gnss::Error::kWrongType;
  if (s.is("GGA") && (e = gnss::parseGga(s, fix)) == gnss::Error::kNone)
    return takeFix(fix, "GGA", t, wall, why);
  if (s.is("GNS") && (e = gnss::parseGns(s, fix)) == gnss::Error::kNone)
    return takeFix(fix, "GNS", t, wall, why);
  if (s.is("RMC") && (e = gnss::parseRmc(s, fix, motion, rmc_variation_)) == gnss::Error::kNone) {
    this->motion(motion, t);
    return takeFix(fix, "RMC", t, wall, why);
  }
  if (s.is("VTG") && (e = gnss::parseVtg(s, motion)) == gnss::Error::kNone) {
    this->motion(motion, t);
    return Use::kUsed;
  }
  const std::optional<double> variation = cfg_.variation ? cfg_.variation : rmc_variation_;
  if ((s.is("HDT") && (e = gnss::parseHdt(s, value)) == gnss::Error::kNone) ||
      (s.is("THS") && (e = gnss::parseThs(s, value)) == gnss::Error::kNone) ||
      (s.is("HDG") && (e = gnss::parseHdg(s, variation, value)) == gnss::Error::kNone)) {
    heading(value, t, wall);
    return Use::kUsed;
  }
  if (s.is("ROT") && (e = gnss::parseRot(s, value)) == gnss::Error::kNone) {
    rate_ = value;
    rate_time_ = t;
    return Use::kUsed;
  }
  if (e == gnss::Error::kWrongType)
    return Use::kNotNavigation;
  why = std::string(s.type) + ": " + gnss::errorText(e);
  ++rejected_;
  return Use::kRejected;
}

void OwnShipEstimator::aisReport(double lat_deg, double lon_deg, bool accurate, std::optional<double> course,
                                 std::optional<double> speed, std::optional<double> heading, double t) {
  if (!validLatLon(lat_deg, lon_deg))
    return;
  OwnShipState s;
  s.position = frame_.toLocal(lat_deg, lon_deg);
  s.position_sigma = accurate ? 10.0 : 30.0;
  s.course = course.value_or(0.0);
  s.speed = speed.value_or(0.0);
  s.heading = heading.value_or(s.course);
  s.heading_from_cog = !heading;
  s.position_source = "AIS";
  s.fix_time = t;
  ais_ = s;
  // Her reports keep the position alive for ais_timeout (stale()), not through the GNSS watch.
}

std::optional<OwnShipState> OwnShipEstimator::state(double t) const {
  const bool gnss_fresh = fix_ && t - fix_->fix_time <= cfg_.watch.input_timeout;
  const bool use_ais = !gnss_fresh && ais_ && t - ais_->fix_time <= cfg_.ais_timeout &&
                       (!fix_ || ais_->fix_time > fix_->fix_time);
  if (!fix_ && !ais_)
    return std::nullopt;
  OwnShipState s = use_ais ? *ais_ : *fix_;
  if (!use_ais) {
    if ((!speed_ && !course_) || t - motion_time_ > cfg_.watch.input_timeout)
      return std::nullopt;  // no velocity: no odometry
    s.speed = speed_.value_or(0.0);
    s.course = course_.value_or(heading_.value_or(0.0));
  }
  const bool heading_fresh = heading_ && t - heading_time_ <= cfg_.watch.input_timeout;
  if (heading_fresh) {
    s.heading = *heading_;
    s.heading_sigma = cfg_.heading_sigma;
    s.heading_from_cog = false;
  } else if (!use_ais || s.heading_from_cog) {
    if (s.speed < cfg_.min_speed_for_cog && !heading_)
      return std::nullopt;  // stopped, no heading sensor: her heading is unknown
    s.heading = heading_ && s.speed < cfg_.min_speed_for_cog ? *heading_ : s.course;
    s.heading_sigma = cfg_.cog_heading_sigma;
    s.heading_from_cog = true;
  } else {
    s.heading_sigma = cfg_.heading_sigma;
  }
  if (rate_ && t - rate_time_ <= cfg_.watch.input_timeout)
    s.yaw_rate = *rate_;
  s.position += courseSpeedToVelocity(s.course, s.speed) * std::max(t - s.fix_time, 0.0);
  return s;
}

std::vector<StaleInput> OwnShipEstimator::stale(double t, double wall) {
  std::vector<StaleInput> out;
  for (StaleInput& s : watch_.stale(t, wall)) {
    // A ship without a heading sensor, making way, steers by her course over ground: not a fault.
    if (s.name == kHeading && !watch_.everReceived(kHeading) && state(t))
      continue;
    // No GNSS fix, but her AIS transponder reports: the position stands on it, at its own pace.
    if (s.name == kFix && ais_ && t - ais_->fix_time <= cfg_.ais_timeout)
      continue;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace asv
