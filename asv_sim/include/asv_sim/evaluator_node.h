// evaluator_node: the run evaluator over ROS topics, a thin wrapper over asv::RunRecorder (the same
// code asv_batch uses), writing the run result of docs/evaluation.md.
//
// Subscribes: sim/ships (asv_msgs/TargetArray: ground truth; the own ship is the entry whose id is
//   ~own_ship), sim/events (asv_msgs/SimEvent: END ends the run), <own>/plan (asv_msgs/Plan: compute
//   times), <own>/cmd (asv_msgs/CourseSpeedSetpoint: manoeuvres)
// Writes: ~result (JSON file, directories created) when END arrives; a summary table on rosconsole.
// Parameters: config/evaluator_node.yaml (every key documented there).
#pragma once

#include <memory>
#include <set>
#include <string>
#include <vector>

#include <asv_core/common/clock_jump.h>
#include <asv_core/eval/evaluation.h>
#include <asv_core/eval/evaluator_node_config.h>
#include <asv_core/world/scenario.h>
#include <asv_msgs/CourseSpeedSetpoint.h>
#include <asv_msgs/Plan.h>
#include <asv_msgs/SimEvent.h>
#include <asv_msgs/TargetArray.h>
#include <asv_ros/lockstep.h>
#include <ros/ros.h>

namespace asv_sim {

// The node's parameters (asv::EvaluatorNodeConfig, config/evaluator_node.yaml); std::invalid_argument
// naming a bad or unknown one.
asv::EvaluatorNodeConfig loadEvaluatorParams(const ros::NodeHandle& pnh);

class EvaluatorNode {
public:
  EvaluatorNode(ros::NodeHandle nh, ros::NodeHandle pnh);
  bool done() const { return done_; }

private:
  void shipsCallback(const asv_msgs::TargetArray::ConstPtr& msg);
  void eventCallback(const asv_msgs::SimEvent::ConstPtr& msg);
  void planCallback(const asv_msgs::Plan::ConstPtr& msg);
  void cmdCallback(const asv_msgs::CourseSpeedSetpoint::ConstPtr& msg);
  void start(const asv_msgs::TargetArray& first);
  void finish();
  void writeOutput(const std::string& file, const std::string& text, const char* what);
  double simTime(const ros::Time& stamp) const { return stamp.toSec() - params_.time_origin; }

  ros::NodeHandle nh_, pnh_;
  asv::EvaluatorNodeConfig params_;
  std::unique_ptr<asv::Scenario> scenario_;
  std::unique_ptr<asv::RunRecorder> recorder_;
  asv::ClockJumpDetector clock_;  // a replayed run that loops starts a new recording
  ros::Subscriber ships_sub_, events_sub_, plan_sub_, cmd_sub_;
  asv_ros::Lockstep lockstep_{nh_, asv_ros::kEvaluation};
  std::set<std::string> arrived_;
  std::vector<asv::SimEvent> pending_;  // events before the first sim/ships message
  std::string planner_seen_;
  ros::WallTime wall_start_;
  bool done_ = false;
};

}  // namespace asv_sim
