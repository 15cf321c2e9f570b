// risk_node: CPA/TCPA, CRI, encounter, own role and the non-compliance flag for every target.
//
// Subscribes: odom (nav_msgs/Odometry, own ship), targets (asv_msgs/TargetArray)
// Publishes:  risk (asv_msgs/RiskAssessment, on every target update), risk_markers
//             (visualization_msgs/MarkerArray), /diagnostics
// Parameters: see config/risk_node.yaml (every key documented there).
#pragma once

#include <array>
#include <optional>
#include <string>

#include <asv_core/common/clock_jump.h>
#include <asv_core/risk/risk_assessment.h>
#include <asv_msgs/RiskAssessment.h>
#include <asv_msgs/TargetArray.h>
#include <asv_ros/lockstep.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/publisher.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <tf2/LinearMath/Transform.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/MarkerArray.h>

#include "asv_risk/conversions.h"

namespace asv_risk {

struct RiskNodeParams {
  std::string own_ship = "own";   // own ship name (labels, RiskAssessment.own_ship)
  std::string frame_id = "map";   // working frame; other frames are transformed through tf2
  double stale_after = 60.0;      // [s] targets whose stamp is older than this are skipped
  double future_tolerance = 2.0;  // [s] targets stamped further in the future are skipped
  double odom_timeout = 5.0;      // [s] no assessment while the own odometry is older than this
  bool publish_markers = true;
  double min_rate = 0.5;   // [Hz] diagnostics: expected /risk rate window
  double max_rate = 50.0;  // [Hz]
  asv::RiskConfig risk;
};

// Reads every parameter (with the defaults above) from the private node handle; throws
// std::invalid_argument naming the parameter when a value is invalid.
RiskNodeParams loadParams(const ros::NodeHandle& pnh);

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
  bool transformToWorking(const std::string& frame, const ros::Time& stamp, tf2::Transform& out);
  visualization_msgs::MarkerArray makeMarkers(const asv_msgs::RiskAssessment& ra) const;
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);

  ros::NodeHandle nh_, pnh_;
  RiskNodeParams params_;
  asv::RiskAssessor assessor_;
  ros::Subscriber odom_sub_, targets_sub_;
  ros::Publisher risk_pub_, marker_pub_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  diagnostic_updater::Updater updater_;
  double diag_min_rate_, diag_max_rate_;
  std::unique_ptr<diagnostic_updater::TopicDiagnostic> risk_diag_;
  ros::Timer diag_timer_;
  asv_ros::Lockstep lockstep_{nh_, asv_ros::kRisk};

  asv::ClockJumpDetector clock_;
  std::optional<asv::ShipState> own_;
  ros::Time own_stamp_;
  std::array<uint64_t, static_cast<size_t>(Reject::kCount)> rejected_{};
  uint64_t assessments_ = 0, targets_seen_ = 0, odom_rejected_ = 0;
  uint64_t rejected_at_last_diag_ = 0;
};

}  // namespace asv_risk
