#include "asv_core/risk/cpa.h"

#include <algorithm>
#include <cmath>

namespace asv {

Cpa computeCpa(const Eigen::Vector2d& own_pos, const Eigen::Vector2d& own_vel, const Eigen::Vector2d& tgt_pos,
               const Eigen::Vector2d& tgt_vel) {
  Cpa c;
  const Eigen::Vector2d p = tgt_pos - own_pos;
  const Eigen::Vector2d w = tgt_vel - own_vel;
  const double w2 = w.squaredNorm();
  c.range = p.norm();
  c.relative_speed = std::sqrt(w2);
  if (c.relative_speed < kMinRelativeSpeed) {
    c.relative_motion = false;
    c.tcpa = 0.0;
    c.dcpa = c.range;
    c.own_at_cpa = own_pos;
    c.target_at_cpa = tgt_pos;
    return c;
  }
  c.tcpa = -p.dot(w) / w2;
  c.dcpa = (p + w * c.tcpa).norm();
  c.own_at_cpa = own_pos + own_vel * c.tcpa;
  c.target_at_cpa = tgt_pos + tgt_vel * c.tcpa;
  return c;
}

WindowedCpa windowedCpa(const Eigen::Vector2d& self0, const Eigen::Vector2d& self_tw,
                        const Eigen::Vector2d& j0, const Eigen::Vector2d& j_tw, double time_window) {
  // Appendix of Hirayama et al. (2019): X1, Y1 relative position now, X2, Y2 relative displacement
  // over the window.
  const double X1 = self0.x() - j0.x();
  const double Y1 = self0.y() - j0.y();
  const double X2 = (self_tw.x() - self0.x()) - (j_tw.x() - j0.x());
  const double Y2 = (self_tw.y() - self0.y()) - (j_tw.y() - j0.y());
  const double a = X2 * X2 + Y2 * Y2;
  const double b = X1 * X2 + Y1 * Y2;
  double t;  // fraction of the window
  if (a > 0.0) {
    if (a + b <= 0.0)
      t = 1.0;  // rule 1: CPA at or beyond the end of the window
    else if (b >= 0.0)
      t = 0.0;  // rule 2: already diverging
    else
      t = -b / a;  // rule 3: CPA inside the window
  } else {
    t = b > 0.0 ? 0.0 : 1.0;  // rules 4 and 5: no relative motion (b is then 0, so TimeWindow)
  }
  WindowedCpa r;
  r.tcpa = t * time_window;
  // DCPA(t) = sqrt(X1^2 + Y1^2 + 2 (X1 X2 + Y1 Y2) t + (X2^2 + Y2^2) t^2), t = TCPA / TimeWindow.
  r.dcpa = std::sqrt(std::max(0.0, X1 * X1 + Y1 * Y1 + 2.0 * b * t + a * t * t));
  return r;
}

}  // namespace asv
