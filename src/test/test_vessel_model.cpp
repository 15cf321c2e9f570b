// Tests of the vessel models: Lazarowska's kinematic model (eq. 4, 6) and the Wu et al. 3-DOF model
// (eq. 13-22), its presets and their loader. Expected values are computed here independently.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "asv_core/sim/vessel_model.h"

using namespace asv;

namespace {

const std::string kPresetDir = std::string(ASV_SOURCE_DIR) + "/src/config/vessels";
const char* kPresets[] = {"wu_asv_40m", "small_asv", "merchant"};

Mmg3DofParams preset(const std::string& name) {
  return loadVesselPreset(name, kPresetDir);
}

// Time step for the preset tests: 0.1 s for the small craft, longer for big ships (Froude scaling keeps
// the step a similar fraction of the ship's time constants).
double stepFor(const Mmg3DofParams& p) {
  return 0.1 * std::max(1.0, std::sqrt(p.L / 40.3));
}

// Steady straight run at the nominal revolutions by integration from a slow start.
Mmg3DofModel steadyModel(const Mmg3DofParams& p) {
  Mmg3DofModel m(p);
  VesselState s;
  s.u = 0.5 * p.steady_speed;
  m.setState(s);
  VesselInput in;
  in.propeller_rps = p.n_nominal;
  const double dt = stepFor(p);
  // 400 ship lengths: the surge time constant (m + m_x) / (dR/du) is a few tens of lengths of travel.
  const double t_end = 400.0 * p.L / p.steady_speed;
  for (double t = 0.0; t < t_end; t += dt)
    m.step(in, Environment{}, dt);
  return m;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// Kinematic model.

TEST(KinematicModel, MatchesEquation4ClosedForm) {
  KinematicParams kp;
  kp.omega = degToRad(2.0);
  kp.t01 = 10.0;
  for (double dpsi_deg : {60.0, -75.0}) {
    KinematicModel m(kp);
    VesselState s0;
    s0.x = 100.0;
    s0.y = -50.0;
    s0.psi = degToRad(30.0);
    m.setState(s0);
    const double V = 5.0, psi0 = s0.psi, dpsi = degToRad(dpsi_deg);
    const double w = dpsi > 0 ? kp.omega : -kp.omega;
    const double t_turn = std::abs(dpsi) / kp.omega;
    VesselInput in;
    in.course = psi0 + dpsi;
    in.speed = V;
    // Eq. (4) integrated by hand: straight for t01, arc at +-omega, straight on the new course.
    auto closed = [&](double t) {
      Eigen::Vector3d q;  // x, y, psi
      const double t1 = std::min(t, kp.t01);
      double x = s0.x + V * t1 * std::sin(psi0), y = s0.y + V * t1 * std::cos(psi0), psi = psi0;
      if (t > kp.t01) {
        const double ta = std::min(t - kp.t01, t_turn);
        const double psi1 = psi0 + w * ta;
        x += V / w * (std::cos(psi0) - std::cos(psi1));
        y += V / w * (std::sin(psi1) - std::sin(psi0));
        psi = psi1;
        if (t > kp.t01 + t_turn) {
          const double ts = t - kp.t01 - t_turn;
          x += V * ts * std::sin(psi);
          y += V * ts * std::cos(psi);
        }
      }
      q << x, y, psi;
      return q;
    };
    const double dt = 0.37;  // deliberately not a divisor of t01 or of the turn time
    double t = 0.0;
    for (int i = 0; i < 300; ++i) {
      m.step(in, Environment{}, dt);
      t += dt;
      const Eigen::Vector3d q = closed(t);
      ASSERT_NEAR(m.state().x, q(0), 1e-9) << "t=" << t;
      ASSERT_NEAR(m.state().y, q(1), 1e-9) << "t=" << t;
      ASSERT_NEAR(wrapPi(m.state().psi - q(2)), 0.0, 1e-12) << "t=" << t;
      // Course and speed over ground are those of eq. (4): V along the heading.
      ASSERT_NEAR(m.speedOverGround(), V, 1e-12);
      ASSERT_NEAR(wrapPi(m.courseOverGround() - q(2)), 0.0, 1e-9);
    }
    EXPECT_NEAR(wrapPi(m.state().psi - (psi0 + dpsi)), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(m.state().r, 0.0);
  }
}

TEST(KinematicModel, ManoeuvreTimeEquation6) {
  KinematicParams kp;
  kp.omega = degToRad(1.5);
  kp.t01 = 12.0;
  KinematicModel m(kp);
  for (double dpsi_deg : {5.0, 30.0, 90.0}) {
    const double a = degToRad(dpsi_deg);
    const double expected = 12.0 + a / kp.omega - std::tan(a / 2.0) / kp.omega;
    EXPECT_NEAR(m.manoeuvreTime(a), expected, 1e-12);
    EXPECT_NEAR(m.manoeuvreTime(-a), expected, 1e-12);
    // The line-segment approximation turns no later than the real ship finishes its turn.
    EXPECT_LE(m.manoeuvreTime(a), m.turnCompletionTime(a));
  }
}

TEST(KinematicModel, RejectsBadParameters) {
  KinematicParams kp;
  kp.omega = 0.0;
  EXPECT_THROW(KinematicModel{kp}, std::invalid_argument);
  kp = KinematicParams{};
  kp.t01 = std::nan("");
  EXPECT_THROW(KinematicModel{kp}, std::invalid_argument);
}

TEST(KinematicModel, PointModelTakesTheCommandedCourseAndSpeedAtOnce) {
  // Hirayama et al. Fig. 1: each step a ship moves straight along her new intention. From the origin
  // heading north at 10 m/s, a command of 090 at 20 m/s moves her (20, 0) in one second, not along an arc.
  KinematicParams kp;
  kp.instant = true;
  KinematicModel m(kp);
  VesselState st;
  st.u = 10.0;
  m.setState(st);
  VesselInput in;
  in.course = degToRad(90.0);
  in.speed = 20.0;
  m.step(in, Environment{}, 1.0);
  EXPECT_NEAR(m.state().x, 20.0, 1e-12);
  EXPECT_NEAR(m.state().y, 0.0, 1e-12);
  EXPECT_NEAR(m.state().psi, degToRad(90.0), 1e-12);
  EXPECT_NEAR(m.speedOverGround(), 20.0, 1e-12);
  // Back to 000 at 5 m/s for 2 s in 0.5 s steps: (20, 10).
  in.course = 0.0;
  in.speed = 5.0;
  for (int i = 0; i < 4; ++i)
    m.step(in, Environment{}, 0.5);
  EXPECT_NEAR(m.state().x, 20.0, 1e-12);
  EXPECT_NEAR(m.state().y, 10.0, 1e-12);
}

// ---------------------------------------------------------------------------------------------------
// 3-DOF model.

TEST(Mmg3DofModel, ShipAtRestStaysExactlyAtRest) {
  for (const char* name : kPresets) {
    Mmg3DofModel m(preset(name));
    VesselState s;
    s.x = 12.5;
    s.y = -7.0;
    s.psi = 1.234;
    m.setState(s);
    for (int i = 0; i < 1000; ++i)
      m.step(VesselInput{}, Environment{}, 0.1);
    EXPECT_EQ(m.state().x, s.x) << name;
    EXPECT_EQ(m.state().y, s.y) << name;
    EXPECT_EQ(m.state().psi, s.psi) << name;
    EXPECT_EQ(m.state().u, 0.0) << name;
    EXPECT_EQ(m.state().v, 0.0) << name;
    EXPECT_EQ(m.state().r, 0.0) << name;
  }
}

TEST(Mmg3DofModel, SteadySpeedMatchesResistanceBalance) {
  for (const char* name : kPresets) {
    const Mmg3DofParams p = preset(name);
    // Independent balance: (1 - t_P) rho n^2 D^4 K_T(J) = 1/2 rho L d R'_0 u^2, J = u (1 - w_P0) / (n D).
    const double n = p.n_nominal, D = p.Dp;
    auto net = [&](double u) {
      const double J = u * (1.0 - p.wP0) / (n * D);
      const double KT = p.kt0 + p.kt1 * J + p.kt2 * J * J;
      return (1.0 - p.tP) * p.rho * n * n * std::pow(D, 4) * KT - 0.5 * p.rho * p.L * p.d * p.R0 * u * u;
    };
    double lo = 0.0, hi = 100.0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (net(mid) > 0.0 ? lo : hi) = mid;
    }
    const double u_balance = 0.5 * (lo + hi);
    const Mmg3DofModel m = steadyModel(p);
    EXPECT_NEAR(m.state().u, u_balance, 1e-4 * u_balance) << name;
    EXPECT_NEAR(m.state().v, 0.0, 1e-12) << name;
    EXPECT_NEAR(m.state().r, 0.0, 1e-12) << name;
    // The preset documents this speed (4 significant digits).
    EXPECT_NEAR(p.steady_speed, u_balance, 2e-4 * u_balance) << name;
    // And the closed-form feed-forward inverts the same balance.
    EXPECT_NEAR(Mmg3DofModel(p).steadyRpsForSpeed(u_balance), n, 1e-9 * n) << name;
  }
}

TEST(Mmg3DofModel, TurningCircleMatchesDocumentedTacticalDiameter) {
  for (const char* name : kPresets) {
    const Mmg3DofParams p = preset(name);
    Mmg3DofModel m = steadyModel(p);
    VesselState s = m.state();
    s.x = s.y = 0.0;
    s.psi = 0.0;  // heading north: the transfer of a starboard turn is the east coordinate
    m.setState(s);
    VesselInput in;
    in.propeller_rps = p.n_nominal;
    in.rudder = p.delta_max;
    const double dt = stepFor(p);
    double turned = 0.0, prev_psi = 0.0, prev_x = 0.0, tactical = NAN;
    for (int i = 0; i < 1000000 && std::isnan(tactical); ++i) {
      prev_x = m.state().x;
      m.step(in, Environment{}, dt);
      const double d = wrapPi(m.state().psi - prev_psi);
      prev_psi = m.state().psi;
      if (turned + d >= kPi) {
        // Tactical diameter: transfer when the heading has changed by 180 deg, interpolated in the step.
        const double f = (kPi - turned) / d;
        tactical = prev_x + f * (m.state().x - prev_x);
      }
      turned += d;
    }
    ASSERT_FALSE(std::isnan(tactical)) << name;
    std::printf("[ info ] %s: tactical diameter %.1f m (%.2f L), speed at 180 deg %.2f m/s\n", name, tactical,
                tactical / p.L, m.speedOverGround());
    // Tolerance 1 %: the documented value is rounded to 0.1 m (small craft) or 1 m.
    EXPECT_NEAR(tactical, p.tactical_diameter, 0.01 * p.tactical_diameter) << name;
    // Plausible hull: IMO MSC.137(76) asks for a tactical diameter below 5 L.
    EXPECT_GT(tactical, 1.0 * p.L) << name;
    EXPECT_LT(tactical, 5.0 * p.L) << name;
  }
}

TEST(Mmg3DofModel, Rk4ConvergesAtFourthOrder) {
  const Mmg3DofParams p = preset("wu_asv_40m");
  Environment env;
  env.wind_speed = 12.0;
  env.wind_direction = degToRad(60.0);
  env.wave_height = 1.5;
  env.wave_direction = degToRad(200.0);
  env.wave_length = 30.0;
  VesselState s0;
  s0.u = p.steady_speed;
  VesselInput in;
  in.propeller_rps = p.n_nominal;
  in.rudder = degToRad(20.0);
  const double t_end = 24.0;
  auto run = [&](double dt) {
    Mmg3DofModel m(p);
    m.setState(s0);
    const int n = static_cast<int>(std::lround(t_end / dt));
    for (int i = 0; i < n; ++i)
      m.step(in, env, dt);
    // psi stays well inside (0, pi) here, so wrapping does not disturb the comparison.
    return Mmg3DofModel::toVector(m.state());
  };
  const auto ref = run(0.4 / 128.0);
  const double e1 = (run(0.4) - ref).norm();
  const double e2 = (run(0.2) - ref).norm();
  const double ratio = e1 / e2;
  std::printf("[ info ] RK4 errors %.3e (dt 0.4) %.3e (dt 0.2), ratio %.2f\n", e1, e2, ratio);
  EXPECT_GT(ratio, 12.0);
  EXPECT_LT(ratio, 20.0);
}

TEST(Mmg3DofModel, StarboardRudderTurnsToStarboard) {
  const Mmg3DofParams p = preset("wu_asv_40m");
  Mmg3DofModel m(p);
  VesselState s;
  s.u = p.steady_speed;
  m.setState(s);
  VesselInput in;
  in.propeller_rps = p.n_nominal;
  in.rudder = degToRad(10.0);
  for (int i = 0; i < 100; ++i)
    m.step(in, Environment{}, 0.1);
  EXPECT_GT(m.state().r, 0.0);
  EXPECT_GT(m.state().x, 0.0);  // heading north, turning east
  EXPECT_LT(m.state().v, 0.0);  // drifts out of the turn (to port) at midship
}

TEST(Mmg3DofModel, WindAndWaveForcesHaveTheRightSigns) {
  const Mmg3DofParams p = preset("wu_asv_40m");
  Mmg3DofModel m(p);
  Mmg3DofModel::StateVector s = Mmg3DofModel::StateVector::Zero();  // at rest, heading north
  Environment env;
  env.wind_speed = 10.0;
  env.wind_direction = degToRad(90.0);  // from the east: on the starboard beam
  MmgForces f = m.forces(s, 0.0, 0.0, env);
  EXPECT_LT(f.wind(1), 0.0);  // pushed to port
  EXPECT_NEAR(f.wind(0), 0.0, 1e-9);
  EXPECT_NEAR(f.wind(1), -0.5 * p.rho_air * p.As * p.cy * 100.0, 1e-9);
  env.wind_direction = 0.0;  // head wind
  f = m.forces(s, 0.0, 0.0, env);
  EXPECT_NEAR(f.wind(0), -0.5 * p.rho_air * p.Af * p.cx * 100.0, 1e-9);

  Environment waves;
  waves.wave_height = 2.0;
  waves.wave_direction = kPi;  // from the south: following sea for a ship heading north
  waves.wave_length = 0.5 * p.L;
  f = m.forces(s, 0.0, 0.0, waves);
  const double x = 0.5;
  const double cxw = 0.05 - 0.2 * x + 0.75 * x * x - 0.51 * x * x * x;  // eq. (21)
  EXPECT_NEAR(f.wave(0), 0.5 * p.rho * p.g * p.L * 1.0 * cxw, 1e-6);    // eq. (20), xi_w = 1 m, chi = 0
  EXPECT_NEAR(f.wave(1), 0.0, 1e-6);
}

TEST(Mmg3DofModel, WaveDriftCoefficientsEquation21) {
  const Eigen::Vector3d c = waveDriftCoefficients(0.3);
  EXPECT_NEAR(c(0), 0.05 - 0.06 + 0.0675 - 0.01377, 1e-12);
  EXPECT_NEAR(c(1), 0.46 + 2.049 - 1.4004 + 0.22788, 1e-12);
  EXPECT_NEAR(c(2), -0.11 + 0.204 - 0.0711 + 0.00567, 1e-12);
  // Held beyond lambda / L = 1, where the cubic fits extrapolate.
  EXPECT_EQ(waveDriftCoefficients(3.0), waveDriftCoefficients(1.0));
}

TEST(Mmg3DofModel, WuPresetUsesEquation16Estimates) {
  const Mmg3DofParams p = preset("wu_asv_40m");
  const double Cp = 0.534;  // documented in the preset
  EXPECT_NEAR(p.tP, hankshireThrustDeduction(Cp), 1e-3);
  EXPECT_NEAR(p.wP0, hankshireWakeFraction(Cp), 1e-3);
  EXPECT_NEAR(p.wP_beta, 0.4, 1e-12);
  EXPECT_NEAR(p.L, 40.3, 1e-12);
  EXPECT_NEAR(p.B, 13.5, 1e-12);
  EXPECT_NEAR(p.d, 3.22, 1e-12);
  EXPECT_NEAR(p.mass, 766.4e3, 1e-6);
}

TEST(Mmg3DofModel, NomotoGainIsPositiveForStableHulls) {
  for (const char* name : {"wu_asv_40m", "small_asv"}) {
    const Mmg3DofParams p = preset(name);
    const NomotoParams nm = Mmg3DofModel(p).nomoto(p.n_nominal);
    EXPECT_GT(nm.K, 0.0) << name;
    EXPECT_GT(nm.T, 0.0) << name;
    EXPECT_NEAR(nm.speed, p.steady_speed, 2e-4 * p.steady_speed) << name;
  }
}

TEST(Mmg3DofModel, InputsAreClampedAndNonFiniteRejected) {
  const Mmg3DofParams p = preset("small_asv");
  Mmg3DofModel a(p), b(p);
  VesselState s;
  s.u = p.steady_speed;
  a.setState(s);
  b.setState(s);
  VesselInput big, full;
  big.rudder = 2.0;
  big.propeller_rps = 1e6;
  full.rudder = p.delta_max;
  full.propeller_rps = p.n_max;
  a.step(big, Environment{}, 0.1);
  b.step(full, Environment{}, 0.1);
  EXPECT_EQ(Mmg3DofModel::toVector(a.state()), Mmg3DofModel::toVector(b.state()));
  VesselInput bad;
  bad.rudder = NAN;
  EXPECT_THROW(a.step(bad, Environment{}, 0.1), std::invalid_argument);
  EXPECT_THROW(a.step(full, Environment{}, 0.0), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------------
// Preset loader.

namespace {

std::string readFile(const std::string& path) {
  std::ifstream f(path);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

// Writes `text` to a temporary preset file and returns the loader's error message ("" if it loaded).
std::string loadError(const std::string& text) {
  const std::string path = testing::TempDir() + "/asv_vessel_preset_test.yaml";
  std::ofstream(path) << text;
  try {
    loadVesselPreset(path);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

std::string replaceLine(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos)
    text.replace(pos, from.size(), to);
  return text;
}

int lineOf(const std::string& text, const std::string& needle) {
  const auto pos = text.find(needle);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + pos, '\n'));
}

}  // namespace

TEST(VesselPreset, LoadsAllPresetsByNameAndPath) {
  for (const char* name : kPresets) {
    const Mmg3DofParams p = loadVesselPreset(name, kPresetDir);
    EXPECT_EQ(p.name, name);
    const Mmg3DofParams q = loadVesselPreset(kPresetDir + "/" + name + ".yaml");
    EXPECT_EQ(q.L, p.L);
  }
  EXPECT_THROW(loadVesselPreset("no_such_ship", kPresetDir), std::runtime_error);
}

TEST(VesselPreset, RejectsUnknownMissingAndBadValues) {
  const std::string good = readFile(kPresetDir + "/small_asv.yaml");
  ASSERT_EQ(loadError(good), "");

  // Unknown key: file, line and key named.
  std::string text = replaceLine(good, "  Yv:", "  Yvx: 1.0\n  Yv:");
  std::string err = loadError(text);
  EXPECT_NE(err.find("asv_vessel_preset_test.yaml:" + std::to_string(lineOf(text, "  Yvx:"))),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("Yvx"), std::string::npos) << err;

  // Unknown top-level section.
  err = loadError(good + "extra: {a: 1}\n");
  EXPECT_NE(err.find("unknown key 'extra'"), std::string::npos) << err;

  // Missing key.
  text = replaceLine(good, "  kt2:", "  # kt2:");
  err = loadError(text);
  EXPECT_NE(err.find("missing key 'kt2'"), std::string::npos) << err;

  // Non-finite value, with the line.
  text = replaceLine(good, "  B: 1.7", "  B: .nan");
  err = loadError(text);
  EXPECT_NE(err.find(":" + std::to_string(lineOf(text, "  B: .nan")) + ":"), std::string::npos) << err;
  EXPECT_NE(err.find("B: must be"), std::string::npos) << err;

  // Out of range.
  text = replaceLine(good, "  delta_max_deg: 35.0", "  delta_max_deg: 80.0");
  err = loadError(text);
  EXPECT_NE(err.find("delta_max"), std::string::npos) << err;

  // Not a number.
  text = replaceLine(good, "  L: 5.0", "  L: five");
  err = loadError(text);
  EXPECT_NE(err.find("'L' must be a number"), std::string::npos) << err;
}

TEST(VesselPreset, ParamsValidateNamesTheField) {
  Mmg3DofParams p = preset("wu_asv_40m");
  p.kzz = -1.0;
  try {
    p.validate();
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("kzz"), std::string::npos);
  }
  Environment env;
  env.wave_height = 1.0;
  env.wave_length = 0.0;
  EXPECT_THROW(env.validate(), std::invalid_argument);
}
