// asv_ais_csv_to_nmea: a decoded AIS log (MarineCadastre CSV) back into AIVDM sentences with NMEA 4
// tag-block times, so that a log of decoded reports replays through ais_node like a receiver's output
// (nmea_to_bag.py turns the sentences into a bag).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "asv_core/codec/nmea_encode.h"
#include "asv_core/common/units.h"
#include "asv_core/sim/scenario_from_ais.h"
#include "tool_main.h"

namespace {

using namespace asv;

const char* const kUsage =
    "usage: asv_ais_csv_to_nmea CSV [--start TIME] [--duration S] [--static-every S] [--out FILE]\n"
    "\n"
    "Turns a decoded AIS log (MarineCadastre CSV columns: BaseDateTime, LON, LAT, MMSI, SOG, COG,\n"
    "Heading, VesselName, Length, Width, TranscieverClass) back into AIVDM sentences, in time order:\n"
    "each report becomes a type 1 (class A) or type 18 (class B) position report, and each vessel's\n"
    "static data (name, length and beam: type 5 for class A, type 24 parts A and B for class B) is sent\n"
    "at her first report and again every --static-every seconds. Every sentence carries an NMEA 4 tag\n"
    "block with the report's time (c:, UNIX seconds) and the source (s:csv), the form ais_node's file\n"
    "input and nmea_to_bag.py read. The log's defects are repaired as asv_scenario_from_ais does: COG < 0\n"
    "is a 12-bit wrap (+409.6), COG 360, SOG 102.3 and Heading 511 are 'not available'; unreadable rows\n"
    "are refused and counted on stderr. The reference point is taken as the middle of the hull.\n"
    "\n"
    "  CSV               the log\n"
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
};

bool parse(int argc, char** argv, Args& a) {
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    exitOnHelp(k, kUsage);
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

// "\s:csv,c:<seconds>*hh\" + sentence.
std::string tagged(const std::string& sentence, double time) {
  char body[64];
  std::snprintf(body, sizeof(body), "s:csv,c:%lld", static_cast<long long>(std::floor(time)));
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
  out.speed = ais::rawSpeed(knotsToMps(r.sog_kn));  // the reader refuses rows without SOG
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

int run(const Args& a) {
  std::ifstream in(a.csv);
  if (!in)
    throw std::runtime_error("cannot read " + a.csv);
  AisLogStats stats;
  std::vector<AisLogReport> log = readMarineCadastreCsv(in, stats);
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
        out << tagged(s, r.time) << '\n';
      ++written;
    }
  }
  std::size_t refused = 0;
  for (const auto& kv : stats.rejected)
    refused += kv.second;
  std::cerr << "asv_ais_csv_to_nmea: " << stats.rows << " rows, " << stats.kept << " reports read, " << refused
            << " refused";
  for (const auto& kv : stats.rejected)
    std::cerr << ", " << kv.first << " " << kv.second;
  std::cerr << "; " << written << " messages written from " << static_sent.size() << " vessels\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return toolMain<Args>("asv_ais_csv_to_nmea", kUsage, argc, argv, parse, run);
}
