// The main() of every node of the stack: ros::init, the node's body, and a fatal start-up error (a bad
// parameter, a missing scenario file) printed on screen and sent to /rosout with its reason.
#pragma once

#include <functional>
#include <string>

#include <ros/ros.h>

namespace asv_ros {

// Runs body(nh, private nh) and returns its exit status; an exception out of it is logged with
// ROS_FATAL ("<node name>: <what>") and gives status 1. The two NodeHandles live over the whole call:
// when the last NodeHandle goes, roscpp shuts down and rosconsole drops what is logged after, which is
// why a node that failed in its constructor used to exit with status 1 and no word.
int runNode(int argc, char** argv, const std::string& name,
            const std::function<int(ros::NodeHandle&, ros::NodeHandle&)>& body);

// Ends the node from a callback after a fatal error it has logged (a map origin that disagrees): ros
// shutdown, and runNode returns 1, so that roslaunch reports the process as died, not finished cleanly.
void shutdownFatal();

// The body of a node that only spins: constructs Node(nh, pnh), spins until shutdown, returns 0.
template <class Node>
int spinNode(int argc, char** argv, const std::string& name) {
  return runNode(argc, argv, name, [](ros::NodeHandle& nh, ros::NodeHandle& pnh) {
    Node node(nh, pnh);
    ros::spin();
    return 0;
  });
}

}  // namespace asv_ros
