// rviz markers of the simulator (sim_node.h): the ships, their trails and names, the summary box, land
// and the clearance zones round it. Drawing only: nothing here changes the simulation or its topics.
#include "asv_sim/sim_node.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <asv_ros/conversions.h>
#include <geometry_msgs/Point.h>
#include <visualization_msgs/MarkerArray.h>

namespace asv_sim {

// Ship i's marker (a box drawn at least 30 px long, faded once she has arrived), her trail and her name.
void SimNode::addShipMarkers(size_t i, const asv_msgs::Target& t, double yaw, const ros::Time& stamp,
                             visualization_msgs::MarkerArray& markers) {
  const asv::SimVessel& v = sim_->vessels()[i];
  visualization_msgs::Marker m;
  m.header.stamp = stamp;
  m.header.frame_id = "map";
  m.ns = "ships";
  m.id = static_cast<int>(i);
  m.type = visualization_msgs::Marker::CUBE;
  m.pose.position = t.position;
  m.pose.orientation = asv_ros::yawToQuaternion(yaw);
  // Drawn at least 30 px long so that ships stay visible at scenario scale.
  const double scale = std::max(1.0, asv_ros::pixelsToMetres(30.0) / std::max(1.0, v.length));
  m.scale.x = v.length * scale;
  m.scale.y = v.beam * scale;
  m.scale.z = 5.0;
  m.color.a = v.arrived ? 0.3f : 1.0f;
  // Own blue, targets light magenta: apart from the grid, the risk colours and the summary marks.
  m.color.r = v.own ? 0.1f : 0.95f;
  m.color.g = v.own ? 0.4f : 0.6f;
  m.color.b = v.own ? 1.0f : 0.95f;
  m.pose.position.z = 2.0;  // above the trails and the grid (top-down view: drawn last)
  markers.markers.push_back(m);
  addTrail(i, m, markers);
  m.ns = "names";
  m.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
  m.pose.position.y += asv_ros::pixelsToMetres(27.0);
  m.scale.z = asv_ros::pixelsToMetres(15.0);
  m.text = v.name;
  m.color.r = m.color.g = m.color.b = 1.0f;
  markers.markers.push_back(m);
}

// Ship i's trail (the whole track: every other point dropped past 2000, for bounded memory), in the
// colour of her marker `ship`.
void SimNode::addTrail(size_t i, const visualization_msgs::Marker& ship,
                       visualization_msgs::MarkerArray& arr) {
  auto& trail = trails_[i];
  geometry_msgs::Point tp = ship.pose.position;
  tp.z = 0.0;
  if (trail.empty() || std::hypot(trail.back().x - tp.x, trail.back().y - tp.y) > 20.0)
    trail.push_back(tp);
  if (trail.size() > 2000) {
    for (size_t k = 1; 2 * k < trail.size(); ++k)
      trail[k] = trail[2 * k];
    trail.resize((trail.size() + 1) / 2);
  }
  if (trail.size() < 2)
    return;
  visualization_msgs::Marker tr;
  tr.header = ship.header;
  tr.ns = "trails";
  tr.id = static_cast<int>(i);
  tr.type = visualization_msgs::Marker::LINE_STRIP;
  tr.pose.orientation.w = 1.0;
  tr.pose.position.z = 1.0;  // above the grid, whose lines a track may follow
  tr.scale.x = asv_ros::pixelsToMetres(3.0);
  tr.color = ship.color;
  tr.color.a = 1.0f;  // opaque, arrived or not: drawn over the plan line where she followed it
  tr.points = trail;
  arr.markers.push_back(tr);
}

namespace {

std::string clockText(double t) {
  const long s = std::lround(std::max(0.0, t));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

visualization_msgs::Marker summaryMarker(const std::string& ns, int id, int type, float r, float g, float b) {
  visualization_msgs::Marker m;
  m.header.frame_id = "map";
  m.ns = ns;
  m.id = id;
  m.type = type;
  m.pose.orientation.w = 1.0;
  m.pose.position.z = 3.0;  // over the ships and trails
  m.color.r = r;
  m.color.g = g;
  m.color.b = b;
  m.color.a = 1.0f;
  return m;
}

geometry_msgs::Point point(const Eigen::Vector2d& p, double dy = 0.0) {
  geometry_msgs::Point q;
  q.x = p.x();
  q.y = p.y() + dy;
  q.z = 3.0;
  return q;
}

}  // namespace

void SimNode::publishSummary() {
  std::map<std::string, Eigen::Vector2d> targets;
  const asv::SimVessel* own = nullptr;
  for (const asv::SimVessel& v : sim_->vessels())
    if (v.own)
      own = &v;
    else
      targets[v.name] = v.position();
  if (!own)
    return;
  summary_.update(sim_->time(), own->position(), own->cog(), targets);
  const std::string& own_name = own->name;
  visualization_msgs::MarkerArray arr;
  const double text = asv_ros::pixelsToMetres(14.0);
  int id = 0;
  for (const auto& [name, c] : summary_.closest()) {
    auto line = summaryMarker("closest", id++, visualization_msgs::Marker::LINE_LIST, 1.0f, 0.3f, 0.3f);
    line.scale.x = 0.15 * text;
    line.points = {point(c.own), point(c.target)};
    arr.markers.push_back(line);
    auto dot = summaryMarker("closest", id++, visualization_msgs::Marker::SPHERE, 1.0f, 0.3f, 0.3f);
    dot.pose.position = point(c.target);
    dot.scale.x = dot.scale.y = dot.scale.z = 0.6 * text;
    arr.markers.push_back(dot);
    auto label =
        summaryMarker("closest", id++, visualization_msgs::Marker::TEXT_VIEW_FACING, 1.0f, 0.6f, 0.6f);
    label.pose.position = point(c.target, -1.2 * text);
    label.scale.z = text;
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s CPA %.2f nm at %s", name.c_str(), asv::metresToNm(c.distance),
                  clockText(c.t).c_str());
    label.text = buf;
    arr.markers.push_back(label);
  }
  for (const asv::CourseAlteration& m : summary_.manoeuvres()) {
    auto dot = summaryMarker("manoeuvres", id++, visualization_msgs::Marker::SPHERE, 1.0f, 0.85f, 0.1f);
    dot.pose.position = point(m.position);
    dot.scale.x = dot.scale.y = dot.scale.z = 0.6 * text;
    arr.markers.push_back(dot);
    auto label =
        summaryMarker("manoeuvres", id++, visualization_msgs::Marker::TEXT_VIEW_FACING, 1.0f, 0.85f, 0.1f);
    label.pose.position = point(m.position, 1.2 * text);
    label.scale.z = text;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s %03.0f -> %03.0f", clockText(m.t).c_str(),
                  asv::wrapDeg360(asv::radToDeg(m.course_from)), asv::wrapDeg360(asv::radToDeg(m.course_to)));
    label.text = buf;
    arr.markers.push_back(label);
  }
  auto hud = summaryMarker("clock", 0, visualization_msgs::Marker::TEXT_VIEW_FACING, 1.0f, 1.0f, 1.0f);
  hud.pose.position = point({scene_box_.min.x() + 0.2 * (scene_box_.max.x() - scene_box_.min.x()),
                             scene_box_.max.y() - 1.5 * text});
  hud.scale.z = 1.5 * text;
  std::string rate = "as fast as possible";
  if (params_.lockstep)
    rate = "lockstep";
  else if (params_.rate > 0.0)
    rate = "x" + std::to_string(std::lround(params_.rate));
  hud.text = sim_->scenario().name + "  t " + clockText(sim_->time()) + "  " + rate + "  own: " + own_name;
  arr.markers.push_back(hud);
  summary_pub_.publish(arr);
}

// The scenario's static obstacles, filled (latched: rviz draws them whenever it joins).
void SimNode::publishLand() {
  visualization_msgs::MarkerArray arr;
  int id = 0;
  for (const auto& o : sim_->scenario().obstacles) {
    visualization_msgs::Marker m;
    m.header.frame_id = "map";
    m.header.stamp = ros::Time(kEpoch);
    m.ns = "land";
    m.id = id++;
    m.type = visualization_msgs::Marker::TRIANGLE_LIST;
    m.pose.orientation.w = 1.0;
    m.scale.x = m.scale.y = m.scale.z = 1.0;
    m.color.r = 0.76f;  // sand
    m.color.g = 0.70f;
    m.color.b = 0.50f;
    m.color.a = 0.9f;
    for (const auto& t : asv::triangulate(o.polygon))
      for (int k : t) {
        geometry_msgs::Point p;
        p.x = o.polygon[k].x();
        p.y = o.polygon[k].y();
        m.points.push_back(p);
      }
    if (!m.points.empty())
      arr.markers.push_back(m);
  }
  addClearanceZones(arr);
  land_pub_.publish(arr);
}

// The clearance zone every planner keeps from land (the scenario's, else the plan follower's default),
// as a dashed outline round each obstacle.
void SimNode::addClearanceZones(visualization_msgs::MarkerArray& arr) const {
  const double scenario_clearance = sim_->scenario().min_obstacle_clearance;
  const double clearance =
      scenario_clearance > 0.0 ? scenario_clearance : asv::PlanFollowerConfig{}.min_obstacle_clearance_m;
  int id = 0;
  for (const auto& o : sim_->scenario().obstacles) {
    for (const auto& ring : asv::offsetOutline(o.polygon, clearance)) {
      visualization_msgs::Marker m;
      m.header.frame_id = "map";
      m.header.stamp = ros::Time(kEpoch);
      m.ns = "clearance";
      m.id = id++;
      m.type = visualization_msgs::Marker::LINE_LIST;  // every other segment: a dashed line
      m.pose.orientation.w = 1.0;
      m.scale.x = 25.0;  // [m] line width: visible at harbour zoom
      m.color.r = 0.85f;
      m.color.g = 0.45f;
      m.color.b = 0.10f;
      m.color.a = 0.9f;
      for (size_t i = 0; i + 1 < ring.size(); i += 2)
        for (size_t k : {i, i + 1}) {
          geometry_msgs::Point p;
          p.x = ring[k].x();
          p.y = ring[k].y();
          m.points.push_back(p);
        }
      arr.markers.push_back(m);
    }
  }
}

}  // namespace asv_sim
