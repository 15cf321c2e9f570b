#include "asv_core/sim/scenario_from_ais.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <stdexcept>

#include "asv_core/charts/charts.h"
#include "asv_core/common/format.h"
#include "asv_core/common/geometry.h"
#include "asv_core/common/units.h"
#include "asv_core/planning/land_route.h"
#include "asv_core/sim/simulation.h"

namespace asv {

namespace {

// Days from 1970-01-01 to a proleptic Gregorian date (H. Hinnant's days_from_civil).
long long daysFromCivil(long long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

// The date of a day count from 1970-01-01 (H. Hinnant's civil_from_days), as "YYYY-MM-DDTHH:MM:SSZ".
std::string formatUtcTime(double t) {
  const long long secs = static_cast<long long>(std::floor(t));
  long long z = (secs >= 0 ? secs : secs - 86399) / 86400;
  const long long sod = secs - z * 86400;
  z += 719468;
  const long long era = (z >= 0 ? z : z - 146096) / 146097;
  const unsigned doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  const unsigned d = doy - (153 * mp + 2) / 5 + 1;
  const unsigned m = mp < 10 ? mp + 3 : mp - 9;
  const long long y = static_cast<long long>(yoe) + era * 400 + (m <= 2);
  return strFormat("%04lld-%02u-%02uT%02lld:%02lld:%02lldZ", y, m, d, sod / 3600, sod / 60 % 60, sod % 60);
}

// One CSV line split into fields; a field may be double-quoted (with "" for a quote).
std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
      out.back() += '"', ++i;
    else if (c == '"')
      quoted = !quoted;
    else if (c == ',' && !quoted)
      out.emplace_back();
    else if (c != '\r')
      out.back() += c;
  }
  return out;
}

// A whole field as a number; empty or trailing text is no number.
std::optional<double> number(const std::string& f) {
  if (f.empty())
    return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(f.c_str(), &end);
  if (end != f.c_str() + f.size() || !std::isfinite(v))
    return std::nullopt;
  return v;
}

struct Columns {
  int time = -1, lon = -1, lat = -1, mmsi = -1, sog = -1, cog = -1, heading = -1;
  int name = -1, length = -1, width = -1, cls = -1;
  size_t count = 0;
};

Columns readHeader(const std::string& line) {
  Columns c;
  const auto fields = splitCsv(line);
  c.count = fields.size();
  for (size_t i = 0; i < fields.size(); ++i) {
    const std::string& f = fields[i];
    const int k = static_cast<int>(i);
    int* slot = f == "BaseDateTime"       ? &c.time
                : f == "LON"              ? &c.lon
                : f == "LAT"              ? &c.lat
                : f == "MMSI"             ? &c.mmsi
                : f == "SOG"              ? &c.sog
                : f == "COG"              ? &c.cog
                : f == "Heading"          ? &c.heading
                : f == "VesselName"       ? &c.name
                : f == "Length"           ? &c.length
                : f == "Width"            ? &c.width
                : f == "TranscieverClass" ? &c.cls
                                          : nullptr;
    if (slot)
      *slot = k;
  }
  for (const auto& [col, what] : {std::pair{c.time, "BaseDateTime"},
                                  {c.lon, "LON"},
                                  {c.lat, "LAT"},
                                  {c.mmsi, "MMSI"},
                                  {c.sog, "SOG"},
                                  {c.cog, "COG"},
                                  {c.heading, "Heading"}})
    if (col < 0)
      throw std::invalid_argument(std::string("AIS CSV: the header has no '") + what +
                                  "' column (MarineCadastre columns expected)");
  return c;
}

// The source's COG: a negative value wrapped as a signed 12-bit number of 0.1 deg; 360 after the
// repair means "not available".
std::optional<double> repairCog(double cog) {
  if (cog < 0.0)
    cog += 409.6;
  if (cog < 0.0 || cog >= 360.0 - 1e-9)
    return std::nullopt;
  return cog;
}

// One data row, or the reason it is refused.
std::string readRow(const std::vector<std::string>& f, const Columns& c, AisLogReport& r) {
  if (f.size() != c.count)
    return "wrong number of columns";
  const auto lat = number(f[c.lat]), lon = number(f[c.lon]), mmsi = number(f[c.mmsi]);
  if (!lat || !lon || !validLatLon(*lat, *lon))
    return "position missing or out of range";
  if (!mmsi || *mmsi < 1 || *mmsi > 999999999 || *mmsi != std::floor(*mmsi))
    return "MMSI not a 9-digit number";
  try {
    r.time = parseUtcTime(f[c.time]);
  } catch (const std::invalid_argument&) {
    return "time not YYYY-MM-DDTHH:MM:SS";
  }
  r.position = {*lat, *lon};
  r.mmsi = static_cast<uint32_t>(*mmsi);
  const auto sog = number(f[c.sog]);
  if (!sog || *sog < 0.0 || *sog >= 102.25)  // 102.3: not available
    return "SOG missing or not available";
  r.sog_kn = *sog;
  if (const auto cog = number(f[c.cog]))
    r.cog_deg = repairCog(*cog);
  if (const auto hdg = number(f[c.heading]); hdg && *hdg >= 0.0 && *hdg < 360.0)
    r.heading_deg = *hdg;
  auto optional = [&](int col) { return col >= 0 ? number(f[col]) : std::nullopt; };
  r.length_m = optional(c.length).value_or(0.0);
  r.beam_m = optional(c.width).value_or(0.0);
  if (c.name >= 0)
    r.name = f[c.name];
  r.ais_class = c.cls >= 0 && f[c.cls] == "B" ? 'B' : 'A';
  return "";
}

}  // namespace

double parseUtcTime(const std::string& text) {
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, s = 0, used = 0;
  char sep = 0;
  const int got =
      std::sscanf(text.c_str(), "%4d-%2d-%2d%c%2d:%2d:%2d%n", &y, &mo, &d, &sep, &h, &mi, &s, &used);
  const std::string rest = got == 7 ? text.substr(static_cast<size_t>(used)) : "x";
  if (got != 7 || (sep != 'T' && sep != ' ') || (!rest.empty() && rest != "Z") || mo < 1 || mo > 12 ||
      d < 1 || d > 31 || h > 23 || mi > 59 || s > 60 || h < 0 || mi < 0 || s < 0)
    throw std::invalid_argument("not a UTC time YYYY-MM-DDTHH:MM:SS: '" + text + "'");
  return static_cast<double>(daysFromCivil(y, static_cast<unsigned>(mo), static_cast<unsigned>(d))) *
             86400.0 +
         h * 3600.0 + mi * 60.0 + s;
}

std::vector<AisLogReport> readMarineCadastreCsv(std::istream& in, AisLogStats& stats) {
  std::string line;
  if (!std::getline(in, line))
    throw std::invalid_argument("AIS CSV: empty input");
  const Columns cols = readHeader(line);
  std::vector<AisLogReport> out;
  while (std::getline(in, line)) {
    if (line.empty() || line == "\r")
      continue;
    ++stats.rows;
    AisLogReport r;
    const std::string why = readRow(splitCsv(line), cols, r);
    if (!why.empty()) {
      ++stats.rejected[why];
      continue;
    }
    out.push_back(std::move(r));
    ++stats.kept;
  }
  return out;
}

namespace {

// [m] How close a leg routed round chart land across her track may pass it: our choice, 1 m. The
// vessel sailed there, so the chart, not the water, is wrong; the route only has to stay off its land.
constexpr double kRouteLandMargin = 1.0;

// One vessel's reports in the scenario's frame, in time order, bad fixes removed.
struct Vessel {
  uint32_t mmsi = 0;
  std::vector<const AisLogReport*> reports;
  std::vector<Eigen::Vector2d> xy;
};

std::map<uint32_t, Vessel> byVessel(const std::vector<AisLogReport>& log, const LocalFrame& frame,
                                    double max_jump_mps, std::size_t& refused) {
  std::map<uint32_t, std::vector<const AisLogReport*>> raw;
  for (const auto& r : log)
    raw[r.mmsi].push_back(&r);
  std::map<uint32_t, Vessel> out;
  for (auto& [mmsi, rs] : raw) {
    std::stable_sort(rs.begin(), rs.end(), [](auto* a, auto* b) { return a->time < b->time; });
    Vessel& v = out[mmsi];
    v.mmsi = mmsi;
    for (const AisLogReport* r : rs) {
      const Eigen::Vector2d p = frame.toLocal(r->position);
      if (!v.reports.empty()) {
        const double dt = r->time - v.reports.back()->time;
        // A second report of the same second, or one implying an impossible speed: a bad fix.
        if (dt <= 0.0 || (p - v.xy.back()).norm() / dt > max_jump_mps) {
          ++refused;
          continue;
        }
      }
      v.reports.push_back(r);
      v.xy.push_back(p);
    }
  }
  return out;
}

// Index of the last report at or before t, or -1.
int lastAtOrBefore(const Vessel& v, double t) {
  int k = -1;
  for (size_t i = 0; i < v.reports.size() && v.reports[i]->time <= t; ++i)
    k = static_cast<int>(i);
  return k;
}

// Where the vessel is at time t by her reports around it (t inside her reporting, no gap over max_gap).
std::optional<Eigen::Vector2d> positionAt(const Vessel& v, double t, double max_gap) {
  const int a = lastAtOrBefore(v, t);
  if (a < 0)
    return std::nullopt;
  if (v.reports[a]->time == t)
    return v.xy[a];
  if (static_cast<size_t>(a) + 1 >= v.reports.size())
    return std::nullopt;
  const double ta = v.reports[a]->time, tb = v.reports[a + 1]->time;
  if (tb - ta > max_gap)
    return std::nullopt;
  return v.xy[a] + (t - ta) / (tb - ta) * (v.xy[a + 1] - v.xy[a]);
}

std::string shipName(const AisLogReport& r, std::set<std::string>& used) {
  std::string n;
  for (char c : r.name)
    n += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::tolower(c)) : '_';
  while (!n.empty() && n.back() == '_')
    n.pop_back();
  n.erase(0, n.find_first_not_of('_'));
  if (n.empty())
    n = "mmsi";
  if (!used.insert(n).second || n == "mmsi")
    used.insert(n += "_" + std::to_string(r.mmsi));
  return n;
}

// A target that replays vessel v from t = 0 (her place at `start`) to her first report at or after
// the window's end, cut at a silence longer than max_gap. Empty track: no report after the start.
ScenarioShip targetOf(const Vessel& v, const Eigen::Vector2d& at_start, const AisScenarioOptions& o) {
  ScenarioShip s;
  s.mmsi = v.mmsi;
  s.behaviour = Behaviour::Track;
  s.position = at_start;
  const int a = lastAtOrBefore(v, o.start);
  double t_prev = v.reports[a]->time;
  for (size_t i = static_cast<size_t>(a) + 1; i < v.reports.size(); ++i) {
    const double t = v.reports[i]->time;
    if (t - t_prev > o.max_gap_s || t_prev >= o.start + o.duration)
      break;
    s.track.push_back({t - o.start, v.xy[i]});
    t_prev = t;
  }
  const AisLogReport& first = *v.reports[a];
  const double course0 = first.cog_deg       ? degToRad(*first.cog_deg)
                         : first.heading_deg ? degToRad(*first.heading_deg)
                                             : 0.0;
  const TrackSample leg = sampleTrack(at_start, course0, s.track, 0.0);
  s.course = wrapTwoPi(leg.course);
  s.speed = leg.speed;
  const AisLogReport& last = *v.reports.back();
  s.length = last.length_m > 0.0 && last.length_m <= 500.0 ? last.length_m : o.default_length_m;
  s.beam = last.beam_m > 0.0 && last.beam_m <= 80.0 && last.beam_m <= s.length ? last.beam_m : 0.0;
  s.ais_class = last.ais_class;
  return s;
}

// A track that never leaves a small circle, at reported speeds under 1 kn over the window: a ship at
// anchor or moored.
bool stationary(const Vessel& v, const ScenarioShip& s, const AisScenarioOptions& o) {
  for (const auto& p : s.track)
    if ((p.position - s.position).norm() > o.stationary_m)
      return false;
  for (const auto* r : v.reports)
    if (r->sog_kn >= 1.0 && r->time >= o.start - o.max_gap_s && r->time <= o.start + o.duration)
      return false;
  return true;
}

double routeDistance(const ScenarioShip& s, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  double d = pointSegmentDistance(s.position, a, b);
  for (const auto& p : s.track)
    d = std::min(d, pointSegmentDistance(p.position, a, b));
  return d;
}

void validate(const AisScenarioOptions& o) {
  if (!(o.duration > 0.0) || o.duration > 7 * 86400.0)
    throw std::invalid_argument("duration must be in (0, 604800] s");
  if (!(o.time_margin >= 0.0) || o.time_margin > 10.0)
    throw std::invalid_argument("time margin must be in [0, 10]");
  if (!(o.route_tolerance_m >= 0.0) || o.route_tolerance_m > 10000.0)
    throw std::invalid_argument("route tolerance must be in [0, 10000] m");
  if (!(o.radius_m > 0.0) || !(o.max_gap_s > 0.0) || !(o.default_length_m > 0.0) ||
      !(o.min_separation_m > 0.0))
    throw std::invalid_argument("radius, max gap, default length and minimum separation must be > 0");
  if (!(o.max_jump_speed_kn > 0.0) || o.max_jump_speed_kn > 60.0)
    throw std::invalid_argument("max jump speed must be in (0, 60] kn (the scenario format's speed limit)");
  if (o.own_mmsi == 0 && (!o.own_start || !o.own_goal))
    throw std::invalid_argument("the own ship needs a start and a goal, or the MMSI of a logged vessel");
}

struct OwnPlace {
  GeoPoint start, goal;
  std::optional<double> course_deg;
  double speed_kn = 0.0;
  double length_m = 120.0;
  double goal_time = 0.0;  // [s] UTC the logged vessel was at the goal (0: the goal is not hers)
};

// The own ship's start, goal and motion: given, or taken from the logged vessel own_mmsi.
OwnPlace ownPlace(const std::vector<AisLogReport>& log, const AisScenarioOptions& o) {
  OwnPlace p{o.own_start.value_or(GeoPoint{}), o.own_goal.value_or(GeoPoint{}), o.own_course_deg,
             o.own_speed_kn, o.own_length_m.value_or(120.0)};
  // In a logged vessel's place, a vessel that reports no length is taken as the targets are: mostly
  // harbour craft (default_length_m), not a 120 m ship whose domain fills the channel.
  if (o.own_mmsi != 0 && !o.own_length_m)
    p.length_m = o.default_length_m;
  if (o.own_mmsi == 0)
    return p;
  // Her reports only, in a frame round one of them to interpolate; the answer goes back to
  // latitude/longitude.
  std::vector<AisLogReport> hers;
  for (const auto& r : log)
    if (r.mmsi == o.own_mmsi)
      hers.push_back(r);
  if (hers.empty())
    throw std::invalid_argument("MMSI " + std::to_string(o.own_mmsi) + " does not report in the log");
  const LocalFrame frame(hers.front().position.lat_deg, hers.front().position.lon_deg);
  std::size_t refused = 0;
  auto vessels = byVessel(hers, frame, knotsToMps(o.max_jump_speed_kn), refused);
  const Vessel& v = vessels.at(o.own_mmsi);
  const auto at = positionAt(v, o.start, o.max_gap_s);
  if (!at)
    throw std::invalid_argument("MMSI " + std::to_string(o.own_mmsi) +
                                " has no report on both sides of the start");
  const auto next = positionAt(v, std::min(o.start + 60.0, v.reports.back()->time), o.max_gap_s);
  p.start = frame.toGeodetic(*at);
  if (!o.own_course_deg && next && (*next - *at).norm() > 1.0)
    p.course_deg = radToDeg(courseOf(*next - *at));
  if (!o.own_goal) {
    p.goal_time = std::min(o.start + o.duration, v.reports.back()->time);
    const auto end = positionAt(v, p.goal_time, o.max_gap_s);
    if (!end)
      p.goal_time = v.reports.back()->time;
    p.goal = frame.toGeodetic(end.value_or(v.xy.back()));
  }
  const AisLogReport& before = *v.reports[lastAtOrBefore(v, o.start)];
  p.speed_kn = before.sog_kn;
  if (!o.own_length_m && before.length_m > 0.0 && before.length_m <= 500.0)
    p.length_m = before.length_m;
  if (p.speed_kn < 1.0)
    throw std::invalid_argument("MMSI " + std::to_string(o.own_mmsi) +
                                " makes under 1 kn at the start: choose a time when she is under way");
  return p;
}

ScenarioShip ownShip(const OwnPlace& p, const AisScenarioOptions& o, const LocalFrame& frame) {
  ScenarioShip own;
  own.name = "own";
  own.mmsi = o.own_mmsi;
  own.model = o.own_model;
  own.length = p.length_m;
  own.position = frame.toLocal(p.start);
  own.goal = frame.toLocal(p.goal);
  own.course =
      p.course_deg ? wrapTwoPi(degToRad(*p.course_deg)) : wrapTwoPi(courseOf(*own.goal - own.position));
  own.speed = knotsToMps(p.speed_kn);
  own.planner = o.planner;
  return own;
}

// A logged place on the chart's land by at most land_accuracy_m, moved to the nearest water (half the
// ship's length, at least 10 m, past the edge) and reported; false when it lies deeper inland.
bool moveAfloat(Eigen::Vector2d& p, double length, const std::string& who, const AisScenarioOptions& o,
                AisScenarioResult& res) {
  const auto w = nearestWater(o.land, p, o.land_accuracy_m, std::max(10.0, 0.5 * length));
  if (!w)
    return false;
  const double moved = (*w - p).norm();
  if (moved > 0.0)
    res.warnings.push_back(strFormat("%s moved %.0f m off chart land", who.c_str(), moved));
  p = *w;
  return true;
}

// The own ship's start and goal off the chart's land (an error when deeper than its accuracy); her
// course follows a moved start or goal unless it was given or logged.
void ownAfloat(ScenarioShip& own, const OwnPlace& place, const AisScenarioOptions& o,
               AisScenarioResult& res) {
  for (auto [what, p] : {std::pair{"start", &own.position}, std::pair{"goal", &*own.goal}})
    if (!moveAfloat(*p, own.length, std::string("own ") + what, o, res))
      throw std::invalid_argument(std::string("the own ship's ") + what +
                                  strFormat(" is on chart land with no water within its accuracy (%.0f m): "
                                            "choose another",
                                            o.land_accuracy_m));
  if (!place.course_deg)
    own.course = wrapTwoPi(courseOf(*own.goal - own.position));
}

// Two ships closer at the start than the scenario format allows (half their lengths summed, 10 m).
bool overlaps(const ScenarioShip& s, const Scenario& sc) {
  auto clash = [&](const ScenarioShip& o) {
    return (s.position - o.position).norm() < std::max(10.0, 0.5 * (s.length + o.length));
  };
  return clash(sc.own) || std::any_of(sc.targets.begin(), sc.targets.end(), clash);
}

// Why a window holds no traffic: where the log's reports are in time.
std::string windowOutsideLog(const std::vector<AisLogReport>& log, const AisScenarioOptions& o) {
  std::string span = "the log is empty";
  if (!log.empty()) {
    const auto [lo, hi] = std::minmax_element(log.begin(), log.end(),
                                              [](const auto& a, const auto& b) { return a.time < b.time; });
    span = "the log covers " + formatUtcTime(lo->time) + " to " + formatUtcTime(hi->time);
  }
  return "no other vessel reports between " + formatUtcTime(o.start) + " and " +
         formatUtcTime(o.start + o.duration) + " (" + span + ")";
}

// Her track from the start to the goal: her place at the start, her reports between, her place at the
// goal time.
std::vector<TrackPoint> herTrack(const Vessel& v, const OwnPlace& place, const AisScenarioOptions& o) {
  std::vector<TrackPoint> track;
  if (const auto at = positionAt(v, o.start, o.max_gap_s))
    track.push_back({o.start, *at});
  for (size_t i = 0; i < v.reports.size(); ++i)
    if (v.reports[i]->time > o.start && v.reports[i]->time < place.goal_time)
      track.push_back({v.reports[i]->time, v.xy[i]});
  track.push_back({place.goal_time, positionAt(v, place.goal_time, o.max_gap_s).value_or(v.xy.back())});
  return track;
}

// Her time and path to the goal: until she first came within `radius` of it (where a run in her place
// arrives), the entry interpolated on her track.
HumanRecord herRun(const std::vector<TrackPoint>& track, double radius) {
  HumanRecord h;
  const Eigen::Vector2d goal = track.back().position;
  for (size_t i = 1; i < track.size(); ++i) {
    const Eigen::Vector2d a = track[i - 1].position, d = track[i].position - a;
    // The first s in [0, 1] with |a + s d - goal| = radius, when the segment ends inside the circle.
    double s = 1.0;
    if ((track[i].position - goal).norm() <= radius && d.squaredNorm() > 0.0) {
      const Eigen::Vector2d f = a - goal;
      const double qa = d.squaredNorm(), qb = 2.0 * f.dot(d), qc = f.squaredNorm() - radius * radius;
      s = std::clamp((-qb - std::sqrt(std::max(0.0, qb * qb - 4.0 * qa * qc))) / (2.0 * qa), 0.0, 1.0);
    }
    h.path_m += s * d.norm();
    h.time_s = track[i - 1].t + s * (track[i].t - track[i - 1].t) - track.front().t;
    if (s < 1.0 || (track[i].position - goal).norm() <= radius)
      break;
  }
  return h;
}

// Indices of `kept` (a thinned copy of pts) in pts: the thinning keeps points of the line in order.
std::vector<size_t> keptIndices(const std::vector<Eigen::Vector2d>& pts,
                                const std::vector<Eigen::Vector2d>& kept) {
  std::vector<size_t> idx;
  size_t k = 0;
  for (size_t i = 0; i < pts.size() && k < kept.size(); ++i)
    if (pts[i] == kept[k]) {
      idx.push_back(i);
      ++k;
    }
  return idx;
}

// Her track thinned (route_tolerance_m) into the own ship's route from her (moved) start to her
// (moved) goal. Her points on chart land within its accuracy are moved off it first; a thinned leg
// that comes closer to land than her own track there and the clearance is replaced by her track. A
// chart coarser than the harbour (GSHHG) can still put land across her track (a pier's end, a narrow
// cut): such a leg is routed round that land (landRoute, kRouteLandMargin from it), with a note; when
// there is no way round, the route is empty, with a note.
Route herRoute(const std::vector<TrackPoint>& track, const ScenarioShip& own, const AisScenarioOptions& o,
               AisScenarioResult& res) {
  std::vector<Eigen::Vector2d> pts;
  size_t moved = 0;
  for (const auto& p : track) {
    const auto w = nearestWater(o.land, p.position, o.land_accuracy_m, std::max(10.0, 0.5 * own.length));
    moved += w && *w != p.position;
    pts.push_back(w.value_or(p.position));
  }
  pts.front() = own.position;
  pts.back() = *own.goal;
  if (moved > 0)
    res.warnings.push_back(strFormat("own route: %zu of her logged points moved off chart land", moved));
  const std::vector<size_t> idx = keptIndices(pts, simplifyPolyline(pts, o.route_tolerance_m));
  std::vector<size_t> legs{idx.front()};
  for (size_t k = 1; k < idx.size(); ++k) {
    double hers = std::numeric_limits<double>::infinity();
    for (size_t i = idx[k - 1]; i < idx[k]; ++i)
      hers = std::min(hers, trackObstacleDistance({pts[i], pts[i + 1]}, o.land));
    const bool cut =
        trackObstacleDistance({pts[idx[k - 1]], pts[idx[k]]}, o.land) < std::min(hers, o.clearance_m);
    for (size_t i = cut ? idx[k - 1] + 1 : idx[k]; i <= idx[k]; ++i)
      legs.push_back(i);
  }
  Route route;
  size_t rounded = 0;
  for (size_t k = 1; k < legs.size(); ++k) {
    const Eigen::Vector2d &from = pts[legs[k - 1]], &to = pts[legs[k]];
    if (trackObstacleDistance({from, to}, o.land) <= 0.0) {
      const auto round = landRoute(from, to, o.land, o.clearance_m, kRouteLandMargin);
      if (!round) {
        res.warnings.push_back(
            strFormat("own route: her logged track crosses chart land %.0f s after the start "
                      "with no way round it: written with a goal only",
                      track[legs[k]].t - o.start));
        return {};
      }
      ++rounded;
      for (const Eigen::Vector2d& p : *round)
        route.push_back(RouteWaypoint{p, 0.0, 0.0, 0.0});
    }
    route.push_back(RouteWaypoint{to, 0.0, 0.0, 0.0});
  }
  if (rounded > 0)
    res.warnings.push_back(strFormat(
        "own route: %zu of her legs cross chart land (a chart coarser than the harbour): routed round it",
        rounded));
  return route;
}

// Her closest approach to the targets of the scenario, by their logged positions (a stopped one at her
// place at the start, as written) every 5 s from the start until she arrived (`end`); infinity when no
// target was there at the same time.
double herSeparation(const Vessel& her, const std::vector<std::pair<const Vessel*, bool>>& targets,
                     double end, const AisScenarioOptions& o) {
  double best = std::numeric_limits<double>::infinity();
  for (double t = o.start; t <= end; t += 5.0) {
    const auto p = positionAt(her, t, o.max_gap_s);
    if (!p)
      continue;
    for (const auto& [v, still] : targets) {
      const auto q = positionAt(*v, still ? o.start : t, o.max_gap_s);
      if (q)
        best = std::min(best, (*q - *p).norm());
    }
  }
  return best;
}

}  // namespace

AisScenarioResult scenarioFromAis(const std::vector<AisLogReport>& log, const AisScenarioOptions& o) {
  validate(o);
  const OwnPlace place = ownPlace(log, o);
  AisScenarioResult res;
  Scenario& sc = res.scenario;
  sc.name = o.name;
  sc.duration = o.duration;
  sc.origin = o.origin.value_or(GeoPoint{0.5 * (place.start.lat_deg + place.goal.lat_deg),
                                         0.5 * (place.start.lon_deg + place.goal.lon_deg)});
  sc.has_origin = true;
  sc.min_separation = o.min_separation_m;
  const LocalFrame frame = sc.frame();
  sc.own = ownShip(place, o, frame);
  ownAfloat(sc.own, place, o, res);
  std::size_t refused_fixes = 0;
  const auto vessels = byVessel(log, frame, knotsToMps(o.max_jump_speed_kn), refused_fixes);
  // In a logged vessel's place: her track as the route, her mean speed, her time with the margin.
  AisScenarioOptions tw = o;  // the targets' window: the scenario's duration
  const Vessel* her = o.own_mmsi != 0 && place.goal_time > o.start ? &vessels.at(o.own_mmsi) : nullptr;
  if (her) {
    const std::vector<TrackPoint> track = herTrack(*her, place, o);
    // The simulator's default arrival radius (simulation.h): max(200 m, 2 L).
    sc.human = herRun(track, std::max(200.0, 2.0 * sc.own.length));
    sc.duration = tw.duration = std::ceil(sc.human->time_s * (1.0 + o.time_margin));
    sc.own.speed = sc.human->path_m / sc.human->time_s;
    if (o.own_route)
      sc.own.route = herRoute(track, sc.own, o, res);
  }
  std::vector<std::pair<const Vessel*, bool>> included;  // the targets written, stopped or not
  std::set<std::string> names{"own"};
  for (const auto& [mmsi, v] : vessels) {
    const bool in_window = std::any_of(v.reports.begin(), v.reports.end(), [&](const AisLogReport* r) {
      return r->time >= o.start - o.max_gap_s && r->time <= o.start + tw.duration;
    });
    if (!in_window || mmsi == o.own_mmsi)
      continue;
    ++res.vessels_seen;
    const int a = lastAtOrBefore(v, o.start);
    const auto at = positionAt(v, o.start, o.max_gap_s);
    std::string skip;
    if (a < 0 || o.start - v.reports[a]->time > o.max_gap_s)
      skip = "first report after the start (ships exist from t = 0)";
    else if (!at)
      skip = "no report after the start within the maximum gap";
    ScenarioShip s;
    if (skip.empty()) {
      s = targetOf(v, *at, tw);
      if (s.track.empty())
        skip = "no report after the start within the maximum gap";
      else if (routeDistance(s, sc.own.position, *sc.own.goal) > o.radius_m)
        skip = "farther than the radius from the own ship's route";
      else if (overlaps(s, sc))
        skip = "overlaps another ship at the start (moored alongside?)";
    }
    if (!skip.empty()) {
      ++res.skipped[skip];
      continue;
    }
    const bool still = stationary(v, s, tw);
    if (still && insideAnyObstacle(o.land, s.position)) {
      ++res.skipped["stopped on chart land (a berth the chart draws as land)"];
      continue;
    }
    s.name = shipName(*v.reports.back(), names);
    if (still) {
      s.behaviour = Behaviour::Constant;
      s.track.clear();
      s.speed = 0.0;
      ++res.stationary;
    } else {
      ++res.tracks;
    }
    included.emplace_back(&v, still);
    sc.targets.push_back(std::move(s));
  }
  if (her) {
    sc.human->min_separation_m = herSeparation(*her, included, o.start + sc.human->time_s, o);
    if (!std::isfinite(sc.human->min_separation_m)) {
      sc.human.reset();
      res.warnings.push_back("no target was logged beside her: written without a human record");
    }
  }
  if (res.vessels_seen == 0)
    throw std::invalid_argument(windowOutsideLog(log, o));
  if (refused_fixes > 0)
    res.skipped["reports refused as bad fixes (jump or repeated time)"] = refused_fixes;
  if (o.charts) {
    sc.charts = o.charts;
    if (sc.charts->radius_m <= 0.0) {
      const double reach = std::max(sc.own.position.norm(), sc.own.goal->norm()) + o.radius_m;
      sc.charts->radius_m = 1000.0 * std::ceil(reach / 1000.0);
    }
    sc.min_obstacle_clearance = o.clearance_m;
  }
  const char* src = o.description_source.empty() ? "an AIS log" : o.description_source.c_str();
  sc.description = strFormat(
      "Real traffic from %s: %zu vessels replaying their recorded tracks and %zu stopped, %.0f s from %s. "
      "Written by asv_scenario_from_ais.",
      src, res.tracks, res.stationary, sc.duration, formatUtcTime(o.start).c_str());
  return res;
}

}  // namespace asv
