#include "asv_core/tracking/ais_targets.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <variant>

namespace asv {

namespace {

constexpr std::uint32_t kMaxMmsi = 999999999;
// Type 27 positions have 1/10 minute resolution (185 m in latitude).
constexpr double kLongRangeSigma = 200.0;

// The class, position sigma and navigational status of a ship's position report; false for a message
// that is not one.
bool reportKind(const ais::Message& m, const AisTargetConfig& cfg, AisTarget& t) {
  if (cfg.sar_aircraft) {
    const auto* r = std::get_if<ais::SarAircraftReport>(&m.body);
    if (!r)
      return false;
    t.ais_class = 'S';
    t.sigma = r->accuracy ? cfg.position_sigma_high : cfg.position_sigma_low;
    t.has_altitude = r->alt < 4095;  // 4095: not available
    t.altitude = t.has_altitude ? static_cast<double>(r->alt) : 0.0;
    return true;
  }
  if (const auto* a = std::get_if<ais::PositionReportA>(&m.body)) {
    t.ais_class = 'A';
    t.sigma = a->accuracy ? cfg.position_sigma_high : cfg.position_sigma_low;
    t.nav_status = a->status;
  } else if (const auto* b = std::get_if<ais::PositionReportB>(&m.body)) {
    t.ais_class = 'B';
    t.sigma = b->accuracy ? cfg.position_sigma_high : cfg.position_sigma_low;
  } else if (const auto* l = std::get_if<ais::LongRangeReport>(&m.body)) {
    t.ais_class = 'A';
    t.sigma = kLongRangeSigma;
    t.nav_status = l->status;
  } else {
    return false;
  }
  return true;
}

void setMotion(const ais::Kinematics& k, AisTarget& t) {
  if (k.has_speed && k.has_course) {
    t.velocity = AisVelocity::Reported;
    t.course = k.course;
    t.speed = k.speed;
  } else if (k.has_speed && k.has_heading) {
    t.velocity = AisVelocity::CourseFromHeading;
    t.course = k.heading;
    t.speed = k.speed;
  } else if (k.has_speed && k.speed == 0.0) {
    t.velocity = AisVelocity::Reported;  // stopped: the course does not matter
  }
  t.has_heading = k.has_heading;
  if (k.has_heading)
    t.heading = k.heading;
  t.has_turn = k.has_turn;
  if (k.has_turn)
    t.rate_of_turn = k.rate_of_turn;
}

}  // namespace

void AisTargetConfig::validate() const {
  if (!(max_range > 0.0))
    throw std::invalid_argument("max_range must be > 0 m");
  if (max_targets < 1)
    throw std::invalid_argument("max_targets must be >= 1");
  if (!(forget_after > 0.0))
    throw std::invalid_argument("forget_after must be > 0 s");
  if (!(position_sigma_high > 0.0 && position_sigma_low > 0.0))
    throw std::invalid_argument("position_sigma_high and position_sigma_low must be > 0 m");
  if (own_mmsi > kMaxMmsi)
    throw std::invalid_argument("own_mmsi must have at most 9 digits");
}

AisTargetTable::AisTargetTable(const AisTargetConfig& cfg, const LocalFrame& frame)
    : cfg_(cfg), frame_(frame) {
  cfg_.validate();
}

AisOutcome AisTargetTable::update(const ais::Message& m, std::int64_t stamp_ns) {
  if (m.own_ship || (cfg_.own_mmsi != 0 && m.mmsi == cfg_.own_mmsi))  // our own transponder
    return AisOutcome::OwnShip;
  AisTarget t;
  // Static data (5, 24), base stations (4), aids to navigation (21), SAR aircraft (9) unless this is
  // their table, and the rest.
  if (!reportKind(m, cfg_, t))
    return AisOutcome::NotAShip;
  ais::Kinematics k;
  if (!ais::toKinematics(m, k) || !k.has_position)
    return AisOutcome::NoPosition;
  if (m.mmsi == 0 || m.mmsi > kMaxMmsi)
    return AisOutcome::BadMmsi;
  t.position = frame_.toLocal(k.lat_deg, k.lon_deg);
  if (!(t.position.allFinite() && t.position.norm() <= cfg_.max_range))
    return AisOutcome::OutOfRange;
  t.mmsi = m.mmsi;
  t.lat_deg = k.lat_deg;
  t.lon_deg = k.lon_deg;
  setMotion(k, t);
  t.stamp_ns = stamp_ns;
  t.updated = true;
  auto it = ships_.find(m.mmsi);
  if (it == ships_.end()) {
    if (ships_.size() >= cfg_.max_targets) {
      ships_.erase(std::min_element(ships_.begin(), ships_.end(), [](const auto& a, const auto& b) {
        return a.second.stamp_ns < b.second.stamp_ns;
      }));
      ++evicted_;
    }
    it = ships_.emplace(m.mmsi, AisTarget()).first;
  }
  it->second = t;
  return AisOutcome::Target;
}

double spanSeconds(std::int64_t ns) {
  std::int64_t sec = ns / 1000000000, nsec = ns % 1000000000;
  if (nsec < 0) {
    nsec += 1000000000;
    --sec;
  }
  return static_cast<double>(sec) + 1e-9 * static_cast<double>(nsec);
}

void AidTableConfig::validate() const {
  if (!(max_range > 0.0))
    throw std::invalid_argument("aids/max_range must be > 0 m");
  if (max_aids < 1)
    throw std::invalid_argument("aids/max_aids must be >= 1");
  if (!(forget_after > 0.0))
    throw std::invalid_argument("aids/forget_after must be > 0 s");
}

AidTable::AidTable(const AidTableConfig& cfg, const LocalFrame& frame) : cfg_(cfg), frame_(frame) {
  cfg_.validate();
}

AisOutcome AidTable::update(const ais::Message& m, std::int64_t stamp_ns) {
  const auto* a = std::get_if<ais::AidToNavigation>(&m.body);
  if (!a)
    return AisOutcome::NotAShip;
  const std::optional<double> lat = ais::latDeg(a->lat), lon = ais::lonDeg(a->lon);
  if (!lat || !lon)
    return AisOutcome::NoPosition;
  if (m.mmsi == 0 || m.mmsi > kMaxMmsi)
    return AisOutcome::BadMmsi;
  AidRecord r;
  r.position = frame_.toLocal(*lat, *lon);
  if (!(r.position.allFinite() && r.position.norm() <= cfg_.max_range))
    return AisOutcome::OutOfRange;
  r.mmsi = m.mmsi;
  r.name = std::string(a->name.view());
  r.aid_type = a->aid_type;
  r.virtual_aid = a->virtual_aid;
  r.off_position = a->off_position;
  r.lat_deg = *lat;
  r.lon_deg = *lon;
  r.to_bow = a->to_bow;
  r.to_stern = a->to_stern;
  r.to_port = a->to_port;
  r.to_starboard = a->to_starboard;
  r.stamp_ns = stamp_ns;
  if (!aids_.count(m.mmsi) && aids_.size() >= cfg_.max_aids) {
    aids_.erase(std::min_element(aids_.begin(), aids_.end(), [](const auto& x, const auto& y) {
      return x.second.stamp_ns < y.second.stamp_ns;
    }));
    ++evicted_;
  }
  aids_[m.mmsi] = std::move(r);
  return AisOutcome::Target;
}

void AidTable::forget(std::int64_t now_ns) {
  for (auto it = aids_.begin(); it != aids_.end();)
    it = spanSeconds(now_ns - it->second.stamp_ns) > cfg_.forget_after ? aids_.erase(it) : std::next(it);
}

}  // namespace asv
