#include <ros/ros.h>

#include "asv_risk/arpa_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "arpa_node");
  try {
    asv_risk::ArpaNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("arpa_node: %s", e.what());
    return 1;
  }
  return 0;
}
