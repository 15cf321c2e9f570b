// Autopilot: heading PID, speed feed-forward + PI, LOS waypoint guidance.
#include "asv_core/sim/autopilot.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace asv {

namespace {

void check(bool ok, const char* field, double v, const char* rule) {
  if (ok && std::isfinite(v))
    return;
  std::ostringstream os;
  os << field << ": must be " << rule << " (got " << v << ")";
  throw std::invalid_argument(os.str());
}

}  // namespace

void HeadingControllerConfig::validate() const {
  check(kp >= 0.0, "heading.kp", kp, ">= 0");
  check(ki >= 0.0, "heading.ki", ki, ">= 0");
  check(kd >= 0.0, "heading.kd", kd, ">= 0");
  check(rudder_limit > 0.0 && rudder_limit <= degToRad(60.0), "heading.rudder_limit", rudder_limit,
        "in (0, 60 deg]");
  check(rudder_rate_limit > 0.0, "heading.rudder_rate_limit", rudder_rate_limit, "> 0");
  check(integral_limit >= 0.0, "heading.integral_limit", integral_limit, ">= 0");
  check(integral_zone > 0.0, "heading.integral_zone", integral_zone, "> 0");
}

void SpeedControllerConfig::validate() const {
  check(kp >= 0.0, "speed.kp", kp, ">= 0");
  check(ki >= 0.0, "speed.ki", ki, ">= 0");
  check(integral_limit >= 0.0, "speed.integral_limit", integral_limit, ">= 0");
}

void LosConfig::validate() const {
  check(lookahead > 0.0, "los.lookahead", lookahead, "> 0");
  check(acceptance_radius > 0.0, "los.acceptance_radius", acceptance_radius, "> 0");
}

void AutopilotConfig::validate() const {
  heading.validate();
  speed.validate();
  los.validate();
}

void AutopilotTuning::validate() const {
  check(omega_n_nd > 0.0, "tuning.omega_n_nd", omega_n_nd, "> 0");
  check(zeta > 0.0, "tuning.zeta", zeta, "> 0");
  check(true, "tuning.rudder_rate", rudder_rate, "finite");
}

SpeedFeedForward SpeedFeedForward::fromModel(const Mmg3DofModel& model) {
  SpeedFeedForward ff;
  // Up to the speed the highest revolutions give, estimated from the nominal point (thrust ~ n^2, drag
  // ~ u^2 make u roughly proportional to n); extrapolation covers the rest.
  const auto& p = model.params();
  ff.u_max_ = p.steady_speed * p.n_max / p.n_nominal;
  for (int i = 0; i < kPoints; ++i)
    ff.rps_[i] = model.steadyRpsForSpeed(ff.u_max_ * i / (kPoints - 1));
  return ff;
}

double SpeedFeedForward::operator()(double speed) const {
  if (!(speed > 0.0))
    return 0.0;
  const double x = speed / u_max_ * (kPoints - 1);
  const int i = std::min(static_cast<int>(x), kPoints - 2);
  const double f = x - i;
  return rps_[i] + f * (rps_[i + 1] - rps_[i]);
}

AutopilotConfig tuneAutopilot(const Mmg3DofModel& model, const AutopilotTuning& tuning) {
  tuning.validate();
  const auto& p = model.params();
  const NomotoParams nm = model.nomoto(p.n_nominal);
  const double w = tuning.omega_n_nd * nm.speed / p.L;
  AutopilotConfig cfg;
  // psi/delta = K / (s (1 + T s)) closed with a PD: T s^2 + (1 + K kd) s + K kp, placed at w, zeta. For a
  // course-unstable hull K and T are both negative and the same formulas hold.
  cfg.heading.kp = nm.T * w * w / nm.K;
  cfg.heading.kd = std::max(0.0, (2.0 * tuning.zeta * w * nm.T - 1.0) / nm.K);
  cfg.heading.ki = w * cfg.heading.kp / 10.0;
  cfg.heading.rudder_limit = p.delta_max;
  cfg.heading.rudder_rate_limit = tuning.rudder_rate > 0.0
                                      ? tuning.rudder_rate
                                      : std::min(degToRad(15.0), degToRad(2.32) * std::sqrt(100.0 / p.L));
  const double gain = p.n_nominal / p.steady_speed;  // [(rev/s)/(m/s)]
  cfg.speed.kp = gain;
  // Integral time of ~10 ship lengths of travel: slow enough not to fight the surge dynamics.
  cfg.speed.ki = gain * p.steady_speed / (10.0 * p.L);
  cfg.speed.integral_limit = 0.3 * p.n_nominal;
  cfg.los.lookahead = 3.0 * p.L;
  cfg.los.acceptance_radius = 2.0 * p.L;
  cfg.validate();
  return cfg;
}

Autopilot::Autopilot(const AutopilotConfig& cfg, const SpeedFeedForward& ff) : cfg_(cfg), ff_(ff) {
  cfg_.validate();
}

void Autopilot::setCourseSpeed(double course, double speed) {
  if (!std::isfinite(course) || !std::isfinite(speed) || speed < 0.0)
    throw std::invalid_argument("Autopilot::setCourseSpeed: course finite, speed finite and >= 0");
  mode_ = Mode::kCourseSpeed;
  course_sp_ = wrapTwoPi(course);
  speed_sp_ = speed;
  finished_ = false;
}

void Autopilot::setWaypoints(const std::vector<Eigen::Vector2d>& waypoints, double speed) {
  if (waypoints.empty())
    throw std::invalid_argument("Autopilot::setWaypoints: empty waypoint list");
  for (const auto& w : waypoints)
    if (!w.allFinite())
      throw std::invalid_argument("Autopilot::setWaypoints: non-finite waypoint");
  if (!std::isfinite(speed) || speed < 0.0)
    throw std::invalid_argument("Autopilot::setWaypoints: speed finite and >= 0");
  mode_ = Mode::kWaypoints;
  waypoints_ = waypoints;
  wp_index_ = 0;
  speed_sp_ = speed;
  leg_start_pending_ = true;
  finished_ = false;
}

void Autopilot::reset() {
  heading_integral_ = 0.0;
  speed_integral_ = 0.0;
  rudder_ = 0.0;
}

void Autopilot::guidance(const VesselState& s) {
  const Eigen::Vector2d pos = s.position();
  if (leg_start_pending_) {
    leg_start_ = pos;
    leg_start_pending_ = false;
  }
  // Advance past every waypoint already inside the acceptance circle or whose leg has been overrun.
  while (!finished_) {
    const Eigen::Vector2d& wp = waypoints_[wp_index_];
    const Eigen::Vector2d leg = wp - leg_start_;
    const double len = leg.norm();
    const double along = len > 0.0 ? (pos - leg_start_).dot(leg) / len : 0.0;
    if ((pos - wp).norm() > cfg_.los.acceptance_radius && along < len)
      break;
    leg_start_ = wp;
    if (++wp_index_ >= waypoints_.size()) {
      wp_index_ = waypoints_.size() - 1;
      finished_ = true;
    }
  }
  if (finished_)
    return;  // keep the last course set-point
  const Eigen::Vector2d& wp = waypoints_[wp_index_];
  const Eigen::Vector2d leg = wp - leg_start_;
  const double alpha = leg.squaredNorm() > 0.0 ? courseOf(leg) : trueBearing(pos, wp);
  // Path frame: tangent (sin a, cos a), starboard normal (cos a, -sin a) in ENU.
  const Eigen::Vector2d rel = pos - leg_start_;
  cross_track_ = rel.x() * std::cos(alpha) - rel.y() * std::sin(alpha);
  // Lookahead-based LOS (Fossen 2011 eq. 10.73): steer back towards the leg, to port when to starboard.
  course_sp_ = wrapTwoPi(alpha - std::atan(cross_track_ / cfg_.los.lookahead));
}

VesselInput Autopilot::update(const VesselState& s, double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw std::invalid_argument("Autopilot::update: dt must be > 0");
  if (mode_ == Mode::kWaypoints)
    guidance(s);

  // Heading: PID on the wrapped error, derivative on the measured yaw rate (no kick on set-point steps).
  // The set-point is a heading: without current, course and heading differ only by the drift angle.
  const auto& hc = cfg_.heading;
  const double e = wrapPi(course_sp_ - s.psi);
  const double unsat = hc.kp * e + hc.ki * heading_integral_ - hc.kd * s.r;
  // Conditional integration (anti-windup): only near the set-point and while the rudder is not saturated
  // (or when the integral unwinds).
  if (std::abs(e) < hc.integral_zone && (std::abs(unsat) < hc.rudder_limit || unsat * e < 0.0)) {
    heading_integral_ += e * dt;
    if (hc.ki > 0.0) {
      const double lim = hc.integral_limit / hc.ki;
      heading_integral_ = std::clamp(heading_integral_, -lim, lim);
    }
  }
  const double cmd =
      std::clamp(hc.kp * e + hc.ki * heading_integral_ - hc.kd * s.r, -hc.rudder_limit, hc.rudder_limit);
  const double max_move = hc.rudder_rate_limit * dt;
  rudder_ += std::clamp(cmd - rudder_, -max_move, max_move);

  // Speed: feed-forward from the steady map plus PI on the surge error.
  const auto& sc = cfg_.speed;
  const double ev = speed_sp_ - s.u;
  if (speed_sp_ > 0.0)
    speed_integral_ += ev * dt;
  if (sc.ki > 0.0) {
    const double lim = sc.integral_limit / sc.ki;
    speed_integral_ = std::clamp(speed_integral_, -lim, lim);
  }
  const double rps =
      speed_sp_ > 0.0 ? std::max(0.0, ff_(speed_sp_) + sc.kp * ev + sc.ki * speed_integral_) : 0.0;

  VesselInput in;
  in.rudder = rudder_;
  in.propeller_rps = rps;
  in.course = course_sp_;
  in.speed = speed_sp_;
  return in;
}

}  // namespace asv
