#include "asv_core/world/fairway.h"

#include <algorithm>
#include <cmath>

namespace asv {

namespace {

// Bisection steps for the distance to land along a ray: 2^-12 of the probe (0.45 m at 1852 m).
constexpr int kRaySteps = 12;

// How far from p along the unit direction d the first obstacle lies, at most `probe` (0: p on land).
double rayToLand(const Eigen::Vector2d& p, const Eigen::Vector2d& d,
                 const std::vector<StaticObstacle>& obstacles, double probe) {
  auto touches = [&](double s) {
    for (const StaticObstacle& o : obstacles)
      if (obstacleDistance(o, p, p + s * d) <= 0.0)
        return true;
    return false;
  };
  if (obstacles.empty() || !touches(probe))
    return probe;
  double lo = 0.0, hi = probe;  // the segment to lo is clear, the one to hi touches land
  if (touches(0.0))
    return 0.0;
  for (int k = 0; k < kRaySteps; ++k) {
    const double mid = 0.5 * (lo + hi);
    (touches(mid) ? hi : lo) = mid;
  }
  return lo;
}

}  // namespace

Fairway fairwayAcross(const Eigen::Vector2d& p, const Eigen::Vector2d& along,
                      const std::vector<StaticObstacle>& obstacles, double port_limit, double starboard_limit,
                      double probe) {
  const Eigen::Vector2d starboard(along.y(), -along.x());  // ENU: the right hand of `along`
  auto side = [&](const Eigen::Vector2d& d, double limit) {
    const double reach = limit > 0.0 ? std::min(limit, probe) : probe;
    return rayToLand(p, d, obstacles, reach);
  };
  return {side(-starboard, port_limit), side(starboard, starboard_limit)};
}

double fairwayBankClearance(const Fairway& f, double land_clearance) {
  return std::max(0.0, std::min(land_clearance, 0.25 * f.width()));
}

double starboardEdgeOffset(const Fairway& f, double land_clearance) {
  return f.starboard - fairwayBankClearance(f, land_clearance);
}

double starboardLaneOffset(const Fairway& f, double land_clearance) {
  const double outer = starboardEdgeOffset(f, land_clearance);
  const double inner = std::min(f.middle() + 0.25 * f.width(), outer);
  return std::clamp(0.0, inner, outer);
}

}  // namespace asv
