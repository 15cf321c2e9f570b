// ARPA radar target sentences (IEC 61162-1): $--TTM (tracked target message), $--TLL (target latitude
// and longitude) and $--OSD (own ship data), converted to SI.
//
// Radars in the field bend the standard: fields padded with spaces, target numbers above 99, empty
// fields while a target is being acquired. Every field is therefore optional here: an empty or
// unparsable field is "unknown" (has_ flag false, value NaN), never zero.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "asv_core/codec/nmea.h"

namespace asv {
namespace arpa {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Reference of a bearing or course field.
enum class Reference : std::uint8_t { kUnknown, kTrue, kRelative };

// Target tracking status.
enum class TargetStatus : std::uint8_t { kUnknown, kLost, kQuery, kTracking };  // L, Q (acquiring), T

enum class Acquisition : std::uint8_t { kUnknown, kAutomatic, kManual, kReported };  // A, M, R

// $--TTM: one tracked target, relative to the own ship.
struct TrackedTarget {
  int number = -1;  // target number; above 99 on some radars; -1 unknown
  bool has_distance = false;
  double distance = kNaN;  // [m] from the own ship
  bool has_bearing = false;
  double bearing = kNaN;  // [rad] from the own ship, clockwise, see bearing_ref
  Reference bearing_ref = Reference::kUnknown;
  bool has_speed = false;
  double speed = kNaN;  // [m/s]
  bool has_course = false;
  double course = kNaN;  // [rad] clockwise, see course_ref
  Reference course_ref = Reference::kUnknown;
  bool has_cpa = false;
  double cpa = kNaN;  // [m] distance at the closest point of approach
  bool has_tcpa = false;
  double tcpa = kNaN;  // [s] time to CPA; negative when the CPA is past
  char units = '\0';   // 'K', 'N' or 'S' as received
  std::string name;
  TargetStatus status = TargetStatus::kUnknown;
  bool reference_target = false;  // 'R': the radar uses it as a reference (e.g. for ground speed)
  bool has_time = false;
  double utc_seconds = kNaN;  // [s] since UTC midnight
  Acquisition acquisition = Acquisition::kUnknown;
};

// $--TLL: target position.
struct TargetPosition {
  int number = -1;
  bool has_position = false;
  double lat_deg = kNaN;
  double lon_deg = kNaN;
  std::string name;
  bool has_time = false;
  double utc_seconds = kNaN;
  TargetStatus status = TargetStatus::kUnknown;
  bool reference_target = false;
};

// $--OSD: own ship data as the radar sees it.
struct OwnShipData {
  bool has_heading = false;
  double heading = kNaN;       // [rad] true
  bool heading_valid = false;  // status A
  bool has_course = false;
  double course = kNaN;    // [rad] true
  char course_ref = '\0';  // B bottom track, M manual, W water, R radar, P positioning
  bool has_speed = false;
  double speed = kNaN;  // [m/s]
  char speed_ref = '\0';
  bool has_set = false;
  double set = kNaN;  // [rad] true, direction of the current
  bool has_drift = false;
  double drift = kNaN;  // [m/s] current speed
  char units = '\0';
};

enum class Error : std::uint8_t {
  kNone = 0,
  kWrongType,  // not a TTM/TLL/OSD sentence (as asked)
  kBadFields,  // too few fields
  kBadUnits,   // unit not K/N/S while a value needs it
  kBadValue,   // a present field that is not a number or out of range
  kCount
};

const char* errorText(Error e);

struct ArpaConfig {
  // Range accepted for distances and CPA [m]; radar range never exceeds 96 nm, so larger is garbage.
  double max_distance = 200000.0;
  // Speeds above this are treated as garbage [m/s] (100 kn).
  double max_speed = 51.5;
  void validate() const;
};

Error parseTtm(const nmea::Sentence& s, TrackedTarget& out, const ArpaConfig& config = ArpaConfig());
Error parseTll(const nmea::Sentence& s, TargetPosition& out, const ArpaConfig& config = ArpaConfig());
Error parseOsd(const nmea::Sentence& s, OwnShipData& out, const ArpaConfig& config = ArpaConfig());

// Converts relative bearing/course to true with the own ship's true heading [rad, nautical]. Fields
// already true are unchanged. Returns false (and leaves `target` alone) when a relative field needs
// the heading and `own_heading` is not finite.
bool toTrue(TrackedTarget& target, double own_heading);

// Speed unit factor to m/s for 'K' (km/h), 'N' (kn), 'S' (statute mph); 0 for an unknown unit.
double speedFactor(char unit);
// Distance unit factor to m for 'K' (km), 'N' (nm), 'S' (statute mile); 0 for an unknown unit.
double distanceFactor(char unit);

}  // namespace arpa
}  // namespace asv
