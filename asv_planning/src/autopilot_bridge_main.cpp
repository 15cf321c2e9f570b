#include <asv_ros/node_main.h>

#include "asv_planning/autopilot_bridge_node.h"

int main(int argc, char** argv) {
  return asv_ros::spinNode<asv_planning::AutopilotBridgeNode>(argc, argv, "autopilot_bridge");
}
