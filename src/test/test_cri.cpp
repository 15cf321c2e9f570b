#include <gtest/gtest.h>

#include "asv_core/risk/cri.h"

using namespace asv;

namespace {
ShipState ship(double x, double y, double course_deg, double speed) {
  ShipState s;
  s.position = {x, y};
  s.course = s.heading = degToRad(course_deg);
  s.speed = speed;
  return s;
}
}  // namespace

TEST(CriMembership, DcpaBreakpointsAndMonotonicity) {
  EXPECT_DOUBLE_EQ(criUDcpa(100.0, 1000.0, 3000.0), 1.0);
  EXPECT_DOUBLE_EQ(criUDcpa(1000.0, 1000.0, 3000.0), 1.0);
  EXPECT_NEAR(criUDcpa(2000.0, 1000.0, 3000.0), 0.5, 1e-12);  // the sine's midpoint
  EXPECT_NEAR(criUDcpa(3000.0, 1000.0, 3000.0), 0.0, 1e-12);
  EXPECT_NEAR(criUDcpa(1500.0, 1000.0, 3000.0), 0.5 - 0.5 * std::sin(-kPi / 4), 1e-12);
  double prev = 1.0;
  for (double d = 1000.0; d <= 3100.0; d += 10.0) {
    EXPECT_LE(criUDcpa(d, 1000.0, 3000.0), prev + 1e-12);
    prev = criUDcpa(d, 1000.0, 3000.0);
  }
}

TEST(CriMembership, TcpaBreakpointsAndSymmetry) {
  EXPECT_DOUBLE_EQ(criUTcpa(100.0, 300.0, 900.0), 1.0);
  EXPECT_DOUBLE_EQ(criUTcpa(300.0, 300.0, 900.0), 1.0);
  EXPECT_NEAR(criUTcpa(600.0, 300.0, 900.0), 0.5, 1e-12);
  EXPECT_NEAR(criUTcpa(-600.0, 300.0, 900.0), 0.5, 1e-12);  // |TCPA|
  EXPECT_DOUBLE_EQ(criUTcpa(901.0, 300.0, 900.0), 0.0);
  // t1 and t2 of eq. (3): DCPA 0, D1 = 1852, relative speed 10 m/s -> t1 = 185.2 s, t2 = 12 nm / 10.
  CriConfig cfg;
  double t1, t2;
  criTcpaBreakpoints(0.0, 5000.0, 10.0, cfg, t1, t2);
  EXPECT_NEAR(t1, 185.2, 1e-9);
  EXPECT_NEAR(t2, 12 * 185.2, 1e-9);
  // DCPA beyond D1: t1 = (D1 - DCPA) / V_r (continuous at DCPA = D1; see cri.cpp).
  criTcpaBreakpoints(3000.0, 8000.0, 10.0, cfg, t1, t2);
  EXPECT_NEAR(t1, (1852.0 - 3000.0) / 10.0, 1e-9);
  EXPECT_NEAR(criUTcpa(0.0, t1, t2), 1.0 * (t2 - 0.0) / (t2 - t1), 1e-12);
  EXPECT_NEAR(t2, std::sqrt(22224.0 * 22224.0 - 9e6) / 10.0, 1e-9);
}

TEST(CriMembership, BearingPeaksAt19AndVanishesAt199) {
  CriConfig cfg;
  EXPECT_NEAR(criUBearing(degToRad(19.0), cfg), 1.0, 1e-12);
  EXPECT_NEAR(criUBearing(degToRad(199.0), cfg), 0.0, 1e-12);
  // At 109 deg cos = 0: U = 0.5 sqrt(440/289) - 5/17.
  EXPECT_NEAR(criUBearing(degToRad(109.0), cfg), 0.5 * std::sqrt(440.0 / 289.0) - 5.0 / 17.0, 1e-12);
  // Starboard targets weigh more than port targets at the same angle off the bow (the paper's remark).
  EXPECT_GT(criUBearing(degToRad(60.0), cfg), criUBearing(degToRad(300.0), cfg));
}

// Wu et al. (2022) eq. (3) and (4) exactly as printed (CriConfig::as_printed, the GA's paper mode), by
// hand: beyond D1, t1 = (D - DCPA) / V_r = (8000 - 3000) / 10 = 500 s; U_B = 0.5 (cos(theta - 19 deg) +
// sqrt(C_B + cos^2)) with C_B = 440/289: 0.5 (1 + 1.58823...) = 1.29412 at 19 deg, 0.5 (-1 + 1.58823)
// = 0.29412 at 199 deg, 0.5 sqrt(440/289) = 0.61695 at 109 deg.
TEST(CriMembership, Eq3And4AsPrinted) {
  CriConfig cfg;
  cfg.as_printed = true;
  double t1, t2;
  criTcpaBreakpoints(3000.0, 8000.0, 10.0, cfg, t1, t2);
  EXPECT_NEAR(t1, 500.0, 1e-9);
  criTcpaBreakpoints(0.0, 5000.0, 10.0, cfg, t1, t2);  // inside D1 both forms agree
  EXPECT_NEAR(t1, 185.2, 1e-9);
  const double root = std::sqrt(440.0 / 289.0 + 1.0);
  EXPECT_NEAR(root, 1.588235, 1e-6);
  EXPECT_NEAR(criUBearing(degToRad(19.0), cfg), 0.5 * (1.0 + root), 1e-12);
  EXPECT_NEAR(criUBearing(degToRad(199.0), cfg), 0.5 * (root - 1.0), 1e-12);
  EXPECT_NEAR(criUBearing(degToRad(109.0), cfg), 0.5 * std::sqrt(440.0 / 289.0), 1e-12);
  EXPECT_NEAR(criUBearing(degToRad(19.0), cfg), 1.294118, 1e-6);
}

TEST(CriMembership, DistanceAndSpeedRatio) {
  CriConfig cfg;
  cfg.dlma_m = 1000.0;
  EXPECT_DOUBLE_EQ(criUDistance(500.0, cfg), 1.0);
  EXPECT_NEAR(criUDistance(1500.0, cfg), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(criUDistance(2000.0, cfg), 0.0);
  EXPECT_DOUBLE_EQ(criUDistance(2500.0, cfg), 0.0);
  // K = 1, crossing at 90 deg: 1 / (1 + 2 / (sqrt(2) + 2)).
  EXPECT_NEAR(criUSpeedRatio(1.0, degToRad(90.0), cfg), 1.0 / (1.0 + 2.0 / (std::sqrt(2.0) + 2.0)), 1e-12);
  // K = 1 on reciprocal courses: sin C = 0.
  EXPECT_NEAR(criUSpeedRatio(1.0, degToRad(180.0), cfg), 1.0 / (1.0 + 2.0 / std::sqrt(2.0)), 1e-12);
  EXPECT_DOUBLE_EQ(criUSpeedRatio(0.0, 0.3, cfg), 0.0);  // target stopped
  double prev = 0.0;
  for (double k = 0.1; k < 5.0; k += 0.1) {  // faster targets are more dangerous
    const double u = criUSpeedRatio(k, 0.5, cfg);
    EXPECT_GT(u, prev);
    prev = u;
  }
}

TEST(Cri, HeadOnAtOneMileByHand) {
  // Own north at 10 m/s, target 1 nm ahead heading south at 10 m/s. DCPA 0 -> U_DCPA 1; TCPA 92.6 s
  // = t1 -> U_TCPA 1; U_D(D1) = 1; U_B(0 deg) and U_K(K=1, C=180) by hand:
  const double cos19 = std::cos(degToRad(19.0));
  const double u_b = 0.5 * (cos19 + std::sqrt(440.0 / 289.0 + cos19 * cos19)) - 5.0 / 17.0;
  const double u_k = 1.0 / (1.0 + 2.0 / std::sqrt(2.0));
  const double expected = 0.40 + 0.367 + 0.033 * u_b + 0.167 + 0.033 * u_k;
  EXPECT_NEAR(expected, 0.979214, 1e-5);  // the same sum evaluated on a calculator
  const ShipState own = ship(0, 0, 0, 10), tgt = ship(0, 1852, 180, 10);
  const CriResult r = computeCri(own, tgt, computeCpa(own, tgt), CriConfig{});
  EXPECT_NEAR(r.u_dcpa, 1.0, 1e-12);
  EXPECT_NEAR(r.u_tcpa, 1.0, 1e-9);
  EXPECT_NEAR(r.u_b, u_b, 1e-12);
  EXPECT_NEAR(r.u_d, 1.0, 1e-12);
  EXPECT_NEAR(r.u_k, u_k, 1e-12);
  EXPECT_NEAR(r.cri, expected, 1e-9);
}

TEST(Cri, FallsAsTheTargetPassesWiderAndIsZeroWhenDiverging) {
  const ShipState own = ship(0, 0, 0, 8);
  double prev = 2.0;
  for (double offset = 0.0; offset <= 8000.0; offset += 500.0) {
    const ShipState tgt = ship(offset, 9000, 180, 8);
    const double cri = computeCri(own, tgt, computeCpa(own, tgt), CriConfig{}).cri;
    EXPECT_LE(cri, prev + 1e-12) << offset;
    EXPECT_GE(cri, 0.0);
    EXPECT_LE(cri, 1.0);
    prev = cri;
  }
  const ShipState gone = ship(0, -500, 180, 8);
  EXPECT_DOUBLE_EQ(computeCri(own, gone, computeCpa(own, gone), CriConfig{}).cri, 0.0);
}

TEST(Cri, ParallelSameSpeedIsFiniteAndOwnStoppedIsFinite) {
  const ShipState own = ship(0, 0, 0, 8), tgt = ship(300, 0, 0, 8);
  const CriResult r = computeCri(own, tgt, computeCpa(own, tgt), CriConfig{});
  EXPECT_TRUE(std::isfinite(r.cri) && std::isfinite(r.t1) && std::isfinite(r.t2));
  const ShipState still = ship(0, 0, 0, 0), mover = ship(0, 3000, 180, 5);
  const CriResult s = computeCri(still, mover, computeCpa(still, mover), CriConfig{});
  EXPECT_TRUE(std::isfinite(s.cri) && std::isfinite(s.speed_ratio));
  EXPECT_DOUBLE_EQ(s.u_k, 1.0);
}

TEST(Cri, ConfigValidation) {
  CriConfig cfg;
  EXPECT_NO_THROW(cfg.validate());
  cfg.c_dcpa = 0.5;  // weights no longer sum to 1
  EXPECT_THROW(cfg.validate(), std::invalid_argument);
  cfg = {};
  cfg.dlma_m = std::nan("");
  EXPECT_THROW(cfg.validate(), std::invalid_argument);
}
