#include <gtest/gtest.h>

#include <GeographicLib/Geodesic.hpp>

#include "asv_core/common/geodesy.h"
#include "asv_core/common/units.h"

using namespace asv;

TEST(Units, KnotsNauticalMilesDegrees) {
  EXPECT_NEAR(knotsToMps(10.0), 18520.0 / 3600.0, 1e-12);  // 10 nm per hour
  EXPECT_NEAR(mpsToKnots(knotsToMps(13.7)), 13.7, 1e-12);
  EXPECT_DOUBLE_EQ(nmToMetres(0.5), 926.0);
  EXPECT_DOUBLE_EQ(metresToNm(3704.0), 2.0);
  EXPECT_NEAR(degToRad(180.0), kPi, 1e-15);
  EXPECT_NEAR(radToDeg(kPi / 2), 90.0, 1e-12);
}

TEST(Units, Wrapping) {
  EXPECT_NEAR(wrapTwoPi(-kPi / 2), 3 * kPi / 2, 1e-12);
  EXPECT_NEAR(wrapTwoPi(5 * kPi), kPi, 1e-12);
  EXPECT_GE(wrapTwoPi(-1e-18), 0.0);
  EXPECT_LT(wrapTwoPi(-1e-18), kTwoPi);
  EXPECT_NEAR(wrapPi(3 * kPi / 2), -kPi / 2, 1e-12);
  EXPECT_NEAR(wrapPi(kPi), -kPi, 1e-12);  // [-pi, pi)
  EXPECT_DOUBLE_EQ(wrapDeg360(-30.0), 330.0);
  EXPECT_DOUBLE_EQ(wrapDeg360(720.0), 0.0);
  EXPECT_TRUE(std::isnan(wrapTwoPi(std::nan(""))));
}

TEST(Units, CourseToYawIsTheOneConversion) {
  // North (course 0) is ENU yaw +90 deg; east (course 90) is yaw 0; south is -90; west is 180 (-180).
  EXPECT_NEAR(courseToYaw(0.0), kPi / 2, 1e-12);
  EXPECT_NEAR(courseToYaw(kPi / 2), 0.0, 1e-12);
  EXPECT_NEAR(courseToYaw(kPi), -kPi / 2, 1e-12);
  EXPECT_NEAR(std::fabs(courseToYaw(3 * kPi / 2)), kPi, 1e-12);
  for (double c = 0.0; c < kTwoPi; c += 0.1)
    EXPECT_NEAR(yawToCourse(courseToYaw(c)), c, 1e-12);
  // The velocity of course 066 deg at 10 kn points east-north-east.
  const Eigen::Vector2d v = courseSpeedToVelocity(degToRad(66.0), knotsToMps(10.0));
  EXPECT_NEAR(v.x(), knotsToMps(10.0) * std::sin(degToRad(66.0)), 1e-12);
  EXPECT_NEAR(v.y(), knotsToMps(10.0) * std::cos(degToRad(66.0)), 1e-12);
  EXPECT_NEAR(radToDeg(courseOf(v)), 66.0, 1e-9);
  EXPECT_NEAR(radToDeg(trueBearing({0, 0}, {-1, -1})), 225.0, 1e-9);
}

TEST(Geodesy, RoundTripBelowOneMillimetreAt50km) {
  const LocalFrame frame(54.60, 18.80);
  const GeographicLib::Geodesic& geod = GeographicLib::Geodesic::WGS84();
  double worst = 0.0;
  for (double az = 0.0; az < 360.0; az += 15.0) {
    double lat, lon;
    geod.Direct(54.60, 18.80, az, 50000.0, lat, lon);
    const Eigen::Vector2d enu = frame.toLocal(lat, lon);
    // Independent check of the projection: the local point lies along the geodesic azimuth at about
    // the geodesic distance (the tangent plane shortens 50 km by about 0.5 m).
    EXPECT_NEAR(enu.norm(), 50000.0, 2.0);
    EXPECT_NEAR(radToDeg(wrapPi(courseOf(enu) - degToRad(az))), 0.0, 0.05);
    const GeoPoint back = frame.toGeodetic(enu);
    double dist;
    geod.Inverse(lat, lon, back.lat_deg, back.lon_deg, dist);
    worst = std::max(worst, dist);
  }
  EXPECT_LT(worst, 1e-3);
}

TEST(Geodesy, OriginIsZeroAndBadOriginThrows) {
  const LocalFrame frame(-33.9, 151.2);
  EXPECT_NEAR(frame.toLocal(-33.9, 151.2).norm(), 0.0, 1e-9);
  EXPECT_THROW(LocalFrame(91.0, 0.0), std::invalid_argument);   // AIS "not available" latitude
  EXPECT_THROW(LocalFrame(0.0, 181.0), std::invalid_argument);  // AIS "not available" longitude
  EXPECT_THROW(LocalFrame(std::nan(""), 0.0), std::invalid_argument);
  EXPECT_FALSE(validLatLon(91.0, 181.0));
  EXPECT_TRUE(validLatLon(-90.0, 180.0));
}

// A node's own map origin: both keys or neither; half of one, or one off the globe, names the keys.
TEST(Geodesy, OriginFromParamsIsWholeOrAbsent) {
  asv::ParamMap p;
  EXPECT_FALSE(asv::originFromParams(p));
  p.set("origin_lat_deg", 54.6);
  EXPECT_THROW(asv::originFromParams(p), std::invalid_argument);
  p.set("origin_lon_deg", 18.8);
  const std::optional<asv::GeoPoint> o = asv::originFromParams(p);
  ASSERT_TRUE(o);
  EXPECT_DOUBLE_EQ(o->lat_deg, 54.6);
  EXPECT_DOUBLE_EQ(o->lon_deg, 18.8);
  p.set("origin_lat_deg", 91.0);  // AIS "not available": no origin
  try {
    asv::originFromParams(p);
    FAIL() << "91 N taken as an origin";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("origin_lat_deg"), std::string::npos);
  }
}
