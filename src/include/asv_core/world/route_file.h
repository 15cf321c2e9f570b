// Route files, as chart plotters and ECDIS export them, read into a voyage plan (route.h):
//  - GPX 1.1 (OpenCPN and most plotters): the first <rte>, its <rtept lat lon> in order; GPX gives no
//    speeds or corridors;
//  - RTZ (IEC 61174's route exchange format, versions 1.0 to 1.2): <waypoints>/<waypoint>, each with
//    <position lat lon> and an optional <leg> for the leg that leads to it: portsideXTD and starboardXTD
//    in nautical miles, speedMax in knots (the leg's planned speed; speedMin when only it is given);
//    <defaultWaypoint>'s <leg> gives the defaults.
// XML is parsed by tinyxml2. Errors name the file and line: a malformed file, a missing or out-of-range
// latitude, longitude, XTD or speed, a route without waypoints.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "asv_core/common/geodesy.h"
#include "asv_core/world/route.h"

namespace asv {

class RouteFileError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// A route file's text (`source` names it in errors): GPX or RTZ, told by its root element (<gpx> or
// <route>). Positions in `frame`; `lines`, when given, gets each waypoint's line. Throws RouteFileError.
Route parseRouteXml(const std::string& text, const std::string& source, const LocalFrame& frame,
                    std::vector<int>* lines = nullptr);
// The same for a file. Throws RouteFileError (also when it cannot be read).
Route readRouteFile(const std::string& path, const LocalFrame& frame, std::vector<int>* lines = nullptr);

}  // namespace asv
