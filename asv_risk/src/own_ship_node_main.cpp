#include <asv_ros/node_main.h>

#include "asv_risk/own_ship_node.h"

int main(int argc, char** argv) {
  return asv_ros::spinNode<asv_risk::OwnShipNode>(argc, argv, "own_ship_node");
}
