// risk_node: CPA/TCPA, CRI, encounter, own role and the non-compliance flag for every target.
//
// Subscribes: odom (nav_msgs/Odometry, own ship), targets (asv_msgs/TargetArray)
// Publishes:  risk (asv_msgs/RiskAssessment, on every target update), risk_markers
//             (visualization_msgs/MarkerArray), alarms (asv_msgs/Alarm, latched: targets or odometry
//             stale), /diagnostics
// Parameters: see config/risk_node.yaml (every key documented there).
#pragma once

#include <array>
#include <optional>
#include <string>

#include <asv_core/common/clock_jump.h>
#include <asv_core/risk/risk_assessment.h>
#include <asv_core/risk/risk_node_config.h>
#include <asv_msgs/RiskAssessment.h>
#include <asv_msgs/TargetArray.h>
#include <asv_ros/alarm.h>
#include <asv_ros/conversions.h>
#include <asv_ros/frames.h>
#include <asv_ros/lockstep.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/publisher.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2/LinearMath/Transform.h>
#include <visualization_msgs/MarkerArray.h>

namespace asv_risk {

using asv_ros::Reject;  // the input checks of asv_ros/conversions.h, counted by reason

// The node's parameters (asv::RiskNodeConfig, config/risk_node.yaml) from the private node handle;
// throws std::invalid_argument naming the parameter when a value is invalid or unknown.
asv::RiskNodeConfig loadParams(const ros::NodeHandle& pnh);

class RiskNode {
public:
  RiskNode(ros::NodeHandle nh, ros::NodeHandle pnh);

  // Counters, exposed for tests and diagnostics.
  uint64_t rejected(Reject r) const { return rejected_[static_cast<size_t>(r)]; }

private:
  void odomCallback(const nav_msgs::Odometry::ConstPtr& msg);
  void targetsCallback(const asv_msgs::TargetArray::ConstPtr& msg);
  void reject(Reject why, const std::string& what);
  // Forgets the own ship and every compliance history when the clock has gone backwards (a looping bag).
  void checkClock();
  visualization_msgs::MarkerArray makeMarkers(const asv_msgs::RiskAssessment& ra) const;
  visualization_msgs::Marker ownRiskLabel(const asv_msgs::RiskAssessment& ra, int id) const;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);
  // The inputs' watch (every kWatchPeriod): the alarm, and while an input is stale the last assessment again
  // with data_ok false.
  void watchInputs();
  void fillDataState(asv_msgs::RiskAssessment& ra, double now);

  ros::NodeHandle nh_, pnh_;
  asv::RiskNodeConfig params_;
  asv::RiskAssessor assessor_;
  ros::Subscriber odom_sub_, targets_sub_;
  ros::Publisher risk_pub_, marker_pub_;
  asv_ros::FrameLookup frames_;
  diagnostic_updater::Updater updater_;
  double diag_min_rate_, diag_max_rate_;
  std::unique_ptr<diagnostic_updater::TopicDiagnostic> risk_diag_;
  ros::Timer diag_timer_;
  asv_ros::Lockstep lockstep_{nh_, asv_ros::kRisk};
  asv::InputWatch watch_{params_.watch};
  asv_ros::AlarmReporter alarm_{nh_};
  asv_msgs::RiskAssessment last_;  // the last assessment made, sent again while the data is stale

  asv::ClockJumpDetector clock_;
  std::optional<asv::ShipState> own_;
  ros::Time own_stamp_;
  std::array<uint64_t, static_cast<size_t>(Reject::kCount)> rejected_{};
  uint64_t assessments_ = 0, targets_seen_ = 0, odom_rejected_ = 0;
  uint64_t rejected_at_last_diag_ = 0;
};

}  // namespace asv_risk
