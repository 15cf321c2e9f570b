// Autopilot tests on the 3-DOF presets: heading steps without overshoot, speed changes, limits, LOS.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "asv_core/sim/autopilot.h"

using namespace asv;

namespace {

const std::string kPresetDir = std::string(ASV_SOURCE_DIR) + "/src/config/vessels";
const char* kPresets[] = {"wu_asv_40m", "small_asv", "merchant"};

struct Rig {
  explicit Rig(const std::string& name)
      : model(loadVesselPreset(name, kPresetDir)),
        pilot(tuneAutopilot(model), SpeedFeedForward::fromModel(model)) {
    VesselState s;
    s.u = model.params().steady_speed;
    model.setState(s);
  }
  Mmg3DofModel model;
  Autopilot pilot;
};

constexpr double kDt = 0.1;

}  // namespace

// Stated overshoot bound: 2 deg for any heading change up to 90 deg; settled within 0.5 deg after 40
// ship lengths of travel.
TEST(Autopilot, HeadingStepWithoutOvershoot) {
  for (const char* name : kPresets) {
    for (double change_deg : {30.0, -90.0}) {
      Rig rig(name);
      const auto& p = rig.model.params();
      rig.pilot.setCourseSpeed(degToRad(change_deg), p.steady_speed);
      double overshoot = 0.0;
      const double t_end = 40.0 * p.L / p.steady_speed;
      for (double t = 0.0; t < t_end; t += kDt) {
        rig.model.step(rig.pilot.update(rig.model.state(), kDt), Environment{}, kDt);
        const double h = radToDeg(wrapPi(rig.model.state().psi));
        overshoot = std::max(overshoot, change_deg > 0 ? h - change_deg : change_deg - h);
      }
      EXPECT_LT(overshoot, 2.0) << name << " change " << change_deg;
      EXPECT_NEAR(radToDeg(wrapPi(rig.model.state().psi)), change_deg, 0.5) << name;
      EXPECT_NEAR(rig.model.state().u, p.steady_speed, 0.02 * p.steady_speed) << name;
    }
  }
}

TEST(Autopilot, RudderRespectsAngleAndRateLimits) {
  Rig rig("wu_asv_40m");
  const auto& hc = rig.pilot.config().heading;
  rig.pilot.setCourseSpeed(degToRad(170.0), rig.model.params().steady_speed);
  double prev = 0.0, peak = 0.0;
  for (int i = 0; i < 3000; ++i) {
    const VesselInput in = rig.pilot.update(rig.model.state(), kDt);
    ASSERT_LE(std::abs(in.rudder), hc.rudder_limit + 1e-12);
    ASSERT_LE(std::abs(in.rudder - prev), hc.rudder_rate_limit * kDt + 1e-12);
    peak = std::max(peak, std::abs(in.rudder));
    prev = in.rudder;
    rig.model.step(in, Environment{}, kDt);
  }
  EXPECT_GT(peak, degToRad(20.0));  // a 170 deg change is taken with a hard turn
}

TEST(Autopilot, SpeedSetPointIsReached) {
  for (const char* name : kPresets) {
    Rig rig(name);
    const auto& p = rig.model.params();
    const double target = 0.6 * p.steady_speed;
    rig.pilot.setCourseSpeed(0.0, target);
    const double t_end = 400.0 * p.L / p.steady_speed;
    for (double t = 0.0; t < t_end; t += kDt)
      rig.model.step(rig.pilot.update(rig.model.state(), kDt), Environment{}, kDt);
    EXPECT_NEAR(rig.model.state().u, target, 0.01 * target) << name;
  }
}

TEST(Autopilot, HoldsHeadingInWind) {
  Rig rig("wu_asv_40m");
  const auto& p = rig.model.params();
  Environment env;
  env.wind_speed = 15.0;
  env.wind_direction = degToRad(70.0);
  rig.pilot.setCourseSpeed(0.0, p.steady_speed);
  for (double t = 0.0; t < 1200.0; t += kDt)
    rig.model.step(rig.pilot.update(rig.model.state(), kDt), env, kDt);
  // The integral term removes the steady heading error the weather helm would leave.
  EXPECT_NEAR(radToDeg(wrapPi(rig.model.state().psi)), 0.0, 0.2);
}

TEST(Autopilot, LosGuidanceReachesWaypoints) {
  for (const char* name : kPresets) {
    Rig rig(name);
    const auto& p = rig.model.params();
    const double L = p.L;
    const std::vector<Eigen::Vector2d> wps = {{10.0 * L, 10.0 * L}, {20.0 * L, 5.0 * L}};
    rig.pilot.setWaypoints(wps, p.steady_speed);
    double t = 0.0;
    std::size_t max_index = 0;
    for (; t < 200.0 * L / p.steady_speed && !rig.pilot.finished(); t += kDt) {
      rig.model.step(rig.pilot.update(rig.model.state(), kDt), Environment{}, kDt);
      max_index = std::max(max_index, rig.pilot.activeWaypoint());
    }
    EXPECT_TRUE(rig.pilot.finished()) << name;
    EXPECT_EQ(max_index, 1u) << name;
    EXPECT_LE((rig.model.state().position() - wps.back()).norm(),
              rig.pilot.config().los.acceptance_radius + 1e-9)
        << name;
  }
}

TEST(Autopilot, LosConvergesOntoTheLeg) {
  Rig rig("wu_asv_40m");
  const auto& p = rig.model.params();
  VesselState s;
  s.y = 5.0 * p.L;  // 5 L north of a leg that runs east along y = 0
  s.u = p.steady_speed;
  rig.model.setState(s);
  // Set the leg explicitly: the first waypoint is the leg's start, reached at once.
  rig.pilot.setWaypoints({{0.0, 5.0 * p.L}, {0.0, 0.0}, {1000.0 * p.L, 0.0}}, p.steady_speed);
  for (double t = 0.0; t < 150.0 * p.L / p.steady_speed; t += kDt)
    rig.model.step(rig.pilot.update(rig.model.state(), kDt), Environment{}, kDt);
  EXPECT_FALSE(rig.pilot.finished());
  EXPECT_EQ(rig.pilot.activeWaypoint(), 2u);
  EXPECT_LT(std::abs(rig.model.state().y), 0.05 * p.L);
  EXPECT_LT(std::abs(rig.pilot.crossTrackError()), 0.05 * p.L);
}

TEST(Autopilot, DrivesTheKinematicModelBySetPoints) {
  KinematicModel m;
  VesselState s;
  s.u = 5.0;
  m.setState(s);
  Autopilot pilot(AutopilotConfig{}, SpeedFeedForward{});
  pilot.setWaypoints({{0.0, 2000.0}, {2000.0, 2000.0}}, 5.0);
  for (int i = 0; i < 20000 && !pilot.finished(); ++i)
    m.step(pilot.update(m.state(), 1.0), Environment{}, 1.0);
  EXPECT_TRUE(pilot.finished());
  EXPECT_LE((m.state().position() - Eigen::Vector2d(2000.0, 2000.0)).norm(), 200.0 + 1e-9);
}

TEST(Autopilot, ConfigValidateNamesTheField) {
  AutopilotConfig cfg;
  cfg.heading.rudder_rate_limit = 0.0;
  try {
    cfg.validate();
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("heading.rudder_rate_limit"), std::string::npos);
  }
  cfg = AutopilotConfig{};
  cfg.los.lookahead = NAN;
  EXPECT_THROW(cfg.validate(), std::invalid_argument);
  Autopilot pilot(AutopilotConfig{}, SpeedFeedForward{});
  EXPECT_THROW(pilot.setWaypoints({}, 1.0), std::invalid_argument);
  EXPECT_THROW(pilot.setCourseSpeed(0.0, -1.0), std::invalid_argument);
}
