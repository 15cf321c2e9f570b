// The ingestion nodes' sign of life on their target topics.
#pragma once

#include <optional>
#include <string>

#include <asv_msgs/TargetArray.h>
#include <ros/time.h>

namespace asv_risk {

// The ingestion nodes' sign of life: an empty array stamped now when nothing went out since `last` for
// `period` (or the clock went back); `last` then becomes now. None while the clock is not running.
std::optional<asv_msgs::TargetArray> heartbeatArray(const ros::Time& now, ros::Time& last, double period,
                                                    const std::string& frame_id);

}  // namespace asv_risk
