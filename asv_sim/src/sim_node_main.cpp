#include <ros/ros.h>

#include "asv_sim/sim_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "sim_node");
  try {
    asv_sim::SimNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    return node.run();
  } catch (const std::exception& e) {
    ROS_FATAL("sim_node: %s", e.what());
    return 1;
  }
}
