#include <asv_ros/node_main.h>

#include "asv_risk/arpa_node.h"

int main(int argc, char** argv) {
  return asv_ros::spinNode<asv_risk::ArpaNode>(argc, argv, "arpa_node");
}
