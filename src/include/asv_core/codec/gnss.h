// The own ship's navigation sentences (NMEA 0183 4.11), converted to SI at the input: positions from
// GGA, GNS and RMC; course and speed over ground from RMC and VTG; true heading from HDT, THS, and HDG
// (magnetic, corrected with its deviation and variation); rate of turn from ROT. Bearings come out as
// radians, nautical (0 = north, clockwise), speeds in m/s, turn rates in rad/s (positive to starboard).
// A field the talker left empty stays empty (std::optional); a sentence that says its data is not valid
// (GGA quality 0, RMC status V, THS mode V, ROT status V) is Error::kNoFix / kInvalid, never a value.
#pragma once

#include <optional>

#include "asv_core/codec/nmea.h"
#include "asv_core/common/param_map.h"

namespace asv {
namespace gnss {

enum class Error {
  kNone = 0,
  kWrongType,  // not the sentence asked for
  kBadFields,  // a required field missing or malformed
  kNoFix,      // the receiver says it has no fix
  kInvalid,    // a status or mode field says the value is not valid
};
const char* errorText(Error e);

// Fix quality, GGA's field 6 (RMC's and GNS's mode letters mapped onto it).
enum class Quality : int {
  kNone = 0,
  kGnss = 1,
  kDifferential = 2,
  kPps = 3,
  kRtkFixed = 4,
  kRtkFloat = 5,
  kDeadReckoning = 6,
  kManual = 7,
  kSimulator = 8
};

struct Fix {
  double lat_deg = 0.0, lon_deg = 0.0;
  Quality quality = Quality::kNone;
  std::optional<double> hdop;
  std::optional<int> satellites;
  std::optional<double> sigma;  // [m] horizontal 1-sigma when the source states it (NavSatFix covariance)
};

struct Motion {
  std::optional<double> course;  // [rad] true course over ground
  std::optional<double> speed;   // [m/s] speed over ground
};

Error parseGga(const nmea::Sentence& s, Fix& out);
Error parseGns(const nmea::Sentence& s, Fix& out);
// RMC: the fix (quality from the mode letter, GNSS without one), course and speed, and the magnetic
// variation [rad, east positive] when given.
Error parseRmc(const nmea::Sentence& s, Fix& fix, Motion& motion, std::optional<double>& variation);
Error parseVtg(const nmea::Sentence& s, Motion& out);
// HDT, THS: true heading [rad].
Error parseHdt(const nmea::Sentence& s, double& heading);
Error parseThs(const nmea::Sentence& s, double& heading);
// HDG: the sensor's magnetic heading corrected to true with its deviation and variation (east
// positive); without a variation field, `variation` (e.g. RMC's or configured) is used; without either,
// kInvalid (a magnetic heading is no true heading).
Error parseHdg(const nmea::Sentence& s, std::optional<double> variation, double& heading);
// The key variation_deg (magnetic variation, east positive) in radians; empty when not set;
// std::invalid_argument beyond +-90 deg.
std::optional<double> variationFromParams(const ParamMap& params);

// ROT: [rad/s], positive when the bow turns to starboard.
Error parseRot(const nmea::Sentence& s, double& rate);

}  // namespace gnss
}  // namespace asv
