#include "asv_risk/heartbeat.h"

namespace asv_risk {

std::optional<asv_msgs::TargetArray> heartbeatArray(const ros::Time& now, ros::Time& last, double period,
                                                    const std::string& frame_id) {
  // 0.99: a timer due every `period` may fire a hair early.
  if (now.isZero() || (now >= last && (now - last).toSec() < 0.99 * period))
    return std::nullopt;
  asv_msgs::TargetArray arr;
  arr.header.stamp = now;
  arr.header.frame_id = frame_id;
  last = now;
  return arr;
}

}  // namespace asv_risk
