// tracker: fuses the AIS and ARPA targets into one track per ship (asv::Tracker, asv_core/tracking/tracker.h:
// association rule and ages documented there and in config/tracker.yaml), dead-reckons the tracks and
// publishes them at a fixed rate with their age, source (AIS/ARPA/FUSED) and quality.
//
// Subscribes: ais/targets, arpa/targets (asv_msgs/TargetArray in frame_id)
// Publishes:  targets (asv_msgs/TargetArray, every live track at publish_rate), alarms (asv_msgs/Alarm,
//             latched: an input silent), /diagnostics
// Parameters: see config/tracker.yaml (every key documented there).
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include <asv_core/common/clock_jump.h>
#include <asv_core/tracking/tracker.h>
#include <asv_core/tracking/tracker_node_config.h>
#include <asv_msgs/TargetArray.h>
#include <asv_ros/alarm.h>
#include <asv_ros/lockstep.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

namespace asv_risk {

// The node's parameters (config/tracker.yaml); std::invalid_argument naming a bad or unknown one.
asv::TrackerNodeConfig loadTrackerParams(const ros::NodeHandle& pnh);

// Why a reported target did not reach the tracker.
enum class TrackReject { kNone = 0, kFrame, kSource, kNonFinite, kFuture, kCount };
const char* toString(TrackReject r);

// Converts one target of an ais/targets or arpa/targets array (header stamp `array_stamp`) into a
// tracker report; kNone on success. Exposed for tests.
TrackReject targetToReport(const asv_msgs::Target& t, const ros::Time& array_stamp,
                           const asv::TrackerNodeConfig& p, asv::TrackReport& out);

class TrackerNode {
public:
  TrackerNode(ros::NodeHandle nh, ros::NodeHandle pnh);

private:
  void targetsCallback(const asv_msgs::TargetArray::ConstPtr& msg);
  void reject(TrackReject why, const std::string& id);
  void publish();
  // The inputs' watch (at each publication): the alarm when an ingestion node has gone silent.
  void watchInputs(const ros::Time& now);
  // Drops every track when the clock has gone backwards (a looping bag); true when it did.
  bool checkClock(const ros::Time& now);
  asv_msgs::Target toMsg(const asv::TrackEstimate& e) const;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);

  ros::NodeHandle nh_, pnh_;
  asv::TrackerNodeConfig params_;
  asv::Tracker tracker_;
  // Last message per MMSI / radar number: static data and names for the published tracks.
  std::map<std::uint32_t, asv_msgs::Target> ais_meta_;
  std::map<int, asv_msgs::Target> arpa_meta_;
  ros::Subscriber ais_sub_, arpa_sub_;
  ros::Publisher targets_pub_;
  ros::Timer diag_timer_;
  asv_ros::Lockstep lockstep_{nh_, asv_ros::kTracking};
  diagnostic_updater::Updater updater_;
  asv::InputWatch watch_{params_.watch};
  asv_ros::AlarmReporter alarm_{nh_};

  asv::ClockJumpDetector clock_;
  std::uint64_t rejected_[static_cast<std::size_t>(TrackReject::kCount)] = {};
  std::size_t alive_ = 0, coasting_ = 0, fused_ = 0;
  ros::WallTime diag_time_;
  std::uint64_t diag_reports_ = 0, diag_rejected_ = 0;
};

}  // namespace asv_risk
