#include "asv_core/tracking/radar_fix.h"

#include <algorithm>
#include <cmath>

#include "asv_core/common/units.h"

namespace asv {

RadarFix radarFix(const Eigen::Vector2d& own, double range, double bearing, const RadarSigmas& sigmas) {
  const Eigen::Vector2d u(std::sin(bearing), std::cos(bearing));  // along the bearing, ENU
  const Eigen::Vector2d w(u.y(), -u.x());                         // across it
  const double sr = std::max(sigmas.range, sigmas.range_fraction * range);
  const double sc = range * degToRad(sigmas.bearing_deg);
  RadarFix f;
  f.position = own + range * u;
  f.covariance = sr * sr * u * u.transpose() + sc * sc * w * w.transpose();
  return f;
}

}  // namespace asv
