// ARPA sentences (TTM, TLL, OSD) in the shapes real radars send: space-padded fields, empty fields
// while acquiring, target numbers above 99, relative bearings. Expected values are the sentence's
// numbers converted by hand (1 kn = 1852/3600 m/s, 1 nm = 1852 m, 1 mi = 1609.344 m).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "asv_core/codec/arpa.h"
#include "asv_core/common/units.h"

using namespace asv;
using namespace asv::arpa;

namespace {

// Frames `body` (without '$' and checksum), keeping the line alive for the Sentence's views.
class Framed {
public:
  explicit Framed(const std::string& body) {
    unsigned x = 0;
    for (char c : body)
      x ^= static_cast<unsigned char>(c);
    char hex[4];
    std::snprintf(hex, sizeof(hex), "%02X", x);
    line_ = "$" + body + "*" + hex;
    reject_ = nmea::parseSentence(line_, sentence_);
  }
  const nmea::Sentence& operator*() const { return sentence_; }
  nmea::Reject reject() const { return reject_; }

private:
  std::string line_;
  nmea::Sentence sentence_;
  nmea::Reject reject_;
};

constexpr double kKn = 1852.0 / 3600.0;

}  // namespace

TEST(ArpaTtm, StandardSentence) {
  Framed f("RATTM,01,2.50,045.0,T,12.0,180.0,T,0.50,-5.5,N,TGT1,T,,123456.78,A");
  ASSERT_EQ(f.reject(), nmea::Reject::kNone);
  TrackedTarget t;
  ASSERT_EQ(parseTtm(*f, t), Error::kNone);
  EXPECT_EQ(t.number, 1);
  EXPECT_TRUE(t.has_distance);
  EXPECT_NEAR(t.distance, 2.5 * 1852.0, 1e-9);
  EXPECT_NEAR(t.bearing, degToRad(45.0), 1e-12);
  EXPECT_EQ(t.bearing_ref, Reference::kTrue);
  EXPECT_NEAR(t.speed, 12.0 * kKn, 1e-12);
  EXPECT_NEAR(t.course, kPi, 1e-12);
  EXPECT_EQ(t.course_ref, Reference::kTrue);
  EXPECT_NEAR(t.cpa, 0.5 * 1852.0, 1e-9);
  EXPECT_NEAR(t.tcpa, -330.0, 1e-9);  // -5.5 min: CPA already passed
  EXPECT_EQ(t.units, 'N');
  EXPECT_EQ(t.name, "TGT1");
  EXPECT_EQ(t.status, TargetStatus::kTracking);
  EXPECT_FALSE(t.reference_target);
  EXPECT_TRUE(t.has_time);
  EXPECT_NEAR(t.utc_seconds, 12 * 3600 + 34 * 60 + 56.78, 1e-9);
  EXPECT_EQ(t.acquisition, Acquisition::kAutomatic);
}

TEST(ArpaTtm, SpacePaddedFieldsAndBigTargetNumbers) {
  // Furuno/JRC style: fixed-width, space-padded fields; target number 101.
  Framed f("RATTM,101, 10.25, 270.5,T,  8.3, 95.0,T,  1.20,  12.0,N,        ,T, ,091500.00,M");
  ASSERT_EQ(f.reject(), nmea::Reject::kNone);
  TrackedTarget t;
  ASSERT_EQ(parseTtm(*f, t), Error::kNone);
  EXPECT_EQ(t.number, 101);
  EXPECT_NEAR(t.distance, 10.25 * 1852.0, 1e-9);
  EXPECT_NEAR(t.bearing, degToRad(270.5), 1e-12);
  EXPECT_NEAR(t.speed, 8.3 * kKn, 1e-12);
  EXPECT_NEAR(t.course, degToRad(95.0), 1e-12);
  EXPECT_NEAR(t.tcpa, 720.0, 1e-9);
  EXPECT_EQ(t.name, "");
  EXPECT_EQ(t.acquisition, Acquisition::kManual);
  EXPECT_NEAR(t.utc_seconds, 9 * 3600 + 15 * 60, 1e-9);
  Framed g("RATTM,  7,1.0,10.0,T,1.0,10.0,T,,,N,,Q,,,");
  ASSERT_EQ(parseTtm(*g, t), Error::kNone);
  EXPECT_EQ(t.number, 7);
}

TEST(ArpaTtm, EmptyFieldsWhileAcquiring) {
  Framed f("RATTM,03,,,,,,,,,N,,Q,,,A");
  ASSERT_EQ(f.reject(), nmea::Reject::kNone);
  TrackedTarget t;
  ASSERT_EQ(parseTtm(*f, t), Error::kNone);
  EXPECT_EQ(t.number, 3);
  EXPECT_EQ(t.status, TargetStatus::kQuery);
  EXPECT_FALSE(t.has_distance || t.has_bearing || t.has_speed || t.has_course || t.has_cpa || t.has_tcpa ||
               t.has_time);
  EXPECT_TRUE(std::isnan(t.distance) && std::isnan(t.bearing) && std::isnan(t.speed) &&
              std::isnan(t.course) && std::isnan(t.cpa) && std::isnan(t.tcpa));
  // Old NMEA 2.x TTM without UTC and acquisition fields.
  Framed old("RATTM,04,1.5,10.0,T,5.0,20.0,T,1.0,3.0,N,,L,");
  ASSERT_EQ(parseTtm(*old, t), Error::kNone);
  EXPECT_EQ(t.status, TargetStatus::kLost);
  EXPECT_EQ(t.acquisition, Acquisition::kUnknown);
  EXPECT_FALSE(t.has_time);
}

TEST(ArpaTtm, RelativeBearingAndCourseToTrue) {
  Framed f("RATTM,12,1.0,030.0,R,10.0,350.0,R,0.2,4.0,N,,T,R,,A");
  TrackedTarget t;
  ASSERT_EQ(parseTtm(*f, t), Error::kNone);
  EXPECT_EQ(t.bearing_ref, Reference::kRelative);
  EXPECT_EQ(t.course_ref, Reference::kRelative);
  EXPECT_TRUE(t.reference_target);
  TrackedTarget copy = t;
  EXPECT_FALSE(toTrue(copy, std::nan("")));  // needs the heading
  ASSERT_TRUE(toTrue(t, degToRad(90.0)));
  EXPECT_EQ(t.bearing_ref, Reference::kTrue);
  EXPECT_NEAR(t.bearing, degToRad(120.0), 1e-12);
  EXPECT_NEAR(t.course, degToRad(80.0), 1e-12);  // 350 + 90 wraps to 80
  // True fields are left alone.
  Framed g("RATTM,13,1.0,030.0,T,10.0,350.0,T,0.2,4.0,N,,T,,,A");
  ASSERT_EQ(parseTtm(*g, t), Error::kNone);
  ASSERT_TRUE(toTrue(t, std::nan("")));
  EXPECT_NEAR(t.bearing, degToRad(30.0), 1e-12);
}

TEST(ArpaTtm, UnitsKilometresAndStatuteMiles) {
  Framed k("RATTM,05,3.0,0.0,T,36.0,0.0,T,1.5,2.0,K,,T,,,A");
  TrackedTarget t;
  ASSERT_EQ(parseTtm(*k, t), Error::kNone);
  EXPECT_NEAR(t.distance, 3000.0, 1e-9);
  EXPECT_NEAR(t.speed, 10.0, 1e-12);
  EXPECT_NEAR(t.cpa, 1500.0, 1e-9);
  Framed s("RATTM,06,2.0,0.0,T,10.0,0.0,T,1.0,2.0,S,,T,,,A");
  ASSERT_EQ(parseTtm(*s, t), Error::kNone);
  EXPECT_NEAR(t.distance, 2 * 1609.344, 1e-9);
  EXPECT_NEAR(t.speed, 10 * 1609.344 / 3600.0, 1e-12);
  Framed bad("RATTM,06,2.0,0.0,T,10.0,0.0,T,1.0,2.0,X,,T,,,A");
  EXPECT_EQ(parseTtm(*bad, t), Error::kBadUnits);
}

TEST(ArpaTtm, Errors) {
  TrackedTarget t;
  Framed tll("RATLL,01,5433.12,N,01848.30,E,,,T,");
  EXPECT_EQ(parseTtm(*tll, t), Error::kWrongType);
  Framed few("RATTM,01,2.5");
  EXPECT_EQ(parseTtm(*few, t), Error::kBadFields);
  Framed no_number("RATTM,,2.5,10,T,1,1,T,1,1,N,,T,,,A");
  EXPECT_EQ(parseTtm(*no_number, t), Error::kBadFields);
  Framed bad_number("RATTM,A1,2.5,10,T,1,1,T,1,1,N,,T,,,A");
  EXPECT_EQ(parseTtm(*bad_number, t), Error::kBadValue);
  // Out-of-range values are unknown, not errors: the rest of the target is still usable.
  Framed odd("RATTM,02,2.5,400.0,T,1.0,10.0,T,1.0,1.0,N,,T,,256199.00,A");
  ASSERT_EQ(parseTtm(*odd, t), Error::kNone);
  EXPECT_FALSE(t.has_bearing);
  EXPECT_FALSE(t.has_time);
  EXPECT_TRUE(t.has_distance);
  for (int e = 0; e < static_cast<int>(Error::kCount); ++e)
    EXPECT_STRNE(errorText(static_cast<Error>(e)), "unknown");
}

TEST(ArpaTll, Position) {
  Framed f("RATLL,01,5433.120,N,01848.300,E,TGT 1,123456.00,T,");
  ASSERT_EQ(f.reject(), nmea::Reject::kNone);
  TargetPosition p;
  ASSERT_EQ(parseTll(*f, p), Error::kNone);
  EXPECT_EQ(p.number, 1);
  ASSERT_TRUE(p.has_position);
  EXPECT_NEAR(p.lat_deg, 54.0 + 33.12 / 60.0, 1e-9);
  EXPECT_NEAR(p.lon_deg, 18.0 + 48.3 / 60.0, 1e-9);
  EXPECT_EQ(p.name, "TGT 1");
  EXPECT_EQ(p.status, TargetStatus::kTracking);
  EXPECT_NEAR(p.utc_seconds, 12 * 3600 + 34 * 60 + 56.0, 1e-9);
  Framed sw("RATLL,120,3345.500,S,07030.250,W,,,Q,R");
  ASSERT_EQ(parseTll(*sw, p), Error::kNone);
  EXPECT_EQ(p.number, 120);
  EXPECT_NEAR(p.lat_deg, -(33.0 + 45.5 / 60.0), 1e-9);
  EXPECT_NEAR(p.lon_deg, -(70.0 + 30.25 / 60.0), 1e-9);
  EXPECT_TRUE(p.reference_target);
  EXPECT_EQ(p.status, TargetStatus::kQuery);
  Framed empty("RATLL,09,,,,,,,Q,");
  ASSERT_EQ(parseTll(*empty, p), Error::kNone);
  EXPECT_FALSE(p.has_position);
  EXPECT_TRUE(std::isnan(p.lat_deg));
  Framed bad_min("RATLL,09,5475.000,N,01848.300,E,,,T,");
  ASSERT_EQ(parseTll(*bad_min, p), Error::kNone);
  EXPECT_FALSE(p.has_position);  // 75 minutes
}

TEST(ArpaOsd, OwnShipData) {
  Framed f("RAOSD,035.1,A,036.0,P,10.5,P,015.0,1.2,N");
  ASSERT_EQ(f.reject(), nmea::Reject::kNone);
  OwnShipData o;
  ASSERT_EQ(parseOsd(*f, o), Error::kNone);
  EXPECT_NEAR(o.heading, degToRad(35.1), 1e-12);
  EXPECT_TRUE(o.heading_valid);
  EXPECT_NEAR(o.course, degToRad(36.0), 1e-12);
  EXPECT_EQ(o.course_ref, 'P');
  EXPECT_NEAR(o.speed, 10.5 * kKn, 1e-12);
  EXPECT_EQ(o.speed_ref, 'P');
  EXPECT_NEAR(o.set, degToRad(15.0), 1e-12);
  EXPECT_NEAR(o.drift, 1.2 * kKn, 1e-12);
  Framed partial("RAOSD, 90.0,V,,,,,,,K");
  ASSERT_EQ(parseOsd(*partial, o), Error::kNone);
  EXPECT_NEAR(o.heading, kPi / 2, 1e-12);
  EXPECT_FALSE(o.heading_valid);
  EXPECT_FALSE(o.has_course || o.has_speed || o.has_set || o.has_drift);
  TrackedTarget t;
  ASSERT_TRUE(toTrue(t, o.heading));  // nothing relative: nothing to do
  Framed few("RAOSD,90.0,A");
  EXPECT_EQ(parseOsd(*few, o), Error::kBadFields);
  ArpaConfig c;
  EXPECT_NO_THROW(c.validate());
  c.max_speed = 0.0;
  EXPECT_THROW(c.validate(), std::invalid_argument);
}

// Found by fuzzing (src/fuzz/fuzz_arpa.cpp): std::from_chars reads "nan" and "inf", and a finite
// TCPA in minutes can overflow in seconds; none of them may become a known value.
TEST(ArpaFuzzRegression, NonFiniteFieldsAreUnknown) {
  TargetPosition p;
  Framed nan_lat("RATLL,01,nan,N,01848.300,E,,123456.00,T,");
  ASSERT_EQ(parseTll(*nan_lat, p), Error::kNone);
  EXPECT_FALSE(p.has_position);
  EXPECT_TRUE(std::isnan(p.lat_deg));
  Framed inf_lon("RATLL,01,5433.120,N,inf,E,,,T,");
  ASSERT_EQ(parseTll(*inf_lon, p), Error::kNone);
  EXPECT_FALSE(p.has_position);
  TrackedTarget t;
  Framed big_tcpa("RATTM,01,2.50,045.0,T,12.0,180.0,T,0.50,1e308,N,TGT1,T,,1234nan,A");
  ASSERT_EQ(parseTtm(*big_tcpa, t), Error::kNone);
  EXPECT_FALSE(t.has_tcpa);
  EXPECT_TRUE(std::isnan(t.tcpa));
  EXPECT_FALSE(t.has_time);  // seconds "nan"
  EXPECT_TRUE(std::isnan(t.utc_seconds));
}
