#include "asv_ros/frames.h"

#include <utility>

#include <tf2_geometry_msgs/tf2_geometry_msgs.h>

namespace asv_ros {

bool lookupInto(const tf2::BufferCore& buffer, const std::string& working, const std::string& frame,
                const ros::Time& stamp, tf2::Transform& out, bool latest_ok) {
  if (frame.empty())
    return false;
  const std::string f = frame[0] == '/' ? frame.substr(1) : frame;
  if (f == working) {
    out.setIdentity();
    return true;
  }
  for (const ros::Time& t : {stamp, ros::Time(0)}) {
    try {
      tf2::fromMsg(buffer.lookupTransform(working, f, t).transform, out);
      return true;
    } catch (const tf2::TransformException&) {
      if (t.isZero() || !latest_ok)
        return false;
    }
  }
  return false;
}

geometry_msgs::Pose transformPose(const tf2::Transform& t, const geometry_msgs::Pose& pose) {
  tf2::Transform p;
  tf2::fromMsg(pose, p);
  geometry_msgs::Pose out;
  tf2::toMsg(t * p, out);
  return out;
}

FrameLookup::FrameLookup(std::string working) : working_(std::move(working)) {}

}  // namespace asv_ros
