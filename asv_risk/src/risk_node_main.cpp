#include <ros/ros.h>

#include "asv_risk/risk_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "risk_node");
  try {
    asv_risk::RiskNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("risk_node: %s", e.what());
    return 1;
  }
  return 0;
}
