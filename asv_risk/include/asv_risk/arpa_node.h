// arpa_node: radar ARPA sentences in ($--TTM, $--TLL, $--OSD over UDP, TCP, serial, file or the
// nmea_in topic), radar targets out in the local ENU frame.
//
// TTM gives range and bearing from the own ship: the target's position is the own position (from
// odom, pose in `map`, REP 105) plus the range along the true bearing; relative bearings and courses
// become true with the own heading (odom's yaw, or the radar's OSD heading while odom has none). TLL
// gives latitude/longitude, placed in the map frame of origin_lat_deg/origin_lon_deg. A target's
// velocity comes from its last TTM.
//
// Subscribes: odom (nav_msgs/Odometry), nmea_in (asv_msgs/NmeaSentence) when input/type is topic
// Publishes:  nmea (asv_msgs/NmeaSentence, every line read from a device), arpa/targets
//             (asv_msgs/TargetArray: the radar targets reported since the previous array; an empty one
//             every heartbeat_period when none was), /diagnostics
// Parameters: see config/arpa_node.yaml (every key documented there).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include <asv_core/codec/arpa.h>
#include <asv_core/common/clock_jump.h>
#include <asv_core/common/geodesy.h>
#include <asv_core/tracking/arpa_targets.h>
#include <asv_msgs/TargetArray.h>
#include <asv_ros/lockstep.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include "asv_risk/nmea_input.h"
#include "asv_risk/params.h"

namespace asv_risk {

// arpa_node's parameters (config/arpa_node.yaml): asv::ArpaNodeConfig and the input (frame "radar",
// port 10111, 4800 baud: a radar's NMEA output).
using ArpaNodeParams = IngestionNodeParams<asv::ArpaNodeConfig>;

ArpaNodeParams loadArpaParams(const ros::NodeHandle& pnh);

enum class ArpaReject {
  kNone = 0,
  kNoNumber,
  kNoPosition,
  kNoOwnPosition,
  kNoOwnHeading,
  kOutOfRange,
  kOdom,
  kCount
};
const char* toString(ArpaReject r);

class ArpaNode {
public:
  ArpaNode(ros::NodeHandle nh, ros::NodeHandle pnh);

  void handleLine(const std::string& line, const ros::Time& stamp);

private:
  void handleSentence(const asv::nmea::Sentence& s, const ros::Time& stamp);
  void handleTtm(const asv::nmea::Sentence& s, const ros::Time& stamp);
  void handleTll(const asv::nmea::Sentence& s, const ros::Time& stamp);
  void handleOsd(const asv::nmea::Sentence& s, const ros::Time& stamp);
  void odomCallback(const nav_msgs::Odometry::ConstPtr& msg);
  void reject(ArpaReject why, int number);
  void parseError(asv::arpa::Error e, const char* type);
  void publish();
  // An empty array when nothing was published for heartbeat_period (the tracker's sign of life).
  void heartbeat();
  // Forgets every radar target and the own ship when the clock has gone backwards (a looping bag).
  void checkClock();
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);

  ros::NodeHandle nh_, pnh_;
  ArpaNodeParams params_;
  asv_ros::MapOrigin map_origin_;
  asv::LocalFrame frame_;
  asv::nmea::LineFramer framer_;
  asv::ArpaTargetTable table_;
  ros::Subscriber odom_sub_;
  ros::Publisher targets_pub_;
  ros::Timer diag_timer_;
  asv_ros::Lockstep lockstep_{nh_, asv_ros::kIngestion};  // before input_, which subscribes through it
  diagnostic_updater::Updater updater_;

  ros::Time last_publish_;
  std::uint64_t rejected_[static_cast<std::size_t>(ArpaReject::kCount)] = {};
  std::uint64_t parse_errors_[static_cast<std::size_t>(asv::arpa::Error::kCount)] = {};
  std::uint64_t ttm_ = 0, tll_ = 0, osd_ = 0, other_ = 0, published_ = 0;
  ros::WallTime last_sentence_, diag_time_;
  std::uint64_t diag_sentences_ = 0, diag_rejected_ = 0, diag_drops_ = 0;
  asv::ClockJumpDetector clock_;
  std::unique_ptr<NmeaInput> input_;  // last: its thread starts once everything else exists
};

}  // namespace asv_risk
