// A node's alarm on `alarms` (asv_msgs/Alarm, latched): the inputs its InputWatch found stale, or any
// other cause the node names, and the degraded action in force. One helper for every node, so that an
// alarm looks and logs the same wherever it is raised.
#pragma once

#include <string>
#include <vector>

#include <asv_core/common/input_watch.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

namespace asv_ros {

class AlarmReporter {
public:
  // Advertises `alarms` (latched) and publishes the node's clear state, so that a node that comes back
  // replaces the alarm its predecessor left.
  explicit AlarmReporter(ros::NodeHandle nh);

  // Publishes when the failed inputs or the action changed since the last call: ROS_ERROR with the
  // causes when raised or changed, ROS_INFO when cleared. No failed input: cleared.
  void update(const std::vector<asv::StaleInput>& failed, const std::string& action);
  bool active() const { return !inputs_.empty(); }
  // "targets: none for 1.6 s (timeout 1.5 s); odom: ..." ("" when clear).
  std::string causes() const;
  // While active: the diagnostic summary turns ERROR with the causes (key "alarm"); else only the key.
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat) const;

private:
  void publish();

  ros::Publisher pub_;
  std::vector<std::string> inputs_, causes_;
  std::string action_;
  uint64_t raised_ = 0;
};

// [s] how often a node checks its inputs' watch: an input stale after 1.5 s is seen within 1.75 s.
constexpr double kWatchPeriod = 0.25;

// The watch's two clocks now: ROS time (simulated in a simulation) and wall time, in seconds.
double rosNow();
double wallNow();

}  // namespace asv_ros
