// libFuzzer target for the ARPA parsers ($--TTM, $--TLL, $--OSD) and the relative-to-true conversion,
// and the own ship's navigation parsers (GGA, GNS, RMC, VTG, HDT, THS, HDG, ROT; codec/gnss.h).
// Not built by CMake; scripts/fuzz_smoke.sh builds and runs it, or by hand from the repository root:
//
//   clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -I src/include -I /usr/include/eigen3
//   src/fuzz/fuzz_arpa.cpp src/lib/codec/nmea.cpp src/lib/codec/arpa.cpp src/lib/codec/gnss.cpp
//   src/lib/common/param_map.cpp -o fuzz_arpa
//   ./fuzz_arpa src/fuzz/corpus/arpa -max_total_time=20
//
// Every line of the input goes through the NMEA framer with the checksum optional (so mutations of a
// field are not all rejected by a stale checksum), and every framed sentence through all three parsers,
// whatever its type. Invariants checked on a sentence a parser accepts: a field is either known (has_
// flag set, value finite and in its documented range) or unknown (flag clear, value NaN), never a
// number made from garbage; after toTrue() with a finite heading every known bearing/course is true
// and in [0, 2 pi). A navigation sentence a parser accepts gives a position in range with a fix quality,
// bearings in [0, 2 pi), speeds finite and >= 0, a finite turn rate.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "asv_core/codec/arpa.h"
#include "asv_core/codec/gnss.h"
#include "asv_core/codec/nmea.h"

namespace {

using asv::arpa::Reference;

constexpr double kTwoPi = 2.0 * M_PI;

// Known: finite and in [lo, hi]; unknown: NaN.
void checkField(bool known, double v, double lo, double hi) {
  if (known && !(std::isfinite(v) && v >= lo && v <= hi))
    __builtin_trap();
  if (!known && !std::isnan(v))
    __builtin_trap();
}

void checkAngle(bool known, double v) {
  checkField(known, v, 0.0, kTwoPi);
  if (known && !(v < kTwoPi))
    __builtin_trap();
}

void checkTime(bool known, double v) {
  checkField(known, v, 0.0, 86400.0 + 1.0);
}

void checkBearing(std::optional<double> v) {
  if (v && !(*v >= 0.0 && *v < kTwoPi))
    __builtin_trap();
}

void checkNavigation(const asv::nmea::Sentence& s) {
  namespace g = asv::gnss;
  g::Fix f;
  g::Motion m;
  std::optional<double> variation;
  double v = 0.0;
  for (const g::Error e : {g::parseGga(s, f), g::parseGns(s, f), g::parseRmc(s, f, m, variation)})
    if (e == g::Error::kNone &&
        (!(std::fabs(f.lat_deg) <= 90.0 && std::fabs(f.lon_deg) <= 180.0) || f.quality == g::Quality::kNone ||
         (f.hdop && !(*f.hdop > 0.0 && std::isfinite(*f.hdop)))))
      __builtin_trap();
  if (g::parseVtg(s, m) == g::Error::kNone || g::parseRmc(s, f, m, variation) == g::Error::kNone) {
    checkBearing(m.course);
    if (m.speed && !(*m.speed >= 0.0 && std::isfinite(*m.speed)))
      __builtin_trap();
  }
  for (const g::Error e : {g::parseHdt(s, v), g::parseThs(s, v), g::parseHdg(s, 0.1, v)})
    if (e == g::Error::kNone)
      checkBearing(v);
  if (g::parseRot(s, v) == g::Error::kNone && !std::isfinite(v))
    __builtin_trap();
}

void checkTtm(const asv::arpa::TrackedTarget& t, const asv::arpa::ArpaConfig& c) {
  if (t.number < 0 || t.number > 9999)
    __builtin_trap();
  if (t.units != 'K' && t.units != 'N' && t.units != 'S')
    __builtin_trap();
  checkField(t.has_distance, t.distance, 0.0, c.max_distance);
  checkAngle(t.has_bearing, t.bearing);
  checkField(t.has_speed, t.speed, 0.0, c.max_speed);
  checkAngle(t.has_course, t.course);
  checkField(t.has_cpa, t.cpa, 0.0, c.max_distance);
  checkField(t.has_tcpa, t.tcpa, -HUGE_VAL, HUGE_VAL);  // any sign, but finite when known
  checkTime(t.has_time, t.utc_seconds);
  // An absent reference field means true: the parser never leaves it unknown.
  if (t.bearing_ref == Reference::kUnknown || t.course_ref == Reference::kUnknown)
    __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  asv::nmea::FramerConfig pc;
  pc.require_checksum = false;
  asv::arpa::ArpaConfig ac;
  asv::nmea::Sentence s;
  std::size_t begin = 0;
  double heading = 0.0;
  while (begin <= input.size()) {
    std::size_t end = input.find('\n', begin);
    if (end == std::string_view::npos)
      end = input.size();
    const std::string_view line = input.substr(begin, end - begin);
    begin = end + 1;
    std::size_t pos = 0;
    while ((pos = asv::nmea::findSentenceStart(line, pos)) != std::string_view::npos) {
      if (asv::nmea::parseSentence(line.substr(pos), s, pc) != asv::nmea::Reject::kNone) {
        ++pos;
        continue;
      }
      pos += s.end;

      checkNavigation(s);
      asv::arpa::OwnShipData o;
      if (asv::arpa::parseOsd(s, o, ac) == asv::arpa::Error::kNone) {
        if (o.units != 'K' && o.units != 'N' && o.units != 'S')
          __builtin_trap();
        checkAngle(o.has_heading, o.heading);
        checkAngle(o.has_course, o.course);
        checkField(o.has_speed, o.speed, 0.0, ac.max_speed);
        checkAngle(o.has_set, o.set);
        checkField(o.has_drift, o.drift, 0.0, ac.max_speed);
        if (o.has_heading)
          heading = o.heading;  // later TTMs of this input are converted with it
      }

      asv::arpa::TrackedTarget t;
      if (asv::arpa::parseTtm(s, t, ac) == asv::arpa::Error::kNone) {
        checkTtm(t, ac);
        // Unknown own heading: refused exactly when a known field is relative, target untouched.
        asv::arpa::TrackedTarget u = t;
        const bool needs = (t.has_bearing && t.bearing_ref == Reference::kRelative) ||
                           (t.has_course && t.course_ref == Reference::kRelative);
        if (asv::arpa::toTrue(u, std::nan("")) == needs)
          __builtin_trap();
        if (needs && (u.bearing_ref != t.bearing_ref || u.course_ref != t.course_ref))
          __builtin_trap();
        // Finite heading (the last OSD's, or a large one built from the target number): always true.
        for (double h : {heading, t.number * 1.0e3, -t.number * 0.7}) {
          u = t;
          if (!asv::arpa::toTrue(u, h))
            __builtin_trap();
          if (u.bearing_ref != Reference::kTrue || u.course_ref != Reference::kTrue)
            __builtin_trap();
          checkTtm(u, ac);
        }
      }

      asv::arpa::TargetPosition p;
      if (asv::arpa::parseTll(s, p, ac) == asv::arpa::Error::kNone) {
        if (p.number < 0 || p.number > 9999)
          __builtin_trap();
        checkField(p.has_position, p.lat_deg, -90.0, 90.0);
        checkField(p.has_position, p.lon_deg, -180.0, 180.0);
        checkTime(p.has_time, p.utc_seconds);
      }
    }
    if (end == input.size())
      break;
  }
  return 0;
}
