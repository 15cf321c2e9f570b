// asv_scenario_from_ais: a time window of a decoded AIS log (MarineCadastre CSV) as a format-1 scenario
// whose targets replay their recorded tracks round an own ship (asv_core/sim/scenario_from_ais.h).
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

#include "asv_core/common/format.h"
#include "asv_core/common/geometry.h"
#include "asv_core/sim/scenario_from_ais.h"
#include "asv_core/sim/simulation.h"
#include "asv_core/world/scenario_write.h"
#include "tool_main.h"

namespace {

using namespace asv;

const char* const kUsage =
    "usage: asv_scenario_from_ais CSV --start TIME --duration S --out FILE\n"
    "                             (--own-start LAT,LON --own-goal LAT,LON | --own-mmsi MMSI) [options]\n"
    "\n"
    "Turns the window [TIME, TIME + S] of a decoded AIS log (MarineCadastre CSV columns: BaseDateTime,\n"
    "LON, LAT, MMSI, SOG, COG, Heading, VesselName, Length, Width, TranscieverClass) into a scenario file\n"
    "(format 1). Every vessel that reports on both sides of TIME and comes within --radius of the own\n"
    "ship's straight route replays her recorded track (behaviour track: straight legs from report to\n"
    "report, each sailed in its recorded time; she leaves after her last report or a silence longer than\n"
    "--max-gap); a vessel that does not move is written stopped. Vessels that first report after TIME\n"
    "are left out (a scenario's ships exist from t = 0): choose TIME a few minutes into the log. The\n"
    "source's defects are repaired: COG < 0 is a 12-bit wrap (+409.6), COG 360, SOG 102.3 and Heading 511\n"
    "are 'not available'; unreadable rows and position jumps faster than 60 kn are refused and counted.\n"
    "\n"
    "  CSV                  the log (any CSV with those columns; sorted or not)\n"
    "  --start TIME         UTC of the scenario's t = 0, YYYY-MM-DDTHH:MM:SS\n"
    "  --duration S         length of the scenario [s]; with --own-mmsi, the window she is followed\n"
    "                       for: the scenario lasts her time x (1 + --time-margin)\n"
    "  --out FILE           scenario file to write (its name, without .yaml, is the scenario's)\n"
    "  --own-start LAT,LON  own ship's start [deg]; with --own-goal\n"
    "  --own-goal LAT,LON   own ship's goal [deg]\n"
    "  --own-mmsi MMSI      or: the own ship takes the place of this logged vessel (her position, course\n"
    "                       and speed at TIME; her position at the window's end as the goal unless\n"
    "                       --own-goal); she is then no target. Without --own-goal, her track is the\n"
    "                       own ship's route (key own_ship.route), her mean speed her speed, and a\n"
    "                       human record gives her closest approach to the targets, her time and path\n"
    "  --route-tolerance M  thinning of her track into the route, Douglas-Peucker (default 50)\n"
    "  --no-route           with --own-mmsi: a goal only, no route\n"
    "  --time-margin F      the scenario lasts her time x (1 + F) (default 0.3)\n"
    "  --own-speed KN       own ship's speed (default 10; with --own-mmsi: her logged mean speed)\n"
    "  --own-course DEG     own ship's initial course (default: towards the goal)\n"
    "  --own-length M       own ship's length (default 120; with --own-mmsi: the logged vessel's, else\n"
    "                       --default-length)\n"
    "  --own-model NAME     kinematic (default), point or a 3-DOF preset\n"
    "  --planner NAME       own ship's planner written in the file (default none: give it at run time)\n"
    "  --radius M           targets within this of the own ship's route (default 4000)\n"
    "  --max-gap S          a longer silence ends a vessel's track (default 600)\n"
    "  --default-length M   length of vessels that report none (default 20: mostly harbour craft)\n"
    "  --min-separation M   the scenario's minimum separation (default 185.2, 0.1 nm: harbour scale)\n"
    "  --origin LAT,LON     map origin (default: midway between the own ship's start and goal)\n"
    "  --charts SRC         land: gshhg (default), a chart file (.geojson, .shp, S-57 .000) or none\n"
    "  --chart-resolution R GSHHG resolution (default full)\n"
    "  --clearance M        obstacle clearance written with the charts (default 100)\n"
    "  --land-accuracy M    an own start or goal this far or less inside the chart's land is moved to\n"
    "                       the nearest water, with a warning (default 250, GSHHG's scale; 0: never)\n"
    "  --chart-cache DIR    chart extraction cache used to check the file (default $ASV_CHART_CACHE or\n"
    "                       ~/.cache/asv/charts; none: no cache)\n"
    "  --quiet              no summary on stderr\n"
    "  -h, --help           this help\n"
    "\n"
    "The file written is read back by the scenario loader with its land before the tool succeeds: an own\n"
    "start or goal on land (deeper than --land-accuracy) is an error. Exit status: 0, 1 on a bad log, window "
    "or own ship, 2 on a usage\n"
    "error.\n";

struct Args {
  std::string csv, out, start, charts = "gshhg", resolution = "full", cache;
  bool quiet = false;
  AisScenarioOptions o;
};

bool latLon(const std::string& v, std::optional<GeoPoint>& out) {
  const auto comma = v.find(',');
  double lat = 0.0, lon = 0.0;
  if (comma == std::string::npos || !toolNumber(v.substr(0, comma), lat) ||
      !toolNumber(v.substr(comma + 1), lon) || !validLatLon(lat, lon))
    return false;
  out = GeoPoint{lat, lon};
  return true;
}

// Options with a number; false for another key or a value out of range.
bool numberOption(AisScenarioOptions& o, const std::string& k, double x) {
  if (k == "--duration")
    o.duration = x;
  else if (k == "--own-mmsi" && x >= 1 && x <= 999999999 && x == double(long(x)))
    o.own_mmsi = static_cast<uint32_t>(x);
  else if (k == "--own-speed" && x >= 0 && x <= 60)
    o.own_speed_kn = x;
  else if (k == "--own-course" && x >= 0 && x < 360)
    o.own_course_deg = x;
  else if (k == "--own-length" && x > 0 && x <= 500)
    o.own_length_m = x;
  else if (k == "--radius")
    o.radius_m = x;
  else if (k == "--max-gap")
    o.max_gap_s = x;
  else if (k == "--default-length" && x > 0 && x <= 500)
    o.default_length_m = x;
  else if (k == "--min-separation")
    o.min_separation_m = x;
  else if (k == "--clearance" && x > 0)
    o.clearance_m = x;
  else if (k == "--land-accuracy" && x >= 0 && x <= 5000)
    o.land_accuracy_m = x;
  else if (k == "--time-margin" && x >= 0 && x <= 10)
    o.time_margin = x;
  else if (k == "--route-tolerance" && x >= 0 && x <= 10000)
    o.route_tolerance_m = x;
  else
    return false;
  return true;
}

bool option(Args& a, const std::string& k, const std::string& v) {
  double x = 0.0;
  AisScenarioOptions& o = a.o;
  if (k == "--start")
    a.start = v;
  else if (k == "--out")
    a.out = v;
  else if (k == "--own-start")
    return latLon(v, o.own_start);
  else if (k == "--own-goal")
    return latLon(v, o.own_goal);
  else if (k == "--origin")
    return latLon(v, o.origin);
  else if (k == "--charts")
    a.charts = v;
  else if (k == "--chart-resolution")
    a.resolution = v;
  else if (k == "--chart-cache")
    a.cache = v;
  else if (k == "--own-model")
    o.own_model = v;
  else if (k == "--planner")
    o.planner = v;
  else
    return toolNumber(v, x) && numberOption(o, k, x);
  return true;
}

bool parse(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    exitOnHelp(k, kUsage);
    if (k == "--quiet") {
      a.quiet = true;
    } else if (k == "--no-route") {
      a.o.own_route = false;
    } else if (k.rfind("--", 0) != 0 && a.csv.empty()) {
      a.csv = k;
    } else if (i + 1 >= argc || !option(a, k, argv[i + 1])) {
      std::cerr << "asv_scenario_from_ais: bad or incomplete option " << k << "\n";
      return false;
    } else {
      ++i;
    }
  }
  for (const auto& [missing, what] :
       {std::pair{a.csv.empty(), "the CSV log"}, {a.start.empty(), "--start"}, {a.out.empty(), "--out"}})
    if (missing) {
      std::cerr << "asv_scenario_from_ais: " << what << " is required\n";
      return false;
    }
  return true;
}

std::string baseName(const std::string& path) {
  std::string b = path.substr(path.find_last_of('/') + 1);
  const auto dot = b.rfind(".yaml");
  return dot == std::string::npos ? b : b.substr(0, dot);
}

// The file as the stack will read it, with its land; when `afloat`, the own ship must start and end
// off it. Returns the land (none without charts).
std::vector<StaticObstacle> checkLoads(const std::string& yaml, const Args& a, bool afloat) {
  Scenario s = parseScenario(yaml, a.out);
  Simulation check(s);  // what the loader leaves to the simulator: an unknown --own-model preset
  if (!s.charts)
    return {};
  ChartOptions co;
  co.cache_dir = a.cache;
  co.own_afloat = afloat;
  loadCharts(s, co);
  for (const auto& ob : s.obstacles)
    for (const auto& [what, p] : {std::pair{"start", s.own.position}, std::pair{"goal", *s.own.goal}})
      if (afloat && insideObstacle(ob, p))
        throw std::invalid_argument(
            std::string("the own ship's ") + what + " is on land (" + ob.name +
            strFormat(") with no water within the chart's accuracy (--land-accuracy %.0f m): "
                      "choose another",
                      a.o.land_accuracy_m));
  return s.obstacles;
}

int run(Args& a) {
  std::ifstream in(a.csv);
  if (!in)
    throw std::invalid_argument("cannot open " + a.csv);
  AisLogStats stats;
  const auto log = readMarineCadastreCsv(in, stats);
  a.o.start = parseUtcTime(a.start);
  a.o.name = baseName(a.out);
  a.o.description_source = a.csv.substr(a.csv.find_last_of('/') + 1);
  if (a.charts != "none") {
    ChartSpec spec;
    spec.source = a.charts;
    spec.resolution = a.resolution;
    spec.radius_m = 0.0;  // scenarioFromAis: the route plus the radius
    a.o.charts = spec;
  }
  // Twice: the first scenario gives the chart's area, whose land then leaves out ships at berths.
  AisScenarioResult r = scenarioFromAis(log, a.o);
  a.o.land = checkLoads(scenarioToYaml(r.scenario), a, false);
  r = scenarioFromAis(log, a.o);
  const std::string yaml = scenarioToYaml(r.scenario);
  checkLoads(yaml, a, true);
  // A logged place moved off the chart's land is the chart's error or the log's: said even with --quiet.
  for (const std::string& m : r.warnings)
    std::cerr << "asv_scenario_from_ais: warning: " << m << "\n";
  std::ofstream out(a.out);
  out << yaml;
  if (!out)
    throw std::invalid_argument("cannot write " + a.out);
  if (a.quiet)
    return 0;
  std::cerr << "asv_scenario_from_ais: " << stats.rows << " rows, " << stats.kept << " read\n";
  for (const auto& [why, n] : stats.rejected)
    std::cerr << "  refused " << n << " row(s): " << why << "\n";
  std::cerr << "  " << r.vessels_seen << " vessels report in the window: " << r.tracks
            << " replay their tracks, " << r.stationary << " stopped\n";
  for (const auto& [why, n] : r.skipped)
    std::cerr << "  left out " << n << ": " << why << "\n";
  if (!r.warnings.empty())
    std::cerr << "  warnings: " << r.warnings.size() << "\n";
  const Scenario& sc = r.scenario;
  if (!sc.own.route.empty())
    std::cerr << "  own route: " << sc.own.route.size() << " waypoint(s)\n";
  if (sc.human)
    std::cerr << strFormat("  the master: closest approach %.0f m, %.0f s, %.0f m sailed; scenario %.0f s\n",
                           sc.human->min_separation_m, sc.human->time_s, sc.human->path_m, sc.duration);
  std::cerr << "  written " << a.out << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return toolMain<Args>("asv_scenario_from_ais", kUsage, argc, argv, parse, run);
}
