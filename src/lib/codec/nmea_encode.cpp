#include "asv_core/codec/nmea_encode.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "asv_core/common/units.h"

namespace asv {

namespace {

// An angle [rad] in degrees [0, 360) rounded to 0.1, as printed: 359.96 deg is 0.0, not "360.0".
double tenthsOfDegree(double rad) {
  const double d = std::round(wrapDeg360(radToDeg(rad)) * 10.0) / 10.0;
  return d >= 360.0 ? 0.0 : d;
}

}  // namespace

namespace nmea {

std::string withChecksum(char start, const std::string& body) {
  std::uint8_t cs = 0;
  for (char c : body)
    cs ^= static_cast<std::uint8_t>(c);
  char tail[4];
  std::snprintf(tail, sizeof tail, "*%02X", cs);
  return std::string(1, start) + body + tail;
}

}  // namespace nmea

namespace ais {

void BitWriter::put(std::uint32_t value, int bits) {
  for (int i = bits - 1; i >= 0; --i)
    bits_.push_back(((value >> i) & 1u) != 0);
}

void BitWriter::putSigned(std::int32_t value, int bits) {
  put(static_cast<std::uint32_t>(value) & (bits >= 32 ? 0xffffffffu : ((1u << bits) - 1u)), bits);
}

void BitWriter::putText(std::string_view text, int chars) {
  for (int i = 0; i < chars; ++i) {
    char c = i < static_cast<int>(text.size()) ? text[i] : '@';
    if (c >= 'a' && c <= 'z')
      c = static_cast<char>(c - 'a' + 'A');
    if (c < 32 || c > 95)
      c = '?';
    put(c >= 64 ? c - 64 : c, 6);  // six-bit ASCII: '@'..'_' are 0..31, ' '..'?' are 32..63
  }
}

std::string BitWriter::armour(int& fill) const {
  const std::size_t n = bits_.size();
  fill = static_cast<int>((6 - n % 6) % 6);
  std::string out;
  out.reserve((n + 5) / 6);
  for (std::size_t i = 0; i < n; i += 6) {
    unsigned v = 0;
    for (std::size_t k = 0; k < 6; ++k)
      v = (v << 1) | (i + k < n && bits_[i + k] ? 1u : 0u);
    out.push_back(static_cast<char>(v < 40 ? v + 48 : v + 56));
  }
  return out;
}

std::int32_t rawLat(std::optional<double> lat_deg) {
  if (!lat_deg || !std::isfinite(*lat_deg) || std::fabs(*lat_deg) > 90.0)
    return kLatNotAvailable;
  return static_cast<std::int32_t>(std::lround(*lat_deg * 600000.0));
}

std::int32_t rawLon(std::optional<double> lon_deg) {
  if (!lon_deg || !std::isfinite(*lon_deg) || std::fabs(*lon_deg) > 180.0)
    return kLonNotAvailable;
  return static_cast<std::int32_t>(std::lround(*lon_deg * 600000.0));
}

std::uint32_t rawSpeed(std::optional<double> speed_mps) {
  if (!speed_mps || !std::isfinite(*speed_mps) || *speed_mps < 0.0)
    return kSpeedNotAvailable;
  const long v = std::lround(mpsToKnots(*speed_mps) * 10.0);
  return static_cast<std::uint32_t>(std::min(v, 1022L));
}

std::uint32_t rawCourse(std::optional<double> course_rad) {
  if (!course_rad || !std::isfinite(*course_rad))
    return kCourseNotAvailable;
  return static_cast<std::uint32_t>(std::lround(wrapDeg360(radToDeg(*course_rad)) * 10.0)) % 3600;
}

std::uint32_t rawHeading(std::optional<double> heading_rad) {
  if (!heading_rad || !std::isfinite(*heading_rad))
    return kHeadingNotAvailable;
  return static_cast<std::uint32_t>(std::lround(wrapDeg360(radToDeg(*heading_rad)))) % 360;
}

std::int32_t rawTurn(std::optional<double> rate_rad_s) {
  if (!rate_rad_s || !std::isfinite(*rate_rad_s))
    return kTurnNotAvailable;
  const double deg_min = radToDeg(*rate_rad_s) * 60.0;
  const double rot = 4.733 * std::sqrt(std::fabs(deg_min));
  const long v = std::lround(std::min(rot, 126.0));
  return static_cast<std::int32_t>(deg_min < 0 ? -v : v);
}

BitWriter encodePositionA(std::uint8_t type, std::uint32_t mmsi, const PositionReportA& r) {
  BitWriter w;  // 168 bits
  w.put(type, 6);
  w.put(0, 2);  // repeat
  w.put(mmsi, 30);
  w.put(r.status, 4);
  w.putSigned(r.turn, 8);
  w.put(r.speed, 10);
  w.put(r.accuracy, 1);
  w.putSigned(r.lon, 28);
  w.putSigned(r.lat, 27);
  w.put(r.course, 12);
  w.put(r.heading, 9);
  w.put(r.second, 6);
  w.put(r.maneuver, 2);
  w.put(0, 3);  // spare
  w.put(r.raim, 1);
  w.put(r.radio, 19);
  return w;
}

BitWriter encodeStaticVoyage(std::uint32_t mmsi, const StaticVoyageData& d) {
  BitWriter w;  // 424 bits
  w.put(5, 6);
  w.put(0, 2);
  w.put(mmsi, 30);
  w.put(d.ais_version, 2);
  w.put(d.imo, 30);
  w.putText(d.callsign.view(), 7);
  w.putText(d.shipname.view(), 20);
  w.put(d.shiptype, 8);
  w.put(d.to_bow, 9);
  w.put(d.to_stern, 9);
  w.put(d.to_port, 6);
  w.put(d.to_starboard, 6);
  w.put(d.epfd, 4);
  w.put(d.month, 4);
  w.put(d.day, 5);
  w.put(d.hour, 5);
  w.put(d.minute, 6);
  w.put(d.draught, 8);
  w.putText(d.destination.view(), 20);
  w.put(d.dte, 1);
  w.put(0, 1);
  return w;
}

BitWriter encodePositionB(std::uint32_t mmsi, const PositionReportB& r) {
  BitWriter w;  // 168 bits
  w.put(18, 6);
  w.put(0, 2);
  w.put(mmsi, 30);
  w.put(r.reserved, 8);
  w.put(r.speed, 10);
  w.put(r.accuracy, 1);
  w.putSigned(r.lon, 28);
  w.putSigned(r.lat, 27);
  w.put(r.course, 12);
  w.put(r.heading, 9);
  w.put(r.second, 6);
  w.put(r.regional, 2);
  w.put(r.cs, 1);
  w.put(r.display, 1);
  w.put(r.dsc, 1);
  w.put(r.band, 1);
  w.put(r.msg22, 1);
  w.put(r.assigned, 1);
  w.put(r.raim, 1);
  w.put(r.radio, 20);
  return w;
}

BitWriter encodeStaticDataReport(std::uint32_t mmsi, const StaticDataReport& d) {
  BitWriter w;  // 168 bits either part
  w.put(24, 6);
  w.put(0, 2);
  w.put(mmsi, 30);
  w.put(d.part, 2);
  if (d.part == 0) {
    w.putText(d.shipname.view(), 20);
    w.put(0, 8);
    return w;
  }
  w.put(d.shiptype, 8);
  w.putText(d.vendorid.view(), 3);
  w.put(d.model, 4);
  w.put(d.serial, 20);
  w.putText(d.callsign.view(), 7);
  w.put(d.to_bow, 9);
  w.put(d.to_stern, 9);
  w.put(d.to_port, 6);
  w.put(d.to_starboard, 6);
  w.put(0, 6);
  return w;
}

std::vector<std::string> toSentences(const BitWriter& payload, char channel, int seq_id,
                                     const std::string& talker, std::size_t max_chars,
                                     const std::string& formatter) {
  int fill = 0;
  const std::string all = payload.armour(fill);
  const std::size_t n = std::max<std::size_t>(1, (all.size() + max_chars - 1) / max_chars);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string part = all.substr(i * max_chars, max_chars);
    const int f = i + 1 == n ? fill : 0;
    std::string body = talker + formatter + "," + std::to_string(n) + "," + std::to_string(i + 1) + "," +
                       (n > 1 ? std::to_string(seq_id % 10) : std::string()) + "," + std::string(1, channel) +
                       "," + part + "," + std::to_string(f);
    out.push_back(nmea::withChecksum('!', body));
  }
  return out;
}

}  // namespace ais

namespace gnss {

namespace {

// "ddmm.mmmm,N" or "dddmm.mmmm,E": degrees and decimal minutes, rounded to 1/10000 minute first so that
// 59.99995' becomes the next degree rather than "60.0000".
std::string angle(double deg, int deg_digits, char pos, char neg) {
  const long long units = std::llround(std::fabs(deg) * 600000.0);  // 1/10000 minute
  char b[32];
  std::snprintf(b, sizeof b, "%0*lld%02lld.%04lld,%c", deg_digits, units / 600000, (units % 600000) / 10000,
                units % 10000, deg < 0.0 ? neg : pos);
  return b;
}

}  // namespace

std::string encodeRmc(const RmcOut& r, const std::string& talker) {
  const double t = std::floor(r.unix_time * 100.0 + 0.5) / 100.0;  // to the 1/100 s printed
  const long long days = static_cast<long long>(std::floor(t / 86400.0));
  const double sod = t - static_cast<double>(days) * 86400.0;
  const std::time_t midnight = static_cast<std::time_t>(days * 86400);
  std::tm date{};
  gmtime_r(&midnight, &date);  // the civil date, from the C library
  char b[160];
  std::snprintf(b, sizeof b, "%sRMC,%02d%02d%05.2f,%c,%s,%s,%.1f,%.1f,%02d%02d%02d,,,%c", talker.c_str(),
                static_cast<int>(sod / 3600.0), static_cast<int>(std::fmod(sod, 3600.0) / 60.0),
                std::fmod(sod, 60.0), r.valid ? 'A' : 'V', angle(r.lat_deg, 2, 'N', 'S').c_str(),
                angle(r.lon_deg, 3, 'E', 'W').c_str(), mpsToKnots(r.speed), tenthsOfDegree(r.course),
                date.tm_mday, date.tm_mon + 1, date.tm_year % 100, r.valid ? 'A' : 'N');
  return nmea::withChecksum('$', b);
}

std::string encodeHdt(double heading, const std::string& talker) {
  char b[32];
  std::snprintf(b, sizeof b, "%sHDT,%.1f,T", talker.c_str(), tenthsOfDegree(heading));
  return nmea::withChecksum('$', b);
}

}  // namespace gnss

namespace arpa {

std::string encodeTtm(const TtmOut& t, const std::string& talker) {
  char buf[160];
  auto opt = [](std::optional<double> v, double scale, const char* fmt) {
    if (!v || !std::isfinite(*v))
      return std::string();
    char b[32];
    std::snprintf(b, sizeof b, fmt, *v * scale);
    return std::string(b);
  };
  std::string utc;
  if (t.utc_seconds_of_day >= 0.0) {
    // Rounded to the 1/100 s printed first, so that 59.996 s is the next minute, never "60.00".
    const double s = std::fmod(std::round(t.utc_seconds_of_day * 100.0) / 100.0, 86400.0);
    char b[16];
    std::snprintf(b, sizeof b, "%02d%02d%05.2f", static_cast<int>(s / 3600),
                  static_cast<int>(std::fmod(s, 3600) / 60), std::fmod(s, 60.0));
    utc = b;
  }
  // A name keeps the sentence within 82 characters and holds no field or checksum delimiter.
  std::string name;
  for (char c : t.name.substr(0, 20))
    if (c != ',' && c != '*' && c != '$' && c != '!' && c != '\\')
      name += c;
  std::snprintf(buf, sizeof buf, "%sTTM,%02d,%.2f,%.1f,T,%.1f,%.1f,T,%s,%s,N,%s,%c,,%s,%c", talker.c_str(),
                t.number % 1000, metresToNm(t.distance), tenthsOfDegree(t.bearing), mpsToKnots(t.speed),
                tenthsOfDegree(t.course), opt(t.cpa, 1.0 / kMetresPerNauticalMile, "%.2f").c_str(),
                opt(t.tcpa, 1.0 / 60.0, "%.1f").c_str(), name.c_str(), t.status, utc.c_str(), t.acquisition);
  return nmea::withChecksum('$', buf);
}

}  // namespace arpa
}  // namespace asv
