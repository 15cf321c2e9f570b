// planner_node: hosts one planner plugin for one ship.
//
// Subscribes: odom (nav_msgs/Odometry, own ship), risk (asv_msgs/RiskAssessment), targets
//   (asv_msgs/TargetArray), goal (geometry_msgs/PoseStamped, optional: replaces the configured goal),
//   alarms (asv_msgs/Alarm: the upstream nodes' alarms), aids_to_navigation
//   (asv_msgs/AidToNavigationArray from ais_node, when use_aids: hazards the plans keep clear of), route
//   (nav_msgs/Path: a voyage plan, replaces the scenario's route or the goal)
// Publishes: plan (asv_msgs/Plan), path (nav_msgs/Path), cmd (asv_msgs/CourseSpeedSetpoint),
//   plan_markers (visualization_msgs/MarkerArray), domains (MarkerArray: the planner's domain round each
//   target of its problem), route_markers (MarkerArray, latched: the route in force and its corridors),
//   active_route (nav_msgs/Path, latched: the route in force, for plotter_node; empty: none),
//   route_status (asv_msgs/RouteStatus: active waypoint, cross-track error), alarms (asv_msgs/Alarm, latched:
//   its inputs lost and the degraded action), /diagnostics
// Parameters: config/planner_node.yaml; the planner's own under ~<planner>/ (each algorithm's keys are its
//   config struct's, asv_core/planning/<planner>/, defaults in its constructor; config/dssa.yaml shows
//   DSSA's).
//   Live (dynamic_reconfigure, cfg/Planner.cfg): planner, mode, min_separation, replan_period,
//   min_replan_interval, time_budget, stand_on_policy.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include <asv_core/common/clock_jump.h>
#include <asv_core/planning/plan_follower.h>
#include <asv_core/planning/planner_node_config.h>
#include <asv_core/planning/planning.h>
#include <asv_core/planning/planning_cycle.h>
#include <asv_msgs/AidToNavigationArray.h>
#include <asv_msgs/Alarm.h>
#include <asv_msgs/RiskAssessment.h>
#include <asv_msgs/RouteStatus.h>
#include <asv_msgs/TargetArray.h>
#include <asv_ros/alarm.h>
#include <asv_ros/frames.h>
#include <asv_ros/lockstep.h>
#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/PoseStamped.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <ros/ros.h>

#include "asv_planning/PlannerConfig.h"
#include "asv_planning/dssa_ros_agent.h"
#include "asv_planning/plugin_loader.h"

namespace asv_planning {

class PlannerNode {
public:
  PlannerNode(ros::NodeHandle nh, ros::NodeHandle pnh);

private:
  PlannerNode(ros::NodeHandle nh, ros::NodeHandle pnh, const asv::ParamMap& params);
  void odomCallback(const nav_msgs::Odometry::ConstPtr& msg);
  void riskCallback(const asv_msgs::RiskAssessment::ConstPtr& msg);
  void targetsCallback(const asv_msgs::TargetArray::ConstPtr& msg);
  void goalCallback(const geometry_msgs::PoseStamped::ConstPtr& msg);
  // A voyage plan (nav_msgs/Path, any frame tf2 connects to map): the ship sails it from the leg
  // nearest to her; the last pose is the goal. Speeds and corridors are not in a Path: the cruise speed.
  void routeCallback(const nav_msgs::Path::ConstPtr& msg);
  void setRoute(const asv::Route& route, const std::string& from);
  void publishRoute();        // route_markers: the route, its waypoints and corridors (latched)
  void publishRouteStatus();  // route_status: active waypoint and cross-track error
  // Aids to navigation become point hazards of the plans (use_aids, aid_clearance).
  void aidsCallback(const asv_msgs::AidToNavigationArray::ConstPtr& msg);
  // The scenario's obstacles and the aids' hazards, as the plan follower gets them.
  std::vector<asv::StaticObstacle> allObstacles() const;
  void applyScenario();
  asv::ParamMap pluginParams(const std::string& planner) const;
  void start();
  void timerCallback();
  void watchJob();  // free-running, every kWatchPeriod: degraded operation as soon as an input is lost
  std::vector<asv::PlannerTarget> targetsNow() const;
  // The last tracks with their last risk picture, however old, dead-reckoned to now (degraded operation).
  std::vector<asv::PlannerTarget> lastPicture(const ros::Time& now) const;
  std::vector<asv::PlannerTarget> withRisk(const std::vector<asv::ShipState>& tracks, bool risk_fresh) const;
  // What the picture lacks now: stale inputs, risk with data_ok false, upstream ERROR alarms.
  std::vector<asv::StaleInput> lostInputs();
  void alarmCallback(const asv_msgs::Alarm::ConstPtr& msg);
  // Degraded operation while `lost` is not empty (PlanFollower::degrade), else back to planning.
  void degrade(const std::vector<asv::StaleInput>& lost);
  // The planning cycle (asv_core/planning/planning_cycle.h) with the picture `targets`: logs, counts and
  // publishes a new plan; returns the set-point to steer, if any.
  asv::CycleResult plan(const std::vector<asv::PlannerTarget>& targets);
  void publishPlan();
  void publishSetpoint();
  void publishSetpoint(double course, double speed);
  void publishDomains(const std::vector<asv::PlannerTarget>& targets);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& stat);
  // dynamic_reconfigure: applies a change of the live parameters as a whole, or refuses it (ERROR on
  // screen, the values in force shown again); the first call shows the values in force.
  void reconfigure(PlannerConfig& config, uint32_t level);
  PlannerConfig liveConfig() const;
  pluginlib::UniquePtr<asv::PlannerAlgorithm> loadPlugin(const std::string& planner, const std::string& mode);
  // Drops the own ship, the inputs and the plan when the clock has gone backwards (a looping bag).
  void checkClock();

  ros::NodeHandle nh_, pnh_;
  asv::PlannerNodeConfig params_;  // follower: as loaded (the plan follower gets followerConfig())
  PluginLoader loader_;
  pluginlib::UniquePtr<asv::PlannerAlgorithm> plugin_;
  std::vector<asv::StaticObstacle> obstacles_;      // the scenario's (land, structures)
  std::vector<asv::StaticObstacle> aid_obstacles_;  // one per aid to navigation
  ros::Subscriber odom_sub_, risk_sub_, targets_sub_, goal_sub_, alarms_sub_, aids_sub_, route_sub_;
  ros::Publisher plan_pub_, path_pub_, cmd_pub_, markers_pub_, domains_pub_, route_markers_pub_,
      route_status_pub_, active_route_pub_;
  asv::Route route_;                               // the voyage plan in force (empty: none), for its markers
  asv_ros::FrameLookup frames_{params_.frame_id};  // odometry and goals in any frame tf2 connects to map
  diagnostic_updater::Updater updater_;
  asv_ros::Lockstep lockstep_{nh_, asv_ros::kPlanning};

  asv::InputWatch watch_;
  std::unique_ptr<asv_ros::AlarmReporter> alarm_;
  std::map<std::string, asv_msgs::Alarm::ConstPtr> upstream_alarms_;  // by source node

  std::optional<asv::ShipState> own_;
  double first_input_ = -1.0;  // [s] ROS time of the first odometry (-1: none yet)
  asv_msgs::RiskAssessment::ConstPtr risk_;
  asv_msgs::TargetArray::ConstPtr targets_;
  // Replanning policy and plan-to-set-point logic, shared with asv_batch (asv_core/planning/plan_follower.h).
  std::unique_ptr<asv::PlanFollower> follower_;
  asv::PlanFollowerConfig follower_config_;
  asv::ClockJumpDetector clock_;
  ros::Time plan_stamp_;
  uint64_t overruns_ = 0;
  double last_compute_ = 0.0, max_compute_ = 0.0;
  std::string last_reason_;
  std::unique_ptr<DssaRosAgent>
      dssa_;                   // distributed DSSA/DSSA+ (~distributed): drives cmd instead of the plugin
  asv::ParamMap node_params_;  // ~ (a planner switch reads the new plugin's ~<planner>/)
  asv::ParamMap scenario_planners_;      // the scenario's planner_params, all planners
  std::string scenario_planner_;         // the scenario's planner for this ship ("" without scenario)
  std::string mode_ = "sea";             // the plugin's mode in force (its key mode)
  double scenario_min_separation_ = 0;   // [m] the scenario's (0: none)
  double scenario_goal_radius_ = 0;      // [m] this ship's arrival radius in the scenario (0: none)
  bool scenario_stays_at_goal_ = false;  // this ship stays at her goal once arrived (scenario)
  asv::Route scenario_route_;            // this ship's voyage plan in the scenario (unless goal_x/y given)
  std::unique_ptr<dynamic_reconfigure::Server<PlannerConfig>> live_;
  bool live_started_ = false;
};

}  // namespace asv_planning
