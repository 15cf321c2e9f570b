#include <gtest/gtest.h>

#include "asv_core/risk/domain.h"

using namespace asv;

TEST(Polygon, ConvexAndConcaveContainment) {
  const Polygon square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  EXPECT_TRUE(pointInPolygon(square, {5, 5}));
  EXPECT_TRUE(pointInPolygon(square, {10, 5}));  // on an edge
  EXPECT_FALSE(pointInPolygon(square, {10.01, 5}));
  // A "U": the notch (4..6, 3..10) is outside.
  const Polygon u{{0, 0}, {10, 0}, {10, 10}, {6, 10}, {6, 3}, {4, 3}, {4, 10}, {0, 10}};
  EXPECT_TRUE(pointInPolygon(u, {2, 8}));
  EXPECT_TRUE(pointInPolygon(u, {8, 8}));
  EXPECT_FALSE(pointInPolygon(u, {5, 8}));
  EXPECT_TRUE(pointInPolygon(u, {5, 1}));
  EXPECT_FALSE(pointInPolygon(Polygon{{0, 0}, {1, 1}}, {0, 0}));  // degenerate
}

TEST(CircleDomain, Containment) {
  const CircleDomain c{926.0};
  EXPECT_TRUE(c.contains({100, 100}, {100, 1026}));
  EXPECT_FALSE(c.contains({100, 100}, {100, 1027}));
}

TEST(HexagonDomain, PaperDimensionsHeadingNorth) {
  const HexagonDomain hex;  // a = 1 nm, b = c = 0.6 nm, d = e = 0.25 nm
  const Eigen::Vector2d o(0, 0);
  EXPECT_TRUE(hex.contains(o, 0.0, {0, 1852}));  // bow vertex
  EXPECT_TRUE(hex.contains(o, 0.0, {0, 1800}));
  EXPECT_FALSE(hex.contains(o, 0.0, {0, 1900}));
  EXPECT_TRUE(hex.contains(o, 0.0, {1100, 0}));  // starboard 0.6 nm
  EXPECT_FALSE(hex.contains(o, 0.0, {1120, 0}));
  EXPECT_TRUE(hex.contains(o, 0.0, {-460, 0}));  // port 0.25 nm
  EXPECT_FALSE(hex.contains(o, 0.0, {-470, 0}));
  EXPECT_TRUE(hex.contains(o, 0.0, {0, -460}));  // stern 0.25 nm
  EXPECT_FALSE(hex.contains(o, 0.0, {0, -470}));
  // Bow-to-shoulder edge: at 1500 m ahead the starboard half-width is (1852-1500)/(1852-1111.2)*1111.2.
  const double w = (1852.0 - 1500.0) / (1852.0 - 1111.2) * 1111.2;
  EXPECT_TRUE(hex.contains(o, 0.0, {w - 1.0, 1500}));
  EXPECT_FALSE(hex.contains(o, 0.0, {w + 1.0, 1500}));
}

TEST(HexagonDomain, RotatesWithCourse) {
  const HexagonDomain hex;
  const Eigen::Vector2d o(1000, -2000);
  // Heading east: the bow points east, starboard is south, port is north.
  const double east = degToRad(90.0);
  EXPECT_TRUE(hex.contains(o, east, o + Eigen::Vector2d(1800, 0)));
  EXPECT_FALSE(hex.contains(o, east, o + Eigen::Vector2d(0, 1000)));  // 1000 m to port > e
  EXPECT_TRUE(hex.contains(o, east, o + Eigen::Vector2d(0, -1000)));  // 1000 m to starboard < c
  const Polygon p = hex.polygon(o, east);
  ASSERT_EQ(p.size(), 6u);
  EXPECT_NEAR(p[0].x(), 1000 + 1852, 1e-9);  // bow vertex
  EXPECT_NEAR(p[0].y(), -2000, 1e-9);
  EXPECT_NEAR(p[3].x(), 1000 - 463, 1e-9);  // stern vertex
}

TEST(HexagonDomain, RejectsBadConfig) {
  HexagonDomainConfig cfg;
  cfg.c = -1;
  EXPECT_THROW(HexagonDomain{cfg}, std::invalid_argument);
  cfg = {};
  cfg.b = cfg.a;
  EXPECT_THROW(cfg.validate(), std::invalid_argument);
}

TEST(WuDomain, Eq9AndEq8AtHandPoints) {
  EXPECT_NEAR(wuDomainNm(0.0), 0.85, 1e-12);
  EXPECT_NEAR(wuDomainNm(90.0), 0.85 - 0.1, 1e-12);
  EXPECT_NEAR(wuDomainNm(180.0), 1.18 - 0.73, 1e-12);
  EXPECT_NEAR(wuDomainNm(200.0), 1.02 - 160.0 / 180.0 * 0.57, 1e-12);
  EXPECT_NEAR(wuDomainNm(300.0), 0.85 - 60.0 / 180.0 * 0.3, 1e-12);
  EXPECT_NEAR(wuDomainNm(-60.0), wuDomainNm(300.0), 1e-12);
  EXPECT_DOUBLE_EQ(wuDomainStepNm(45.0), 0.85);
  EXPECT_DOUBLE_EQ(wuDomainStepNm(180.0), 0.45);
  EXPECT_DOUBLE_EQ(wuDomainStepNm(300.0), 0.70);
}

TEST(WuDomain, RhoAndSafeEncounterDistances) {
  EXPECT_NEAR(wuRhoNm(0.0), 1.1, 1e-12);
  EXPECT_NEAR(wuRhoNm(90.0), 1.0, 1e-12);
  EXPECT_NEAR(wuRhoNm(180.0), 0.6, 1e-12);
  EXPECT_NEAR(wuRhoNm(270.0), 1.1 - 0.2, 1e-12);
  SafeEncounterConfig cfg;
  cfg.turn90_time_s = 60.0;
  cfg.advance_m = 450.0;
  const SafeEncounter s = wuSafeEncounter(degToRad(90.0), 5.0, cfg);
  EXPECT_NEAR(s.rho_m, 1852.0, 1e-9);
  EXPECT_NEAR(s.d1_m, 1.5 * 1852.0, 1e-9);          // eq. (10)
  EXPECT_NEAR(s.td_m, 5.0 * 60.0 + 450.0, 1e-9);    // Td = V_T t + Ad
  EXPECT_NEAR(s.d2_m, 1.5 * 1852.0 + 750.0, 1e-9);  // eq. (11)
  cfg.domain_unit_m = 100.0;                        // a small craft scales the domain
  EXPECT_NEAR(wuSafeEncounter(0.0, 0.0, cfg).d1_m, 1.5 * 1.1 * 100.0, 1e-9);
  cfg.advance_m = -1;
  EXPECT_THROW(cfg.validate(), std::invalid_argument);
}

// Kijima and Nakiri (2003), worked with a calculator from the formulas in domain.h: 94 m at 10 kn,
// log10 V = 1: k_AD = 10^0.4543 = 2.8466, k_DT = 10^0.4646 = 2.9150, sqrt(k_AD^2 + (k_DT/2)^2) = 3.1985:
// fore 5.2860 L = 496.8 m, aft 3.1430 L = 295.4 m, starboard 3.1150 L = 292.8 m, port 2.3863 L = 224.3 m.
TEST(KijimaDomain, LengthAndSpeedScaleIt) {
  const asv::KijimaDomain d = asv::kijimaDomain(94.0, 10.0 * 1852.0 / 3600.0);
  EXPECT_NEAR(d.fore, 496.8, 0.1);
  EXPECT_NEAR(d.aft, 295.4, 0.1);
  EXPECT_NEAR(d.starboard, 292.8, 0.1);
  EXPECT_NEAR(d.port, 224.3, 0.1);
  // Linear in the length; a stopped ship counts as making 1 kn (k_AD = 10^0.0952, k_DT = 10^-0.0795):
  // 50 m: fore 138.0, starboard 51.6 m.
  const asv::KijimaDomain half = asv::kijimaDomain(47.0, 10.0 * 1852.0 / 3600.0);
  EXPECT_NEAR(half.fore, d.fore / 2.0, 1e-9);
  const asv::KijimaDomain still = asv::kijimaDomain(50.0, 0.0);
  EXPECT_NEAR(still.fore, 138.0, 0.1);
  EXPECT_NEAR(still.starboard, 51.6, 0.1);
}
