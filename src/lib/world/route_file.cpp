#include "asv_core/world/route_file.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include <tinyxml2.h>

#include "asv_core/common/units.h"

namespace asv {

namespace {

using tinyxml2::XMLElement;

[[noreturn]] void fail(const std::string& source, int line, const std::string& what) {
  throw RouteFileError(source + (line > 0 ? ":" + std::to_string(line) : "") + ": " + what);
}

// An element's name without a namespace prefix ("rtz:waypoint" is a waypoint).
bool named(const XMLElement* e, const char* name) {
  const char* n = e->Name();
  const char* colon = std::strrchr(n, ':');
  return std::strcmp(colon ? colon + 1 : n, name) == 0;
}

std::vector<const XMLElement*> children(const XMLElement* parent, const char* name) {
  std::vector<const XMLElement*> out;
  for (const XMLElement* e = parent ? parent->FirstChildElement() : nullptr; e; e = e->NextSiblingElement())
    if (named(e, name))
      out.push_back(e);
  return out;
}

const XMLElement* child(const XMLElement* parent, const char* name) {
  const auto all = children(parent, name);
  return all.empty() ? nullptr : all.front();
}

// An attribute that must be a finite number, when present; nullopt when absent.
std::optional<double> number(const XMLElement* e, const char* attr, const std::string& source) {
  if (!e || !e->Attribute(attr))
    return std::nullopt;
  double v = 0.0;
  if (e->QueryDoubleAttribute(attr, &v) != tinyxml2::XML_SUCCESS || !std::isfinite(v))
    fail(source, e->GetLineNum(),
         std::string("'") + attr + "' is not a number: '" + e->Attribute(attr) + "'");
  return v;
}

Eigen::Vector2d position(const XMLElement* e, const std::string& source, const LocalFrame& frame) {
  const auto lat = number(e, "lat", source), lon = number(e, "lon", source);
  if (!lat || !lon)
    fail(source, e->GetLineNum(), "a waypoint needs lat and lon");
  if (!validLatLon(*lat, *lon))
    fail(source, e->GetLineNum(), "latitude/longitude out of range");
  return frame.toLocal(GeoPoint{*lat, *lon});
}

// RTZ's <leg> over the defaults: XTDs in nautical miles, speeds in knots.
void readLeg(const XMLElement* leg, const std::string& source, RouteWaypoint& w) {
  for (auto [attr, field] :
       {std::pair{"portsideXTD", &w.port_xtd}, std::pair{"starboardXTD", &w.starboard_xtd}})
    if (const auto nm = number(leg, attr, source)) {
      if (!(*nm > 0.0) || *nm > 10.0)
        fail(source, leg->GetLineNum(), std::string(attr) + " must be in (0, 10] nm");
      *field = nmToMetres(*nm);
    }
  const auto speed =
      number(leg, "speedMax", source) ? number(leg, "speedMax", source) : number(leg, "speedMin", source);
  if (speed) {
    if (!(*speed > 0.0) || *speed > 60.0)
      fail(source, leg->GetLineNum(), "the leg's speed must be in (0, 60] kn");
    w.speed = knotsToMps(*speed);
  }
}

Route readRtz(const XMLElement* root, const std::string& source, const LocalFrame& frame,
              std::vector<int>& lines) {
  const XMLElement* wps = child(root, "waypoints");
  if (!wps)
    fail(source, root->GetLineNum(), "an RTZ route needs <waypoints>");
  RouteWaypoint defaults;
  if (const XMLElement* d = child(wps, "defaultWaypoint"))
    readLeg(child(d, "leg"), source, defaults);
  Route route;
  for (const XMLElement* w : children(wps, "waypoint")) {
    RouteWaypoint wp = defaults;
    const XMLElement* pos = child(w, "position");
    if (!pos)
      fail(source, w->GetLineNum(), "a waypoint needs <position lat lon>");
    wp.position = position(pos, source, frame);
    readLeg(child(w, "leg"), source, wp);
    route.push_back(wp);
    lines.push_back(w->GetLineNum());
  }
  return route;
}

Route readGpx(const XMLElement* root, const std::string& source, const LocalFrame& frame,
              std::vector<int>& lines) {
  const XMLElement* rte = child(root, "rte");
  if (!rte)
    fail(source, root->GetLineNum(),
         "a GPX file needs a route (<rte>); tracks and waypoints alone are not one");
  Route route;
  for (const XMLElement* p : children(rte, "rtept")) {
    RouteWaypoint wp;
    wp.position = position(p, source, frame);
    route.push_back(wp);
    lines.push_back(p->GetLineNum());
  }
  return route;
}

}  // namespace

Route parseRouteXml(const std::string& text, const std::string& source, const LocalFrame& frame,
                    std::vector<int>* lines) {
  std::vector<int> wp_lines;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    fail(source, doc.ErrorLineNum(), std::string("not well-formed XML: ") + doc.ErrorStr());
  const XMLElement* root = doc.RootElement();
  if (!root)
    fail(source, 0, "no root element");
  Route route;
  if (named(root, "gpx"))
    route = readGpx(root, source, frame, wp_lines);
  else if (named(root, "route"))
    route = readRtz(root, source, frame, wp_lines);
  else
    fail(source, root->GetLineNum(),
         std::string("not a route file: root <") + root->Name() +
             ">, expected <gpx> (GPX 1.1) or <route> (RTZ)");
  if (route.empty())
    fail(source, root->GetLineNum(), "the route has no waypoints");
  if (lines)
    *lines = std::move(wp_lines);
  return route;
}

Route readRouteFile(const std::string& path, const LocalFrame& frame, std::vector<int>* lines) {
  std::ifstream f(path);
  if (!f)
    throw RouteFileError(path + ": cannot open route file");
  std::stringstream ss;
  ss << f.rdbuf();
  return parseRouteXml(ss.str(), path, frame, lines);
}

}  // namespace asv
