// IMO289 meteorological and hydrographic data (type 8, DAC 1 FID 31): typed decoding and SI views.
// Field layout and codes: IMO SN.1/Circ.289, annex, table 1.1 (the same layout gpsd decodes).
#include <cstddef>
#include <cstdint>
#include <optional>

#include "asv_core/codec/ais.h"
#include "asv_core/common/units.h"

namespace asv {
namespace ais {

namespace {

// The fields end at bit 350 (10 spare bits follow, to 360).
constexpr std::size_t kMetHydroFieldBits = 350;
constexpr std::size_t kMaxType8Bits = 1008;  // 5 slots; gpsd rejects longer type 8 messages

// Position, time and wind: bits 56..153.
void readHead(const Payload& p, MetHydroReport& r) {
  r.lon = p.s(56, 25);
  r.lat = p.s(81, 24);
  r.accuracy = p.u(105, 1) != 0;
  r.day = static_cast<std::uint8_t>(p.u(106, 5));
  r.hour = static_cast<std::uint8_t>(p.u(111, 5));
  r.minute = static_cast<std::uint8_t>(p.u(116, 6));
  r.wspeed = static_cast<std::uint8_t>(p.u(122, 7));
  r.wgust = static_cast<std::uint8_t>(p.u(129, 7));
  r.wdir = static_cast<std::uint16_t>(p.u(136, 9));
  r.wgustdir = static_cast<std::uint16_t>(p.u(145, 9));
}

// Air, visibility and water level: bits 154..214.
void readAir(const Payload& p, MetHydroReport& r) {
  r.airtemp = static_cast<std::int16_t>(p.s(154, 11));
  r.humidity = static_cast<std::uint8_t>(p.u(165, 7));
  r.dewpoint = static_cast<std::int16_t>(p.s(172, 10));
  r.pressure = static_cast<std::uint16_t>(p.u(182, 9));
  r.pressuretend = static_cast<std::uint8_t>(p.u(191, 2));
  r.visgreater = p.u(193, 1) != 0;
  r.visibility = static_cast<std::uint8_t>(p.u(194, 7));
  r.waterlevel = static_cast<std::uint16_t>(p.u(201, 12));
  r.leveltrend = static_cast<std::uint8_t>(p.u(213, 2));
}

// Currents at three levels: bits 215..275.
void readCurrents(const Payload& p, MetHydroReport& r) {
  r.cspeed = static_cast<std::uint8_t>(p.u(215, 8));
  r.cdir = static_cast<std::uint16_t>(p.u(223, 9));
  r.cspeed2 = static_cast<std::uint8_t>(p.u(232, 8));
  r.cdir2 = static_cast<std::uint16_t>(p.u(240, 9));
  r.cdepth2 = static_cast<std::uint8_t>(p.u(249, 5));
  r.cspeed3 = static_cast<std::uint8_t>(p.u(254, 8));
  r.cdir3 = static_cast<std::uint16_t>(p.u(262, 9));
  r.cdepth3 = static_cast<std::uint8_t>(p.u(271, 5));
}

// Waves, swell, sea state, water temperature, precipitation, salinity and ice: bits 276..349.
void readSea(const Payload& p, MetHydroReport& r) {
  r.waveheight = static_cast<std::uint8_t>(p.u(276, 8));
  r.waveperiod = static_cast<std::uint8_t>(p.u(284, 6));
  r.wavedir = static_cast<std::uint16_t>(p.u(290, 9));
  r.swellheight = static_cast<std::uint8_t>(p.u(299, 8));
  r.swellperiod = static_cast<std::uint8_t>(p.u(307, 6));
  r.swelldir = static_cast<std::uint16_t>(p.u(313, 9));
  r.seastate = static_cast<std::uint8_t>(p.u(322, 4));
  r.watertemp = static_cast<std::int16_t>(p.s(326, 10));
  r.preciptype = static_cast<std::uint8_t>(p.u(336, 3));
  r.salinity = static_cast<std::uint16_t>(p.u(339, 9));
  r.ice = static_cast<std::uint8_t>(p.u(348, 2));
}

// Wind speed or gust: 0..125 kn, 126 = 126 kn or more (the bound is the best value), 127 = n/a.
std::optional<double> windMps(std::uint8_t raw) {
  if (raw > 126)
    return std::nullopt;
  return knotsToMps(raw);
}

}  // namespace

bool decodeMetHydro31(const Payload& p, MetHydroReport& out) {
  if (p.bits() < kMetHydroFieldBits || p.bits() > kMaxType8Bits)
    return false;
  if (p.u(0, 6) != 8 || p.u(40, 10) != 1 || p.u(50, 6) != 31)
    return false;
  MetHydroReport r;
  readHead(p, r);
  readAir(p, r);
  readCurrents(p, r);
  readSea(p, r);
  out = r;
  return true;
}

// Positions: 1/1000 min; 91 and 181 deg (the defaults) are "not available", larger values invalid.
std::optional<double> MetHydroReport::latDeg() const {
  if (lat < -90 * 60000 || lat > 90 * 60000)
    return std::nullopt;
  return lat / 60000.0;
}

std::optional<double> MetHydroReport::lonDeg() const {
  if (lon < -180 * 60000 || lon > 180 * 60000)
    return std::nullopt;
  return lon / 60000.0;
}

std::optional<double> MetHydroReport::windSpeedMps() const {
  return windMps(wspeed);
}

std::optional<double> MetHydroReport::windGustMps() const {
  return windMps(wgust);
}

// 0..359 deg; 360 = not available, 361..511 reserved.
std::optional<double> MetHydroReport::windDirectionRad() const {
  if (wdir >= 360)
    return std::nullopt;
  return degToRad(wdir);
}

// 0..126 (12.6 NM) in 0.1 NM; 127 = not available.
std::optional<double> MetHydroReport::visibilityM() const {
  if (visibility >= 127)
    return std::nullopt;
  return visibility * 0.1 * kMetresPerNauticalMile;
}

// -60.0..+60.0 degC in 0.1 degC; -1024 = not available, the rest reserved.
std::optional<double> MetHydroReport::airTemperatureC() const {
  if (airtemp < -600 || airtemp > 600)
    return std::nullopt;
  return airtemp / 10.0;
}

// raw + 799 hPa for 0..402; 511 = not available, 403..510 reserved.
std::optional<double> MetHydroReport::airPressureHpa() const {
  if (pressure > 402)
    return std::nullopt;
  return pressure + 799.0;
}

// Beaufort 0..12; 13 = not available, 14 and 15 reserved.
std::optional<int> MetHydroReport::seaStateBeaufort() const {
  if (seastate > 12)
    return std::nullopt;
  return seastate;
}

// raw / 100 - 10 m for 0..4000; 4001 = not available, 4002..4095 reserved.
std::optional<double> MetHydroReport::waterLevelM() const {
  if (waterlevel > 4000)
    return std::nullopt;
  return waterlevel / 100.0 - 10.0;
}

}  // namespace ais
}  // namespace asv
