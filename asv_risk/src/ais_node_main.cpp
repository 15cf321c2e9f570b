#include <ros/ros.h>

#include "asv_risk/ais_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "ais_node");
  try {
    asv_risk::AisNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("ais_node: %s", e.what());
    return 1;
  }
  return 0;
}
