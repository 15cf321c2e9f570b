// The own ship's state from its odometry, shared by planner_node and the distributed DSSA agent.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include <asv_core/common/types.h>
#include <asv_core/common/units.h>
#include <nav_msgs/Odometry.h>
#include <tf2/utils.h>

namespace asv_planning {

// Position and heading from the pose, course and speed over ground from the twist, which REP 105 gives
// in the body frame (rotated here into map). Empty when any value is not finite: the caller counts and
// logs the rejection.
inline std::optional<asv::ShipState> shipStateFromOdometry(const nav_msgs::Odometry& msg,
                                                           const std::string& id) {
  const auto& q = msg.pose.pose.orientation;
  const auto& v = msg.twist.twist.linear;
  if (!asv::allFinite({msg.pose.pose.position.x, msg.pose.pose.position.y, q.x, q.y, q.z, q.w, v.x, v.y}))
    return std::nullopt;
  const double yaw = tf2::getYaw(q);
  const double ve = v.x * std::cos(yaw) - v.y * std::sin(yaw), vn = v.x * std::sin(yaw) + v.y * std::cos(yaw);
  asv::ShipState s;
  s.id = id;
  s.position = {msg.pose.pose.position.x, msg.pose.pose.position.y};
  s.heading = asv::yawToCourse(yaw);
  s.speed = std::hypot(ve, vn);
  s.course = s.speed > 0.01 ? asv::courseOf({ve, vn}) : s.heading;
  return s;
}

}  // namespace asv_planning
