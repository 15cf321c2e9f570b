// autopilot_bridge: the planner's set-points to a real autopilot (asv::AutopilotBridge has the rules).
//
// Subscribes: cmd (asv_msgs/CourseSpeedSetpoint), odom (nav_msgs/Odometry, own ship in map)
// Publishes:  NMEA 0183 APB, RMB, XTE, HSC over UDP or serial (output/*), cmd_vel
//             (geometry_msgs/TwistStamped, when publish_twist), alarms (asv_msgs/Alarm, latched: set-points
//             or odometry lost, and the safe action), /diagnostics
// Services:   ~arm (std_srvs/SetBool): true arms (sentences go out), false disarms (nothing goes out)
// Parameters: config/autopilot_bridge.yaml (every key documented there).
#pragma once

#include <memory>
#include <optional>

#include <asv_core/common/geodesy.h>
#include <asv_core/planning/autopilot_bridge.h>
#include <asv_msgs/CourseSpeedSetpoint.h>
#include <asv_ros/alarm.h>
#include <asv_ros/map_origin.h>
#include <asv_ros/nmea_output.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>
#include <std_srvs/SetBool.h>

namespace asv_planning {

class AutopilotBridgeNode {
public:
  AutopilotBridgeNode(ros::NodeHandle nh, ros::NodeHandle pnh);

private:
  void cmdCallback(const asv_msgs::CourseSpeedSetpoint::ConstPtr& msg);
  void odomCallback(const nav_msgs::Odometry::ConstPtr& msg);
  void routeCallback(const nav_msgs::Path::ConstPtr& msg);
  bool armService(std_srvs::SetBool::Request& req, std_srvs::SetBool::Response& res);
  void tick();
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);

  ros::NodeHandle nh_, pnh_;
  asv::AutopilotBridgeConfig config_;
  asv_ros::NmeaOutputConfig output_config_;
  std::unique_ptr<asv_ros::MapOrigin> map_origin_;
  std::optional<asv::LocalFrame> frame_;
  bool publish_twist_ = false;
  std::unique_ptr<asv::AutopilotBridge> bridge_;
  std::unique_ptr<asv_ros::NmeaOutput> output_;
  ros::Subscriber cmd_sub_, odom_sub_, route_sub_;
  ros::Publisher twist_pub_;
  ros::ServiceServer arm_srv_;
  ros::Timer timer_, diag_timer_;
  diagnostic_updater::Updater updater_;
  std::unique_ptr<asv_ros::AlarmReporter> alarm_;
  asv::AutopilotBridge::Output last_;
  uint64_t ticks_sent_ = 0;
  size_t route_waypoints_ = 0;  // of the route in force (0: none)
};

}  // namespace asv_planning
