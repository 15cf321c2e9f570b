#include "asv_core/codec/autopilot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "asv_core/codec/nmea_encode.h"
#include "asv_core/common/units.h"

namespace asv {
namespace autopilot {

namespace {

constexpr double kMetresPerNm = 1852.0;

std::string fixed(double v, int decimals) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

// Bearings in whole tenths of a degree, 0.0-359.9.
std::string degrees(double rad) {
  double d = std::round(wrapDeg360(radToDeg(rad)) * 10.0) / 10.0;
  if (d >= 360.0)
    d -= 360.0;
  return fixed(d, 1);
}

// Cross-track magnitude [nm] and the direction to steer: right of the leg, steer left.
std::string crossTrack(const Steering& s, int decimals) {
  return fixed(std::fabs(s.cross_track) / kMetresPerNm, decimals) + "," + (s.cross_track > 0.0 ? "L" : "R");
}

std::string angleField(double deg, int whole_digits, char pos, char neg) {
  const double a = std::fabs(deg);
  int whole = static_cast<int>(a);
  double minutes = std::round((a - whole) * 60.0 * 1e4) / 1e4;
  if (minutes >= 60.0) {  // 59.99995' rounds up to the next degree
    minutes -= 60.0;
    ++whole;
  }
  char b[32];
  std::snprintf(b, sizeof b, "%0*d%07.4f,%c", whole_digits, whole, minutes, deg < 0.0 ? neg : pos);
  return b;
}

}  // namespace

void LegConfig::validate() const {
  if (!(lookahead > 0.0) || !std::isfinite(lookahead))
    throw std::invalid_argument("lookahead must be > 0 m");
  if (!(leg_change > 0.0) || !(leg_change < kPi))
    throw std::invalid_argument("leg_change_deg must be in (0, 180) deg");
}

SetpointLeg::SetpointLeg(const LegConfig& config) : cfg_(config) {
  cfg_.validate();
}

Steering SetpointLeg::update(double setpoint_course, const Eigen::Vector2d& position,
                             double course_over_ground, double speed) {
  if (!have_leg_ || std::fabs(wrapPi(setpoint_course - course_)) > cfg_.leg_change) {
    have_leg_ = true;
    origin_ = position;
    course_ = wrapTwoPi(setpoint_course);
    ++legs_;
  }
  const Eigen::Vector2d along = courseSpeedToVelocity(course_, 1.0);  // unit vector of the leg
  const Eigen::Vector2d rel = position - origin_;
  const double foot = rel.dot(along);
  destination_ = origin_ + along * (std::max(foot, 0.0) + cfg_.lookahead);
  Steering s;
  // Right of the leg is positive: the leg's direction crossed with the offset (x east, y north).
  s.cross_track = along.y() * rel.x() - along.x() * rel.y();
  s.bearing_leg = course_;
  s.bearing_to_dest = trueBearing(position, destination_);
  s.heading_to_steer = s.bearing_to_dest;
  s.range_to_dest = (destination_ - position).norm();
  s.closing_speed = speed * std::cos(course_over_ground - s.bearing_to_dest);
  s.origin_id = "ASV" + std::to_string(legs_ - 1);
  s.dest_id = "ASV" + std::to_string(legs_);
  return s;
}

std::string encodeApb(const Steering& s, const std::string& talker) {
  const char* status = s.valid ? "A" : "V";
  const std::string body = talker + "APB," + status + "," + status + "," + crossTrack(s, 3) + ",N,V,V," +
                           degrees(s.bearing_leg) + ",T," + s.dest_id + "," + degrees(s.bearing_to_dest) +
                           ",T," + degrees(s.heading_to_steer) + ",T," + (s.valid ? "A" : "N");
  return nmea::withChecksum('$', body);
}

std::string encodeRmb(const Steering& s, const std::string& talker) {
  // RMB's cross-track field holds 0-9.99 nm; its range 0-999.9 nm.
  Steering c = s;
  c.cross_track = std::clamp(s.cross_track, -9.99 * kMetresPerNm, 9.99 * kMetresPerNm);
  const std::string body =
      talker + "RMB," + (s.valid ? "A" : "V") + "," + crossTrack(c, 2) + "," + s.origin_id + "," + s.dest_id +
      "," + latitudeField(s.dest_lat_deg) + "," + longitudeField(s.dest_lon_deg) + "," +
      fixed(std::min(s.range_to_dest / kMetresPerNm, 999.9), 1) + "," + degrees(s.bearing_to_dest) + "," +
      fixed(mpsToKnots(s.closing_speed), 1) + ",V," + (s.valid ? "A" : "N");
  return nmea::withChecksum('$', body);
}

std::string encodeXte(const Steering& s, const std::string& talker) {
  const char* status = s.valid ? "A" : "V";
  return nmea::withChecksum(
      '$', talker + "XTE," + status + "," + status + "," + crossTrack(s, 3) + ",N," + (s.valid ? "A" : "N"));
}

std::string encodeHsc(double heading_true, std::optional<double> variation, const std::string& talker) {
  // Magnetic = true - variation (east positive).
  const std::string magnetic = variation ? degrees(heading_true - *variation) : std::string();
  return nmea::withChecksum('$', talker + "HSC," + degrees(heading_true) + ",T," + magnetic + ",M");
}

std::string encodeWpl(double lat_deg, double lon_deg, const std::string& name, const std::string& talker) {
  return nmea::withChecksum(
      '$', talker + "WPL," + latitudeField(lat_deg) + "," + longitudeField(lon_deg) + "," + name);
}

std::vector<std::string> encodeRte(const std::string& route_name, const std::vector<std::string>& waypoints,
                                   const std::string& talker) {
  // NMEA 0183: at most 82 characters from '$' to the line end: 79 before "*hh", less the fields ahead
  // of the names ("RTE,nn,nn,c,<name>"); two digits leave room for 99 sentences.
  const std::size_t room = 79 - 1 - (talker.size() + std::string("RTE,99,99,c,").size() + route_name.size());
  std::vector<std::vector<std::string>> parts(1);
  std::size_t used = 0;
  for (const std::string& w : waypoints) {
    if (!parts.back().empty() && used + 1 + w.size() > room) {
      parts.emplace_back();
      used = 0;
    }
    parts.back().push_back(w);
    used += 1 + w.size();
  }
  std::vector<std::string> out;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    std::string body =
        talker + "RTE," + std::to_string(parts.size()) + "," + std::to_string(k + 1) + ",c," + route_name;
    for (const std::string& w : parts[k])
      body += "," + w;
    out.push_back(nmea::withChecksum('$', body));
  }
  return out;
}

std::string latitudeField(double lat_deg) {
  return angleField(lat_deg, 2, 'N', 'S');
}

std::string longitudeField(double lon_deg) {
  return angleField(lon_deg, 3, 'E', 'W');
}

}  // namespace autopilot
}  // namespace asv
