#include <asv_ros/node_main.h>

#include "asv_sim/evaluator_node.h"

int main(int argc, char** argv) {
  return asv_ros::spinNode<asv_sim::EvaluatorNode>(argc, argv, "evaluator_node");
}
