// Autopilot for the simulated ships: heading PID with rudder angle and rate limits, speed controller
// (feed-forward from the model's steady-speed map plus PI on the surge error), and line-of-sight (LOS)
// waypoint guidance (Fossen 2011, Handbook of Marine Craft Hydrodynamics and Motion Control, ch. 10
// and 12). Works for both models: it fills the rudder/propeller fields for the 3-DOF model and the
// course/speed fields for the kinematic one.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "asv_core/sim/vessel_model.h"

namespace asv {

struct HeadingControllerConfig {
  double kp = 1.0;                            // [rad rudder / rad heading error]
  double ki = 0.005;                          // [rad rudder / (rad s)]
  double kd = 20.0;                           // [rad rudder / (rad/s) yaw rate], on the measured yaw rate
  double rudder_limit = degToRad(35.0);       // [rad] largest commanded rudder angle
  double rudder_rate_limit = degToRad(2.32);  // [rad/s] steering gear rate; SOLAS II-1 reg. 29: 35 deg
                                              // one side to 30 deg the other in 28 s
  double integral_limit = degToRad(10.0);     // [rad] largest rudder contribution of the integral term
  double integral_zone = degToRad(5.0);       // [rad] the integral only accumulates while |error| is below
                                              // this, so a large course change does not wind it up
  void validate() const;
};

struct SpeedControllerConfig {
  double kp = 1.0;              // [(rev/s) / (m/s)] on the surge-speed error, on top of the feed-forward
  double ki = 0.02;             // [(rev/s) / m]
  double integral_limit = 2.0;  // [rev/s] largest contribution of the integral term
  void validate() const;
};

struct LosConfig {
  double lookahead = 300.0;          // [m] Delta: desired course = path course - atan(e / Delta);
                                     // Fossen (2011) suggests 2-5 ship lengths (300 m for ~100 m)
  double acceptance_radius = 200.0;  // [m] a waypoint counts as reached inside this circle
  void validate() const;
};

struct AutopilotConfig {
  HeadingControllerConfig heading;
  SpeedControllerConfig speed;
  LosConfig los;
  void validate() const;
};

// Steady calm-water propeller revolutions as a function of surge speed, tabulated once (no allocation)
// from the model for the speed controller's feed-forward; linear interpolation, linear extrapolation
// beyond the table's last speed.
class SpeedFeedForward {
public:
  static constexpr int kPoints = 33;
  SpeedFeedForward() { rps_.fill(0.0); }
  static SpeedFeedForward fromModel(const Mmg3DofModel& model);
  double operator()(double speed) const;  // [rev/s] for speed [m/s]; 0 for speed <= 0
  double maxSpeed() const { return u_max_; }

private:
  double u_max_ = 1.0;
  std::array<double, kPoints> rps_;
};

// How tuneAutopilot picks gains from the model.
struct AutopilotTuning {
  double omega_n_nd = 0.5;  // [-] heading loop natural frequency times L / U (Froude-scaled bandwidth)
  double zeta = 1.0;        // [-] heading loop damping ratio (1: no overshoot in the linear loop)
  // [rad/s] steering gear rate; <= 0 picks SOLAS's 2.32 deg/s Froude-scaled to the ship's length,
  // 2.32 sqrt(100 m / L) deg/s, capped at 15 deg/s (small craft have faster steering).
  double rudder_rate = 0.0;
  void validate() const;
};

// Heading gains by pole placement on the first-order Nomoto model linearised at the nominal revolutions
// (Fossen 2011, sec. 12.2.3): kp = T w^2 / K, kd = (2 zeta w T - 1) / K, ki = w kp / 10; speed gains
// scaled by n_nominal / steady_speed; LOS lookahead 3 L and acceptance radius 2 L.
AutopilotConfig tuneAutopilot(const Mmg3DofModel& model, const AutopilotTuning& tuning = {});

class Autopilot {
public:
  enum class Mode { kCourseSpeed, kWaypoints };

  Autopilot(const AutopilotConfig& cfg, const SpeedFeedForward& ff);

  // Hold a heading [rad, nautical] and surge speed [m/s].
  void setCourseSpeed(double course, double speed);
  // Follow waypoints (ENU [m]) at `speed` [m/s] by LOS guidance; the first leg starts where the ship is at
  // the next update(). Allocates (copies the list); update() never does.
  void setWaypoints(const std::vector<Eigen::Vector2d>& waypoints, double speed);

  // One control step of dt [s]: returns rudder and revolutions (for the 3-DOF model) and the course and
  // speed set-points (for the kinematic model).
  VesselInput update(const VesselState& state, double dt);

  Mode mode() const { return mode_; }
  double courseSetPoint() const { return course_sp_; }  // [rad] current desired heading
  double speedSetPoint() const { return speed_sp_; }    // [m/s]
  bool finished() const { return finished_; }           // last waypoint reached (waypoint mode)
  std::size_t activeWaypoint() const { return wp_index_; }
  double crossTrackError() const { return cross_track_; }  // [m] positive: ship to starboard of the leg
  double rudder() const { return rudder_; }                // [rad] last rudder command
  const AutopilotConfig& config() const { return cfg_; }
  void reset();  // clears integrators and the rudder; keeps the set-points

private:
  void guidance(const VesselState& s);

  AutopilotConfig cfg_;
  SpeedFeedForward ff_;
  Mode mode_ = Mode::kCourseSpeed;
  double course_sp_ = 0.0;
  double speed_sp_ = 0.0;
  std::vector<Eigen::Vector2d> waypoints_;
  std::size_t wp_index_ = 0;
  Eigen::Vector2d leg_start_ = Eigen::Vector2d::Zero();
  bool leg_start_pending_ = false;
  bool finished_ = false;
  double cross_track_ = 0.0;
  double heading_integral_ = 0.0;  // [rad s]
  double speed_integral_ = 0.0;    // [m]
  double rudder_ = 0.0;            // [rad]
};

}  // namespace asv
