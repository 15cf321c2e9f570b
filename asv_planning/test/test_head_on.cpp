// rostest through the whole pipeline: the own ship's plan turns to starboard (Rule 14) and the ships
// pass clear (no collision, separation above the scenario's 400 m).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <asv_msgs/Plan.h>
#include <asv_msgs/RiskAssessment.h>
#include <asv_msgs/SimEvent.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>

TEST(PlannerPipeline, HeadOnTurnsToStarboardAndPassesClear) {
  ros::NodeHandle nh;
  std::vector<asv_msgs::Plan> plans;
  std::vector<asv_msgs::SimEvent> events;
  bool saw_risk = false, ended = false;
  double max_course_change = 0.0;
  auto p_sub = nh.subscribe<asv_msgs::Plan>("own/plan", 10,
                                            [&](const asv_msgs::Plan::ConstPtr& m) { plans.push_back(*m); });
  auto e_sub =
      nh.subscribe<asv_msgs::SimEvent>("sim/events", 100, [&](const asv_msgs::SimEvent::ConstPtr& m) {
        events.push_back(*m);
        ended |= m->type == asv_msgs::SimEvent::END;
      });
  auto r_sub =
      nh.subscribe<asv_msgs::RiskAssessment>("risk", 10, [&](const asv_msgs::RiskAssessment::ConstPtr& m) {
        for (const auto& t : m->targets)
          saw_risk |= t.risk_level >= 1 && t.encounter == t.ENCOUNTER_HEAD_ON;
      });
  auto o_sub = nh.subscribe<nav_msgs::Odometry>("own/odom", 10, [&](const nav_msgs::Odometry::ConstPtr& m) {
    const double yaw = 2.0 * std::atan2(m->pose.pose.orientation.z, m->pose.pose.orientation.w);
    const double change = std::remainder(M_PI / 2 - yaw, 2 * M_PI);  // course - 000, positive to starboard
    if (std::fabs(change) > std::fabs(max_course_change))
      max_course_change = change;
  });
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(100.0);
  while (ros::ok() && !ended && ros::WallTime::now() < deadline) {
    ros::spinOnce();
    ros::WallDuration(0.01).sleep();
  }
  ASSERT_TRUE(ended) << "the scenario did not end";
  EXPECT_TRUE(saw_risk) << "risk_node never saw the head-on risk through AIS/ARPA";
  ASSERT_FALSE(plans.empty());
  bool starboard_plan = false;
  for (const auto& p : plans)
    if (p.status == asv_msgs::Plan::STATUS_OK && p.waypoints.size() >= 3) {
      // A northbound ship's plan that leaves the meeting line eastwards turns to starboard; none may
      // go west of it.
      double east = 0.0, west = 0.0;
      for (const auto& w : p.waypoints) {
        east = std::max(east, w.position.x - p.waypoints[0].position.x);
        west = std::min(west, w.position.x - p.waypoints[0].position.x);
      }
      starboard_plan |= east > 100.0 && east > -west;
    }
  EXPECT_TRUE(starboard_plan);
  EXPECT_GT(max_course_change * 180.0 / M_PI, 10.0) << "the own ship never altered to starboard";
  for (const auto& e : events) {
    EXPECT_NE(e.type, asv_msgs::SimEvent::COLLISION) << e.ship_a << " " << e.ship_b;
    EXPECT_NE(e.type, asv_msgs::SimEvent::NEAR_MISS) << e.ship_a << " " << e.ship_b << " " << e.distance;
    if (e.type == asv_msgs::SimEvent::END) {
      EXPECT_GT(e.distance, 400.0);  // minimum separation over the run
    }
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_head_on");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
