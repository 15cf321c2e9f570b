// OGR helpers private to the charts stage: owning geometry pointers and the geographic box of an area.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <ogr_geometry.h>

#include "asv_core/common/geodesy.h"

namespace asv::charts_detail {

struct GeomDeleter {
  void operator()(OGRGeometry* g) const { OGRGeometryFactory::destroyGeometry(g); }
};
using GeomPtr = std::unique_ptr<OGRGeometry, GeomDeleter>;

// Longitude/latitude bounds [deg] that cover a local square (with a margin).
struct LonLatBox {
  double west = 0.0, east = 0.0, south = 0.0, north = 0.0;
};
LonLatBox geoBox(const LocalFrame& frame, double half_side_m);
// The box as a closed polygon, in lon/lat.
GeomPtr boxPolygon(const LonLatBox& box);

// Land polygons in lon/lat (WGS84, x = lon) of GSHHG inside `box`, through GMT (charts/gshhg.cpp).
std::vector<GeomPtr> readGshhgLand(char resolution_code, const LonLatBox& box);

}  // namespace asv::charts_detail
