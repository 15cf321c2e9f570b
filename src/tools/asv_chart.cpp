// asv_chart: the land round a point (or a scenario's origin) from GSHHG or a chart file, as the
// simulator and planners see it: local ENU polygons, printed as a summary and written as GeoJSON
// (lon/lat, for any GIS) or as local-frame text.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>

#include "asv_core/charts/charts.h"
#include "asv_core/world/scenario.h"
#include "tool_main.h"

namespace {

using namespace asv;

const char* const kUsage =
    "usage: asv_chart (--scenario FILE | --lat DEG --lon DEG) [--source gshhg|FILE]\n"
    "                 [--resolution NAME] [--layer NAME] [--radius M] [--simplify M]\n"
    "                 [--cache DIR|none] [--geojson OUT] [--local OUT] [-h|--help]\n"
    "\n"
    "Extracts the land round a point as the asv stack uses it: clipped to a square of half side\n"
    "--radius round the point, projected to its local ENU frame, simplified, unreachable lakes filled.\n"
    "Prints the number of polygons and vertices and the land's extent. With --scenario, the land is\n"
    "all of the scenario's obstacles: its static_obstacles and its chart land.\n"
    "\n"
    "  --scenario FILE    a scenario with a charts key: its origin, own-ship start and chart settings\n"
    "                     (--resolution, --layer, --radius, --simplify are then refused)\n"
    "  --lat, --lon DEG   the origin, without a scenario (the point itself must be water)\n"
    "  --source S         gshhg (default) or a chart file: GeoJSON, ESRI shapefile, S-57 cell (.000)\n"
    "  --resolution NAME  GSHHG: crude | low | intermediate | high (default) | full\n"
    "  --layer NAME       chart file layer (default: every layer; S-57: LNDARE)\n"
    "  --radius M         half side of the square [m] (default 10000)\n"
    "  --simplify M       simplification tolerance [m] (default 10; 0: none)\n"
    "  --cache DIR|none   cache folder (default $ASV_CHART_CACHE or ~/.cache/asv/charts)\n"
    "  --geojson OUT      write the land as a GeoJSON FeatureCollection (lon/lat)\n"
    "  --local OUT        write the land as text: 'polygon N' then N lines 'x y' (ENU metres)\n"
    "  -h, --help         this help\n"
    "\n"
    "Exit status: 0, 1 when the chart cannot be read or OUT written, 2 on a usage error.\n";

struct Args {
  std::string scenario, geojson, local, cache;
  double lat = 1e9, lon = 1e9;
  ChartSpec spec;
  bool source_given = false;
  bool settings_given = false;  // --resolution, --layer, --radius or --simplify
};

bool parse(int argc, char** argv, Args& a) {
  a.spec.source = "gshhg";
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if (k == "-h" || k == "--help") {
      std::cout << kUsage;
      std::exit(0);
    }
    if (i + 1 >= argc)
      return false;
    const std::string v = argv[++i];
    char* end = nullptr;
    const double num = std::strtod(v.c_str(), &end);
    const bool is_num = end && *end == '\0' && !v.empty();
    if (k == "--scenario")
      a.scenario = v;
    else if (k == "--lat" && is_num)
      a.lat = num;
    else if (k == "--lon" && is_num)
      a.lon = num;
    else if (k == "--source")
      a.spec.source = v, a.source_given = true;
    else if (k == "--resolution")
      a.spec.resolution = v, a.settings_given = true;
    else if (k == "--layer")
      a.spec.layer = v, a.settings_given = true;
    else if (k == "--radius" && is_num)
      a.spec.radius_m = num, a.settings_given = true;
    else if (k == "--simplify" && is_num)
      a.spec.simplify_m = num, a.settings_given = true;
    else if (k == "--cache")
      a.cache = v;
    else if (k == "--geojson")
      a.geojson = v;
    else if (k == "--local")
      a.local = v;
    else
      return false;
  }
  if (!a.scenario.empty() && a.settings_given) {
    std::cerr << "asv_chart: with --scenario the chart settings are the scenario's charts key; only "
                 "--source and --cache apply\n";
    return false;
  }
  return !a.scenario.empty() || (validLatLon(a.lat, a.lon));
}

void writeGeoJson(std::ostream& f, const std::vector<Polygon>& land, const LocalFrame& frame) {
  f.precision(10);
  f << "{\"type\": \"FeatureCollection\", \"features\": [\n";
  for (size_t i = 0; i < land.size(); ++i) {
    f << "{\"type\": \"Feature\", \"properties\": {\"name\": \"land " << i + 1
      << "\"}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[";
    for (size_t k = 0; k <= land[i].size(); ++k) {
      const GeoPoint g = frame.toGeodetic(land[i][k % land[i].size()]);
      f << (k ? ", " : "") << '[' << g.lon_deg << ", " << g.lat_deg << ']';
    }
    f << "]]}}" << (i + 1 < land.size() ? "," : "") << '\n';
  }
  f << "]}\n";
}

int run(const Args& a) {
  std::vector<Polygon> land;
  LocalFrame frame(0.0, 0.0);
  if (!a.scenario.empty()) {
    ChartOptions o;
    o.source = a.source_given ? a.spec.source : "";
    o.cache_dir = a.cache;
    const Scenario s = loadScenario(a.scenario, o);
    frame = s.frame();
    for (const auto& ob : s.obstacles)  // static_obstacles and chart land alike
      land.push_back(ob.polygon);
  } else {
    frame = LocalFrame(a.lat, a.lon);
    ChartSpec spec = a.spec;
    spec.cache_dir = a.cache == "none" ? "" : a.cache.empty() ? defaultChartCacheDir() : a.cache;
    land = loadChartLand(spec, frame, Eigen::Vector2d::Zero());
  }
  size_t vertices = 0;
  Eigen::AlignedBox2d extent;
  for (const auto& p : land) {
    vertices += p.size();
    extent.extend(boundingBox(p));
  }
  std::printf("land: %zu polygons, %zu vertices", land.size(), vertices);
  if (!land.empty())
    std::printf(", extent x %.0f..%.0f m, y %.0f..%.0f m", extent.min().x(), extent.max().x(),
                extent.min().y(), extent.max().y());
  std::printf("\n");
  if (!a.geojson.empty()) {
    std::ofstream f(a.geojson);
    writeGeoJson(f, land, frame);
    if (!f)
      throw std::runtime_error(a.geojson + ": cannot write");
  }
  if (!a.local.empty()) {
    std::ofstream f(a.local);
    f.precision(10);
    for (const auto& p : land) {
      f << "polygon " << p.size() << '\n';
      for (const auto& v : p)
        f << v.x() << ' ' << v.y() << '\n';
    }
    if (!f)
      throw std::runtime_error(a.local + ": cannot write");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return toolMain<Args>("asv_chart", kUsage, argc, argv, parse, run);
}
