// Reading a scenario file and loading the land of its charts (kept apart from the parser, which the
// fuzzer builds without GDAL).
#include <fstream>
#include <sstream>

#include "asv_core/world/scenario.h"

namespace asv {

void loadCharts(Scenario& s, const ChartOptions& options) {
  if (!options.load)
    return;
  if (!options.source.empty()) {
    if (!s.has_origin)
      throw ScenarioError(s.source + ": charts '" + options.source + "' need the scenario's origin");
    if (!s.charts)
      s.charts = ChartSpec{};
    s.charts->source = options.source;
  }
  if (!s.charts)
    return;
  ChartSpec spec = *s.charts;
  spec.cache_dir = options.cache_dir == "none" ? ""
                   : options.cache_dir.empty() ? defaultChartCacheDir()
                                               : options.cache_dir;
  std::vector<Polygon> land;
  try {
    land = loadChartLand(spec, s.frame(), s.own.position);
  } catch (const ChartError& e) {
    throw ScenarioError(s.source + ": 'charts': " + e.what());
  }
  for (size_t i = 0; i < land.size(); ++i) {
    if (options.own_afloat && pointInPolygon(land[i], s.own.position))
      throw ScenarioError(s.source + ": 'charts': the own ship starts on land (" + spec.source + ")");
    s.obstacles.push_back({"land " + std::to_string(i + 1), std::move(land[i]), nullptr});
  }
  indexObstacles(s.obstacles);
  if (options.own_afloat)
    checkRouteOffLand(s);
}

Scenario loadScenario(const std::string& path, const ChartOptions& options) {
  std::ifstream f(path);
  if (!f)
    throw ScenarioError(path + ": cannot open scenario file");
  std::stringstream ss;
  ss << f.rdbuf();
  Scenario s = parseScenario(ss.str(), path);
  loadCharts(s, options);
  return s;
}

}  // namespace asv
