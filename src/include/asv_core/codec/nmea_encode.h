// NMEA 0183 / AIS encoding: what the simulator emits so that the ingestion nodes see exactly what they
// would see at sea (AIVDM types 1, 5, 18, 24 and radar TTM), and the inverse of asv_core/codec/ais.h.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "asv_core/codec/ais.h"

namespace asv {
namespace nmea {

// "$" or "!" + body + "*hh" (checksum of the body).
std::string withChecksum(char start, const std::string& body);

}  // namespace nmea

namespace ais {

// Six-bit payload builder (ITU-R M.1371 bit order: most significant bit first).
class BitWriter {
public:
  void put(std::uint32_t value, int bits);
  void putSigned(std::int32_t value, int bits);
  // `chars` six-bit characters of `text` (upper-cased; characters outside the AIS alphabet become
  // '?'), padded with '@'.
  void putText(std::string_view text, int chars);
  std::size_t bits() const { return bits_.size(); }
  // The armoured payload and the fill bits needed to reach a multiple of six.
  std::string armour(int& fill) const;

private:
  std::vector<bool> bits_;
};

// Raw-field conversions from SI (rounded as a transponder does; sentinels for std::nullopt).
std::int32_t rawLat(std::optional<double> lat_deg);
std::int32_t rawLon(std::optional<double> lon_deg);
std::uint32_t rawSpeed(std::optional<double> speed_mps);    // 1/10 kn, 1022 = 102.2 kn or more
std::uint32_t rawCourse(std::optional<double> course_rad);  // 1/10 deg
std::uint32_t rawHeading(std::optional<double> heading_rad);
std::int32_t rawTurn(std::optional<double> rate_rad_s);  // ROT_AIS = 4.733 sqrt(deg/min)

// Payload bits of one message (types 1-3, 5, 18, 24 A/B).
BitWriter encodePositionA(std::uint8_t type, std::uint32_t mmsi, const PositionReportA& r);
BitWriter encodeStaticVoyage(std::uint32_t mmsi, const StaticVoyageData& d);
BitWriter encodePositionB(std::uint32_t mmsi, const PositionReportB& r);
BitWriter encodeStaticDataReport(std::uint32_t mmsi, const StaticDataReport& d);

// Splits a payload into !AIVDM sentences of at most `max_chars` payload characters each (60 keeps
// every sentence within the 82-character limit). Multi-fragment messages carry `seq_id` (0-9).
// `formatter` "VDO": the own ship's transponder's sentences.
std::vector<std::string> toSentences(const BitWriter& payload, char channel, int seq_id,
                                     const std::string& talker = "AI", std::size_t max_chars = 60,
                                     const std::string& formatter = "VDM");

}  // namespace ais

namespace gnss {

struct RmcOut {
  double unix_time = 0.0;  // [s] UTC of the fix, seconds since 1970-01-01
  double lat_deg = 0.0, lon_deg = 0.0;
  double speed = 0.0;   // [m/s] over ground
  double course = 0.0;  // [rad] true course over ground
  bool valid = true;    // false: status V, mode N (a chart plotter shows no position)
};

// "$GPRMC,hhmmss.ss,A,ddmm.mmmm,N,dddmm.mmmm,E,knots,deg,ddmmyy,,,A" (NMEA 2.3, mode A).
std::string encodeRmc(const RmcOut& r, const std::string& talker = "GP");
// "$HEHDT,deg,T": a true heading [rad].
std::string encodeHdt(double heading, const std::string& talker = "HE");

}  // namespace gnss

namespace arpa {

struct TtmOut {
  int number = 1;              // target number 0-999
  double distance = 0.0;       // [m] from the own ship
  double bearing = 0.0;        // [rad] true bearing from the own ship
  double speed = 0.0;          // [m/s]
  double course = 0.0;         // [rad] true course
  std::optional<double> cpa;   // [m] distance of CPA; empty while acquiring
  std::optional<double> tcpa;  // [s] time to CPA
  std::string name;
  char status = 'T';                 // L lost, Q query (acquiring), T tracking
  double utc_seconds_of_day = -1.0;  // < 0: empty UTC field
  char acquisition = 'A';            // A automatic, M manual, R reported
};

// "$RATTM,..." with distances in nautical miles and speeds in knots (units field N), true bearings.
std::string encodeTtm(const TtmOut& t, const std::string& talker = "RA");

}  // namespace arpa
}  // namespace asv
