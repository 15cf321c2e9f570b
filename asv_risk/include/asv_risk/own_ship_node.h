// own_ship_node: the own ship from her own sensors (asv::OwnShipEstimator has the rules): GNSS (GGA,
// GNS, RMC, VTG), heading (HDT, THS, HDG), rate of turn (ROT) and her AIS transponder (AIVDO, or AIVDM
// from own_mmsi) over the same inputs as ais_node (UDP, TCP, serial, file, topic).
//
// Subscribes: nmea_in (asv_msgs/NmeaSentence) when input/type is topic; with navsat: true also a GNSS
//             driver's fix (sensor_msgs/NavSatFix), vel (geometry_msgs/TwistStamped, ENU m/s over
//             ground) and heading (geometry_msgs/QuaternionStamped, ENU orientation: a heading sensor)
// Publishes:  odom (nav_msgs/Odometry in frame_id, child <ship>/base_link, REP 103/105: pose in map, twist
//             in the body frame, covariance from the fix), tf frame_id -> <ship>/base_link, nmea (every
//             line read from a device), alarms (asv_msgs/Alarm, latched: fix or heading lost), /diagnostics
// Parameters: see config/own_ship_node.yaml (every key documented there).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include <asv_core/codec/ais.h>
#include <asv_core/common/geodesy.h>
#include <asv_core/tracking/odom_frame.h>
#include <asv_core/tracking/own_ship.h>
#include <asv_ros/alarm.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/QuaternionStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/NavSatFix.h>
#include <tf2_ros/transform_broadcaster.h>

#include "asv_risk/nmea_input.h"
#include "asv_risk/params.h"

namespace asv_risk {

using OwnShipNodeParams = IngestionNodeParams<asv::OwnShipConfig>;

// Odometry of a state (pose in frame_id, twist in the body frame), exposed for tests.
nav_msgs::Odometry toOdometry(const asv::OwnShipState& s, const std::string& frame_id,
                              const std::string& child, const ros::Time& stamp);

class OwnShipNode {
public:
  OwnShipNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  void handleLine(const std::string& line, const ros::Time& stamp);
  void fixCallback(const sensor_msgs::NavSatFix& msg);
  void velCallback(const geometry_msgs::TwistStamped& msg);
  void headingCallback(const geometry_msgs::QuaternionStamped& msg);

private:
  void publish();
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);
  void reject(const std::string& why);
  void subscribeNavSat();

  ros::NodeHandle nh_, pnh_;
  OwnShipNodeParams params_;
  asv_ros::MapOrigin map_origin_;
  asv::LocalFrame frame_;
  asv::OwnShipEstimator estimator_;
  asv::nmea::LineFramer framer_;
  asv::ais::Decoder decoder_;
  asv::ais::Message message_;
  ros::Publisher odom_pub_;
  ros::Subscriber fix_sub_, vel_sub_, heading_sub_;
  tf2_ros::TransformBroadcaster tf_;
  asv::OdomFrame odom_;  // REP 105's odom (odom_frame set)
  ros::Timer timer_, diag_timer_;
  diagnostic_updater::Updater updater_;
  asv_ros::AlarmReporter alarm_{nh_};
  std::map<std::string, std::uint64_t> used_;  // sentences used, by type
  std::uint64_t published_ = 0, ais_reports_ = 0, navsat_rejected_ = 0;
  std::string last_rejection_;
  std::unique_ptr<NmeaInput> input_;  // last: its thread starts once everything else exists
};

}  // namespace asv_risk
