// plotter_node: the situation as NMEA 0183 for a chart plotter (OpenCPN or any ECS): the own ship
// (RMC, HDT, her VDO), each tracked target (TTM with the risk picture's CPA and TCPA), the voyage plan
// in force (WPL, RTE) and, forwarded, the traffic's own AIS sentences. asv::PlotterOutput has the rules.
//
// Subscribes: odom (nav_msgs/Odometry, the own ship in map), targets (asv_msgs/TargetArray, the
//             tracker's), risk (asv_msgs/RiskAssessment), nmea_in (asv_msgs/NmeaSentence, forwarded
//             AIVDM/AIVDO when forward_ais), active_route (nav_msgs/Path in map: planner_node's route in
//             force)
// Publishes:  NMEA 0183 over UDP or serial (output/*), /diagnostics
// Parameters: see config/plotter_node.yaml (every key documented there).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <asv_core/tracking/plotter_output.h>
#include <asv_msgs/NmeaSentence.h>
#include <asv_msgs/RiskAssessment.h>
#include <asv_msgs/TargetArray.h>
#include <asv_ros/map_origin.h>
#include <asv_ros/nmea_output.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>

namespace asv_risk {

class PlotterNode {
public:
  PlotterNode(ros::NodeHandle nh, ros::NodeHandle pnh);

private:
  void tick();
  void forward(const asv_msgs::NmeaSentence& msg);
  bool inMap(const std::string& frame, const char* what) const;
  std::optional<asv::PlotterOwn> own(const ros::Time& now) const;
  std::vector<asv::PlotterTarget> targets(const ros::Time& now) const;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);

  ros::NodeHandle nh_, pnh_;
  asv::PlotterConfig config_;
  asv_ros::NmeaOutputConfig output_config_;
  std::unique_ptr<asv_ros::MapOrigin> map_origin_;
  std::unique_ptr<asv::PlotterOutput> plotter_;
  std::unique_ptr<asv_ros::NmeaOutput> output_;
  nav_msgs::Odometry::ConstPtr odom_;
  asv_msgs::TargetArray::ConstPtr targets_;
  std::map<std::string, std::pair<double, double>> cpa_;  // target id -> (DCPA, TCPA) of the last /risk
  ros::Time odom_time_, targets_time_;
  ros::Subscriber odom_sub_, targets_sub_, risk_sub_, nmea_sub_, route_sub_;
  ros::Timer timer_, diag_timer_;
  diagnostic_updater::Updater updater_;
  std::uint64_t periods_ = 0, void_periods_ = 0, forwarded_ = 0;
};

}  // namespace asv_risk
