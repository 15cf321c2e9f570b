#include <ros/ros.h>

#include "asv_planning/planner_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "planner_node");
  try {
    asv_planning::PlannerNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("planner_node: %s", e.what());
    return 1;
  }
  return 0;
}
