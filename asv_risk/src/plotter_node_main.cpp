#include <asv_ros/node_main.h>

#include "asv_risk/plotter_node.h"

int main(int argc, char** argv) {
  return asv_ros::spinNode<asv_risk::PlotterNode>(argc, argv, "plotter_node");
}
