// IMO289 meteorological and hydrographic data (type 8, DAC 1 FID 31): decodeMetHydro31 and the SI
// views of MetHydroReport.
//
// The two real messages are the DAC 1 FID 31 payloads of gpsd's sample.aivdm. Their raw fields are
// the ones gpsd 3.22 prints for them (`gpsdecode -u -j`); every SI value below is worked by hand
// from the field definitions of IMO SN.1/Circ.289 (table 1.1), not from the decoder. The edge case
// is a payload built here bit by bit with the codes at the ends of each range.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "asv_core/codec/ais.h"

namespace {

using asv::ais::decodeMetHydro31;
using asv::ais::MetHydroReport;
using asv::ais::Payload;

// A base station (MMSI 992509977) reporting position and time only, every sensor "not available":
// !AIVDO,1,1,5,A,<payload>,0 (sample.aivdm).
const char* const kAllUnavailable = "8>jR06@0Gwli:QQUP3en?wvlFR06EuOwgwl?wnSwe7wvlOwwsAwwnSGmwvh0";
// MMSI 992611190 with wind, air, pressure and water level: the two fragments of !AIVDM,2,x,9,B
// (sample.aivdm), 4 fill bits at the end.
const char* const kWeather1 = "8>j`;MP0GhRHI1S`CrTW2?u2Ot1owwnews0F003wwwwwww0001wwwwwwwwh0";
const char* const kWeather2 = "00";

constexpr double kKnot = 1852.0 / 3600.0;  // m/s
constexpr double kPi = 3.14159265358979323846;

Payload payloadOf(const std::string& armoured, int fill) {
  Payload p;
  EXPECT_TRUE(p.append(armoured));
  p.dropFill(fill);
  return p;
}

// Bit-by-bit payload builder (MSB first), armoured with the six-bit alphabet of ITU-R M.1371.
class Bits {
public:
  explicit Bits(std::size_t n) : bits_(n, 0) {}
  Bits& set(std::size_t start, std::size_t len, std::int64_t value) {
    for (std::size_t i = 0; i < len; ++i)
      bits_[start + i] = static_cast<int>((static_cast<std::uint64_t>(value) >> (len - 1 - i)) & 1u);
    return *this;
  }
  Payload payload() const {
    std::vector<int> b = bits_;
    const int fill = static_cast<int>((6 - b.size() % 6) % 6);
    b.resize(b.size() + fill, 0);
    std::string s;
    for (std::size_t i = 0; i < b.size(); i += 6) {
      int v = 0;
      for (std::size_t k = 0; k < 6; ++k)
        v = v * 2 + b[i + k];
      s.push_back(static_cast<char>(v < 40 ? v + 48 : v + 56));
    }
    return payloadOf(s, fill);
  }

private:
  std::vector<int> bits_;
};

// A 360-bit type 8 DAC 1 FID 31 message with every field "not available" (the defaults of IMO289).
Bits unavailableReport() {
  Bits b(360);
  b.set(0, 6, 8).set(8, 30, 2300123).set(40, 10, 1).set(50, 6, 31);
  b.set(56, 25, 181 * 60000).set(81, 24, 91 * 60000).set(106, 5, 0).set(111, 5, 24).set(116, 6, 60);
  b.set(122, 7, 127).set(129, 7, 127).set(136, 9, 360).set(145, 9, 360);
  b.set(154, 11, -1024).set(165, 7, 101).set(172, 10, 501).set(182, 9, 511).set(191, 2, 3);
  b.set(194, 7, 127).set(201, 12, 4001).set(213, 2, 3).set(322, 4, 13);
  return b;
}

TEST(AisMet, AllUnavailableFromSample) {
  MetHydroReport r;
  ASSERT_TRUE(decodeMetHydro31(payloadOf(kAllUnavailable, 0), r));
  // Raw fields as gpsd prints them.
  EXPECT_EQ(r.lat, 3197696);
  EXPECT_EQ(r.lon, -368044);
  EXPECT_FALSE(r.accuracy);
  EXPECT_EQ(r.day, 29);
  EXPECT_EQ(r.hour, 23);
  EXPECT_EQ(r.minute, 24);
  EXPECT_EQ(r.wspeed, 127);
  EXPECT_EQ(r.wdir, 360);
  EXPECT_EQ(r.airtemp, -1024);
  EXPECT_EQ(r.humidity, 101);
  EXPECT_EQ(r.dewpoint, 501);
  EXPECT_EQ(r.pressure, 511);
  EXPECT_EQ(r.visibility, 127);
  EXPECT_EQ(r.waterlevel, 4001);
  EXPECT_EQ(r.seastate, 13);
  EXPECT_EQ(r.watertemp, 501);
  EXPECT_EQ(r.salinity, 510);
  // 3197696 / 60000 = 53.2949333 deg N; -368044 / 60000 = 6.1340667 deg W.
  ASSERT_TRUE(r.latDeg());
  EXPECT_NEAR(*r.latDeg(), 53.2949333, 1e-7);
  ASSERT_TRUE(r.lonDeg());
  EXPECT_NEAR(*r.lonDeg(), -6.1340667, 1e-7);
  // 127 kn, 360 deg, 127 (visibility), -1024, 511 hPa code, 13 and 4001 are all "not available".
  EXPECT_FALSE(r.windSpeedMps());
  EXPECT_FALSE(r.windGustMps());
  EXPECT_FALSE(r.windDirectionRad());
  EXPECT_FALSE(r.visibilityM());
  EXPECT_FALSE(r.airTemperatureC());
  EXPECT_FALSE(r.airPressureHpa());
  EXPECT_FALSE(r.seaStateBeaufort());
  EXPECT_FALSE(r.waterLevelM());
}

TEST(AisMet, WeatherStationFromSample) {
  MetHydroReport r;
  ASSERT_TRUE(decodeMetHydro31(payloadOf(std::string(kWeather1) + kWeather2, 4), r));
  EXPECT_EQ(r.lat, 3264671);
  EXPECT_EQ(r.lon, 1126600);
  EXPECT_EQ(r.day, 20);
  EXPECT_EQ(r.hour, 18);
  EXPECT_EQ(r.minute, 28);
  EXPECT_EQ(r.wspeed, 17);
  EXPECT_EQ(r.wgust, 127);
  EXPECT_EQ(r.wdir, 132);
  EXPECT_EQ(r.wgustdir, 511);
  EXPECT_EQ(r.airtemp, 14);
  EXPECT_EQ(r.dewpoint, -1);
  EXPECT_EQ(r.pressure, 214);
  EXPECT_TRUE(r.visgreater);
  EXPECT_EQ(r.visibility, 127);
  EXPECT_EQ(r.waterlevel, 1538);
  EXPECT_EQ(r.cspeed, 0);
  EXPECT_EQ(r.waveheight, 0);
  EXPECT_EQ(r.seastate, 15);
  EXPECT_EQ(r.watertemp, -1);
  // 3264671 / 60000 = 54.4111833 deg N; 1126600 / 60000 = 18.7766667 deg E.
  EXPECT_NEAR(*r.latDeg(), 54.4111833, 1e-7);
  EXPECT_NEAR(*r.lonDeg(), 18.7766667, 1e-7);
  // 17 kn = 17 * 1852 / 3600 = 8.7455556 m/s.
  ASSERT_TRUE(r.windSpeedMps());
  EXPECT_NEAR(*r.windSpeedMps(), 8.7455556, 1e-7);
  EXPECT_FALSE(r.windGustMps());
  // 132 deg = 2.3038346 rad.
  ASSERT_TRUE(r.windDirectionRad());
  EXPECT_NEAR(*r.windDirectionRad(), 2.3038346, 1e-7);
  // Visibility code 127 is "not available", with or without the "greater than" bit.
  EXPECT_FALSE(r.visibilityM());
  // 14 * 0.1 = 1.4 degC; 214 + 799 = 1013 hPa; 1538 / 100 - 10 = 5.38 m.
  EXPECT_NEAR(*r.airTemperatureC(), 1.4, 1e-12);
  EXPECT_NEAR(*r.airPressureHpa(), 1013.0, 1e-12);
  EXPECT_NEAR(*r.waterLevelM(), 5.38, 1e-12);
  // Sea state 15 is a reserved code.
  EXPECT_FALSE(r.seaStateBeaufort());
}

TEST(AisMet, RangeEndsAndSentinels) {
  Bits b = unavailableReport();
  MetHydroReport r;
  ASSERT_TRUE(decodeMetHydro31(b.payload(), r));
  EXPECT_FALSE(r.latDeg());  // 91 deg
  EXPECT_FALSE(r.lonDeg());  // 181 deg
  EXPECT_FALSE(r.windSpeedMps());
  EXPECT_FALSE(r.airTemperatureC());
  EXPECT_FALSE(r.waterLevelM());

  // Lowest ends: 0 kn, 0 deg, 0 NM, -60.0 degC, code 0 = 799 hPa or less, -10.00 m, Beaufort 0.
  b.set(56, 25, -180 * 60000).set(81, 24, -90 * 60000);
  b.set(122, 7, 0).set(129, 7, 0).set(136, 9, 0).set(154, 11, -600).set(182, 9, 0);
  b.set(194, 7, 0).set(201, 12, 0).set(322, 4, 0);
  ASSERT_TRUE(decodeMetHydro31(b.payload(), r));
  EXPECT_DOUBLE_EQ(*r.latDeg(), -90.0);
  EXPECT_DOUBLE_EQ(*r.lonDeg(), -180.0);
  EXPECT_DOUBLE_EQ(*r.windSpeedMps(), 0.0);
  EXPECT_DOUBLE_EQ(*r.windDirectionRad(), 0.0);
  EXPECT_DOUBLE_EQ(*r.visibilityM(), 0.0);
  EXPECT_DOUBLE_EQ(*r.airTemperatureC(), -60.0);
  EXPECT_DOUBLE_EQ(*r.airPressureHpa(), 799.0);
  EXPECT_DOUBLE_EQ(*r.waterLevelM(), -10.0);
  EXPECT_EQ(*r.seaStateBeaufort(), 0);

  // Highest ends: 126 = 126 kn or more (64.82 m/s), 359 deg, 12.6 NM (23335.2 m), +60.0 degC,
  // code 402 = 1201 hPa or more, +30.00 m, Beaufort 12.
  b.set(122, 7, 126).set(129, 7, 126).set(136, 9, 359).set(154, 11, 600).set(182, 9, 402);
  b.set(193, 1, 1).set(194, 7, 126).set(201, 12, 4000).set(322, 4, 12);
  ASSERT_TRUE(decodeMetHydro31(b.payload(), r));
  EXPECT_NEAR(*r.windSpeedMps(), 126 * kKnot, 1e-9);
  EXPECT_NEAR(*r.windSpeedMps(), 64.82, 1e-9);
  EXPECT_NEAR(*r.windGustMps(), 64.82, 1e-9);
  EXPECT_NEAR(*r.windDirectionRad(), 359 * kPi / 180, 1e-12);
  EXPECT_TRUE(r.visgreater);
  EXPECT_NEAR(*r.visibilityM(), 23335.2, 1e-6);
  EXPECT_DOUBLE_EQ(*r.airTemperatureC(), 60.0);
  EXPECT_DOUBLE_EQ(*r.airPressureHpa(), 1201.0);
  EXPECT_DOUBLE_EQ(*r.waterLevelM(), 30.0);
  EXPECT_EQ(*r.seaStateBeaufort(), 12);

  // Reserved codes just past each range have no value.
  b.set(136, 9, 361).set(154, 11, 601).set(182, 9, 403).set(201, 12, 4002).set(322, 4, 14);
  ASSERT_TRUE(decodeMetHydro31(b.payload(), r));
  EXPECT_FALSE(r.windDirectionRad());
  EXPECT_FALSE(r.airTemperatureC());
  EXPECT_FALSE(r.airPressureHpa());
  EXPECT_FALSE(r.waterLevelM());
  EXPECT_FALSE(r.seaStateBeaufort());
  b.set(154, 11, -601);
  ASSERT_TRUE(decodeMetHydro31(b.payload(), r));
  EXPECT_FALSE(r.airTemperatureC());
}

TEST(AisMet, RejectsOtherMessagesAndShortPayloads) {
  MetHydroReport r;
  r.wspeed = 42;  // untouched on failure
  Bits b = unavailableReport();
  b.set(50, 6, 11);  // IMO236 met/hydro, another layout
  EXPECT_FALSE(decodeMetHydro31(b.payload(), r));
  b.set(50, 6, 31).set(40, 10, 200);
  EXPECT_FALSE(decodeMetHydro31(b.payload(), r));
  b.set(40, 10, 1).set(0, 6, 6);  // type 6 carries DAC/FID elsewhere
  EXPECT_FALSE(decodeMetHydro31(b.payload(), r));
  EXPECT_EQ(r.wspeed, 42);

  // The fields end at bit 350: shorter payloads would read the missing fields as zeros.
  Bits shortest(350), too_short(349), too_long(1014);
  for (Bits* s : {&shortest, &too_short, &too_long})
    s->set(0, 6, 8).set(40, 10, 1).set(50, 6, 31);
  EXPECT_TRUE(decodeMetHydro31(shortest.payload(), r));
  EXPECT_FALSE(decodeMetHydro31(too_short.payload(), r));
  EXPECT_FALSE(decodeMetHydro31(too_long.payload(), r));
}

}  // namespace
