#include <ros/ros.h>

#include "asv_risk/tracker_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "tracker");
  try {
    asv_risk::TrackerNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("tracker: %s", e.what());
    return 1;
  }
  return 0;
}
