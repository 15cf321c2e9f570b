// AIS decoding: armour, bit fields, every decoded message type, sentinels, fill bits, reassembly.
//
// Expected values come from outside the decoder: the decodes written beside each sentence in gpsd's
// sample.aivdm (checked there with the noaadata tools and the Maritec decoder), or sentences built
// for these tests by a separate encoder from the ITU-R M.1371 bit layouts with the values asserted
// below (the encoder is a 40-line Python script; its inputs are the numbers in the comments).
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>

#include "asv_core/codec/ais.h"
#include "asv_core/codec/nmea_encode.h"
#include "asv_core/common/units.h"

// Counts heap allocations, to check that decoding a type 1 sentence allocates nothing. malloc/free
// behind a replaced global operator new/delete is legitimate; GCC's heuristic flags it anyway.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
static std::atomic<long> g_allocations{0};
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1))
    return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1))
    return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

using namespace asv;
using namespace asv::ais;

namespace {

Status decodeLine(Decoder& d, const std::string& line, Message& m, double now = 0.0) {
  nmea::Reject r;
  Status s = d.feedLine(line, now, m, &r);
  EXPECT_EQ(r, nmea::Reject::kNone) << line;
  return s;
}

Message decodeOne(const std::string& line) {
  Decoder d;
  Message m;
  EXPECT_EQ(decodeLine(d, line, m), Status::kMessage) << line;
  return m;
}

// Two interleaved type 5 messages from sample.aivdm ("Channel multiplexing test").
const char* const kT5B1 = "!AIVDM,2,1,6,B,542M92h00001@<7;?G0PD4i@R0<tqA8tj37>220o0h:2240Ht50000000000,0*3B";
const char* const kT5A1 =
    "!AIVDM,2,1,2,A,542M92h00001@<7;?G0PD4i@R0<tqA8tj37>220o0h:2240Ht500000000000000,0*3C";
const char* const kT5A2 = "!AIVDM,2,2,2,A,0000002,2*24";
const char* const kT5B2 = "!AIVDM,2,2,6,B,00000000000,2*21";

// Hand-built type 5 (encoder inputs: MMSI 351759000, IMO 9134270, "3FOF8", "EVER DIADEM", type 70,
// 225/70/1/31 m, EPFD 1, ETA 05-15 14:00, draught 12.2 m, "NEW YORK"), sequence id 3, channel A/B.
const char* const kT5p1A = "!AIVDM,2,1,3,A,55?MbV02;H;s<HtKP00EHE:0@T4@Dl0000000016L961O5Gf0NSQEp6ClRh0,0*0C";
const char* const kT5p2A = "!AIVDM,2,2,3,A,00000000000,2*27";
const char* const kT5p1B = "!AIVDM,2,1,3,B,55?MbV02;H;s<HtKP00EHE:0@T4@Dl0000000016L961O5Gf0NSQEp6ClRh0,0*0F";
const char* const kT5p2B = "!AIVDM,2,2,3,B,00000000000,2*24";
const char* const kT5p1A4 =
    "!AIVDM,2,1,4,A,55?MbV02;H;s<HtKP00EHE:0@T4@Dl0000000016L961O5Gf0NSQEp6ClRh0,0*0B";
const char* const kT5p2A4 = "!AIVDM,2,2,4,A,00000000000,2*20";

}  // namespace

TEST(AisArmour, SixBitAlphabet) {
  Payload p;
  ASSERT_TRUE(p.append("0W`w"));  // 0, 39, 40, 63
  ASSERT_EQ(p.bits(), 24u);
  EXPECT_EQ(p.u(0, 6), 0u);
  EXPECT_EQ(p.u(6, 6), 39u);
  EXPECT_EQ(p.u(12, 6), 40u);
  EXPECT_EQ(p.u(18, 6), 63u);
  EXPECT_EQ(p.u(0, 24), (39u << 12) | (40u << 6) | 63u);
  EXPECT_EQ(p.s(18, 6), -1);
  EXPECT_EQ(p.s(6, 6), -25);  // 100111b
  Payload bad;
  EXPECT_FALSE(bad.append("X"));  // 88: between the two armour ranges
  EXPECT_FALSE(bad.append("_"));
  EXPECT_FALSE(bad.append("x"));  // 120: above
  EXPECT_FALSE(bad.append("/"));  // 47: below
  EXPECT_EQ(Payload::sixbitChar(0), '@');
  EXPECT_EQ(Payload::sixbitChar(32), ' ');
  EXPECT_EQ(Payload::sixbitChar(45), '-');
}

TEST(AisArmour, FieldsPastTheEndReadOnlyPresentBits) {
  Payload p;
  ASSERT_TRUE(p.append("w"));  // 111111
  p.dropFill(2);
  ASSERT_EQ(p.bits(), 4u);
  EXPECT_EQ(p.u(0, 6), 15u);  // 4 bits present
  EXPECT_EQ(p.u(4, 2), 0u);
  EXPECT_EQ(p.u(10, 3), 0u);
}

TEST(AisType1, SampleFromGpsd) {
  // sample.aivdm: MMSI 371798000, status 0, ROT -127, SOG 12.3, accuracy 1, lon -123.395383333,
  // lat 48.38163333333, COG 224, heading 215, second 33.
  const Message m = decodeOne("!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4A");
  EXPECT_EQ(m.type, 1);
  EXPECT_EQ(m.repeat, 0);
  EXPECT_EQ(m.mmsi, 371798000u);
  EXPECT_EQ(m.channel, 'A');
  const auto& r = std::get<PositionReportA>(m.body);
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.turn, -127);
  EXPECT_EQ(r.speed, 123u);
  EXPECT_TRUE(r.accuracy);
  EXPECT_NEAR(*lonDeg(r.lon), -123.395383333, 1e-6);
  EXPECT_NEAR(*latDeg(r.lat), 48.38163333333, 1e-6);
  EXPECT_EQ(r.course, 2240u);
  EXPECT_EQ(r.heading, 215u);
  EXPECT_EQ(r.second, 33);
  EXPECT_FALSE(r.raim);
  EXPECT_NEAR(*speedMps(r.speed), 12.3 * 1852.0 / 3600.0, 1e-9);
  EXPECT_NEAR(*courseRad(r.course), degToRad(224.0), 1e-12);
  EXPECT_NEAR(*headingRad(r.heading), degToRad(215.0), 1e-12);
  EXPECT_FALSE(rateOfTurn(r.turn).has_value());  // -127: fast left, no rate
  Kinematics k;
  ASSERT_TRUE(toKinematics(m, k));
  EXPECT_TRUE(k.has_position && k.has_speed && k.has_course && k.has_heading);
  EXPECT_FALSE(k.has_turn);
  EXPECT_EQ(k.turn_direction, -1);
}

TEST(AisType1, SentinelsAreUnknown) {
  // sample.aivdm: ROT -128, heading 511.
  Message m = decodeOne("!AIVDM,1,1,,A,16SteH0P00Jt63hHaa6SagvJ087r,0*42");
  EXPECT_EQ(m.mmsi, 440348000u);
  const auto& r = std::get<PositionReportA>(m.body);
  EXPECT_EQ(r.turn, -128);
  EXPECT_EQ(r.heading, 511u);
  EXPECT_FALSE(rateOfTurn(r.turn));
  EXPECT_FALSE(headingRad(r.heading));
  EXPECT_NEAR(*lonDeg(r.lon), -70.7582, 1e-6);
  EXPECT_NEAR(*latDeg(r.lat), 43.08015, 1e-6);
  EXPECT_NEAR(*courseRad(r.course), degToRad(93.4), 1e-12);

  // Encoder inputs: every field "not available" (lat 91, lon 181, speed 1023, course 3600,
  // heading 511, turn -128, second 60, status 15).
  m = decodeOne("!AIVDM,1,1,,A,11mg=5OP?w<tSF0l4Q@>4?wp0000,0*65");
  const auto& n = std::get<PositionReportA>(m.body);
  EXPECT_EQ(m.mmsi, 123456789u);
  EXPECT_EQ(n.lat, kLatNotAvailable);
  EXPECT_EQ(n.lon, kLonNotAvailable);
  EXPECT_EQ(n.speed, kSpeedNotAvailable);
  EXPECT_EQ(n.course, kCourseNotAvailable);
  EXPECT_FALSE(latDeg(n.lat));
  EXPECT_FALSE(lonDeg(n.lon));
  EXPECT_FALSE(speedMps(n.speed));
  EXPECT_FALSE(courseRad(n.course));
  Kinematics k;
  ASSERT_TRUE(toKinematics(m, k));
  EXPECT_FALSE(k.has_position || k.has_speed || k.has_course || k.has_heading || k.has_turn);
  EXPECT_TRUE(std::isnan(k.lat_deg) && std::isnan(k.lon_deg) && std::isnan(k.speed) && std::isnan(k.course) &&
              std::isnan(k.heading) && std::isnan(k.rate_of_turn));
  // Out-of-range values are not positions either.
  EXPECT_FALSE(latDeg(-101 * 600000));
  EXPECT_FALSE(lonDeg(200 * 600000));
  EXPECT_FALSE(headingRad(360));
  EXPECT_FALSE(courseRad(3601));
}

TEST(AisType3, TurnSpeedAndSouthernHemisphere) {
  // Encoder inputs: type 3, repeat 1, MMSI 987654321, status 5, turn +20, speed 1022, accuracy 1,
  // lon 170.25, lat -45.5, course 359.9, heading 359, second 12, maneuver 1, raim 1, radio 12345.
  const Message m = decodeOne("!AIVDM,1,1,,B,3Neq`dE5?vd;EsQUugH>3s>HR30q,0*6E");
  EXPECT_EQ(m.type, 3);
  EXPECT_EQ(m.repeat, 1);
  EXPECT_EQ(m.mmsi, 987654321u);
  EXPECT_EQ(m.channel, 'B');
  const auto& r = std::get<PositionReportA>(m.body);
  EXPECT_EQ(r.status, 5);
  EXPECT_EQ(r.turn, 20);
  EXPECT_EQ(r.speed, 1022u);
  EXPECT_NEAR(*lonDeg(r.lon), 170.25, 1e-9);
  EXPECT_NEAR(*latDeg(r.lat), -45.5, 1e-9);
  EXPECT_EQ(r.course, 3599u);
  EXPECT_EQ(r.heading, 359u);
  EXPECT_EQ(r.maneuver, 1);
  EXPECT_TRUE(r.raim);
  EXPECT_EQ(r.radio, 12345u);
  EXPECT_NEAR(*speedMps(r.speed), knotsToMps(102.2), 1e-9);  // ">= 102.2 kn": kept as 102.2
  // ROT_AIS 20 -> (20 / 4.733)^2 = 17.856 deg/min, turning right.
  const double expected = degToRad(std::pow(20.0 / 4.733, 2)) / 60.0;
  EXPECT_NEAR(*rateOfTurn(r.turn), expected, 1e-12);
  EXPECT_NEAR(*rateOfTurn(-20), -expected, 1e-12);
  EXPECT_DOUBLE_EQ(*rateOfTurn(0), 0.0);
}

TEST(AisType1, ShortMessageReadsLikeGpsd) {
  // sample.aivdm "type=1 length=163" (fill 5) and the same payload at 168 bits: gpsd prints radio
  // 1076 and 34463: the short radio field is the 14 bits present.
  Message m = decodeOne("!AIVDM,1,1,,A,13aIkM@P00PJ@qPNL=e@0?wJ28JO,5*63");
  EXPECT_EQ(std::get<PositionReportA>(m.body).radio, 1076u);
  m = decodeOne("!AIVDM,1,1,,A,13aIkM@P00PJ@qPNL=e@0?wJ28JO,0*66");
  EXPECT_EQ(std::get<PositionReportA>(m.body).radio, 34463u);
  Decoder d;
  // 150 bits: below the 163 gpsd and we require.
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,13aIkM@P00PJ@qPNL=e@0?,0*54", m), Status::kTooShort);
  EXPECT_EQ(d.counters().too_short, 1u);
}

TEST(AisType4, BaseStation) {
  // sample.aivdm: MMSI 3669702, 2007-05-14 19:57:39, lon -76.352362, lat 36.883767, EPFD 7.
  const Message m = decodeOne("!AIVDM,1,1,,A,403OviQuMGCqWrRO9>E6fE700@GO,0*4D");
  const auto& r = std::get<BaseStationReport>(m.body);
  EXPECT_EQ(m.mmsi, 3669702u);
  EXPECT_EQ(r.year, 2007u);
  EXPECT_EQ(r.month, 5u);
  EXPECT_EQ(r.day, 14u);
  EXPECT_EQ(r.hour, 19u);
  EXPECT_EQ(r.minute, 57u);
  EXPECT_EQ(r.second, 39u);
  EXPECT_TRUE(r.accuracy);
  EXPECT_NEAR(*lonDeg(r.lon), -76.352362, 1e-6);
  EXPECT_NEAR(*latDeg(r.lat), 36.883767, 1e-6);
  EXPECT_EQ(r.epfd, 7);
  EXPECT_EQ(r.radio, 67039u);
  EXPECT_STREQ(epfdText(r.epfd), "Surveyed");
}

TEST(AisType11, UtcResponseSharesTheBaseStationLayout) {
  // sample.aivdm (noaadata): MMSI 304137000, 2009-05-22 02:22:40, accuracy 1, lon -94.4076833,
  // lat 28.4091167, EPFD 1; the USCG receiver suffix after the checksum is not part of it.
  const Message m = decodeOne("!AIVDM,1,1,,B,;4R33:1uUK2F`q?mOt@@GoQ00000,0*5D,s28089,d-103,T39.44353985");
  ASSERT_EQ(m.type, 11);
  const auto& r = std::get<BaseStationReport>(m.body);
  EXPECT_EQ(m.mmsi, 304137000u);
  EXPECT_EQ(r.year, 2009u);
  EXPECT_EQ(r.month, 5u);
  EXPECT_EQ(r.day, 22u);
  EXPECT_EQ(r.hour, 2u);
  EXPECT_EQ(r.minute, 22u);
  EXPECT_EQ(r.second, 40u);
  EXPECT_TRUE(r.accuracy);
  EXPECT_NEAR(*lonDeg(r.lon), -94.4076833, 1e-6);
  EXPECT_NEAR(*latDeg(r.lat), 28.4091167, 1e-6);
  EXPECT_EQ(r.epfd, 1);
}

TEST(AisType9, SarAircraftIsAMovingPosition) {
  // sample.aivdm (noaadata): MMSI 111232511, altitude 303 m, SOG 42 kn, lon -6.27884, lat 58.144,
  // COG 154.5, second 15, DTE 1.
  const Message m = decodeOne("!AIVDM,1,1,,B,91b55wi;hbOS@OdQAC062Ch2089h,0*30");
  ASSERT_EQ(m.type, 9);
  const auto& r = std::get<SarAircraftReport>(m.body);
  EXPECT_EQ(m.mmsi, 111232511u);
  EXPECT_EQ(r.alt, 303u);
  EXPECT_EQ(r.speed, 42u);
  EXPECT_EQ(r.course, 1545u);
  EXPECT_EQ(r.second, 15);
  EXPECT_TRUE(r.dte);
  Kinematics k;
  ASSERT_TRUE(toKinematics(m, k));
  ASSERT_TRUE(k.has_position && k.has_speed && k.has_course);
  EXPECT_NEAR(k.lon_deg, -6.27884, 1e-5);
  EXPECT_NEAR(k.lat_deg, 58.144, 1e-5);
  EXPECT_NEAR(k.speed, 42 * 1852.0 / 3600.0, 1e-9);  // whole knots, not tenths
  EXPECT_NEAR(k.course, 154.5 * M_PI / 180.0, 1e-9);
  EXPECT_FALSE(k.has_heading);  // an aircraft reports no heading
}

TEST(AisSafetyText, AddressedAndBroadcast) {
  // sample.aivdm (ais.py): type 12 from 2275200 to 215724000, and two type 14 broadcasts.
  Message m = decodeOne("!AIVDM,1,1,,A,<02:oP0kKcv0@<51C5PB5@?BDPD?P:?2?EB7PDB16693P381>>5<PikP,0*37");
  ASSERT_EQ(m.type, 12);
  const auto& a = std::get<SafetyText>(m.body);
  EXPECT_EQ(m.mmsi, 2275200u);
  EXPECT_EQ(a.dest_mmsi, 215724000u);
  EXPECT_EQ(a.seqno, 0);
  EXPECT_FALSE(a.retransmit);
  EXPECT_EQ(a.text.view(), "PLEASE REPORT TO JOBOURG TRAFFIC CHANNEL 13");
  m = decodeOne("!AIVDM,1,1,,A,>5?Per18=HB1U:1@E=B0m<L,2*51");
  ASSERT_EQ(m.type, 14);
  EXPECT_EQ(m.mmsi, 351809000u);
  EXPECT_EQ(std::get<SafetyText>(m.body).text.view(), "RCVD YR TEST MSG");
  m = decodeOne("!AIVDM,1,1,,A,>3R1p10E3;;R0USCR0HO>0@gN10kGJp,2*7F");
  EXPECT_EQ(std::get<SafetyText>(m.body).text.view(), "EP228 IX48 FG3 DK7 PL56.");
  Kinematics k;
  EXPECT_FALSE(toKinematics(m, k));
}

// A message of `type` with `nbits` zero bits after the header, decoded.
Status decodeLength(unsigned type, std::size_t nbits) {
  BitWriter w;
  w.put(type, 6);
  w.put(0, 2);
  w.put(123456789, 30);
  for (std::size_t k = 38; k < nbits; ++k)
    w.put(0, 1);
  Decoder d;
  Message m;
  Status last = Status::kPending;
  for (const auto& s : toSentences(w, 'A', 1))
    last = decodeLine(d, s.c_str(), m);
  return last;
}

TEST(AisLengths, GpsdLimitsPerType) {
  // gpsd 3.22's limits (found against its gpsdecode; the differential test checks them on random
  // lengths): type 9 from 168 bits, 20 from 72 to 186, 25 from 40 to 168, 7 from 72 to 168.
  EXPECT_EQ(decodeLength(9, 167), Status::kTooShort);
  EXPECT_EQ(decodeLength(9, 168), Status::kMessage);
  EXPECT_EQ(decodeLength(9, 400), Status::kMessage);
  EXPECT_EQ(decodeLength(20, 71), Status::kTooShort);
  EXPECT_EQ(decodeLength(20, 186), Status::kMessage);
  EXPECT_EQ(decodeLength(20, 187), Status::kTooLong);
  EXPECT_EQ(decodeLength(25, 168), Status::kMessage);
  EXPECT_EQ(decodeLength(25, 169), Status::kTooLong);
  EXPECT_EQ(decodeLength(7, 72), Status::kMessage);
  EXPECT_EQ(decodeLength(7, 169), Status::kTooLong);
  EXPECT_EQ(decodeLength(6, 88), Status::kMessage);
  EXPECT_EQ(decodeLength(6, 87), Status::kTooShort);
}

TEST(AisArmour, RawFieldsPastTheEndAsGpsdReadsThem) {
  // "ww" is 12 one-bits; with 2 fill bits the payload is 10 bits.
  Payload p;
  ASSERT_TRUE(p.append("ww"));
  p.dropFill(2);
  ASSERT_EQ(p.bits(), 10u);
  EXPECT_EQ(p.u(8, 4), 3u);      // clipped: the 2 bits present, right-aligned
  EXPECT_EQ(p.ur(8, 4), 15u);    // as gpsd: the fill bits as sent (11), left-aligned
  EXPECT_EQ(p.ur(8, 8), 0xF0u);  // then zeros
  EXPECT_EQ(p.sr(8, 4), -1);
  EXPECT_EQ(p.ur(12, 8), 0u);
  EXPECT_EQ(p.rawByte(8), 0xF0u);
  EXPECT_EQ(p.rawByte(4, 10), 0xFCu);  // bits from 10 on masked
  // A shorter payload after a longer one reads zeros past its end, not the old bits.
  p.clear();
  ASSERT_TRUE(p.append("0"));
  EXPECT_EQ(p.ur(0, 16), 0u);
}

TEST(AisType5, TwoFragments) {
  Decoder d;
  Message m;
  EXPECT_EQ(decodeLine(d, kT5p1A, m), Status::kPending);
  EXPECT_EQ(d.pendingCount(), 1u);
  ASSERT_EQ(decodeLine(d, kT5p2A, m), Status::kMessage);
  EXPECT_EQ(d.pendingCount(), 0u);
  EXPECT_EQ(m.type, 5);
  EXPECT_EQ(m.mmsi, 351759000u);
  const auto& v = std::get<StaticVoyageData>(m.body);
  EXPECT_EQ(v.imo, 9134270u);
  EXPECT_EQ(v.callsign, "3FOF8");
  EXPECT_EQ(v.shipname, "EVER DIADEM");  // '@' padding removed
  EXPECT_EQ(v.shiptype, 70);
  EXPECT_EQ(v.to_bow, 225u);
  EXPECT_EQ(v.to_stern, 70u);
  EXPECT_EQ(v.to_port, 1u);
  EXPECT_EQ(v.to_starboard, 31u);
  EXPECT_EQ(v.epfd, 1);
  EXPECT_EQ(v.month, 5u);
  EXPECT_EQ(v.day, 15u);
  EXPECT_EQ(v.hour, 14u);
  EXPECT_EQ(v.minute, 0u);
  EXPECT_EQ(v.draught, 122u);
  EXPECT_EQ(v.destination, "NEW YORK");
  EXPECT_FALSE(v.dte);
  EXPECT_STREQ(shipTypeText(v.shiptype), "Cargo - all ships of this type");
  Kinematics k;
  EXPECT_FALSE(toKinematics(m, k));
}

TEST(AisType18, ClassB) {
  // Encoder inputs: MMSI 338087471, speed 5.7 kn, accuracy 1, lon -74.072132, lat 40.684540,
  // course 79.6, heading 127, second 49, cs 1, display 0, dsc 1, band 1, msg22 1, assigned 0,
  // raim 1, radio 917510.
  const Message m = decodeOne("!AIVDM,1,1,,A,B52K>;h0>Nc>jpUlNV@ihwpUoP06,0*49");
  const auto& b = std::get<PositionReportB>(m.body);
  EXPECT_EQ(m.type, 18);
  EXPECT_EQ(m.mmsi, 338087471u);
  EXPECT_EQ(b.speed, 57u);
  EXPECT_TRUE(b.accuracy);
  EXPECT_EQ(b.lon, -44443279);
  EXPECT_EQ(b.lat, 24410724);
  EXPECT_EQ(b.course, 796u);
  EXPECT_EQ(b.heading, 127u);
  EXPECT_EQ(b.second, 49);
  EXPECT_TRUE(b.cs);
  EXPECT_FALSE(b.display);
  EXPECT_TRUE(b.dsc && b.band && b.msg22 && b.raim);
  EXPECT_FALSE(b.assigned);
  EXPECT_EQ(b.radio, 917510u);
  Kinematics k;
  ASSERT_TRUE(toKinematics(m, k));
  EXPECT_NEAR(k.speed, knotsToMps(5.7), 1e-9);
  EXPECT_NEAR(k.heading, degToRad(127.0), 1e-12);
}

TEST(AisType19, ExtendedClassB) {
  // Encoder inputs from sample.aivdm's decode: MMSI 367059850, reserved 248, speed 8.7, lon/lat raw
  // -53286235/17726217, course 335.9, heading 511, second 46, regional 4, "CAPT.J.RIMES", type 70,
  // 5/21/4/4 m, EPFD 1.
  const Message m = decodeOne("!AIVDM,1,1,,A,C5N3SRgPEnJGEBT>NhWAwwo862PaLELTBJ:V00000000S0D:R220,0*08");
  const auto& b = std::get<PositionReportB>(m.body);
  EXPECT_EQ(m.type, 19);
  EXPECT_EQ(b.reserved, 248u);
  EXPECT_EQ(b.speed, 87u);
  EXPECT_EQ(b.lon, -53286235);
  EXPECT_EQ(b.lat, 17726217);
  EXPECT_EQ(b.course, 3359u);
  EXPECT_EQ(b.heading, 511u);
  EXPECT_EQ(b.regional, 4u);
  EXPECT_EQ(b.shipname, "CAPT.J.RIMES");
  EXPECT_EQ(b.shiptype, 70);
  EXPECT_EQ(b.to_bow, 5u);
  EXPECT_EQ(b.to_stern, 21u);
  EXPECT_EQ(b.to_port, 4u);
  EXPECT_EQ(b.to_starboard, 4u);
  EXPECT_EQ(b.epfd, 1);
  Kinematics k;
  ASSERT_TRUE(toKinematics(m, k));
  EXPECT_FALSE(k.has_heading);
}

TEST(AisType21, NameExtensionAndPadding) {
  // Encoder inputs: aid type 20, name "ABCDEFGHIJKLMNOPQRST" + extension "EXTENDED NAME", lon -122.5,
  // lat 47.25, 5/6/7/8 m, EPFD 7, second 50, virtual 1.
  Message m = decodeOne("!AIVDM,1,1,,A,E>jHC6:0Q1R2S3T4U5V6W7`8a9bKWWbP=Q;6050hq3q011F51CQ1A83PCA@,4*79");
  const auto& n = std::get<AidToNavigation>(m.body);
  EXPECT_EQ(n.aid_type, 20);
  EXPECT_EQ(n.name, "ABCDEFGHIJKLMNOPQRSTEXTENDED NAME");
  EXPECT_NEAR(*lonDeg(n.lon), -122.5, 1e-9);
  EXPECT_NEAR(*latDeg(n.lat), 47.25, 1e-9);
  EXPECT_EQ(n.to_bow, 5u);
  EXPECT_EQ(n.to_stern, 6u);
  EXPECT_EQ(n.to_port, 7u);
  EXPECT_EQ(n.to_starboard, 8u);
  EXPECT_EQ(n.epfd, 7);
  EXPECT_EQ(n.second, 50);
  EXPECT_TRUE(n.virtual_aid);
  EXPECT_FALSE(n.off_position);
  EXPECT_STREQ(aidTypeText(n.aid_type), "Cardinal Mark N");
  // Name "BUOY 7" + spaces + '@': trailing spaces and padding trimmed; position not available.
  m = decodeOne("!AIVDM,1,1,,A,E>jHC6@Q:WdhKh@@000000000006NAc0J2@`000000N@00,4*51");
  const auto& p = std::get<AidToNavigation>(m.body);
  EXPECT_EQ(p.name, "BUOY 7");
  EXPECT_TRUE(p.off_position);
  Kinematics k;
  ASSERT_TRUE(toKinematics(m, k));
  EXPECT_FALSE(k.has_position);
}

TEST(AisType24, PartsAndStaticStore) {
  // Part A "PROGUY" and part B (type 60, vendor "1D0", model 12, serial 199796, "TC6163",
  // 0/15/0/5 m) of MMSI 271041815.
  Decoder d;
  StaticStore store;
  Message m;
  ASSERT_EQ(decodeLine(d, "!AIVDM,1,1,,A,H42O55i18tMET000000000000000,0*5F", m), Status::kMessage);
  const auto& a = std::get<StaticDataReport>(m.body);
  EXPECT_EQ(a.part, 0);
  EXPECT_EQ(a.shipname, "PROGUY");
  const ShipStatic* s = store.update(m);
  ASSERT_NE(s, nullptr);
  EXPECT_TRUE(s->has_name);
  EXPECT_FALSE(s->has_dimensions);
  ASSERT_EQ(decodeLine(d, "!AIVDM,1,1,,A,H42O55lti4hhhilD3nink000?050,0*40", m), Status::kMessage);
  const auto& b = std::get<StaticDataReport>(m.body);
  EXPECT_EQ(b.part, 1);
  EXPECT_EQ(b.shiptype, 60);
  EXPECT_EQ(b.vendorid.view().substr(0, 3), "1D0");
  EXPECT_EQ(b.model, 12u);
  EXPECT_EQ(b.serial, 199796u);
  EXPECT_EQ(b.callsign, "TC6163");
  EXPECT_EQ(b.to_stern, 15u);
  EXPECT_EQ(b.to_starboard, 5u);
  s = store.update(m);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->mmsi, 271041815u);
  EXPECT_EQ(s->shipname, "PROGUY");
  EXPECT_EQ(s->callsign, "TC6163");
  EXPECT_EQ(s->shiptype, 60);
  EXPECT_DOUBLE_EQ(s->length(), 15.0);
  EXPECT_DOUBLE_EQ(s->beam(), 5.0);
  EXPECT_EQ(store.size(), 1u);

  // Auxiliary craft (MMSI 98XXXYYYY): the mother ship's MMSI instead of the dimensions.
  ASSERT_EQ(decodeLine(d, "!AIVDM,1,1,,A,H>WikQlO12340021EHi000?S`e00,0*4D", m), Status::kMessage);
  EXPECT_EQ(m.mmsi, 981234567u);
  EXPECT_EQ(std::get<StaticDataReport>(m.body).mothership_mmsi, 261000000u);

  // Part number 2 does not exist.
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,H42O55q18tMET000000000000000,0*47", m), Status::kBadPart);
  EXPECT_EQ(d.counters().bad_part, 1u);
}

TEST(AisStaticStore, BoundedAndMergesType5) {
  StaticStoreConfig c;
  c.max_ships = 2;
  StaticStore store(c);
  Message m;
  m.type = 5;
  m.mmsi = 1;
  StaticVoyageData v;
  v.shipname.assign("ONE");
  v.to_bow = 100;
  v.to_stern = 20;
  m.body = v;
  ASSERT_NE(store.update(m), nullptr);
  EXPECT_DOUBLE_EQ(store.find(1)->length(), 120.0);
  m.mmsi = 2;
  store.update(m);
  m.mmsi = 3;
  store.update(m);
  EXPECT_EQ(store.size(), 2u);
  EXPECT_EQ(store.find(1), nullptr);  // the least recently updated went
  m.body = PositionReportA();
  EXPECT_EQ(store.update(m), nullptr);
  c.max_ships = 0;
  EXPECT_THROW(c.validate(), std::invalid_argument);
}

TEST(AisType27, LongRange) {
  // Encoder inputs: accuracy 1, status 2, lon 137.0, lat 4.8 (1/10 min), speed 57 kn, course 167.
  Message m = decodeOne("!AIVDM,1,1,,A,K35E2bHU160FPLbL,0*20");
  const auto& l = std::get<LongRangeReport>(m.body);
  EXPECT_EQ(m.type, 27);
  EXPECT_TRUE(l.accuracy);
  EXPECT_EQ(l.status, 2);
  EXPECT_EQ(l.lon, 82200);
  EXPECT_EQ(l.lat, 2880);
  EXPECT_EQ(l.speed, 57u);
  EXPECT_EQ(l.course, 167u);
  Kinematics k;
  ASSERT_TRUE(toKinematics(m, k));
  EXPECT_NEAR(k.lon_deg, 137.0, 1e-9);
  EXPECT_NEAR(k.lat_deg, 4.8, 1e-9);
  EXPECT_NEAR(k.speed, knotsToMps(57.0), 1e-9);
  EXPECT_NEAR(k.course, degToRad(167.0), 1e-12);
  // Not available: lon 181, lat 91, speed 63, course 511.
  m = decodeOne("!AIVDM,1,1,,A,K35E2bSn`>6bTOwv,0*53");
  ASSERT_TRUE(toKinematics(m, k));
  EXPECT_FALSE(k.has_position || k.has_speed || k.has_course);
}

TEST(AisFill, ValidatedAndApplied) {
  Decoder d;
  Message m;
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,6*4C", m), Status::kBadFill);
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,x*02", m), Status::kBadFill);
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,*7A", m), Status::kBadFill);
  EXPECT_EQ(d.counters().bad_fill, 3u);
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,5*4F", m), Status::kMessage);
  EXPECT_EQ(std::get<PositionReportA>(m.body).radio, 34017u >> 5);
  // Bad armour and empty payloads.
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208C~,0*65", m), Status::kBadArmour);
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,,0*26", m), Status::kEmptyPayload);
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ*56", m), Status::kBadFields);
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,2,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*49", m), Status::kBadFields);
  EXPECT_EQ(decodeLine(d, "$GPGLL,4916.45,N,12311.12,W,225444,A*31", m), Status::kNotAis);
  // A binary message keeps its application id (type 8, DAC 1 FID 16, from sample.aivdm; gpsdecode
  // prints the same dac and fid).
  ASSERT_EQ(decodeLine(d, "!AIVDM,1,1,,A,802At?00D000qFap02:lA0b@?3fw0001<:iFP2:rf0cCGp0w00,4*5E", m),
            Status::kMessage);
  EXPECT_EQ(std::get<PayloadMessage>(m.body).dac, 1u);
  EXPECT_EQ(std::get<PayloadMessage>(m.body).fid, 16u);
  // Types 0 and 28-63 are not defined by ITU-R M.1371: counted, not decoded.
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,0000000000000,0*16", m), Status::kUnsupportedType);
  EXPECT_EQ(decodeLine(d, "!AIVDM,1,1,,A,t000000000000,0*52", m), Status::kUnsupportedType);
  EXPECT_EQ(d.counters().unsupported, 2u);
}

TEST(AisReassembly, InterleavedChannels) {
  // sample.aivdm: messages on B (seq 6) and A (seq 2) interleaved; both complete.
  Decoder d;
  Message m;
  EXPECT_EQ(decodeLine(d, kT5B1, m), Status::kPending);
  EXPECT_EQ(decodeLine(d, kT5A1, m), Status::kPending);
  EXPECT_EQ(d.pendingCount(), 2u);
  ASSERT_EQ(decodeLine(d, kT5A2, m), Status::kMessage);
  EXPECT_EQ(m.channel, 'A');
  EXPECT_EQ(m.mmsi, 271010059u);
  EXPECT_EQ(std::get<StaticVoyageData>(m.body).shipname, "HEALTH CONTROL 13");
  ASSERT_EQ(decodeLine(d, kT5B2, m), Status::kMessage);
  EXPECT_EQ(m.channel, 'B');
  EXPECT_EQ(std::get<StaticVoyageData>(m.body).callsign, "TCA2350");
  EXPECT_EQ(d.counters().messages, 2u);
  EXPECT_EQ(d.counters().orphans, 0u);

  // Same sequence id on both channels: keyed apart by the channel.
  EXPECT_EQ(decodeLine(d, kT5p1A, m), Status::kPending);
  EXPECT_EQ(decodeLine(d, kT5p1B, m), Status::kPending);
  ASSERT_EQ(decodeLine(d, kT5p2B, m), Status::kMessage);
  EXPECT_EQ(m.channel, 'B');
  ASSERT_EQ(decodeLine(d, kT5p2A, m), Status::kMessage);
  EXPECT_EQ(m.channel, 'A');
}

TEST(AisReassembly, SameChannelBySequenceId) {
  Decoder d;
  Message m;
  EXPECT_EQ(decodeLine(d, kT5p1A, m), Status::kPending);   // seq 3
  EXPECT_EQ(decodeLine(d, kT5p1A4, m), Status::kPending);  // seq 4, same channel
  ASSERT_EQ(decodeLine(d, kT5p2A, m), Status::kMessage);
  ASSERT_EQ(decodeLine(d, kT5p2A4, m), Status::kMessage);
  EXPECT_EQ(std::get<StaticVoyageData>(m.body).destination, "NEW YORK");
  EXPECT_EQ(d.pendingCount(), 0u);
}

TEST(AisReassembly, OrphansOutOfOrderAndRestart) {
  Decoder d;
  Message m;
  // sample.aivdm "That fragment misses part 1" (with its '!' restored).
  EXPECT_EQ(decodeLine(d, "!AIVDM,2,2,1,B,00000000000,2*26", m), Status::kOrphanFragment);
  EXPECT_EQ(d.counters().orphans, 1u);
  // Part 2 of 3 arrives before anything: orphan; 1 then 3: out of order, message dropped.
  const std::string p1 = "!AIVDM,3,1,7,A,85Mwp=iKfGwushJ?gNlt2QU3osVGe:4?cNhQqf2VH8t,0*08";
  const std::string p3 = "!AIVDM,3,3,7,A,Uq:1Kk`e8,4*27";
  EXPECT_EQ(decodeLine(d, p1, m), Status::kPending);
  EXPECT_EQ(decodeLine(d, p3, m), Status::kOutOfOrder);
  EXPECT_EQ(d.counters().out_of_order, 1u);
  EXPECT_EQ(d.pendingCount(), 0u);
  // A new first fragment with the key of a pending message restarts it.
  EXPECT_EQ(decodeLine(d, kT5p1A, m), Status::kPending);
  EXPECT_EQ(decodeLine(d, kT5p1A, m), Status::kPending);
  EXPECT_EQ(d.counters().restarted, 1u);
  EXPECT_EQ(decodeLine(d, kT5p2A, m), Status::kMessage);
  // A repeated last fragment is now an orphan.
  EXPECT_EQ(decodeLine(d, kT5p2A, m), Status::kOrphanFragment);
}

TEST(AisReassembly, TimeoutAndBoundedMemory) {
  DecoderConfig c;
  c.fragment_timeout = 5.0;
  c.max_pending = 2;
  Decoder d(c);
  Message m;
  EXPECT_EQ(decodeLine(d, kT5p1A, m, 100.0), Status::kPending);
  EXPECT_EQ(decodeLine(d, kT5p2A, m, 106.0), Status::kOrphanFragment);  // timed out first
  EXPECT_EQ(d.counters().timeouts, 1u);
  EXPECT_EQ(decodeLine(d, kT5p1A, m, 200.0), Status::kPending);
  EXPECT_EQ(decodeLine(d, kT5p2A, m, 204.0), Status::kMessage);  // within the timeout

  // Three first fragments with max_pending 2: the oldest is evicted.
  EXPECT_EQ(decodeLine(d, kT5p1A, m, 300.0), Status::kPending);
  EXPECT_EQ(decodeLine(d, kT5p1B, m, 300.0), Status::kPending);
  EXPECT_EQ(decodeLine(d, kT5p1A4, m, 300.0), Status::kPending);
  EXPECT_EQ(d.pendingCount(), 2u);
  EXPECT_EQ(d.counters().evicted, 1u);
  EXPECT_EQ(decodeLine(d, kT5p2A, m, 300.0), Status::kOrphanFragment);
  EXPECT_EQ(decodeLine(d, kT5p2B, m, 300.0), Status::kMessage);
  EXPECT_EQ(decodeLine(d, kT5p2A4, m, 300.0), Status::kMessage);
  d.expire(1000.0);
  EXPECT_EQ(d.pendingCount(), 0u);

  // clearPending (the clock went back): a first fragment is forgotten, uncounted, so its second part
  // is an orphan.
  const uint64_t timeouts = d.counters().timeouts;
  EXPECT_EQ(decodeLine(d, kT5p1A, m, 50.0), Status::kPending);
  d.clearPending();
  EXPECT_EQ(d.pendingCount(), 0u);
  EXPECT_EQ(d.counters().timeouts, timeouts);
  EXPECT_EQ(decodeLine(d, kT5p2A, m, 50.0), Status::kOrphanFragment);

  DecoderConfig bad;
  bad.max_pending = 0;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
  bad = DecoderConfig();
  bad.fragment_timeout = -1.0;
  EXPECT_THROW(bad.validate(), std::invalid_argument);
}

TEST(AisReassembly, TagBlockSourcesKeptApart) {
  // Two receivers send fragments of different messages with the same channel and sequence id.
  Decoder d;
  Message m;
  auto tag = [](const std::string& content) {
    unsigned x = 0;
    for (char c : content)
      x ^= static_cast<unsigned char>(c);
    char hex[3];
    std::snprintf(hex, sizeof(hex), "%02X", x);
    return "\\" + content + "*" + hex + "\\";
  };
  EXPECT_EQ(decodeLine(d, tag("s:rx1,c:1000") + kT5p1A, m), Status::kPending);
  EXPECT_EQ(decodeLine(d, tag("s:rx2,c:1000") + kT5p1A, m), Status::kPending);
  EXPECT_EQ(d.pendingCount(), 2u);
  ASSERT_EQ(decodeLine(d, tag("s:rx1,c:1001") + kT5p2A, m), Status::kMessage);
  EXPECT_TRUE(m.has_time);
  EXPECT_DOUBLE_EQ(m.unix_time, 1001.0);
  ASSERT_EQ(decodeLine(d, tag("s:rx2,c:1001") + kT5p2A, m), Status::kMessage);
}

TEST(AisDecoder, Type1DoesNotAllocate) {
  Decoder d;
  Message m;
  nmea::Sentence s;
  const std::string line = "!AIVDM,1,1,,A,15RTgt0PAso;90TKcjM8h6g208CQ,0*4A";
  // Warm up (the variant may hold another alternative before).
  ASSERT_EQ(d.feedLine(line, 0.0, m), Status::kMessage);
  const long before = g_allocations.load();
  for (int i = 0; i < 100; ++i) {
    ASSERT_EQ(nmea::parseSentence(line, s), nmea::Reject::kNone);
    ASSERT_EQ(d.feed(s, 0.0, m), Status::kMessage);
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  // Nor does a two-fragment message.
  const long before5 = g_allocations.load();
  ASSERT_EQ(d.feedLine(kT5p1A, 0.0, m), Status::kPending);
  ASSERT_EQ(d.feedLine(kT5p2A, 0.0, m), Status::kMessage);
  EXPECT_EQ(g_allocations.load() - before5, 0);
}

TEST(AisDecoder, StatusTexts) {
  for (int s = 0; s < static_cast<int>(Status::kCount); ++s)
    EXPECT_STRNE(statusText(static_cast<Status>(s)), "unknown");
  EXPECT_STREQ(navStatusText(5), "Moored");
  EXPECT_STREQ(shipTypeText(37), "Pleasure Craft");
  EXPECT_STREQ(shipTypeText(55), "Law Enforcement");
  EXPECT_STREQ(shipTypeText(100), "INVALID SHIP TYPE");
  EXPECT_STREQ(epfdText(14), "INVALID EPFD");
}
