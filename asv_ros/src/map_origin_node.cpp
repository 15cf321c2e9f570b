// map_origin: the one source of the map origin of a run (asv_ros/map_origin.h). Takes it from a scenario
// file (`scenario`; a scenario without `origin` places the map at 0 N 0 E, the simulator's documented
// default, with a warning) or from `lat_deg`/`lon_deg`; sets /map_origin/lat_deg and /map_origin/lon_deg
// and publishes it latched on /map_origin, then stays up so that late subscribers (and rosbag record)
// get it. Parameters: asv_ros/config/map_origin.yaml.
#include <asv_core/world/scenario.h>
#include <asv_ros/map_origin.h>
#include <asv_ros/node_main.h>
#include <asv_ros/params.h>

#include <stdexcept>

namespace {

asv::GeoPoint originFromParams(const ros::NodeHandle& pnh) {
  const asv::ParamMap p = asv_ros::readParams(pnh);
  const std::string scenario = p.getString("scenario", "");
  const bool given = p.has("lat_deg") || p.has("lon_deg");
  if (given && !(p.has("lat_deg") && p.has("lon_deg")))
    throw std::invalid_argument("give both lat_deg and lon_deg (the map origin)");
  asv::GeoPoint o{p.getDouble("lat_deg", 0.0), p.getDouble("lon_deg", 0.0)};
  asv_ros::rejectUnknown(p, "config/map_origin.yaml");
  if (given == !scenario.empty())
    throw std::invalid_argument("give either scenario or lat_deg/lon_deg (the map origin), not " +
                                std::string(given ? "both" : "neither"));
  if (!scenario.empty()) {
    const asv::Scenario s =
        asv::loadScenario(scenario, asv::ChartOptions{"", "", false});  // names file, line, key
    if (!s.has_origin)
      ROS_WARN(
          "map_origin: scenario '%s' has no origin: the map origin is 0 N 0 E (the default); give the "
          "scenario an origin to place it on the chart",
          scenario.c_str());
    o = s.origin;
  }
  if (!asv::validLatLon(o.lat_deg, o.lon_deg))
    throw std::invalid_argument("lat_deg/lon_deg out of range (the map origin)");
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  return asv_ros::runNode(argc, argv, "map_origin_node", [](ros::NodeHandle& nh, ros::NodeHandle& pnh) {
    const asv::GeoPoint o = originFromParams(pnh);
    nh.setParam("/map_origin/lat_deg", o.lat_deg);
    nh.setParam("/map_origin/lon_deg", o.lon_deg);
    ros::Publisher pub = nh.advertise<sensor_msgs::NavSatFix>(asv_ros::kMapOriginTopic, 1, true);
    // Stamped with wall time: under /use_sim_time the clock may not run yet, and the origin is timeless.
    pub.publish(asv_ros::mapOriginMessage(o, ros::Time(ros::WallTime::now().toSec())));
    ROS_INFO("map_origin: %.7f %.7f on %s", o.lat_deg, o.lon_deg, asv_ros::kMapOriginTopic);
    ros::spin();
    return 0;
  });
}
