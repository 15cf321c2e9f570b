#include <asv_ros/node_main.h>

#include "asv_planning/planner_node.h"

int main(int argc, char** argv) {
  return asv_ros::spinNode<asv_planning::PlannerNode>(argc, argv, "planner_node");
}
