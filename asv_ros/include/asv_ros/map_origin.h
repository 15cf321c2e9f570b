// The one map origin of a run. The geodetic point of the `map` frame's (0, 0) is published once, latched,
// as sensor_msgs/NavSatFix on /map_origin (by the map_origin node, or by a bag that recorded it) and set
// as the global parameters /map_origin/lat_deg and /map_origin/lon_deg. Every node that converts between
// latitude/longitude and map metres takes it from there, so no two nodes can place the map differently.
#pragma once

#include <optional>
#include <string>

#include <asv_core/common/geodesy.h>
#include <ros/ros.h>
#include <sensor_msgs/NavSatFix.h>

namespace asv_ros {

constexpr const char* kMapOriginTopic = "/map_origin";
// [s, wall] default of the global /map_origin_timeout: how long a node waits for /map_origin
constexpr double kMapOriginTimeout = 30.0;
// [deg] two origins closer than this (about 1 cm) are the same origin (a YAML round trip of a double)
constexpr double kMapOriginTolerance = 1e-7;

// The latched /map_origin message for `origin` (frame_id "map", status fix, zero altitude).
sensor_msgs::NavSatFix mapOriginMessage(const asv::GeoPoint& origin, const ros::Time& stamp);

// The map origin of a node. With `given` (the node's own origin parameters or its scenario file) the
// node uses it at once and checks every /map_origin it hears against it; without, the constructor waits
// for /map_origin (at most the global /map_origin_timeout, wall seconds; progress logged every 5 s) and
// throws std::runtime_error naming the topic when none comes. A /map_origin that differs from the
// origin in use (by more than kMapOriginTolerance) is logged FATAL with both origins and shuts the
// node down: a node that placed the map elsewhere would put every ship in the wrong place.
class MapOrigin {
public:
  MapOrigin(ros::NodeHandle nh, const std::optional<asv::GeoPoint>& given);
  MapOrigin(const MapOrigin&) = delete;  // its subscriber's callback holds `this`
  MapOrigin& operator=(const MapOrigin&) = delete;

  asv::GeoPoint get() const { return origin_; }
  bool fromTopic() const { return from_topic_; }  // false: the node's own origin

private:
  void check(const sensor_msgs::NavSatFix& msg);

  asv::GeoPoint origin_;
  bool from_topic_ = false;
  ros::Subscriber sub_;
};

}  // namespace asv_ros
