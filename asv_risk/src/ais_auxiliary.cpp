#include "asv_risk/ais_auxiliary.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <asv_core/common/units.h>

#include "asv_risk/target_quality.h"

namespace asv_risk {

namespace {

constexpr double kHpaToPa = 100.0;
// Marker sizes [m]: visible at harbour scale, small against the ships' domains.
constexpr double kAidMarkerRadius = 8.0;
constexpr double kSarMarkerRadius = 25.0;
constexpr double kSarMarkerLifetime = 30.0;  // [s] SAR aircraft report every 10 s (ITU-R M.1371)

ros::Time fromNs(std::int64_t ns) {
  return ros::Time().fromNSec(static_cast<std::uint64_t>(std::max<std::int64_t>(0, ns)));
}

visualization_msgs::Marker marker(const std::string& frame, const ros::Time& now, const std::string& ns,
                                  int id, int type, double x, double y) {
  visualization_msgs::Marker m;
  m.header.frame_id = frame;
  m.header.stamp = now;
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.position.x = x;
  m.pose.position.y = y;
  m.pose.orientation.w = 1.0;
  m.color.a = 1.0;
  return m;
}

const char* outcomeText(asv::AisOutcome o) {
  switch (o) {
    case asv::AisOutcome::NoPosition:
      return "no position";
    case asv::AisOutcome::BadMmsi:
      return "invalid MMSI";
    case asv::AisOutcome::OutOfRange:
      return "beyond max_range";
    default:
      return "not of its kind";
  }
}

}  // namespace

asv_msgs::Target aisTargetMsg(const asv::AisTarget& s) {
  asv_msgs::Target t;
  t.id = (s.ais_class == 'S' ? "sar:" : "ais:") + std::to_string(s.mmsi);
  t.source = asv_msgs::Target::SOURCE_AIS;
  t.ais_class = s.ais_class == 'B'   ? asv_msgs::Target::AIS_CLASS_B
                : s.ais_class == 'A' ? asv_msgs::Target::AIS_CLASS_A
                                     : asv_msgs::Target::AIS_CLASS_NONE;
  t.mmsi = s.mmsi;
  t.nav_status = s.nav_status;
  t.position.x = s.position.x();
  t.position.y = s.position.y();
  t.position.z = s.has_altitude ? s.altitude : 0.0;
  t.has_geodetic = true;
  t.latitude = s.lat_deg;
  t.longitude = s.lon_deg;
  t.quality = s.velocity == asv::AisVelocity::Reported            ? kQualityFull
              : s.velocity == asv::AisVelocity::CourseFromHeading ? kQualityCourseFromHeading
                                                                  : kQualityNoVelocity;
  if (s.velocity != asv::AisVelocity::Unknown) {
    t.course_over_ground = asv::wrapTwoPi(s.course);
    t.speed_over_ground = s.speed;
    const Eigen::Vector2d v = asv::courseSpeedToVelocity(s.course, s.speed);
    t.velocity.x = v.x();
    t.velocity.y = v.y();
  }
  t.has_heading = s.has_heading;
  if (s.has_heading)
    t.heading = s.heading;
  t.has_rate_of_turn = s.has_turn;
  if (s.has_turn)
    t.rate_of_turn = s.rate_of_turn;
  t.position_covariance = {s.sigma * s.sigma, 0.0, 0.0, s.sigma * s.sigma};
  t.stamp = fromNs(s.stamp_ns);
  return t;
}

asv_msgs::AidToNavigation aidMsg(const asv::AidRecord& a, const ros::Time& now) {
  asv_msgs::AidToNavigation m;
  m.mmsi = a.mmsi;
  m.name = a.name;
  m.aid_type = a.aid_type;
  m.aid_type_text = asv::ais::aidTypeText(a.aid_type);
  m.virtual_aid = a.virtual_aid;
  m.off_position = a.off_position;
  m.position.x = a.position.x();
  m.position.y = a.position.y();
  m.latitude = a.lat_deg;
  m.longitude = a.lon_deg;
  m.to_bow = static_cast<float>(a.to_bow);
  m.to_stern = static_cast<float>(a.to_stern);
  m.to_port = static_cast<float>(a.to_port);
  m.to_starboard = static_cast<float>(a.to_starboard);
  m.stamp = fromNs(a.stamp_ns);
  m.age = std::max(0.0, (now - m.stamp).toSec());
  return m;
}

asv_msgs::AisSafetyMessage safetyMsg(const asv::ais::Message& m, const asv::ais::SafetyText& t) {
  asv_msgs::AisSafetyMessage s;
  s.message_type = m.type;
  s.mmsi = m.mmsi;
  s.dest_mmsi = t.dest_mmsi;
  s.seqno = t.seqno;
  s.retransmit = t.retransmit;
  s.text = std::string(t.text.view());
  return s;
}

asv_msgs::AisWeather weatherMsg(std::uint32_t mmsi, const asv::ais::MetHydroReport& r,
                                const asv::LocalFrame& frame) {
  asv_msgs::AisWeather w;
  w.mmsi = mmsi;
  if (const auto lat = r.latDeg(), lon = r.lonDeg(); lat && lon) {
    const Eigen::Vector2d p = frame.toLocal(*lat, *lon);
    w.has_position = p.allFinite();
    w.position.x = w.has_position ? p.x() : 0.0;
    w.position.y = w.has_position ? p.y() : 0.0;
    w.latitude = *lat;
    w.longitude = *lon;
  }
  const auto speed = r.windSpeedMps(), dir = r.windDirectionRad(), gust = r.windGustMps();
  w.has_wind = speed && dir;
  w.wind_speed = w.has_wind ? *speed : 0.0;
  w.wind_direction = w.has_wind ? *dir : 0.0;
  w.has_wind_gust = gust.has_value();
  w.wind_gust = gust.value_or(0.0);
  const auto vis = r.visibilityM();
  w.has_visibility = vis.has_value();
  w.visibility = vis.value_or(0.0);
  w.visibility_greater = w.has_visibility && r.visgreater;
  const auto temp = r.airTemperatureC(), pressure = r.airPressureHpa(), level = r.waterLevelM();
  w.has_air_temperature = temp.has_value();
  w.air_temperature = temp.value_or(0.0);
  w.has_air_pressure = pressure.has_value();
  w.air_pressure = pressure ? *pressure * kHpaToPa : 0.0;
  const auto sea = r.seaStateBeaufort();
  w.has_sea_state = sea.has_value();
  w.sea_state = static_cast<std::uint8_t>(sea.value_or(0));
  w.has_water_level = level.has_value();
  w.water_level = level.value_or(0.0);
  return w;
}

AisAuxiliary::AisAuxiliary(ros::NodeHandle nh, const asv::AisNodeConfig& config, const asv::LocalFrame& frame)
    : config_(config),
      frame_(frame),
      aids_(config.aids, frame),
      sar_(
          [&config] {
            asv::AisTargetConfig c = config.targets;
            c.sar_aircraft = true;
            return c;
          }(),
          frame) {
  aids_pub_ = nh.advertise<asv_msgs::AidToNavigationArray>("ais/aids_to_navigation", 1, true);
  sar_pub_ = nh.advertise<asv_msgs::TargetArray>("ais/sar_aircraft", 10);
  safety_pub_ = nh.advertise<asv_msgs::AisSafetyMessage>("ais/safety_messages", 50);
  weather_pub_ = nh.advertise<asv_msgs::AisWeather>("ais/weather", 10);
  if (config.publish_markers) {
    markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("ais/markers", 2, true);
    sar_markers_pub_ = nh.advertise<visualization_msgs::MarkerArray>("ais/sar_markers", 10);
  }
}

void AisAuxiliary::refuse(const char* what, std::uint32_t mmsi, const char* why) {
  ++refused_;
  ROS_WARN_THROTTLE(10.0, "ais_node: %s MMSI %u refused (%s); counted in diagnostics", what, mmsi, why);
}

bool AisAuxiliary::handle(const asv::ais::Message& m, const asv::ais::Payload& p, const ros::Time& stamp) {
  const auto ns = static_cast<std::int64_t>(stamp.toNSec());
  if (std::holds_alternative<asv::ais::AidToNavigation>(m.body)) {
    const asv::AisOutcome o = aids_.update(m, ns);
    o == asv::AisOutcome::Target ? void(++aid_reports_) : refuse("aid to navigation", m.mmsi, outcomeText(o));
    return true;
  }
  if (std::holds_alternative<asv::ais::SarAircraftReport>(m.body)) {
    const asv::AisOutcome o = sar_.update(m, ns);
    o == asv::AisOutcome::Target ? void(++sar_reports_) : refuse("SAR aircraft", m.mmsi, outcomeText(o));
    return true;
  }
  if (const auto* t = std::get_if<asv::ais::SafetyText>(&m.body)) {
    asv_msgs::AisSafetyMessage s = safetyMsg(m, *t);
    s.header.stamp = stamp;
    s.header.frame_id = config_.frame_id;
    ROS_WARN("ais_node: safety message (type %u) from MMSI %u%s: %s", m.type, m.mmsi,
             m.type == 12 ? (" to " + std::to_string(t->dest_mmsi)).c_str() : "", s.text.c_str());
    safety_pub_.publish(s);
    ++texts_;
    return true;
  }
  const auto* b = std::get_if<asv::ais::PayloadMessage>(&m.body);
  if (!b || m.type != 8 || b->dac != 1 || b->fid != 31)
    return false;
  handleWeather(m, p, stamp);
  return true;
}

void AisAuxiliary::handleWeather(const asv::ais::Message& m, const asv::ais::Payload& p,
                                 const ros::Time& stamp) {
  asv::ais::MetHydroReport r;
  if (!asv::ais::decodeMetHydro31(p, r)) {
    refuse("weather report", m.mmsi, "shorter than the 350 bits of the IMO289 fields");
    return;
  }
  asv_msgs::AisWeather w = weatherMsg(m.mmsi, r, frame_);
  w.header.stamp = stamp;
  w.header.frame_id = config_.frame_id;
  weather_pub_.publish(w);
  ++weather_reports_;
}

void AisAuxiliary::publishSar(const ros::Time& now) {
  asv_msgs::TargetArray arr;
  arr.header.stamp = now;
  arr.header.frame_id = config_.frame_id;
  sar_.due(static_cast<std::int64_t>(now.toNSec()), [&](const asv::AisTarget& s, double age) {
    asv_msgs::Target t = aisTargetMsg(s);
    t.age = std::max(0.0, age);
    arr.targets.push_back(std::move(t));
  });
  if (arr.targets.empty())
    return;
  sar_pub_.publish(arr);
  if (!config_.publish_markers)
    return;
  // One sphere and label per aircraft, kept for a few reports' time: an aircraft no longer heard fades.
  visualization_msgs::MarkerArray markers;
  for (const auto& t : arr.targets) {
    const int id = static_cast<int>(t.mmsi % 1000000000u);
    auto m = marker(config_.frame_id, now, "sar", 2 * id, visualization_msgs::Marker::SPHERE, t.position.x,
                    t.position.y);
    m.scale.x = m.scale.y = m.scale.z = 2 * kSarMarkerRadius;
    m.color.r = 1.0;
    m.color.g = 0.5;
    m.lifetime = ros::Duration(kSarMarkerLifetime);
    markers.markers.push_back(m);
    auto label =
        marker(config_.frame_id, now, "sar", 2 * id + 1, visualization_msgs::Marker::TEXT_VIEW_FACING,
               t.position.x, t.position.y + 2 * kSarMarkerRadius);
    label.scale.z = 15.0;
    label.color.r = label.color.g = label.color.b = 1.0;
    label.text =
        "SAR " + std::to_string(t.mmsi) + " " + std::to_string(static_cast<int>(t.position.z)) + " m";
    label.lifetime = m.lifetime;
    markers.markers.push_back(label);
  }
  sar_markers_pub_.publish(markers);
}

void AisAuxiliary::publishAids(const ros::Time& now) {
  aids_.forget(static_cast<std::int64_t>(now.toNSec()));
  asv_msgs::AidToNavigationArray arr;
  arr.header.stamp = now;
  arr.header.frame_id = config_.frame_id;
  for (const auto& kv : aids_.aids())
    arr.aids.push_back(aidMsg(kv.second, now));
  aids_pub_.publish(arr);
  if (config_.publish_markers)
    publishMarkers(now);
}

void AisAuxiliary::publishMarkers(const ros::Time& now) {
  visualization_msgs::MarkerArray arr;
  visualization_msgs::Marker clear;
  clear.action = visualization_msgs::Marker::DELETEALL;
  arr.markers.push_back(clear);
  const std::string& frame = config_.frame_id;
  int id = 0;
  for (const auto& kv : aids_.aids()) {
    const asv::AidRecord& a = kv.second;
    auto m = marker(frame, now, "aids", id++, visualization_msgs::Marker::CYLINDER, a.position.x(),
                    a.position.y());
    m.scale.x = m.scale.y = 2 * kAidMarkerRadius;
    m.scale.z = 4.0;
    // Yellow: a physical mark; magenta, see-through: a virtual one; red: off position.
    m.color.r = 1.0;
    m.color.g = a.off_position || a.virtual_aid ? 0.0 : 0.85;
    m.color.b = a.virtual_aid && !a.off_position ? 1.0 : 0.0;
    m.color.a = a.virtual_aid ? 0.5 : 1.0;
    arr.markers.push_back(m);
    auto label = marker(frame, now, "aids", id++, visualization_msgs::Marker::TEXT_VIEW_FACING,
                        a.position.x(), a.position.y() + 2 * kAidMarkerRadius);
    label.scale.z = 12.0;
    label.color.r = label.color.g = label.color.b = 1.0;
    label.text = (a.name.empty() ? std::to_string(a.mmsi) : a.name) + (a.virtual_aid ? " (V-AIS)" : "") +
                 (a.off_position ? " OFF POSITION" : "");
    arr.markers.push_back(label);
  }
  markers_pub_.publish(arr);
}

void AisAuxiliary::clear() {
  aids_.clear();
  sar_.clear();
}

void AisAuxiliary::diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) const {
  stat.add("aids to navigation known", aids_.size());
  stat.add("aid reports", aid_reports_);
  stat.add("SAR aircraft known", sar_.size());
  stat.add("SAR aircraft reports", sar_reports_);
  stat.add("safety messages", texts_);
  stat.add("weather reports", weather_reports_);
  stat.add("aid/SAR/weather reports refused (position, MMSI, range, length)", refused_);
}

}  // namespace asv_risk
