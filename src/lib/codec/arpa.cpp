#include "asv_core/codec/arpa.h"

#include <cmath>
#include <stdexcept>

#include "asv_core/common/units.h"

namespace asv {
namespace arpa {

namespace {

constexpr double kMetresPerStatuteMile = 1609.344;

Reference reference(std::string_view f) {
  switch (nmea::letter(f)) {
    case 'T':
      return Reference::kTrue;
    case 'R':
      return Reference::kRelative;
    default:
      return Reference::kUnknown;
  }
}

TargetStatus status(std::string_view f) {
  switch (nmea::letter(f)) {
    case 'L':
      return TargetStatus::kLost;
    case 'Q':
      return TargetStatus::kQuery;
    case 'T':
      return TargetStatus::kTracking;
    default:
      return TargetStatus::kUnknown;
  }
}

// Target number: radars send "01", " 7" or "101".
Error targetNumber(std::string_view f, int& number) {
  long n;
  if (!nmea::parseInt(f, n))
    return nmea::trim(f).empty() ? Error::kBadFields : Error::kBadValue;
  if (n < 0 || n > 9999)
    return Error::kBadValue;
  number = static_cast<int>(n);
  return Error::kNone;
}

// hhmmss.ss -> seconds since midnight.
bool utcSeconds(std::string_view f, double& out) {
  f = nmea::trim(f);
  if (f.size() < 6)
    return false;
  long hh, mm;
  double ss;
  if (!nmea::parseInt(f.substr(0, 2), hh) || !nmea::parseInt(f.substr(2, 2), mm) ||
      !nmea::parseDouble(f.substr(4), ss))
    return false;
  if (hh < 0 || hh > 23 || mm < 0 || mm > 59 || !(ss >= 0.0 && ss < 61.0))  // "nan" parses: reject it
    return false;
  out = hh * 3600.0 + mm * 60.0 + ss;
  return true;
}

// Angle field in degrees [0, 360] -> rad in [0, 2 pi).
bool angle(std::string_view f, double& out) {
  double d;
  if (!nmea::parseDouble(f, d) || !(d >= 0.0 && d <= 360.0))
    return false;
  out = wrapTwoPi(degToRad(d));
  return true;
}

bool scaled(std::string_view f, double factor, double max, double& out) {
  double v;
  if (!nmea::parseDouble(f, v) || !std::isfinite(v))
    return false;
  v *= factor;
  if (v < 0.0 || v > max)
    return false;
  out = v;
  return true;
}

// Unit letter of a sentence: empty means knots/nautical miles (what every marine radar defaults to).
Error unitOf(std::string_view f, char& unit) {
  char u = nmea::letter(f);
  if (u == '\0')
    u = 'N';
  if (speedFactor(u) == 0.0)
    return Error::kBadUnits;
  unit = u;
  return Error::kNone;
}

std::string name(std::string_view f) {
  return std::string(nmea::trim(f));
}

}  // namespace

void ArpaConfig::validate() const {
  if (!(max_distance > 0.0) || !(max_speed > 0.0))
    throw std::invalid_argument("arpa::ArpaConfig: max_distance and max_speed must be > 0");
}

const char* errorText(Error e) {
  switch (e) {
    case Error::kNone:
      return "ok";
    case Error::kWrongType:
      return "wrong sentence type";
    case Error::kBadFields:
      return "missing fields";
    case Error::kBadUnits:
      return "unknown unit";
    case Error::kBadValue:
      return "bad value";
    case Error::kCount:
      break;
  }
  return "unknown";
}

double speedFactor(char unit) {
  switch (unit) {
    case 'K':
      return 1000.0 / 3600.0;
    case 'N':
      return kMpsPerKnot;
    case 'S':
      return kMetresPerStatuteMile / 3600.0;
    default:
      return 0.0;
  }
}

double distanceFactor(char unit) {
  switch (unit) {
    case 'K':
      return 1000.0;
    case 'N':
      return kMetresPerNauticalMile;
    case 'S':
      return kMetresPerStatuteMile;
    default:
      return 0.0;
  }
}

Error parseTtm(const nmea::Sentence& s, TrackedTarget& t, const ArpaConfig& config) {
  if (s.type != "TTM")
    return Error::kWrongType;
  if (s.field_count < 11)
    return Error::kBadFields;
  t = TrackedTarget();
  if (Error e = targetNumber(s.field(1), t.number); e != Error::kNone)
    return e;
  if (Error e = unitOf(s.field(10), t.units); e != Error::kNone)
    return e;
  const double dist_k = distanceFactor(t.units), speed_k = speedFactor(t.units);

  t.has_distance = scaled(s.field(2), dist_k, config.max_distance, t.distance);
  t.bearing_ref = reference(s.field(4));
  t.has_bearing = angle(s.field(3), t.bearing);
  if (t.bearing_ref == Reference::kUnknown)
    t.bearing_ref = Reference::kTrue;  // field empty: true by default
  t.has_speed = scaled(s.field(5), speed_k, config.max_speed, t.speed);
  t.course_ref = reference(s.field(7));
  t.has_course = angle(s.field(6), t.course);
  if (t.course_ref == Reference::kUnknown)
    t.course_ref = Reference::kTrue;
  t.has_cpa = scaled(s.field(8), dist_k, config.max_distance, t.cpa);
  double tcpa_min;
  // Finite after the conversion too: 1e308 min is a finite field but an infinite number of seconds.
  if (nmea::parseDouble(s.field(9), tcpa_min) && std::isfinite(tcpa_min * 60.0)) {
    t.has_tcpa = true;
    t.tcpa = tcpa_min * 60.0;
  }
  t.name = name(s.field(11));
  t.status = status(s.field(12));
  t.reference_target = nmea::letter(s.field(13)) == 'R';
  t.has_time = utcSeconds(s.field(14), t.utc_seconds);
  switch (nmea::letter(s.field(15))) {
    case 'A':
      t.acquisition = Acquisition::kAutomatic;
      break;
    case 'M':
      t.acquisition = Acquisition::kManual;
      break;
    case 'R':
      t.acquisition = Acquisition::kReported;
      break;
    default:
      t.acquisition = Acquisition::kUnknown;
      break;
  }
  return Error::kNone;
}

Error parseTll(const nmea::Sentence& s, TargetPosition& t, const ArpaConfig&) {
  if (s.type != "TLL")
    return Error::kWrongType;
  if (s.field_count < 6)
    return Error::kBadFields;
  t = TargetPosition();
  if (Error e = targetNumber(s.field(1), t.number); e != Error::kNone)
    return e;
  double lat, lon;
  if (nmea::parseLatLon(s.field(2), s.field(3), true, lat) &&
      nmea::parseLatLon(s.field(4), s.field(5), false, lon)) {
    t.has_position = true;
    t.lat_deg = lat;
    t.lon_deg = lon;
  }
  t.name = name(s.field(6));
  t.has_time = utcSeconds(s.field(7), t.utc_seconds);
  t.status = status(s.field(8));
  t.reference_target = nmea::letter(s.field(9)) == 'R';
  return Error::kNone;
}

Error parseOsd(const nmea::Sentence& s, OwnShipData& o, const ArpaConfig& config) {
  if (s.type != "OSD")
    return Error::kWrongType;
  if (s.field_count < 10)
    return Error::kBadFields;
  o = OwnShipData();
  if (Error e = unitOf(s.field(9), o.units); e != Error::kNone)
    return e;
  const double speed_k = speedFactor(o.units);
  o.has_heading = angle(s.field(1), o.heading);
  o.heading_valid = nmea::letter(s.field(2)) == 'A';
  o.has_course = angle(s.field(3), o.course);
  o.course_ref = nmea::letter(s.field(4));
  o.has_speed = scaled(s.field(5), speed_k, config.max_speed, o.speed);
  o.speed_ref = nmea::letter(s.field(6));
  o.has_set = angle(s.field(7), o.set);
  o.has_drift = scaled(s.field(8), speed_k, config.max_speed, o.drift);
  return Error::kNone;
}

bool toTrue(TrackedTarget& t, double own_heading) {
  const bool need = (t.has_bearing && t.bearing_ref == Reference::kRelative) ||
                    (t.has_course && t.course_ref == Reference::kRelative);
  if (need && !std::isfinite(own_heading))
    return false;
  if (t.bearing_ref == Reference::kRelative) {
    if (t.has_bearing)
      t.bearing = wrapTwoPi(t.bearing + own_heading);
    t.bearing_ref = Reference::kTrue;
  }
  if (t.course_ref == Reference::kRelative) {
    if (t.has_course)
      t.course = wrapTwoPi(t.course + own_heading);
    t.course_ref = Reference::kTrue;
  }
  return true;
}

}  // namespace arpa
}  // namespace asv
