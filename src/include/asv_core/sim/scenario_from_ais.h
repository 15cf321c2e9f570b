// Real-traffic scenarios: a time window of a decoded AIS log (MarineCadastre CSV columns) becomes a
// format-1 scenario whose targets replay their recorded tracks (behaviour track) round an own ship
// that is inserted with a start, goal and planner, or that takes the place of one logged vessel.
#pragma once

#include <cstdint>
#include <istream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "asv_core/common/geodesy.h"
#include "asv_core/world/scenario.h"

namespace asv {

// One decoded position report of the log.
struct AisLogReport {
  double time = 0.0;  // [s] UTC since 1970-01-01
  uint32_t mmsi = 0;
  GeoPoint position;
  double sog_kn = 0.0;
  std::optional<double> cog_deg;      // [0, 360), true; absent when not available
  std::optional<double> heading_deg;  // [0, 360), true; absent when 511
  std::string name;
  double length_m = 0.0, beam_m = 0.0;  // 0: not given
  char ais_class = 'A';
};

// What reading a log kept and refused, refusals by reason.
struct AisLogStats {
  std::size_t rows = 0, kept = 0;
  std::map<std::string, std::size_t> rejected;
};

// "YYYY-MM-DDTHH:MM:SS" (UTC; a space may replace the T, a trailing Z is allowed) -> seconds since
// 1970-01-01. Throws std::invalid_argument naming the text.
double parseUtcTime(const std::string& text);

// MarineCadastre "AIS Data" CSV (header BaseDateTime,LON,LAT,MMSI,SOG,COG,Heading,VesselName,...,
// Length,Width,...,TranscieverClass). The source's defects are repaired as documented by NOAA's data
// and seen in its files: a negative COG is a signed 12-bit wrap (true course = COG + 409.6); COG 360
// after that (-49.6 raw), SOG 102.3 and Heading 511 are "not available". A row that cannot be read
// (wrong column count, a number that is not one, position or MMSI out of range) is refused and
// counted, never guessed. Throws std::invalid_argument when the header lacks a needed column.
std::vector<AisLogReport> readMarineCadastreCsv(std::istream& in, AisLogStats& stats);

struct AisScenarioOptions {
  std::string name = "real_traffic";
  std::string description_source;  // the log's file name, for the description
  double start = 0.0;              // [s] UTC of the scenario's t = 0
  double duration = 1800.0;        // [s]
  // Own ship: inserted at own_start towards own_goal, or (own_mmsi != 0) the logged vessel's place at
  // `start`, her course and speed there, and her recorded position at the window's end as the goal
  // unless own_goal is given; she is then no target.
  uint32_t own_mmsi = 0;
  std::optional<GeoPoint> own_start, own_goal;
  std::optional<double> own_course_deg;  // default: towards the goal
  double own_speed_kn = 10.0;
  std::optional<double>
      own_length_m;  // default 120 m; with own_mmsi the logged vessel's, else default_length_m
  std::string own_model = "kinematic";
  std::string planner;  // empty: none in the file (given at run time)
  // Targets: every vessel that comes within `radius_m` of the own ship's straight route during the window.
  double radius_m = 4000.0;
  // A vessel silent longer than this has left: her track ends at the report before the gap [s].
  double max_gap_s = 600.0;
  // Implied speed between two reports above this is a bad fix: the later report is refused [kn].
  double max_jump_speed_kn = 60.0;
  // A vessel that moves less than this over the window (and reports SOG < 1 kn) is written stopped
  // (behaviour constant, speed 0) at her place at t = 0 [m].
  double stationary_m = 30.0;
  double default_length_m = 20.0;   // for vessels that report none (most harbour craft) [m]
  double min_separation_m = 185.2;  // harbour scale, 0.1 nm
  std::optional<GeoPoint> origin;   // default: midway between the own ship's start and goal
  std::optional<ChartSpec> charts;  // radius_m 0: covers the route plus radius_m
  double clearance_m = 100.0;       // the obstacle clearance written with charts
  // Land in the scenario's frame (the charts' polygons, loaded by the caller). The own ship's start or
  // goal on it by no more than land_accuracy_m is taken as afloat: moved to the nearest water, half her
  // length (at least 10 m) past the chart's edge, and reported in warnings; deeper inland it is
  // an error. A stopped vessel on it is left out: a berth on a pier the chart draws as land (GSHHG
  // does), which the land already keeps the own ship away from; moved, a moored ship would become a
  // phantom in the fairway (in New York, up to 235 m off the chart's edge, two onto one place).
  std::vector<StaticObstacle> land;
  // [m] our choice for GSHHG, which states no accuracy: its full-resolution shoreline comes from World
  // Vector Shoreline, digitised from charts of about 1:250,000, where 1 mm on paper is 250 m. With a
  // finer chart of the user's, set it lower (--land-accuracy).
  double land_accuracy_m = 250.0;
  // In a logged vessel's place (own_mmsi, no own_goal): her track from the start to the window's end
  // (or her last report) is the own ship's route, thinned by Douglas-Peucker to route_tolerance_m (our
  // choice, 50 m: a quarter of a narrow channel's width, and no thinned leg comes closer to land than
  // her track did or the clearance; a leg that a chart coarser than the harbour puts across land she
  // sailed past is routed round it, with a warning); her mean speed over it the own ship's speed; the
  // scenario lasts her
  // time x (1 + time_margin) (our choice, 0.3: the 30 % more time a run may take and still count as
  // arriving like her); and a human record (scenario key human) holds her closest approach to the
  // targets written (every 5 s, by their logged positions), her time and her path until she came within
  // the simulator's default arrival radius of her goal (max(200 m, 2 L)), where a run in her place
  // arrives.
  bool own_route = true;  // false: a goal only, as before routes
  double route_tolerance_m = 50.0;
  double time_margin = 0.3;
};

struct AisScenarioResult {
  Scenario scenario;             // parsed form: positions in the scenario's frame, charts not loaded
  std::size_t vessels_seen = 0;  // distinct MMSIs reporting in the window
  std::size_t tracks = 0, stationary = 0;      // targets written of each kind
  std::map<std::string, std::size_t> skipped;  // vessels left out, by reason
  // What the user should know of the log's data: logged places moved off chart land, who and how far
  // ("own start moved 84 m off chart land"); a route or human record that could not be written, and why.
  std::vector<std::string> warnings;
};

// Builds the scenario. Throws std::invalid_argument for options that cannot make one (no own start or
// goal, an own MMSI not reporting at `start` or stopped there, a window with no other vessel in it).
AisScenarioResult scenarioFromAis(const std::vector<AisLogReport>& log, const AisScenarioOptions& options);

}  // namespace asv
