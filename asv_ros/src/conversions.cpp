#include "asv_ros/conversions.h"

#include <cmath>

#include <tf2/LinearMath/Quaternion.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace asv_ros {

geometry_msgs::Quaternion yawToQuaternion(double yaw) {
  tf2::Quaternion q;
  q.setRPY(0.0, 0.0, yaw);
  return tf2::toMsg(q);
}

bool resetOnClockJump(asv::ClockJumpDetector& clock, diagnostic_updater::Updater& updater,
                      const ros::Time& now, const std::function<std::string()>& reset) {
  if (!clock.jumpedBack(now.toSec()))
    return false;
  const std::string forgotten = reset();
  ROS_WARN("%s: time went back %.1f s (a looping bag or a restarted clock): %s",
           ros::this_node::getName().c_str(), clock.lastJump(), forgotten.c_str());
  updater.force_update();
  return true;
}

double pixelsToMetres(double px) {
  constexpr double kDefaultScale = 0.06;  // [px/m] asv.rviz's
  double scale = kDefaultScale;
  if (!ros::param::getCached("/view_scale", scale) || !(scale > 0.0) || !std::isfinite(scale))
    scale = kDefaultScale;
  return px / scale;
}

}  // namespace asv_ros
