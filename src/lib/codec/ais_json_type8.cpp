// Structured application payloads (DAC/FID) of AIS type 8 messages, in gpsd 3.22's JSON.
//
// What gpsd 3.22 decodes, and at which payload lengths (whole message, header included), was found by
// running its `gpsdecode` on random payloads of every length from 56 to 1008 bits:
//  - DAC 1 FIDs 11, 13, 15, 17, 19, 27, 29, 31: every length. gpsd reads the fields without checking
//    the length; past the payload end its bit buffer holds the fill bits as sent, then zeros, so the
//    fields are read with Payload::ur/sr, and six-bit text runs until the first zero character ('@').
//  - DAC 1 FID 16: 128 or 192 bits only.
//  - DAC 200 FIDs 10, 24, 40: 168 bits only (FID 10 also needs a hazard code 0..5); FID 23: 256 only.
//  - Every other DAC/FID (the IMO289 area notice 1/22, environmental 1/26, weather observation 1/21,
//    extended static data 1/24, dangerous cargo 1/25, inland 200/55, all regional DACs...): "data".
// Where gpsd 3.22 prints its JSON oddly (a missing comma, an unescaped string, swapped date fields, a
// field of the wrong message), this file prints the same bytes: the comments say where.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "asv_core/codec/ais_json.h"

namespace asv {
namespace ais {

namespace {

// "name":"MM-DDTHH:MM" (no zone letter).
void date(AisFields& w, const char* name, unsigned month, unsigned day, unsigned hour, unsigned minute) {
  w.key(name);
  w.out().ch('"');
  w.stampBody(month, day, hour, minute);
  w.out().ch('"');
}

// A legend from `table` (of `n` entries), or `fallback` past its end (gpsd's *_DISPLAY macros).
const char* legend(const char* const* table, std::size_t n, unsigned v, const char* fallback) {
  return v < n ? table[v] : fallback;
}

template <std::size_t N>
const char* legend(const char* const (&table)[N], unsigned v, const char* fallback) {
  return legend(table, N, v, fallback);
}

// ---- DAC 1 (IMO236, IMO289) ----

// Legends of the IMO met/hydro messages (gpsd's tables: trend codes, WMO 306 code table 4.201 for
// the precipitation, ice).
const char* const kTrends[4] = {"steady", "increasing", "decreasing", "N/A"};
const char* const kPrecipTypes[8] = {"reserved",  "rain", "thunderstorm", "freezing rain",
                                     "mixed/ice", "snow", "reserved",     "N/A"};
const char* const kIce[4] = {"no", "yes", "reserved", "N/A"};

// IMO289 VTS target identifier types: also the key of the identifier.
const char* const kIdTypes[4] = {"mmsi", "imo", "callsign", "other"};

// IMO289 marine traffic signals (as gpsd 3.22 words them, the en dash in UTF-8).
const char* const kSignals[15] = {
    "N/A",
    "Serious emergency \xe2\x80\x93 stop or divert according to instructions.",
    "Vessels shall not proceed.",
    "Vessels may proceed. One way traffic.",
    "Vessels may proceed. Two way traffic.",
    "Vessels shall proceed on specific orders only.",
    "Vessels in main channel shall not proceed.",
    "Vessels in main channel shall proceed on specific orders only.",
    "Vessels in main channel shall proceed on specific orders only.",
    "I = \"in-bound\" only acceptable.",
    "O = \"out-bound\" only acceptable.",
    "F = both \"in- and out-bound\" acceptable.",
    "XI = Code will shift to \"I\" in due time.",
    "XO = Code will shift to \"O\" in due time.",
    "X = Vessels shall proceed only on direction.",
};

// IMO289 route types 0..5; 6..30 are reserved and 31 cancels a route.
const char* const kRouteTypes[6] = {
    "Undefined (default)",           "Mandatory",      "Recommended", "Alternative",
    "Recommended route through ice", "Ship route plan"};

const char* routeTypeText(unsigned rtype) {
  if (rtype == 31)
    return "Cancel route identified by message linkage";
  return legend(kRouteTypes, rtype, "Reserved for future use.");
}

// Positions of the DAC 1 messages are in 1/1000 min; gpsd prints them with four decimals (IMO289
// route waypoints: 1/10000 min, six decimals).
constexpr double kThousandthMinutesPerDeg = 60000.0;
constexpr double kTenThousandthMinutesPerDeg = 600000.0;

// Unscaled: the raw value; scaled: (raw - offset) / divisor with `decimals` decimals, computed as gpsd
// does (the integer difference, divided in double).
void offsetDiv(AisFields& w, const char* name, std::int64_t raw, std::int64_t offset, double divisor,
               int decimals) {
  if (w.scaled())
    w.f(name, static_cast<double>(raw - offset) / divisor, decimals);
  else
    w.i(name, raw);
}

// Currents, waves, swell and sea state: the same 114-bit block in IMO236 (from bit 211) and IMO289
// (from bit 215). Speeds and heights in 0.1 kn / 0.1 m.
void writeCurrentsWaves(const Payload& p, std::size_t b, AisFields& w) {
  w.scaledDiv("cspeed", p.ur(b, 8), 10.0, 1);
  w.u("cdir", p.ur(b + 8, 9));
  w.scaledDiv("cspeed2", p.ur(b + 17, 8), 10.0, 1);
  w.u("cdir2", p.ur(b + 25, 9));
  w.u("cdepth2", p.ur(b + 34, 5));
  w.scaledDiv("cspeed3", p.ur(b + 39, 8), 10.0, 1);
  w.u("cdir3", p.ur(b + 47, 9));
  w.u("cdepth3", p.ur(b + 56, 5));
  w.scaledDiv("waveheight", p.ur(b + 61, 8), 10.0, 1);
  w.u("waveperiod", p.ur(b + 69, 6));
  w.u("wavedir", p.ur(b + 75, 9));
  w.scaledDiv("swellheight", p.ur(b + 84, 8), 10.0, 1);
  w.u("swellperiod", p.ur(b + 92, 6));
  w.u("swelldir", p.ur(b + 98, 9));
  w.u("seastate", p.ur(b + 107, 4));
}

// IMO236 meteorological and hydrological data, DAC 1 FID 11 (352 bits; gpsd: any length). Air and
// water fields are unsigned with an offset: air temperature raw 600 = 0 degC and dew point raw 200 =
// 0 degC (0.1 degC), pressure raw + 800 hPa (gpsd prints it as an integer), water level raw 100 = 0 m
// and water temperature raw 100 = 0 degC (0.1 m, 0.1 degC).
void writeMetHydro11(const Payload& p, AisFields& w) {
  w.scaledDiv("lat", p.sr(56, 24), kThousandthMinutesPerDeg, 4);
  w.scaledDiv("lon", p.sr(80, 25), kThousandthMinutesPerDeg, 4);
  w.stamp("timestamp", 0, p.ur(105, 5), p.ur(110, 5), p.ur(115, 6), false);
  w.u("wspeed", p.ur(121, 7));
  w.u("wgust", p.ur(128, 7));
  w.u("wdir", p.ur(135, 9));
  w.u("wgustdir", p.ur(144, 9));
  w.u("humidity", p.ur(164, 7));
  offsetDiv(w, "airtemp", p.ur(153, 11), 600, 10.0, 1);
  offsetDiv(w, "dewpoint", p.ur(171, 10), 200, 10.0, 1);
  w.u("pressure", p.ur(181, 9) + (w.scaled() ? 800 : 0));
  w.legendOrNumber("pressuretend", p.ur(190, 2), kTrends[p.ur(190, 2)]);
  w.scaledDiv("visibility", p.ur(192, 8), 10.0, 1);
  offsetDiv(w, "waterlevel", p.ur(200, 9), 100, 10.0, 1);
  w.legendOrNumber("leveltrend", p.ur(209, 2), kTrends[p.ur(209, 2)]);
  writeCurrentsWaves(p, 211, w);
  offsetDiv(w, "watertemp", p.ur(322, 10), 100, 10.0, 1);
  w.withText("preciptype", p.ur(332, 3), "preciptype_text", kPrecipTypes[p.ur(332, 3)]);
  w.scaledDiv("salinity", p.ur(335, 9), 10.0, 1);
  w.withText("ice", p.ur(344, 2), "ice_text", kIce[p.ur(344, 2)]);
}

// IMO289 water level, scaled: (raw - 1000) / 100 m with one decimal. gpsd 3.22 subtracts in unsigned
// arithmetic, so a level below 0 m wraps round 2^32 (raw 0, -10 m, prints 42949663.0): a gpsd bug we do
// not copy (deliberate difference; equal output from 0 m up).
double waterLevel31(std::uint32_t raw) {
  return (static_cast<double>(raw) - 1000.0) / 100.0;
}

// IMO289 meteorological and hydrographic data, DAC 1 FID 31 (360 bits; gpsd: any length). The same
// fields as IMO236's FID 11 with signed temperatures, accuracy and a "visibility greater than" flag.
void writeMetHydro31(const Payload& p, AisFields& w) {
  w.scaledDiv("lat", p.sr(81, 24), kThousandthMinutesPerDeg, 4);
  w.scaledDiv("lon", p.sr(56, 25), kThousandthMinutesPerDeg, 4);
  w.b("accuracy", p.ur(105, 1) != 0);
  w.stamp("timestamp", 0, p.ur(106, 5), p.ur(111, 5), p.ur(116, 6), false);
  w.u("wspeed", p.ur(122, 7));
  w.u("wgust", p.ur(129, 7));
  w.u("wdir", p.ur(136, 9));
  w.u("wgustdir", p.ur(145, 9));
  w.u("humidity", p.ur(165, 7));
  w.scaledDiv("airtemp", p.sr(154, 11), 10.0, 1);
  w.scaledDiv("dewpoint", p.sr(172, 10), 10.0, 1);
  w.u("pressure", p.ur(182, 9) + (w.scaled() ? 799 : 0));
  w.legendOrNumber("pressuretend", p.ur(191, 2), kTrends[p.ur(191, 2)]);
  w.b("visgreater", p.ur(193, 1) != 0);
  w.scaledDiv("visibility", p.ur(194, 7), 10.0, 1);
  if (w.scaled())
    w.f("waterlevel", waterLevel31(p.ur(201, 12)), 1);
  else
    w.u("waterlevel", p.ur(201, 12));
  w.legendOrNumber("leveltrend", p.ur(213, 2), kTrends[p.ur(213, 2)]);
  writeCurrentsWaves(p, 215, w);
  w.scaledDiv("watertemp", p.sr(326, 10), 10.0, 1);
  w.legendOrNumber("preciptype", p.ur(336, 3), kPrecipTypes[p.ur(336, 3)]);
  w.scaledDiv("salinity", p.ur(339, 9), 10.0, 1);
  w.legendOrNumber("ice", p.ur(348, 2), kIce[p.ur(348, 2)]);
}

// IMO236 fairway closed, DAC 1 FID 13 (472 bits; gpsd: any length). The dates are sent day first
// and printed month first.
void writeFairwayClosed13(const Payload& p, AisFields& w) {
  w.text6("reason", p, 56, 20);
  w.text6("closefrom", p, 176, 20);
  w.text6("closeto", p, 296, 20);
  w.u("radius", p.ur(416, 10));
  w.u("extunit", p.ur(426, 2));
  date(w, "from", p.ur(433, 4), p.ur(428, 5), p.ur(437, 5), p.ur(442, 6));
  date(w, "to", p.ur(453, 4), p.ur(448, 5), p.ur(457, 5), p.ur(462, 6));
}

// IMO289 VTS-generated/synthetic targets, DAC 1 FID 17: one 122-bit target starting at each bit
// 56 + 122 k that is not past the payload end (gpsd: so a target may be read partly or wholly from
// beyond the end). An MMSI or IMO number is a 42-bit field that gpsd keeps in 32 bits (its low 32
// bits) and prints quoted; a call sign or other id is 7 characters.
void writeTarget17(const Payload& p, std::size_t a, AisFields& w) {
  const unsigned idtype = p.ur(a, 2);
  w.beginObject();
  w.withText("idtype", idtype, "idtype_text", kIdTypes[idtype]);
  if (idtype < 2) {
    w.key(kIdTypes[idtype]);
    w.out().ch('"');
    w.out().u(p.ur(a + 12, 32));
    w.out().ch('"');
  } else {
    w.text6(kIdTypes[idtype], p, a + 2, 7);
  }
  w.scaledDiv("lat", p.sr(a + 48, 24), kThousandthMinutesPerDeg, 4);
  w.scaledDiv("lon", p.sr(a + 72, 25), kThousandthMinutesPerDeg, 4);
  w.u("course", p.ur(a + 97, 9));
  w.u("second", p.ur(a + 106, 6));
  w.u("speed", p.ur(a + 112, 10));
  w.endObject();
}

void writeTargets17(const Payload& p, AisFields& w) {
  w.beginArray("targets");
  for (std::size_t a = 56; a <= p.bits(); a += 122)
    writeTarget17(p, a, w);
  w.endArray();
}

// IMO289 marine traffic signal, DAC 1 FID 19 (360 bits; gpsd: any length). gpsd 3.22 prints the
// position scaled in both modes (kept), and no comma between "nextsignal" and "nextsignal_text",
// which makes the line invalid JSON (not copied: a deliberate difference).
void writeTrafficSignal19(const Payload& p, AisFields& w) {
  const unsigned signal = p.ur(237, 5), next = p.ur(253, 5);
  w.u("linkage", p.ur(56, 10));
  w.text6("station", p, 66, 20);
  w.f("lon", p.sr(186, 25) / kThousandthMinutesPerDeg, 4);
  w.f("lat", p.sr(211, 24) / kThousandthMinutesPerDeg, 4);
  w.u("status", p.ur(235, 2));
  w.withText("signal", signal, "signal_text", legend(kSignals, signal, "INVALID SIGNAL TYPE"));
  w.u("hour", p.ur(242, 5));
  w.u("minute", p.ur(247, 6));
  w.withText("nextsignal", next, "nextsignal_text", legend(kSignals, next, "INVALID SIGNAL TYPE"));
}

// IMO289 route information (broadcast), DAC 1 FID 27: gpsd prints `waycount` waypoints of 55 bits
// from bit 117 whatever the length, those past the payload end read from beyond it.
void writeRoute27(const Payload& p, AisFields& w) {
  writeRouteInformation(p, 56, routeTypeText(p.ur(69, 5)), w);
}

// IMO289 text description (broadcast), DAC 1 FID 29: the text runs from bit 66 to the payload end.
// Below 66 bits gpsd's character count wraps around and it reads until the first '@', which is at
// once: bit 66 lies past the payload and its fill bits.
void writeText29(const Payload& p, AisFields& w) {
  w.u("linkage", p.ur(56, 10));
  w.text6("text", p, 66, p.bits() > 66 ? (p.bits() - 66) / 6 : 0);
}

bool writeDac1(const Payload& p, unsigned fid, AisFields& w) {
  switch (fid) {
    case 11:
      writeMetHydro11(p, w);
      return true;
    case 13:
      writeFairwayClosed13(p, w);
      return true;
    case 15:  // IMO236 extended ship static and voyage data (72 bits; gpsd: any length)
      w.u("airdraught", p.ur(56, 11));
      return true;
    case 16:
      // IMO236/IMO289 number of persons on board (13 bits): gpsd 3.22 decodes only 128-bit (IMO236)
      // and 192-bit (IMO289) messages, then prints the persons of its type 6 structure, always 0.
      // We print the number sent (a deliberate difference).
      if (p.bits() != 128 && p.bits() != 192)
        return false;
      w.u("persons", p.ur(56, 13));
      return true;
    case 17:
      writeTargets17(p, w);
      return true;
    case 19:
      writeTrafficSignal19(p, w);
      return true;
    case 27:
      writeRoute27(p, w);
      return true;
    case 29:
      writeText29(p, w);
      return true;
    case 31:
      writeMetHydro31(p, w);
      return true;
    default:
      return false;
  }
}

// ---- DAC 200 (inland AIS) ----

// Inland ship types (ERI codes) and the ITU type each stands for: gpsd's table, searched for the
// first entry whose ERI code or ITU type equals the field.
struct InlandShipType {
  unsigned code, ais;
  const char* legend;
};
const InlandShipType kInlandShipTypes[] = {
    {8000, 99, "Vessel, type unknown"},
    {8010, 79, "Motor freighter"},
    {8020, 89, "Motor tanker"},
    {8021, 80, "Motor tanker, liquid cargo, type N"},
    {8022, 80, "Motor tanker, liquid cargo, type C"},
    {8023, 89, "Motor tanker, dry cargo as if liquid (e.g. cement)"},
    {8030, 79, "Container vessel"},
    {8040, 80, "Gas tanker"},
    {8050, 79, "Motor freighter, tug"},
    {8060, 89, "Motor tanker, tug"},
    {8070, 79, "Motor freighter with one or more ships alongside"},
    {8080, 89, "Motor freighter with tanker"},
    {8090, 79, "Motor freighter pushing one or more freighters"},
    {8100, 89, "Motor freighter pushing at least one tank-ship"},
    {8110, 79, "Tug, freighter"},
    {8120, 89, "Tug, tanker"},
    {8130, 31, "Tug freighter, coupled"},
    {8140, 31, "Tug, freighter/tanker, coupled"},
    {8150, 99, "Freightbarge"},
    {8160, 99, "Tankbarge"},
    {8161, 90, "Tankbarge, liquid cargo, type N"},
    {8162, 90, "Tankbarge, liquid cargo, type C"},
    {8163, 99, "Tankbarge, dry cargo as if liquid (e.g. cement)"},
    {8170, 99, "Freightbarge with containers"},
    {8180, 90, "Tankbarge, gas"},
    {8210, 79, "Pushtow, one cargo barge"},
    {8220, 79, "Pushtow, two cargo barges"},
    {8230, 79, "Pushtow, three cargo barges"},
    {8240, 79, "Pushtow, four cargo barges"},
    {8250, 79, "Pushtow, five cargo barges"},
    {8260, 79, "Pushtow, six cargo barges"},
    {8270, 79, "Pushtow, seven cargo barges"},
    {8280, 79, "Pushtow, eigth cargo barges"},
    {8290, 79, "Pushtow, nine or more barges"},
    {8310, 80, "Pushtow, one tank/gas barge"},
    {8320, 80, "Pushtow, two barges at least one tanker or gas barge"},
    {8330, 80, "Pushtow, three barges at least one tanker or gas barge"},
    {8340, 80, "Pushtow, four barges at least one tanker or gas barge"},
    {8350, 80, "Pushtow, five barges at least one tanker or gas barge"},
    {8360, 80, "Pushtow, six barges at least one tanker or gas barge"},
    {8370, 80, "Pushtow, seven barges at least one tanker or gas barg"},
};

// Inland static data: hazardous cargo (blue cones or lights), loaded status.
const char* const kHazards[6] = {"0 blue cones/lights", "1 blue cone/light", "2 blue cones/lights",
                                 "3 blue cones/lights", "4 B-Flag",          "Unknown"};
const char* const kLoaded[3] = {"N/A (default)", "Unloaded", "Loaded"};

// EMMA warnings: type of weather, intensity class, wind direction.
const char* const kEmmaTypes[10] = {
    "Not Available",    "Wind",  "Rain",       "Snow and ice", "Thunderstorm", "Fog", "Low temperature",
    "High temperature", "Flood", "Forest Fire"};
const char* const kEmmaClasses[3] = {"Slight", "Medium", "Strong"};
const char* const kEmmaWinds[9] = {"N/A",   "North",      "North East", "East",      "South East",
                                   "South", "South West", "West",       "North West"};

// Inland signal status: direction of the signal, light shown.
const char* const kSignalDirections[5] = {"Unknown", "Upstream", "Downstream", "To left bank",
                                          "To right bank"};
const char* const kLights[8] = {"Unknown", "No light", "White",          "Yellow",
                                "Green",   "Red",      "White flashing", "Yellow flashing."};

const char* inlandShipTypeText(unsigned type) {
  for (const InlandShipType& t : kInlandShipTypes)
    if (t.code == type || t.ais == type)
      return t.legend;
  return "Illegal ship type value.";
}

// Inland ship static and voyage related data, DAC 200 FID 10: 168 bits only, and only with a hazard
// code 0..5 (gpsd's check against false matches). Both modes print the same raw fields.
bool writeInlandStatic10(const Payload& p, AisFields& w) {
  const unsigned hazard = p.ur(141, 3), shiptype = p.ur(127, 14), loaded = p.ur(155, 2);
  if (p.bits() != 168 || hazard > 5)
    return false;
  w.text6("vin", p, 56, 8);
  w.u("length", p.ur(104, 13));
  w.u("beam", p.ur(117, 10));
  w.withText("shiptype", shiptype, "shiptype_text", inlandShipTypeText(shiptype));
  w.withText("hazard", hazard, "hazard_text", kHazards[hazard]);
  w.u("draught", p.ur(144, 11));
  w.withText("loaded", loaded, "loaded_text", legend(kLoaded, loaded, "INVALID LOAD STATUS"));
  w.b("speed_q", p.ur(157, 1) != 0);
  w.b("course_q", p.ur(158, 1) != 0);
  w.b("heading_q", p.ur(159, 1) != 0);
  return true;
}

// EMMA weather warning, DAC 200 FID 23: 256 bits only. gpsd 3.22 prints the start date with its
// fields out of order (hour where the day goes, then minute, then day: "YYYY-MM-hhTmm:DD"); we print
// it in order, like the end date (a deliberate difference). Years are sent from 2000.
void writeEmmaDates(const Payload& p, AisFields& w) {
  const unsigned start_day = p.ur(68, 5), start_hour = p.ur(90, 5), start_minute = p.ur(95, 6);
  json::Out& o = w.out();
  w.key("start");
  o.ch('"');
  o.u(p.ur(56, 8) + 2000);
  o.ch('-');
  w.stampBody(p.ur(64, 4), start_day, start_hour, start_minute);
  o.ch('"');
  w.key("end");
  o.ch('"');
  o.u(p.ur(73, 8) + 2000);
  o.ch('-');
  w.stampBody(p.ur(81, 4), p.ur(85, 5), p.ur(101, 5), p.ur(106, 6));
  o.ch('"');
}

bool writeEmmaWarning23(const Payload& p, AisFields& w) {
  if (p.bits() != 256)
    return false;
  const unsigned type = p.ur(222, 4), intensity = p.ur(244, 2), wind = p.ur(246, 4);
  writeEmmaDates(p, w);
  w.scaledDiv("start_lon", p.sr(112, 28), kTenThousandthMinutesPerDeg, 6);
  w.scaledDiv("start_lat", p.sr(140, 27), kTenThousandthMinutesPerDeg, 6);
  w.scaledDiv("end_lon", p.sr(167, 28), kTenThousandthMinutesPerDeg, 6);
  w.scaledDiv("end_lat", p.sr(195, 27), kTenThousandthMinutesPerDeg, 6);
  w.withText("type", type, "type_text", legend(kEmmaTypes, type, "INVALID EMMA TYPE"));
  w.i("min", p.sr(226, 9));
  w.i("max", p.sr(235, 9));
  w.withText("class", intensity, "class_text", legend(kEmmaClasses, intensity, "INVALID EMMA TYPE"));
  w.withText("wind", wind, "wind_text", legend(kEmmaWinds, wind, "INVALID EMMA WIND DIRECTION"));
  return true;
}

// Inland water levels, DAC 200 FID 24: 168 bits only; a 2-character country code (gpsd prints it
// unescaped, so a quote makes invalid JSON; escaped here), then four gauges of 25 bits (id, signed
// level in cm).
bool writeWaterLevels24(const Payload& p, AisFields& w) {
  if (p.bits() != 168)
    return false;
  w.text6("country", p, 56, 2);
  w.beginArray("gauges");
  for (std::size_t a = 68; a < p.bits(); a += 25) {
    w.beginObject();
    w.u("id", p.ur(a, 11));
    w.i("level", p.sr(a + 11, 14));
    w.endObject();
  }
  w.endArray();
  return true;
}

// Inland signal status, DAC 200 FID 40: 168 bits only.
bool writeSignalStatus40(const Payload& p, AisFields& w) {
  if (p.bits() != 168)
    return false;
  const unsigned direction = p.ur(124, 3), status = p.ur(127, 30);
  w.scaledDiv("lon", p.sr(56, 28), kTenThousandthMinutesPerDeg, 6);
  w.scaledDiv("lat", p.sr(84, 27), kTenThousandthMinutesPerDeg, 6);
  w.u("form", p.ur(111, 4));
  w.u("facing", p.ur(115, 9));
  w.withText("direction", direction, "direction_text",
             legend(kSignalDirections, direction, "INVALID DIRECTION"));
  w.withText("status", status, "status_text", legend(kLights, status, "INVALID STATUS"));
  return true;
}

bool writeDac200(const Payload& p, unsigned fid, AisFields& w) {
  switch (fid) {
    case 10:
      return writeInlandStatic10(p, w);
    case 23:
      return writeEmmaWarning23(p, w);
    case 24:
      return writeWaterLevels24(p, w);
    case 40:
      return writeSignalStatus40(p, w);
    default:
      return false;
  }
}

}  // namespace

bool writeType8Application(const Payload& p, unsigned dac, unsigned fid, AisFields& w) {
  if (dac == 1)
    return writeDac1(p, fid, w);
  if (dac == 200)
    return writeDac200(p, fid, w);
  return false;
}

}  // namespace ais
}  // namespace asv
