// Small ROS conversions and the clock-jump reset shared by the nodes (one helper each).
#pragma once

#include <functional>
#include <string>

#include <asv_core/common/clock_jump.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/Quaternion.h>
#include <ros/ros.h>

namespace asv_ros {

// The orientation of an ENU yaw [rad] (REP 103: counter-clockwise from east, about z up).
geometry_msgs::Quaternion yawToQuaternion(double yaw);

// rviz marker sizes: `px` screen pixels as metres in the map, at the global parameter /view_scale
// [px/m] (default 0.06, asv_bringup/rviz/asv.rviz's top-down scale; rviz/record.sh sets the scale of
// its fitted view), so that ships and labels stay readable at any zoom the run is shown at.
double pixelsToMetres(double px);

// When ROS time has gone back (a looping bag, a restarted simulator; asv::ClockJumpDetector), a node
// forgets its time-dependent state rather than computing ages and rates across the jump: `reset`
// forgets it and says what it forgot ("12 tracks dropped"), which is logged as a warning; the
// diagnostics are published at once (diagnostic_updater schedules by ROS time and would otherwise
// stay silent until the clock caught up). Returns true when the clock jumped.
bool resetOnClockJump(asv::ClockJumpDetector& clock, diagnostic_updater::Updater& updater,
                      const ros::Time& now, const std::function<std::string()>& reset);

}  // namespace asv_ros
