#include "asv_ros/node_main.h"

#include <atomic>
#include <exception>

#include <ros/topic_manager.h>

namespace asv_ros {

namespace {
std::atomic<bool> fatal{false};
}  // namespace

void shutdownFatal() {
  fatal = true;
  ros::shutdown();
}

int runNode(int argc, char** argv, const std::string& name,
            const std::function<int(ros::NodeHandle&, ros::NodeHandle&)>& body) {
  ros::init(argc, argv, name);
  ros::NodeHandle nh, pnh("~");
  try {
    const int status = body(nh, pnh);
    return fatal ? 1 : status;
  } catch (const std::exception& e) {
    // /rosout (rqt_console, the launch's log) drops what is logged before the rosout node has
    // connected, and a node failing in its constructor is only a few ms old: wait for the connection
    // (at most 2 s, then the message is at least on screen), log, and give the sending thread a moment.
    const ros::WallTime give_up = ros::WallTime::now() + ros::WallDuration(2.0);
    while (ros::TopicManager::instance()->getNumSubscribers("/rosout") == 0 && ros::WallTime::now() < give_up)
      ros::WallDuration(0.02).sleep();
    ROS_FATAL("%s: %s", ros::this_node::getName().c_str(), e.what());
    ros::WallDuration(0.3).sleep();
    return 1;
  }
}

}  // namespace asv_ros
