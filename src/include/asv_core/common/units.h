// Units and angle conventions of the asv stack.
//
// SI inside (m, s, rad, m/s). Knots, nautical miles and degrees only at the edges, through these
// functions. The core speaks nautical course/heading (clockwise from true north) because every paper
// does; ROS poses carry ENU yaw (counter-clockwise from east, REP 103). courseToYaw/yawToCourse are
// the one place that conversion lives.
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace asv {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kMetresPerNauticalMile = 1852.0;  // international nautical mile
constexpr double kMpsPerKnot = 1852.0 / 3600.0;    // 1 kn = 1 nm/h

constexpr double degToRad(double deg) {
  return deg * kPi / 180.0;
}
constexpr double radToDeg(double rad) {
  return rad * 180.0 / kPi;
}
constexpr double knotsToMps(double kn) {
  return kn * kMpsPerKnot;
}
constexpr double mpsToKnots(double mps) {
  return mps / kMpsPerKnot;
}
constexpr double nmToMetres(double nm) {
  return nm * kMetresPerNauticalMile;
}
constexpr double metresToNm(double m) {
  return m / kMetresPerNauticalMile;
}

// Wraps an angle to [0, 2 pi). NaN stays NaN.
inline double wrapTwoPi(double a) {
  double w = std::fmod(a, kTwoPi);
  if (w < 0.0)
    w += kTwoPi;
  return w >= kTwoPi ? 0.0 : w;
}

// Wraps an angle to [-pi, pi). NaN stays NaN.
inline double wrapPi(double a) {
  return wrapTwoPi(a + kPi) - kPi;
}

// Same as wrapTwoPi for degrees: [0, 360).
inline double wrapDeg360(double d) {
  double w = std::fmod(d, 360.0);
  if (w < 0.0)
    w += 360.0;
  return w >= 360.0 ? 0.0 : w;
}

// Nautical course/heading (rad, clockwise from north) <-> ENU yaw (rad, counter-clockwise from east).
// yaw = pi/2 - course, both wrapped: course to [0, 2 pi), yaw to [-pi, pi).
inline double courseToYaw(double course) {
  return wrapPi(kPi / 2.0 - course);
}
inline double yawToCourse(double yaw) {
  return wrapTwoPi(kPi / 2.0 - yaw);
}

// Velocity in ENU (x east, y north) of a ship sailing `course` (nautical, rad) at `speed` (m/s).
inline Eigen::Vector2d courseSpeedToVelocity(double course, double speed) {
  return {speed * std::sin(course), speed * std::cos(course)};
}

// Nautical course (rad, [0, 2 pi)) of an ENU vector; 0 for the zero vector.
inline double courseOf(const Eigen::Vector2d& v) {
  if (v.x() == 0.0 && v.y() == 0.0)
    return 0.0;
  return wrapTwoPi(std::atan2(v.x(), v.y()));
}

// True bearing (nautical, rad) from `from` to `to`, both ENU.
inline double trueBearing(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  return courseOf(to - from);
}

inline bool allFinite(std::initializer_list<double> values) {
  for (double v : values)
    if (!std::isfinite(v))
      return false;
  return true;
}

}  // namespace asv
