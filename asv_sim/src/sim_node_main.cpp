#include <asv_ros/node_main.h>

#include "asv_sim/sim_node.h"

int main(int argc, char** argv) {
  return asv_ros::runNode(argc, argv, "sim_node", [](ros::NodeHandle& nh, ros::NodeHandle& pnh) {
    asv_sim::SimNode node(nh, pnh);
    return node.run();
  });
}
