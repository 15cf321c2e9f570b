#include "asv_ros/map_origin.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <ros/callback_queue.h>

#include "asv_ros/node_main.h"
#include "asv_ros/params.h"

namespace asv_ros {

namespace {

std::string describe(const asv::GeoPoint& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.7f %.7f", p.lat_deg, p.lon_deg);
  return buf;
}

asv::GeoPoint pointOf(const sensor_msgs::NavSatFix& msg) {
  return {msg.latitude, msg.longitude};
}

// The first /map_origin, waited for on a queue of its own (the node's other callbacks do not run yet).
asv::GeoPoint waitForOrigin(const ros::NodeHandle& nh, const std::string& node) {
  double timeout = kMapOriginTimeout;
  getParam(nh, "/map_origin_timeout", timeout);
  if (!(timeout > 0.0 && std::isfinite(timeout)))
    throw std::invalid_argument("/map_origin_timeout must be a finite number of seconds > 0");
  ros::CallbackQueue queue;
  ros::NodeHandle wait_nh(nh);
  wait_nh.setCallbackQueue(&queue);
  std::optional<asv::GeoPoint> got;
  const ros::Subscriber sub = wait_nh.subscribe<sensor_msgs::NavSatFix>(
      kMapOriginTopic, 1, [&got](const sensor_msgs::NavSatFixConstPtr& m) { got = pointOf(*m); });
  const ros::WallTime start = ros::WallTime::now();
  ros::WallTime next_note = start;
  while (!got && ros::ok()) {
    const double waited = (ros::WallTime::now() - start).toSec();
    if (waited >= timeout)
      throw std::runtime_error("no map origin: nothing was published on " + std::string(kMapOriginTopic) +
                               " within " + std::to_string(static_cast<int>(timeout)) +
                               " s (/map_origin_timeout). Start the map_origin node (asv_ros), give the node "
                               "origin_lat_deg/origin_lon_deg, or replay a bag that recorded /map_origin");
    if (ros::WallTime::now() >= next_note) {
      ROS_INFO("%s: waiting for the map origin on %s (%.0f of %.0f s)", node.c_str(), kMapOriginTopic, waited,
               timeout);
      next_note += ros::WallDuration(5.0);
    }
    queue.callAvailable(ros::WallDuration(0.05));
  }
  if (!got)
    throw std::runtime_error("shut down while waiting for the map origin on " + std::string(kMapOriginTopic));
  if (!asv::validLatLon(got->lat_deg, got->lon_deg))
    throw std::runtime_error("the map origin on " + std::string(kMapOriginTopic) +
                             " is no position: " + describe(*got));
  return *got;
}

}  // namespace

sensor_msgs::NavSatFix mapOriginMessage(const asv::GeoPoint& origin, const ros::Time& stamp) {
  sensor_msgs::NavSatFix m;
  m.header.stamp = stamp;
  m.header.frame_id = "map";
  m.status.status = sensor_msgs::NavSatStatus::STATUS_FIX;
  m.status.service = sensor_msgs::NavSatStatus::SERVICE_GPS;
  m.latitude = origin.lat_deg;
  m.longitude = origin.lon_deg;
  m.altitude = 0.0;
  m.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN;
  return m;
}

MapOrigin::MapOrigin(ros::NodeHandle nh, const std::optional<asv::GeoPoint>& given) {
  const std::string& node = ros::this_node::getName();
  if (given) {
    origin_ = *given;
  } else {
    origin_ = waitForOrigin(nh, node);
    from_topic_ = true;
  }
  ROS_INFO("%s: map origin %s (%s)", node.c_str(), describe(origin_).c_str(),
           from_topic_ ? kMapOriginTopic : "own parameters");
  sub_ = nh.subscribe<sensor_msgs::NavSatFix>(kMapOriginTopic, 10,
                                              [this](const sensor_msgs::NavSatFixConstPtr& m) { check(*m); });
}

void MapOrigin::check(const sensor_msgs::NavSatFix& msg) {
  const asv::GeoPoint p = pointOf(msg);
  if (std::fabs(p.lat_deg - origin_.lat_deg) <= kMapOriginTolerance &&
      std::fabs(p.lon_deg - origin_.lon_deg) <= kMapOriginTolerance)
    return;
  ROS_FATAL(
      "%s: %s says the map origin is %s, but this node uses %s (%s): two map origins would put every "
      "ship in the wrong place; shutting down",
      ros::this_node::getName().c_str(), kMapOriginTopic, describe(p).c_str(), describe(origin_).c_str(),
      from_topic_ ? "the first /map_origin heard" : "its own parameters");
  ros::WallDuration(0.5).sleep();  // rosout publishes from its own thread: let the reason go out first
  shutdownFatal();
}

}  // namespace asv_ros
