// Poses in any frame tf2 can transform into the working frame (`map`, REP 105): one lookup for every
// node that takes odometry, goals or targets from elsewhere (a GNSS/INS driver's `odom` or `utm`, rviz's
// goal tool in its fixed frame).
#pragma once

#include <memory>
#include <string>

#include <geometry_msgs/Pose.h>
#include <ros/ros.h>
#include <tf2/LinearMath/Transform.h>
#include <tf2/buffer_core.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

namespace asv_ros {

// `out` takes a pose in `frame` into `working`: identity for the working frame itself (a leading '/'
// ignored), else tf2's transform at `stamp`; with `latest_ok`, the latest one when there is none at
// `stamp` (a goal is placed once, by the transform known now). False for an empty frame or one tf2
// cannot connect (at `stamp`: a dead transform publisher is not used forever).
bool lookupInto(const tf2::BufferCore& buffer, const std::string& working, const std::string& frame,
                const ros::Time& stamp, tf2::Transform& out, bool latest_ok = false);

// A pose moved by `t` (position and orientation).
geometry_msgs::Pose transformPose(const tf2::Transform& t, const geometry_msgs::Pose& pose);

// A node's tf2 buffer and listener, and lookupInto() against them.
class FrameLookup {
public:
  explicit FrameLookup(std::string working);
  bool get(const std::string& frame, const ros::Time& stamp, tf2::Transform& out,
           bool latest_ok = false) const {
    return lookupInto(buffer_, working_, frame, stamp, out, latest_ok);
  }
  const std::string& working() const { return working_; }

private:
  std::string working_;
  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_{buffer_};
};

}  // namespace asv_ros
