#include "asv_core/codec/gnss.h"

#include <cmath>
#include <stdexcept>

#include "asv_core/common/units.h"

namespace asv {
namespace gnss {

namespace {

std::optional<double> number(std::string_view f) {
  double v = 0.0;
  if (!nmea::parseDouble(f, v) || !std::isfinite(v))
    return std::nullopt;
  return v;
}

// A bearing field in degrees -> radians in [0, 2 pi); empty for an empty, malformed or negative value.
std::optional<double> bearing(std::string_view f) {
  const std::optional<double> d = number(f);
  if (!d || *d < 0.0 || *d > 360.0)
    return std::nullopt;
  return wrapTwoPi(degToRad(*d));
}

// A magnitude and its E/W letter -> radians, east positive.
std::optional<double> eastWest(std::string_view value, std::string_view hemisphere) {
  const std::optional<double> d = number(value);
  const char h = nmea::letter(hemisphere);
  if (!d || (h != 'E' && h != 'W'))
    return std::nullopt;
  return degToRad(h == 'E' ? *d : -*d);
}

Error position(const nmea::Sentence& s, std::size_t lat_field, Fix& out) {
  if (!nmea::parseLatLon(s.field(lat_field), s.field(lat_field + 1), true, out.lat_deg) ||
      !nmea::parseLatLon(s.field(lat_field + 2), s.field(lat_field + 3), false, out.lon_deg))
    return Error::kBadFields;
  return Error::kNone;
}

// RMC's and GNS's mode letters (NMEA 4.11) on GGA's quality scale.
Quality modeQuality(char mode) {
  switch (mode) {
    case 'A':
      return Quality::kGnss;
    case 'D':
      return Quality::kDifferential;
    case 'P':
      return Quality::kPps;
    case 'R':
      return Quality::kRtkFixed;
    case 'F':
      return Quality::kRtkFloat;
    case 'E':
      return Quality::kDeadReckoning;
    case 'M':
      return Quality::kManual;
    case 'S':
      return Quality::kSimulator;
    default:
      return Quality::kNone;  // N (no fix) or unknown
  }
}

// Better fixes rank higher (GGA's numbers are not in order of accuracy).
int rank(Quality q) {
  switch (q) {
    case Quality::kRtkFixed:
      return 7;
    case Quality::kRtkFloat:
      return 6;
    case Quality::kDifferential:
      return 5;
    case Quality::kPps:
      return 4;
    case Quality::kGnss:
      return 3;
    case Quality::kDeadReckoning:
      return 2;
    case Quality::kManual:
    case Quality::kSimulator:
      return 1;
    default:
      return 0;
  }
}

void dilution(const nmea::Sentence& s, std::size_t sats_field, Fix& out) {
  long n = 0;
  if (nmea::parseInt(s.field(sats_field), n) && n >= 0 && n < 100)
    out.satellites = static_cast<int>(n);
  const std::optional<double> h = number(s.field(sats_field + 1));
  if (h && *h > 0.0)
    out.hdop = h;
}

}  // namespace

const char* errorText(Error e) {
  switch (e) {
    case Error::kNone:
      return "ok";
    case Error::kWrongType:
      return "wrong sentence type";
    case Error::kBadFields:
      return "missing or malformed field";
    case Error::kNoFix:
      return "no fix";
    case Error::kInvalid:
      return "marked not valid";
  }
  return "?";
}

Error parseGga(const nmea::Sentence& s, Fix& out) {
  if (!s.is("GGA"))
    return Error::kWrongType;
  long q = 0;
  if (!nmea::parseInt(s.field(6), q) || q < 0 || q > 8)
    return Error::kBadFields;
  if (q == 0)
    return Error::kNoFix;
  out = Fix();
  out.quality = static_cast<Quality>(q);
  if (const Error e = position(s, 2, out); e != Error::kNone)
    return e;
  dilution(s, 7, out);
  return Error::kNone;
}

Error parseGns(const nmea::Sentence& s, Fix& out) {
  if (!s.is("GNS"))
    return Error::kWrongType;
  // One mode letter per constellation: the best of them.
  Quality best = Quality::kNone;
  for (char c : nmea::trim(s.field(6)))
    if (rank(modeQuality(c)) > rank(best))
      best = modeQuality(c);
  if (best == Quality::kNone)
    return Error::kNoFix;
  out = Fix();
  out.quality = best;
  if (const Error e = position(s, 2, out); e != Error::kNone)
    return e;
  dilution(s, 7, out);
  return Error::kNone;
}

Error parseRmc(const nmea::Sentence& s, Fix& fix, Motion& motion, std::optional<double>& variation) {
  if (!s.is("RMC"))
    return Error::kWrongType;
  if (nmea::letter(s.field(2)) != 'A')
    return Error::kNoFix;  // V: navigation receiver warning
  const char mode = nmea::letter(s.field(12));
  fix = Fix();
  fix.quality = mode == '\0' ? Quality::kGnss : modeQuality(mode);  // NMEA 2.3 added the mode
  if (fix.quality == Quality::kNone)
    return Error::kNoFix;
  if (const Error e = position(s, 3, fix); e != Error::kNone)
    return e;
  motion = Motion();
  if (const std::optional<double> sog = number(s.field(7)); sog && *sog >= 0.0)
    motion.speed = knotsToMps(*sog);
  motion.course = bearing(s.field(8));
  variation = eastWest(s.field(10), s.field(11));
  return Error::kNone;
}

Error parseVtg(const nmea::Sentence& s, Motion& out) {
  if (!s.is("VTG"))
    return Error::kWrongType;
  if (nmea::letter(s.field(9)) == 'N')
    return Error::kInvalid;
  out = Motion();
  if (nmea::letter(s.field(2)) == 'T')
    out.course = bearing(s.field(1));
  if (const std::optional<double> kn = number(s.field(5));
      kn && *kn >= 0.0 && nmea::letter(s.field(6)) == 'N')
    out.speed = knotsToMps(*kn);
  else if (const std::optional<double> kmh = number(s.field(7));
           kmh && *kmh >= 0.0 && nmea::letter(s.field(8)) == 'K')
    out.speed = *kmh / 3.6;
  if (!out.course && !out.speed)
    return Error::kBadFields;
  return Error::kNone;
}

Error parseHdt(const nmea::Sentence& s, double& heading) {
  if (!s.is("HDT"))
    return Error::kWrongType;
  const std::optional<double> h = bearing(s.field(1));
  if (!h || nmea::letter(s.field(2)) != 'T')
    return Error::kBadFields;
  heading = *h;
  return Error::kNone;
}

Error parseThs(const nmea::Sentence& s, double& heading) {
  if (!s.is("THS"))
    return Error::kWrongType;
  const char mode = nmea::letter(s.field(2));
  if (mode == 'V' || mode == '\0')
    return Error::kInvalid;
  const std::optional<double> h = bearing(s.field(1));
  if (!h)
    return Error::kBadFields;
  heading = *h;
  return Error::kNone;
}

Error parseHdg(const nmea::Sentence& s, std::optional<double> variation, double& heading) {
  if (!s.is("HDG"))
    return Error::kWrongType;
  const std::optional<double> magnetic = bearing(s.field(1));
  if (!magnetic)
    return Error::kBadFields;
  const double deviation = eastWest(s.field(2), s.field(3)).value_or(0.0);
  if (const std::optional<double> v = eastWest(s.field(4), s.field(5)))
    variation = v;
  if (!variation)
    return Error::kInvalid;
  heading = wrapTwoPi(*magnetic + deviation + *variation);
  return Error::kNone;
}

std::optional<double> variationFromParams(const ParamMap& p) {
  if (!p.has("variation_deg"))
    return std::nullopt;
  const double deg = p.getDouble("variation_deg", 0.0);
  if (!(std::fabs(deg) <= 90.0))
    throw std::invalid_argument("variation_deg must be within +-90 deg");
  return degToRad(deg);
}

Error parseRot(const nmea::Sentence& s, double& rate) {
  if (!s.is("ROT"))
    return Error::kWrongType;
  if (nmea::letter(s.field(2)) != 'A')
    return Error::kInvalid;
  const std::optional<double> r = number(s.field(1));  // [deg/min], negative: bow to port
  if (!r)
    return Error::kBadFields;
  rate = degToRad(*r) / 60.0;
  return Error::kNone;
}

}  // namespace gnss
}  // namespace asv
