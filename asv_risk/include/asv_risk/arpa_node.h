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
//             (asv_msgs/TargetArray: the radar targets reported since the previous array), /diagnostics
// Parameters: see config/arpa_node.yaml (every key documented there).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include <asv_core/codec/arpa.h>
#include <asv_core/common/clock_jump.h>
#include <asv_core/common/geodesy.h>
#include <asv_msgs/TargetArray.h>
#include <asv_ros/lockstep.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

#include "asv_risk/nmea_input.h"
#include "asv_risk/params.h"

namespace asv_risk {

// arpa_node's parameters: the ingestion nodes' shared ones (asv_risk/params.h; radar defaults: 1000
// targets, forgotten after 120 s, input on port 10111 at 4800 baud) and the radar-specific ones.
struct ArpaNodeParams : IngestionParams {
  ArpaNodeParams() {
    input.frame_id = "radar";
    input.udp_port = 10111;
    input.tcp_port = 10111;
    input.serial_baud = 4800;
  }
  double odom_timeout = 2.0;           // [s] own position/heading older than this is not used
  double range_sigma = 30.0;           // [m] smallest 1-sigma of a TTM range
  double range_sigma_fraction = 0.01;  // 1-sigma of a TTM range as a fraction of it (IMO: 1 %)
  double bearing_sigma_deg = 1.0;      // [deg] 1-sigma of a TTM bearing
  double tll_sigma = 50.0;             // [m] 1-sigma of a TLL position
  asv::arpa::ArpaConfig arpa;
};

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
  struct Radar {
    asv_msgs::Target target;
    bool has_velocity = false;
    bool dirty = false;
  };

  void handleSentence(const asv::nmea::Sentence& s, const ros::Time& stamp);
  void handleTtm(const asv::nmea::Sentence& s, const ros::Time& stamp);
  void handleTll(const asv::nmea::Sentence& s, const ros::Time& stamp);
  void handleOsd(const asv::nmea::Sentence& s, const ros::Time& stamp);
  Radar* radar(int number, const ros::Time& stamp);
  void setVelocity(Radar& r, const asv::arpa::TrackedTarget& tt);
  void odomCallback(const nav_msgs::Odometry::ConstPtr& msg);
  bool ownHeading(const ros::Time& stamp, double& heading) const;
  void reject(ArpaReject why, int number);
  void parseError(asv::arpa::Error e, const char* type);
  void publish();
  // Forgets every radar target and the own ship when the clock has gone backwards (a looping bag).
  void checkClock();
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);

  ros::NodeHandle nh_, pnh_;
  ArpaNodeParams params_;
  asv::LocalFrame frame_;
  LineFramer framer_;
  std::map<int, Radar> radars_;
  ros::Subscriber odom_sub_;
  ros::Publisher targets_pub_;
  ros::Timer diag_timer_;
  asv_ros::Lockstep lockstep_{nh_, asv_ros::kIngestion};  // before input_, which subscribes through it
  diagnostic_updater::Updater updater_;

  bool has_odom_ = false;
  Eigen::Vector2d own_position_ = Eigen::Vector2d::Zero();
  double own_heading_ = 0.0;  // [rad] nautical
  ros::Time odom_stamp_;
  bool has_osd_heading_ = false;
  double osd_heading_ = 0.0;
  ros::Time osd_stamp_;

  std::uint64_t rejected_[static_cast<std::size_t>(ArpaReject::kCount)] = {};
  std::uint64_t parse_errors_[static_cast<std::size_t>(asv::arpa::Error::kCount)] = {};
  std::uint64_t ttm_ = 0, tll_ = 0, osd_ = 0, other_ = 0, lost_ = 0, published_ = 0;
  ros::WallTime last_sentence_, diag_time_;
  std::uint64_t diag_sentences_ = 0, diag_rejected_ = 0, diag_drops_ = 0;
  asv::ClockJumpDetector clock_;
  std::unique_ptr<NmeaInput> input_;  // last: its thread starts once everything else exists
};

}  // namespace asv_risk
