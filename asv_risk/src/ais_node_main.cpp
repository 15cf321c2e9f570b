#include <asv_ros/node_main.h>

#include "asv_risk/ais_node.h"

int main(int argc, char** argv) {
  return asv_ros::spinNode<asv_risk::AisNode>(argc, argv, "ais_node");
}
