// Closest point of approach between two ships moving at constant velocity.
#pragma once

#include <Eigen/Core>

#include "asv_core/common/types.h"

namespace asv {

struct Cpa {
  double tcpa = 0.0;            // [s] time to CPA from now; negative when the CPA is in the past (diverging)
  double dcpa = 0.0;            // [m] distance at CPA
  double range = 0.0;           // [m] current distance
  double relative_speed = 0.0;  // [m/s] |v_target - v_own|
  Eigen::Vector2d own_at_cpa = Eigen::Vector2d::Zero();     // [m] ENU position of the own ship at CPA
  Eigen::Vector2d target_at_cpa = Eigen::Vector2d::Zero();  // [m] ENU position of the target at CPA
  bool relative_motion = true;  // false when the relative velocity is (numerically) zero
};

// Relative speed below which the geometry is taken as frozen [m/s]: 1 mm/s is far below any log or
// AIS resolution (0.1 kn = 51 mm/s), so no real encounter is affected.
constexpr double kMinRelativeSpeed = 1e-3;

// Vector form: with relative position p = p_t - p_o and relative velocity w = v_t - v_o,
// TCPA = -(p . w) / |w|^2 and DCPA = |p + w TCPA|. With no relative motion the distance never changes:
// TCPA = 0 and DCPA = the current range (relative_motion = false). Diverging ships get a negative TCPA
// and the DCPA of that past CPA, as a plotting officer reads it.
Cpa computeCpa(const Eigen::Vector2d& own_pos, const Eigen::Vector2d& own_vel, const Eigen::Vector2d& tgt_pos,
               const Eigen::Vector2d& tgt_vel);
inline Cpa computeCpa(const ShipState& own, const ShipState& target) {
  return computeCpa(own.position, own.velocity(), target.position, target.velocity());
}

// The windowed TCPA/DCPA rules of the DSSA+ paper's appendix (Hirayama et al. 2019). Both ships'
// positions are predicted over one TimeWindow; TCPA is clamped to [0, TimeWindow]: 0 when the ships
// are already diverging, TimeWindow when the CPA lies beyond the window.
struct WindowedCpa {
  double tcpa = 0.0;  // [same time unit as the window] in [0, time_window]
  double dcpa = 0.0;  // [same length unit as the positions]
};
// self0/self_tw: self's position now and after TimeWindow with its candidate (course, speed change);
// j0/j_tw: ship j's position now and after TimeWindow with its received intention.
WindowedCpa windowedCpa(const Eigen::Vector2d& self0, const Eigen::Vector2d& self_tw,
                        const Eigen::Vector2d& j0, const Eigen::Vector2d& j_tw, double time_window);

}  // namespace asv
