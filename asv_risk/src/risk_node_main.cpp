#include <asv_ros/node_main.h>

#include "asv_risk/risk_node.h"

int main(int argc, char** argv) {
  return asv_ros::spinNode<asv_risk::RiskNode>(argc, argv, "risk_node");
}
