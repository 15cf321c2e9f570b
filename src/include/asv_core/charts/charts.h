// Land from charts: polygons of the land round a scenario's origin, in its local ENU frame, read from
// GSHHG shorelines (through GMT, Debian's gmt and gmt-gshhg-* packages) or from a user's chart file
// (GeoJSON, ESRI shapefile, S-57 ENC cell: anything GDAL/OGR reads). Every source goes through the
// same steps: clip to the area, project, simplify, resolve holes, cache.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "asv_core/common/geodesy.h"
#include "asv_core/common/geometry.h"
#include "asv_core/common/param_map.h"

namespace asv {

class ChartError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

struct ChartSpec {
  // "gshhg" or a file path: .geojson/.json, .shp, an S-57 cell (.000), or any OGR vector source.
  std::string source;
  // GSHHG resolution: crude, low, intermediate, high or full. Full (our default) is the only one that
  // keeps harbours and rivers navigable: at high, New York's East River is partly land.
  std::string resolution = "full";
  // File sources: the layer to read; empty: every polygon layer, except S-57 cells, where it is
  // LNDARE (land areas), the only S-57 object class that is land.
  std::string layer;
  double radius_m = 10000.0;  // half side of the square round the origin that is kept [m]
  // Douglas-Peucker tolerance of the topology-preserving simplification [m]; 0: none. 10 m is our
  // choice: far below any clearance a planner keeps, it thins only wiggles no ship could use.
  double simplify_m = 10.0;
  // Where extractions are cached (one file per source, area and settings); empty: no cache.
  std::string cache_dir;

  // ChartError naming the setting that is out of range (inline: the scenario parser checks a
  // charts key without linking GDAL).
  void validate() const;
};

// How a program loads the charts a scenario names: the launch argument `charts` and asv_batch's
// --charts override the scenario's charts.source (or add charts to a scenario with an origin), so that
// a boat's own ENC cells replace GSHHG without editing the scenario. Node parameters `charts` and
// `chart_cache_dir` (sim_node, planner_node, evaluator_node read them through fromParams).
struct ChartOptions {
  std::string source;     // empty: the scenario's own charts.source
  std::string cache_dir;  // empty: defaultChartCacheDir(); "none": no cache
  bool load = true;       // false: parse the charts key only (a node that needs the origin alone)
  // An own ship starting on the land is an error; false: asv_scenario_from_ais, which reads the land
  // first to move a logged start off it (within the chart's accuracy).
  bool own_afloat = true;

  static ChartOptions fromParams(const ParamMap& params);
};

// The GSHHG resolution letter GMT takes (-D) for a resolution name; throws ChartError for another name.
// Inline: the scenario parser checks names without linking GDAL.
inline char gshhgResolutionCode(const std::string& resolution) {
  const char* names[] = {"crude", "low", "intermediate", "high", "full"};
  for (const char* n : names)
    if (resolution == n)
      return n[0];
  throw ChartError("charts: resolution '" + resolution +
                   "' is not one of crude, low, intermediate, high, full");
}

// The land round `frame`'s origin, as simple polygons (no holes) in its ENU frame [m].
// Water that the point `water` (ENU, e.g. the own ship's start) cannot reach inside the square (a lake,
// a pond on an island) is land to a surface vessel: such holes are filled. When `water` itself lies in
// a hole of a land polygon (a ship on a lake), that polygon is cut open along a bridge from the hole to
// its outline (a keyhole), so that the crossing rule still finds the lake water outside the land.
// Throws ChartError naming the source and what went wrong (file unreadable, no such layer, GMT missing).
std::vector<Polygon> loadChartLand(const ChartSpec& spec, const LocalFrame& frame,
                                   const Eigen::Vector2d& water);

// The cache file an extraction would be kept in (cache_dir/land-<hash>.txt); empty without cache_dir.
std::string chartCachePath(const ChartSpec& spec, const LocalFrame& frame, const Eigen::Vector2d& water);

// A polyline thinned by Douglas-Peucker (GEOS through OGR, as the charts' outlines): the points kept are
// points of `line` (the first and the last always), none farther than `tolerance` [m] from the result.
std::vector<Eigen::Vector2d> simplifyPolyline(const std::vector<Eigen::Vector2d>& line, double tolerance);

// The default cache folder: $ASV_CHART_CACHE, else $XDG_CACHE_HOME/asv/charts, else ~/.cache/asv/charts.
std::string defaultChartCacheDir();

inline void ChartSpec::validate() const {
  if (source.empty())
    throw ChartError("charts: no source (gshhg or a chart file)");
  if (!(radius_m > 0.0) || radius_m > 500e3)
    throw ChartError("charts: radius_m must be in (0, 500000] m");
  if (!(simplify_m >= 0.0))
    throw ChartError("charts: simplify_m must be >= 0 m");
  if (source == "gshhg")
    gshhgResolutionCode(resolution);
}

}  // namespace asv
