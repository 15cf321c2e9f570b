// Structured application payloads (DAC/FID) of AIS type 6 messages, in gpsd 3.22's JSON.
//
// gpsd 3.22 decodes DAC 1 FIDs 12, 14, 15, 16, 18, 20, 25, 28, 30 and 32 at every length (88-1008
// bits), reading fields that lie past the end of a short payload from its bit buffer (the fill bits,
// then zeros: Payload::ur/sr). The inland (DAC 200) and GLA (DAC 235/250) sub-types are decoded only
// at their exact lengths. Everything else is printed as raw "data" by the caller.
#include <cstddef>
#include <cstdint>

#include "asv_core/codec/ais_json.h"

namespace asv {
namespace ais {

namespace {

// gpsd 3.22 scales the positions of DAC 1 FIDs 14, 18, 20 and 32 as 1/1000 minute with four decimals
// (also FID 14's, which IMO236 sends in 1/10000 minute: copied, the output must match); the route
// waypoints of FID 28 are 1/10000 minute (writeRouteInformation).
constexpr double kMilliMinutesPerDeg = 60000.0;

const char* const kRaconText[4] = {"No RACON installed", "RACON not monitored", "RACON operational",
                                   "RACON ERROR"};
const char* const kLightText[4] = {"No light or no monitoring", "Light ON", "Light OFF", "Light ERROR"};
const char* const kRtaStatusText[4] = {"Operational", "Limited operation", "Out of order", "N/A"};
const char* const kMooringPositionText[8] = {
    "Not available", "Port-side to", "Starboard-side to",       "Mediterranean (end-on) mooring",
    "Mooring buoy",  "Anchorage",    "Reserved for future use", "Reserved for future use"};
// Route types of DAC 1 FID 28: 6-30 are reserved, 31 cancels the route named by the linkage id.
const char* routeTypeText(unsigned rtype) {
  static const char* const kNamed[6] = {
      "Undefined (default)",           "Mandatory",      "Recommended", "Alternative",
      "Recommended route through ice", "Ship route plan"};
  if (rtype < 6)
    return kNamed[rtype];
  return rtype == 31 ? "Cancel route identified by message linkage" : "Reserved for future use.";
}

// "M-DTH:M" without zero padding (gpsd's "%u-%uT%u:%u" in the inland and berthing sub-types).
void unpaddedStamp(AisFields& w, const char* name, unsigned month, unsigned day, unsigned hour,
                   unsigned minute) {
  json::Out& o = w.out();
  w.key(name);
  o.ch('"');
  o.u(month);
  o.ch('-');
  o.u(day);
  o.ch('T');
  o.u(hour);
  o.ch(':');
  o.u(minute);
  o.ch('"');
}

// IMO236 dangerous cargo indication, DAC 1 FID 12. Any length: the 357-bit layout is read whole.
void writeDangerousCargo(const Payload& p, AisFields& w) {
  w.text6("lastport", p, 88, 5);
  w.stamp("departure", p.ur(118, 4), p.ur(122, 5), p.ur(127, 5), p.ur(132, 6));
  w.text6("nextport", p, 138, 5);
  w.stamp("eta", p.ur(168, 4), p.ur(172, 5), p.ur(177, 5), p.ur(182, 6));
  w.text6("dangerous", p, 188, 20);
  w.text6("imdcat", p, 308, 4);
  w.u("unid", p.ur(332, 13));
  w.u("amount", p.ur(345, 10));
  w.u("unit", p.ur(355, 2));
}

// One tidal window entry (DAC 1 FIDs 14 and 32); `start` is its first bit.
void writeTidal(const Payload& p, std::size_t start, bool imo236, AisFields& w) {
  // IMO236 (FID 14): lat 27 bits, lon 28, times, cdir 9, cspeed 7 (93 bits); IMO289 (FID 32): lon
  // 25 bits, lat 24, times, cdir 9, cspeed 8 (88 bits). Both are printed in 1/1000 minute units.
  const std::int32_t lon = imo236 ? p.sr(start + 27, 28) : p.sr(start, 25);
  const std::int32_t lat = imo236 ? p.sr(start, 27) : p.sr(start + 25, 24);
  const std::size_t t = start + (imo236 ? 55 : 49);
  w.beginObject();
  w.scaledDiv("lon", lon, kMilliMinutesPerDeg, 4);
  w.scaledDiv("lat", lat, kMilliMinutesPerDeg, 4);
  w.u("from_hour", p.ur(t, 5));
  w.u("from_min", p.ur(t + 5, 6));
  w.u("to_hour", p.ur(t + 11, 5));
  w.u("to_min", p.ur(t + 16, 6));
  w.u("cdir", p.ur(t + 22, 9));
  w.scaledDiv("cspeed", p.ur(t + 31, imo236 ? 7 : 8), 10.0, 1);
  w.endObject();
}

// Tidal window: IMO236, DAC 1 FID 14 (93-bit entries), and IMO289, DAC 1 FID 32 (88-bit entries).
// Any length: gpsd prints one entry per entry start at or before the payload end (none below 97
// bits), the last ones read partly past the end.
void writeTidalWindow(const Payload& p, bool imo236, AisFields& w) {
  const std::size_t size = imo236 ? 93 : 88;
  w.u("month", p.ur(88, 4));
  w.u("day", p.ur(92, 5));
  w.beginArray("tidals");
  for (std::size_t a = 97; a <= p.bits(); a += size)
    writeTidal(p, a, imo236, w);
  w.endArray();
}

// IMO236 extended ship static and voyage data, DAC 1 FID 15. Any length: gpsd reads the air draught
// at bit 56, inside the header, not at bit 88 where the application data starts.
void writeAirDraught(const Payload& p, AisFields& w) {
  w.u("airdraught", p.ur(56, 11));
}

// IMO236 number of persons on board, DAC 1 FID 16. Any length: at 224 bits (the IMO289 layout)
// the count is at bit 88; otherwise gpsd reads it at bit 55, inside the header.
void writePersons(const Payload& p, AisFields& w) {
  w.u("persons", p.bits() == 224 ? p.ur(88, 13) : p.ur(55, 13));
}

// IMO289 clearance time to enter port, DAC 1 FID 18. Any length: the 317-bit layout is read whole.
void writeClearance(const Payload& p, AisFields& w) {
  w.u("linkage", p.ur(88, 10));
  w.stamp("arrival", p.ur(98, 4), p.ur(102, 5), p.ur(107, 5), p.ur(112, 6));
  w.text6("portname", p, 118, 20);
  w.text6("destination", p, 238, 5);
  w.scaledDiv("lon", p.sr(268, 25), kMilliMinutesPerDeg, 4);
  w.scaledDiv("lat", p.sr(293, 24), kMilliMinutesPerDeg, 4);
}

// IMO289 berthing data, DAC 1 FID 20. Any length: the 360-bit layout is read whole.
void writeBerthing(const Payload& p, AisFields& w) {
  static const char* const kServices[] = {
      "agent",      "fuel",      "chandler",  "stevedore",  "electrical",  "water",          "customs",
      "cartage",    "crane",     "lift",      "medical",    "navrepair",   "provisions",     "shiprepair",
      "surveyor",   "steam",     "tugs",      "solidwaste", "liquidwaste", "hazardouswaste", "ballast",
      "additional", "regional1", "regional2", "future1",    "future2"};
  const unsigned position = p.ur(115, 3);
  w.u("linkage", p.ur(88, 10));
  w.u("berth_length", p.ur(98, 9));
  w.withText("position", position, "position_text", kMooringPositionText[position]);
  unpaddedStamp(w, "arrival", p.ur(118, 4), p.ur(122, 5), p.ur(127, 5), p.ur(132, 6));
  w.u("availability", p.ur(138, 1));
  std::size_t b = 139;  // 26 services of 2 bits
  for (const char* name : kServices) {
    w.u(name, p.ur(b, 2));
    b += 2;
  }
  w.text6("berth_name", p, 191, 20);
  w.scaledDiv("berth_lon", p.sr(311, 25), kMilliMinutesPerDeg, 4);
  w.scaledDiv("berth_lat", p.sr(336, 24), kMilliMinutesPerDeg, 4);
  w.scaledNum("berth_depth", p.ur(107, 8), 0.1, 1);  // gpsd multiplies by 0.1
}

// IMO289 dangerous cargo indication, DAC 1 FID 25. Any length: one 17-bit cargo entry per entry
// start strictly before the payload end (none at 100 bits or less), the last one read partly past it.
void writeCargos(const Payload& p, AisFields& w) {
  w.u("unit", p.ur(88, 2));
  w.u("amount", p.ur(90, 10));
  w.beginArray("cargos");
  for (std::size_t a = 100; a < p.bits(); a += 17) {
    w.beginObject();
    w.u("code", p.ur(a, 4));
    w.u("subtype", p.ur(a + 4, 13));
    w.endObject();
  }
  w.endArray();
}

// IMO289 route information (addressed), DAC 1 FID 28. Any length: as many 55-bit waypoints as the
// 5-bit count says, read past the payload end when it is short.
void writeRoute(const Payload& p, AisFields& w) {
  writeRouteInformation(p, 88, routeTypeText(p.ur(101, 5)), w);
}

// IMO289 text description (addressed), DAC 1 FID 30. Any length: the text is the whole six-bit
// characters from bit 98 to the payload end.
void writeTextDescription(const Payload& p, AisFields& w) {
  w.u("linkage", p.ur(88, 10));
  w.text6ToEnd("text", p, 98);
}

// International application identifiers (DAC 1): decoded at any length 88-1008.
bool writeInternational(const Payload& p, unsigned fid, AisFields& w) {
  switch (fid) {
    case 12:
      writeDangerousCargo(p, w);
      return true;
    case 14:
    case 32:
      writeTidalWindow(p, fid == 14, w);
      return true;
    case 15:
      writeAirDraught(p, w);
      return true;
    case 16:
      writePersons(p, w);
      return true;
    case 18:
      writeClearance(p, w);
      return true;
    case 20:
      writeBerthing(p, w);
      return true;
    case 25:
      writeCargos(p, w);
      return true;
    case 28:
      writeRoute(p, w);
      return true;
    case 30:
      writeTextDescription(p, w);
      return true;
    default:
      return false;  // 23 (area notice) and the rest: raw data
  }
}

// The location and time shared by the inland ETA (FID 21) and RTA (FID 22) messages.
void writeInlandPlace(const Payload& p, AisFields& w) {
  // gpsd 3.22 prints these with "%s", unescaped: a quote or backslash of the six-bit alphabet makes
  // its output invalid JSON. Ours escapes them (a deliberate difference).
  w.text6("country", p, 88, 2);
  w.text6("locode", p, 100, 3);
  w.text6("section", p, 118, 5);
  w.text6("terminal", p, 148, 5);
  w.text6("hectometre", p, 178, 5);
  unpaddedStamp(w, "eta", p.u(208, 4), p.u(212, 5), p.u(217, 5), p.u(222, 6));
}

// Inland ETA at lock/bridge/terminal, DAC 200 FID 21. Only at exactly 248 bits.
void writeInlandEta(const Payload& p, AisFields& w) {
  writeInlandPlace(p, w);
  w.u("tugs", p.u(228, 3));
  w.u("airdraught", p.u(231, 12));
}

// Inland RTA at lock/bridge/terminal, DAC 200 FID 22. Only at exactly 232 bits.
void writeInlandRta(const Payload& p, AisFields& w) {
  const unsigned status = p.u(228, 2);
  writeInlandPlace(p, w);
  w.withText("status", status, "status_text", kRtaStatusText[status]);
}

// Inland number of persons on board, DAC 200 FID 55. Only at exactly 168 bits.
void writeInlandPersons(const Payload& p, AisFields& w) {
  w.u("crew", p.u(88, 8));
  w.u("passengers", p.u(96, 13));
  w.u("personnel", p.u(109, 8));
}

// Inland AIS (DAC 200): gpsd decodes these only at their exact layout length, spare bits included.
bool writeInland(const Payload& p, unsigned fid, AisFields& w) {
  if (fid == 21 && p.bits() == 248)
    writeInlandEta(p, w);
  else if (fid == 22 && p.bits() == 232)
    writeInlandRta(p, w);
  else if (fid == 55 && p.bits() == 168)
    writeInlandPersons(p, w);
  else
    return false;
  return true;
}

// GLA AtoN monitoring data, DAC 235 (UK) or 250 (Ireland) FID 10. Only at exactly 136 bits. The
// analogue values are in 0.05 V; gpsd prints a scaled 0 as the integer 0.
bool writeAtonMonitoring(const Payload& p, AisFields& w) {
  if (p.bits() != 136)
    return false;
  w.b("off_pos", p.u(131, 1) != 0);
  w.b("alarm", p.u(122, 1) != 0);
  w.u("stat_ext", p.u(123, 8));
  static const char* const kAnalogue[] = {"ana_int", "ana_ext1", "ana_ext2"};
  for (unsigned k = 0; k < 3; ++k) {
    const unsigned v = p.u(88 + 10 * k, 10);
    if (w.scaled() && v != 0)
      w.f(kAnalogue[k], v * 0.05, 2);
    else
      w.u(kAnalogue[k], v);
  }
  const unsigned racon = p.u(118, 2), light = p.u(120, 2);
  w.withText("racon", racon, "racon_text", kRaconText[racon]);
  w.withText("light", light, "light_text", kLightText[light]);
  return true;
}

}  // namespace

bool writeType6Application(const Payload& p, unsigned dac, unsigned fid, AisFields& w) {
  switch (dac) {
    case 1:
      return writeInternational(p, fid, w);
    case 200:
      return writeInland(p, fid, w);
    case 235:
    case 250:
      return fid == 10 && writeAtonMonitoring(p, w);
    default:
      return false;
  }
}

}  // namespace ais
}  // namespace asv
