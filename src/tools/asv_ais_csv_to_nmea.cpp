// asv_ais_csv_to_nmea: a decoded AIS log (MarineCadastre CSV, or gpsd's JSON) back into AIVDM sentences
// with NMEA 4 tag-block times, so that a log of decoded reports replays through ais_node like a
// receiver's output (nmea_to_bag.py turns the sentences into a bag).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "asv_core/codec/nmea_encode.h"
#include "asv_core/common/geodesy.h"
#include "asv_core/common/units.h"
#include "asv_core/sim/scenario_from_ais.h"
#include "tool_main.h"

namespace {

using namespace asv;

const char* const kUsage =
    "usage: asv_ais_csv_to_nmea CSV [--start TIME] [--duration S] [--static-every S] [--out FILE]\n"
    "       asv_ais_csv_to_nmea --gpsd-json LOG [same options]\n"
    "\n"
    "Turns a decoded AIS log (MarineCadastre CSV columns: BaseDateTime, LON, LAT, MMSI, SOG, COG,\n"
    "Heading, VesselName, Length, Width, TranscieverClass) back into AIVDM sentences, in time order:\n"
    "each report becomes a type 1 (class A) or type 18 (class B) position report, and each vessel's\n"
    "static data (name, length and beam: type 5 for class A, type 24 parts A and B for class B) is sent\n"
    "at her first report and again every --static-every seconds. Every sentence carries an NMEA 4 tag\n"
    "block with the report's time (c:, UNIX seconds) and the source (s:csv, s:gpsd), the form ais_node's "
    "file\n"
    "input and nmea_to_bag.py read. The log's defects are repaired as asv_scenario_from_ais does: COG < 0\n"
    "is a 12-bit wrap (+409.6), COG 360, SOG 102.3 and Heading 511 are 'not available'; unreadable rows\n"
    "are refused and counted on stderr. The reference point is taken as the middle of the hull.\n"
    "\n"
    "With --gpsd-json the log is gpsd's JSON (gpspipe -w, gpsdecode; scaled or -u unscaled), one object\n"
    "a line: AIS types 1-3, 18 and 19 are the position reports, types 5, 19 and 24 give each vessel's name\n"
    "and size. gpsd's AIS objects carry no time: a report takes its line's leading time column (gpspipe\n"
    "-t -Z: 'YYYY-MM-DD HH:MM:SS: {...}', UTC; without -Z gpspipe writes local time, which is read as UTC;\n"
    "or UNIX seconds) or else the time of the last TPV object; a report\n"
    "before any time is refused as untimed. Other classes and types are skipped, counted.\n"
    "\n"
    "  CSV, LOG          the log\n"
    "  --gpsd-json       the log is gpsd JSON\n"
    "  --start TIME      first report time kept, UTC YYYY-MM-DDTHH:MM:SS (default: the log's first)\n"
    "  --duration S      seconds kept from the start (default: all)\n"
    "  --static-every S  static data period per vessel [s] (default 360, the class A rate)\n"
    "  --out FILE        write here (default: standard output)\n"
    "  -h, --help        this help\n"
    "\n"
    "Exit status: 0, 1 on a bad log, 2 on a usage error.\n";

struct Args {
  std::string csv, out, start;
  double duration = -1.0, static_every = 360.0;
  bool gpsd_json = false;
};

bool parse(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    exitOnHelp(k, kUsage);
    if (k == "--gpsd-json") {
      a.gpsd_json = true;
      continue;
    }
    if (k.rfind("--", 0) != 0) {
      if (!a.csv.empty())
        return false;
      a.csv = k;
      continue;
    }
    if (i + 1 >= argc)
      return false;
    const std::string v = argv[++i];
    double x = 0.0;
    if (k == "--start")
      a.start = v;
    else if (k == "--out")
      a.out = v;
    else if (k == "--duration" && toolNumber(v, x) && x > 0)
      a.duration = x;
    else if (k == "--static-every" && toolNumber(v, x) && x > 0)
      a.static_every = x;
    else
      return false;
  }
  return !a.csv.empty();
}

// "\s:<source>,c:<seconds>*hh\" + sentence.
std::string tagged(const std::string& sentence, double time, const char* source) {
  char body[64];
  std::snprintf(body, sizeof(body), "s:%s,c:%lld", source, static_cast<long long>(std::floor(time)));
  unsigned sum = 0;
  for (const char* p = body; *p; ++p)
    sum ^= static_cast<unsigned char>(*p);
  char tag[96];
  std::snprintf(tag, sizeof(tag), "\\%s*%02X\\", body, sum);
  return tag + sentence;
}

// The kinematic fields a class A and a class B position report share.
template <class Report>
Report kinematics(const AisLogReport& r) {
  const auto rad = [](const std::optional<double>& deg) {
    return deg ? std::optional<double>(degToRad(*deg)) : std::nullopt;
  };
  Report out;
  out.lat = ais::rawLat(r.position.lat_deg);
  out.lon = ais::rawLon(r.position.lon_deg);
  out.speed = ais::rawSpeed(knotsToMps(r.sog_kn));  // the CSV reader refuses rows without SOG; JSON: NaN
  out.course = ais::rawCourse(rad(r.cog_deg));
  out.heading = ais::rawHeading(rad(r.heading_deg));
  return out;
}

ais::BitWriter positionReport(const AisLogReport& r) {
  if (r.ais_class == 'B')
    return ais::encodePositionB(r.mmsi, kinematics<ais::PositionReportB>(r));
  return ais::encodePositionA(1, r.mmsi, kinematics<ais::PositionReportA>(r));
}

// Static data of a vessel: type 5 (class A) or 24 A and B (class B).
std::vector<ais::BitWriter> staticReports(const AisLogReport& r) {
  const auto half = [](double m) { return static_cast<std::uint32_t>(std::lround(std::max(0.0, m) / 2.0)); };
  const std::uint32_t bow = half(r.length_m), stern = half(r.length_m), side = half(r.beam_m);
  if (r.ais_class == 'B') {
    ais::StaticDataReport pa, pb;
    pa.part = 0;
    pa.shipname.assign(r.name);
    pb.part = 1;
    pb.to_bow = bow;
    pb.to_stern = stern;
    pb.to_port = pb.to_starboard = side;
    return {ais::encodeStaticDataReport(r.mmsi, pa), ais::encodeStaticDataReport(r.mmsi, pb)};
  }
  ais::StaticVoyageData d;
  d.shipname.assign(r.name);
  d.to_bow = bow;
  d.to_stern = stern;
  d.to_port = d.to_starboard = side;
  return {ais::encodeStaticVoyage(r.mmsi, d)};
}

// --- gpsd JSON ---------------------------------------------------------------------------------------

// A time column's or TPV's time: UNIX seconds, or UTC "YYYY-MM-DD[T ]HH:MM:SS[.fff][Z]".
std::optional<double> timeOf(const std::string& text) {
  double x = 0.0;
  if (toolNumber(text, x))
    return x;
  if (text.size() < 19)
    return std::nullopt;
  try {
    double t = parseUtcTime(text.substr(0, 19));
    const std::string rest = text.substr(19);
    if (!rest.empty() && rest[0] == '.' &&
        toolNumber("0" + rest.substr(0, rest.find_first_not_of("0123456789", 1)), x))
      t += x;
    return t;
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
}

// What gpsd knows of a vessel from its static reports (types 5, 19, 24).
struct GpsdStatic {
  std::string name;
  double length_m = 0.0, beam_m = 0.0;
};

void takeStatic(const YAML::Node& o, GpsdStatic& s) {
  if (o["shipname"])
    s.name = o["shipname"].as<std::string>();
  if (o["to_bow"] && o["to_stern"])
    s.length_m = o["to_bow"].as<double>() + o["to_stern"].as<double>();
  if (o["to_port"] && o["to_starboard"])
    s.beam_m = o["to_port"].as<double>() + o["to_starboard"].as<double>();
}

// A number of a gpsd object, or `fallback` when absent or not a number (scaled gpsd writes "nan" for a
// speed not available and "fast" for 102.2 kn or more).
double numberOr(const YAML::Node& o, const char* key, double fallback) {
  if (!o[key])
    return fallback;
  const std::string text = o[key].as<std::string>();
  if (text == "fast")
    return 102.2;
  double x = 0.0;
  return toolNumber(text, x) && std::isfinite(x) ? x : fallback;
}

// A position report's fields, scaled (degrees, knots) or not (1/600000 deg, 1/10 kn, 1/10 deg), with
// gpsd's "not available" values left out. False for no position.
bool takePosition(const YAML::Node& o, AisLogReport& r) {
  const bool scaled = !o["scaled"] || o["scaled"].as<bool>();
  const double deg = scaled ? 1.0 : 1.0 / 600000.0, tenth = scaled ? 1.0 : 0.1;
  r.position = {numberOr(o, "lat", std::nan("")) * deg, numberOr(o, "lon", std::nan("")) * deg};
  if (!validLatLon(r.position.lat_deg, r.position.lon_deg))
    return false;
  const double sog = numberOr(o, "speed", scaled ? 102.3 : 1023.0) * tenth;  // "fast" only in scaled output
  // Not available stays so (NaN encodes as 102.3): the report is a receiver's, not a row to repair.
  r.sog_kn = sog >= 102.25 ? std::nan("") : sog;
  const double cog = numberOr(o, "course", scaled ? 360.0 : 3600.0) * tenth;
  r.cog_deg = cog < 360.0 ? std::optional<double>(cog) : std::nullopt;
  const double hdg = numberOr(o, "heading", 511.0);
  r.heading_deg = hdg < 360.0 ? std::optional<double>(hdg) : std::nullopt;
  return true;
}

// One JSON object of the log at `time` (empty: untimed): a report appended to `log`, or a static
// report or TPV taken; anything else counted in `stats`.
void takeObject(const YAML::Node& o, std::optional<double>& time,
                std::map<std::uint32_t, GpsdStatic>& statics, std::vector<AisLogReport>& log,
                AisLogStats& stats) {
  const std::string cls = o["class"] ? o["class"].as<std::string>() : "";
  if (cls == "TPV") {
    if (o["time"])
      if (const auto t = timeOf(o["time"].as<std::string>()))
        time = t;
    return;
  }
  const int type = cls == "AIS" && o["type"] ? o["type"].as<int>() : 0;
  if (type == 0 || !o["mmsi"]) {
    ++stats.rejected["not an AIS object"];
    return;
  }
  const auto mmsi = o["mmsi"].as<std::uint32_t>();
  GpsdStatic& st = statics[mmsi];
  if (type == 5 || type == 19 || type == 24)
    takeStatic(o, st);
  const bool position = type <= 3 || type == 18 || type == 19;
  if (!position) {
    ++stats.rejected[type == 5 || type == 24 ? "static data (merged)" : "other type"];
    return;
  }
  AisLogReport r;
  r.mmsi = mmsi;
  r.ais_class = type >= 18 ? 'B' : 'A';
  if (!time)
    ++stats.rejected["untimed"];
  else if (!o["lat"] || !o["lon"] || !takePosition(o, r))
    ++stats.rejected["no position"];
  else {
    r.time = *time;
    r.name = st.name;
    r.length_m = st.length_m;
    r.beam_m = st.beam_m;
    log.push_back(r);
    ++stats.kept;
  }
}

std::vector<AisLogReport> readGpsdJson(std::istream& in, AisLogStats& stats) {
  std::vector<AisLogReport> log;
  std::map<std::uint32_t, GpsdStatic> statics;
  std::optional<double> tpv_time;
  for (std::string line; std::getline(in, line);) {
    const std::size_t brace = line.find('{');
    if (brace == std::string::npos)
      continue;
    ++stats.rows;
    std::string column = line.substr(0, brace);
    column.erase(column.find_last_not_of(" :,\t") + 1);  // "2020-06-30 00:00:00: " -> the time
    std::optional<double> time = column.empty() ? tpv_time : timeOf(column);
    try {
      const YAML::Node o = YAML::Load(line.substr(brace));  // JSON is YAML's flow style
      takeObject(o, column.empty() ? tpv_time : time, statics, log, stats);
    } catch (const YAML::Exception&) {
      ++stats.rejected["not JSON"];
    }
  }
  return log;
}

int run(const Args& a) {
  std::ifstream in(a.csv);
  if (!in)
    throw std::runtime_error("cannot read " + a.csv);
  AisLogStats stats;
  std::vector<AisLogReport> log = a.gpsd_json ? readGpsdJson(in, stats) : readMarineCadastreCsv(in, stats);
  std::stable_sort(log.begin(), log.end(), [](const auto& x, const auto& y) { return x.time < y.time; });
  const double start = a.start.empty() ? (log.empty() ? 0.0 : log.front().time) : parseUtcTime(a.start);
  const double end = a.duration > 0 ? start + a.duration : INFINITY;
  std::ofstream file;
  if (!a.out.empty()) {
    file.open(a.out);
    if (!file)
      throw std::runtime_error("cannot write " + a.out);
  }
  std::ostream& out = a.out.empty() ? std::cout : file;
  std::map<std::uint32_t, double> static_sent;
  std::size_t written = 0, seq = 0;
  for (const AisLogReport& r : log) {
    if (r.time < start || r.time >= end)
      continue;
    std::vector<ais::BitWriter> messages{positionReport(r)};
    auto it = static_sent.find(r.mmsi);
    if (it == static_sent.end() || r.time - it->second >= a.static_every) {
      for (auto& m : staticReports(r))
        messages.push_back(std::move(m));
      static_sent[r.mmsi] = r.time;
    }
    for (const auto& m : messages) {
      for (const auto& s : ais::toSentences(m, r.ais_class == 'B' ? 'B' : 'A', static_cast<int>(seq++ % 10)))
        out << tagged(s, r.time, a.gpsd_json ? "gpsd" : "csv") << '\n';
      ++written;
    }
  }
  std::size_t refused = 0;
  for (const auto& kv : stats.rejected)
    refused += kv.second;
  std::cerr << "asv_ais_csv_to_nmea: " << stats.rows << " rows, " << stats.kept << " reports read, "
            << refused << " refused";
  for (const auto& kv : stats.rejected)
    std::cerr << ", " << kv.first << " " << kv.second;
  std::cerr << "; " << written << " messages written from " << static_sent.size() << " vessels\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return toolMain<Args>("asv_ais_csv_to_nmea", kUsage, argc, argv, parse, run);
}
