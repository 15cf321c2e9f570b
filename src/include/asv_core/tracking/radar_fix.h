// A radar target's position from the own ship's position and the ARPA's range and true bearing
// (IEC 62388 TTM), with its uncertainty: range and bearing errors are independent, so the covariance
// is a range variance along the line of sight plus a cross-range variance (range x bearing error)
// across it.
#pragma once

#include <Eigen/Core>

namespace asv {

struct RadarSigmas {
  double range = 30.0;           // [m] smallest 1-sigma of a range
  double range_fraction = 0.01;  // 1-sigma of a range as a fraction of it (IMO performance standard: 1 %)
  double bearing_deg = 1.0;      // [deg] 1-sigma of a bearing
};

struct RadarFix {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();    // [m] map frame (ENU)
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();  // [m^2] of the position, ENU
};

// own: the own ship's position [m, ENU]; range [m]; bearing [rad] true, nautical (clockwise from north).
RadarFix radarFix(const Eigen::Vector2d& own, double range, double bearing, const RadarSigmas& sigmas);

}  // namespace asv
