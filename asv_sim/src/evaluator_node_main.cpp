#include <ros/ros.h>

#include "asv_sim/evaluator_node.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "evaluator_node");
  try {
    asv_sim::EvaluatorNode node(ros::NodeHandle(), ros::NodeHandle("~"));
    ros::spin();
  } catch (const std::exception& e) {
    ROS_FATAL("evaluator_node: %s", e.what());
    return 1;
  }
  return 0;
}
