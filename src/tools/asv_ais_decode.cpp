// asv_ais_decode: AIVDM/AIVDO to JSON, one object per message, in the format of gpsd's
// `gpsdecode -j` (scaled) and `gpsdecode -u -j` (unscaled), for all 27 message types, with the
// DAC/FID application payloads of types 6 and 8 that gpsd 3.22 decodes.
//
// Differences from gpsdecode 3.22, all deliberate (see also test_ais_golden.cpp):
//  - A sentence is never lost to its neighbours: after garbage, a truncated sentence or a bad
//    checksum on the same line, decoding resumes at the next `!`/`$`.
//  - Scaled output (-j without -u): "turn" keeps its sign (gpsd 3.22 prints the square of the rate,
//    losing the direction of the turn).
//  - "device" is the file name for files; "stdin" for standard input (gpsdecode reads stdin only).
//  - Type 1-3 messages longer than 168 bits are accepted (newer gpsd releases accept up to 204).
// Type 24: by default part A is held until its part B and printed merged with it; a part B without
// its part A is dropped, as gpsd does (counted on stderr). With -s every part is printed, part A
// with "part":"A", a part B with "part":"B" unless it completes a held part A (gpsd's --split24).
// A summary line with every rejection, by reason, goes to stderr at the end.
#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "asv_core/codec/ais.h"
#include "asv_core/codec/ais_json.h"
#include "asv_core/codec/json_out.h"
#include "asv_core/codec/nmea.h"

namespace {

using namespace asv;

constexpr std::size_t kReadChunk = 1 << 20;

const char* const kUsage =
    "usage: asv_ais_decode [-u] [-s] [-h] [FILE...]\n"
    "\n"
    "Decodes AIS NMEA 0183 sentences (!AIVDM/!AIVDO, with or without NMEA 4 tag blocks) from the\n"
    "files given, or from standard input when there is none or FILE is '-', and prints one JSON\n"
    "object per decoded message, in the format of gpsd's `gpsdecode -j`.\n"
    "\n"
    "  -u   unscaled output, as `gpsdecode -u -j`: the raw integer fields (lat/lon in 1/10000 min,\n"
    "       speed in 1/10 kn, course in 1/10 deg...)\n"
    "  -s   print type 24 parts A and B separately (gpsdecode --split24); by default part A is\n"
    "       merged into its part B and a part B without part A is dropped, as gpsd does\n"
    "  -h   this help\n"
    "\n"
    "Decoded types: all 27, with the type 6 and 8 application payloads (DAC/FID) gpsd 3.22\n"
    "decodes; other payloads are printed as \"data\":\"<bits>:<hex>\". Rejected lines, fragments\n"
    "and messages are counted by reason and summarised on stderr at the end.\n"
    "Exit status: 0, or 1 when a file could not be read, 2 on a usage error.\n";

using Out = json::Out;

struct Stats {
  std::uint64_t lines = 0;
  std::uint64_t sentences = 0;        // framed sentences, any type
  std::uint64_t other_sentences = 0;  // framed, but not VDM/VDO
  std::uint64_t printed = 0;
  std::uint64_t garbage = 0;         // text outside any sentence
  std::uint64_t type24_held = 0;     // part A waiting for its part B
  std::uint64_t type24_dropped = 0;  // part B without its part A (not printed without -s)
  std::uint64_t reject[static_cast<int>(nmea::Reject::kCount)] = {};
  std::uint64_t status[static_cast<int>(ais::Status::kCount)] = {};
};

// Type 24 part A names waiting for their part B, keyed by MMSI (gpsd keeps 8; a few more cost
// nothing and survive busier channels).
class Type24Queue {
public:
  void put(std::uint32_t mmsi, const ais::Text20& name) {
    for (auto& e : entries_) {
      if (e.mmsi == mmsi) {
        e.name = name;
        return;
      }
    }
    entries_[next_].mmsi = mmsi;
    entries_[next_].name = name;
    next_ = (next_ + 1) % entries_.size();
  }
  bool take(std::uint32_t mmsi, ais::Text20& name) {
    if (mmsi == 0)
      return false;
    for (auto& e : entries_) {
      if (e.mmsi == mmsi) {
        name = e.name;
        e.mmsi = 0;  // a repeated part B must not match again
        return true;
      }
    }
    return false;
  }

private:
  struct Entry {
    std::uint32_t mmsi = 0;
    ais::Text20 name;
  };
  std::array<Entry, 16> entries_{};
  std::size_t next_ = 0;
};

class App {
public:
  App(bool unscaled, bool split24) : unscaled_(unscaled), split24_(split24) {}

  void processLine(std::string_view line);
  void finish(const char* prog);
  void setDevice(std::string_view d) { device_ = d; }

private:
  void handleSentence(const nmea::Sentence& s);
  void print(const ais::Message& m);
  // One message type's fields, in gpsd's order (scaled unless --unscaled).
  void printPositionA(const ais::PositionReportA& x);
  void printBaseStation(const ais::BaseStationReport& x);
  void printStaticVoyage(const ais::StaticVoyageData& x);
  void printPositionB(const ais::PositionReportB& x, unsigned type);
  void printAidToNavigation(const ais::AidToNavigation& x);
  void printStaticData24(const ais::StaticDataReport& x, std::uint32_t mmsi, const ais::Text20* merged_name);
  // False when the message is not printed (type 24 parts held or dropped).
  bool take24(const ais::Message& m, const ais::StaticDataReport& x, ais::Text20& name, bool& merged);
  void printLongRange(const ais::LongRangeReport& x);
  void header(const ais::Message& m);
  void dims(std::uint32_t bow, std::uint32_t stern, std::uint32_t port, std::uint32_t stbd);

  bool unscaled_;
  bool split24_;
  std::string device_ = "stdin";
  nmea::FramerConfig framer_;
  ais::Decoder decoder_;
  nmea::Sentence sentence_;
  ais::Message message_;
  Type24Queue queue24_;
  double now_ = 0.0;
  Stats stats_;
  Out out_;
};

void App::processLine(std::string_view line) {
  ++stats_.lines;
  // '#' starts a comment line, as in gpsd's test logs (which comment out sentences they skip).
  const std::string_view t = nmea::trim(line);
  if (t.empty() || t[0] == '#')
    return;
  std::size_t pos = 0;
  bool any = false;
  while (pos < line.size()) {
    const std::size_t start = nmea::findSentenceStart(line, pos);
    if (start == std::string_view::npos)
      break;
    if (start > pos && !nmea::trim(line.substr(pos, start - pos)).empty())
      ++stats_.garbage;
    any = true;
    const std::string_view rest = line.substr(start);
    const nmea::Reject r = nmea::parseSentence(rest, sentence_, framer_);
    if (r == nmea::Reject::kNone) {
      handleSentence(sentence_);
      pos = start + sentence_.end;
      // Receiver metadata after the checksum (USCG ",d-109,S2105,...") is not garbage; anything up
      // to the next sentence start on the line is part of that suffix.
      const std::size_t next = nmea::findSentenceStart(line, pos);
      if (next == std::string_view::npos)
        break;
      pos = next;
      continue;
    }
    ++stats_.reject[static_cast<int>(r)];
    pos = start + 1;
  }
  if (!any)
    ++stats_.garbage;
}

void App::handleSentence(const nmea::Sentence& s) {
  ++stats_.sentences;
  if (s.tag.has_time)
    now_ = s.tag.unix_time;
  const ais::Status st = decoder_.feed(s, now_, message_);
  if (st == ais::Status::kNotAis) {
    ++stats_.other_sentences;
    return;
  }
  ++stats_.status[static_cast<int>(st)];
  if (st == ais::Status::kMessage)
    print(message_);
}

void App::header(const ais::Message& m) {
  out_.lit("{\"class\":\"AIS\",\"device\":");
  out_.str(device_);
  out_.lit(",\"type\":");
  out_.u(m.type);
  out_.lit(",\"repeat\":");
  out_.u(m.repeat);
  out_.lit(",\"mmsi\":");
  out_.u(m.mmsi);
  if (unscaled_)
    out_.lit(",\"scaled\":false");
  else
    out_.lit(",\"scaled\":true");
}

void App::dims(std::uint32_t bow, std::uint32_t stern, std::uint32_t port, std::uint32_t stbd) {
  out_.lit(",\"to_bow\":");
  out_.u(bow);
  out_.lit(",\"to_stern\":");
  out_.u(stern);
  out_.lit(",\"to_port\":");
  out_.u(port);
  out_.lit(",\"to_starboard\":");
  out_.u(stbd);
}

bool App::take24(const ais::Message& m, const ais::StaticDataReport& x, ais::Text20& name, bool& merged) {
  merged = false;
  if (x.part == 0) {
    queue24_.put(m.mmsi, x.shipname);
    if (!split24_)
      ++stats_.type24_held;
    return split24_;
  }
  merged = queue24_.take(m.mmsi, name);
  if (!merged && !split24_)
    ++stats_.type24_dropped;
  return merged || split24_;
}

void App::print(const ais::Message& m) {
  using namespace ais;
  const auto* t24 = std::get_if<StaticDataReport>(&m.body);
  Text20 name24;
  bool merged24 = false;
  if (t24 && !take24(m, *t24, name24, merged24))
    return;

  out_.reserveRecord(device_.size() * 6);
  header(m);
  if (const auto* a = std::get_if<PositionReportA>(&m.body)) {
    printPositionA(*a);
  } else if (const auto* s = std::get_if<BaseStationReport>(&m.body)) {
    printBaseStation(*s);
  } else if (const auto* v = std::get_if<StaticVoyageData>(&m.body)) {
    printStaticVoyage(*v);
  } else if (const auto* b = std::get_if<PositionReportB>(&m.body)) {
    printPositionB(*b, m.type);
  } else if (const auto* n = std::get_if<AidToNavigation>(&m.body)) {
    printAidToNavigation(*n);
  } else if (t24 && t24->part == 0) {
    out_.lit(",\"part\":\"A\",\"shipname\":");
    out_.str(t24->shipname.view());
  } else if (t24) {
    printStaticData24(*t24, m.mmsi, merged24 ? &name24 : nullptr);
  } else if (const auto* l = std::get_if<LongRangeReport>(&m.body)) {
    printLongRange(*l);
  } else {
    AisFields fields(out_, !unscaled_);
    writePayloadFields(decoder_.payload(), fields);
  }
  out_.lit("}\r\n");
  ++stats_.printed;
}

void App::printPositionA(const ais::PositionReportA& x) {
  const bool sc = !unscaled_;
  out_.lit(",\"status\":");
  out_.u(x.status);
  out_.lit(",\"status_text\":\"");
  out_.raw(ais::navStatusText(x.status));
  out_.lit("\",\"turn\":");
  if (!sc) {
    out_.i(x.turn);
  } else if (x.turn == -128) {
    out_.lit("\"nan\"");
  } else if (x.turn == -127) {
    out_.lit("\"fastleft\"");
  } else if (x.turn == 127) {
    out_.lit("\"fastright\"");
  } else {
    const double r = x.turn / 4.733;
    double v = std::nearbyint(r * r);
    if (x.turn < 0 && v != 0.0)
      v = -v;
    out_.printf1("%.0f", v);
  }
  out_.lit(",\"speed\":");
  if (!sc)
    out_.u(x.speed);
  else if (x.speed == 1023)
    out_.lit("\"nan\"");
  else if (x.speed == 1022)
    out_.lit("\"fast\"");
  else
    out_.tenths(x.speed);
  out_.lit(",\"accuracy\":");
  out_.b(x.accuracy);
  out_.lit(",\"lon\":");
  sc ? out_.latlon(x.lon) : out_.i(x.lon);
  out_.lit(",\"lat\":");
  sc ? out_.latlon(x.lat) : out_.i(x.lat);
  out_.lit(",\"course\":");
  sc ? out_.tenths(x.course) : out_.u(x.course);
  out_.lit(",\"heading\":");
  out_.u(x.heading);
  out_.lit(",\"second\":");
  out_.u(x.second);
  out_.lit(",\"maneuver\":");
  out_.u(x.maneuver);
  out_.lit(",\"raim\":");
  out_.b(x.raim);
  out_.lit(",\"radio\":");
  out_.u(x.radio);
}

void App::printBaseStation(const ais::BaseStationReport& x) {
  const bool sc = !unscaled_;
  out_.lit(",\"timestamp\":\"");
  out_.pad(x.year, 4);
  out_.lit("-");
  out_.pad(x.month, 2);
  out_.lit("-");
  out_.pad(x.day, 2);
  out_.lit("T");
  out_.pad(x.hour, 2);
  out_.lit(":");
  out_.pad(x.minute, 2);
  out_.lit(":");
  out_.pad(x.second, 2);
  out_.lit("Z\",\"accuracy\":");
  out_.b(x.accuracy);
  out_.lit(",\"lon\":");
  sc ? out_.latlon(x.lon) : out_.i(x.lon);
  out_.lit(",\"lat\":");
  sc ? out_.latlon(x.lat) : out_.i(x.lat);
  out_.lit(",\"epfd\":");
  out_.u(x.epfd);
  out_.lit(",\"epfd_text\":\"");
  out_.raw(ais::epfdText(x.epfd));
  out_.lit("\",\"raim\":");
  out_.b(x.raim);
  out_.lit(",\"radio\":");
  out_.u(x.radio);
}

void App::printStaticVoyage(const ais::StaticVoyageData& x) {
  const bool sc = !unscaled_;
  out_.lit(",\"imo\":");
  out_.u(x.imo);
  out_.lit(",\"ais_version\":");
  out_.u(x.ais_version);
  out_.lit(",\"callsign\":");
  out_.str(x.callsign.view());
  out_.lit(",\"shipname\":");
  out_.str(x.shipname.view());
  out_.lit(",\"shiptype\":");
  out_.u(x.shiptype);
  out_.lit(",\"shiptype_text\":\"");
  out_.raw(ais::shipTypeText(x.shiptype));
  out_.lit("\"");
  dims(x.to_bow, x.to_stern, x.to_port, x.to_starboard);
  out_.lit(",\"epfd\":");
  out_.u(x.epfd);
  out_.lit(",\"epfd_text\":\"");
  out_.raw(ais::epfdText(x.epfd));
  out_.lit("\",\"eta\":\"");
  out_.pad(x.month, 2);
  out_.lit("-");
  out_.pad(x.day, 2);
  out_.lit("T");
  out_.pad(x.hour, 2);
  out_.lit(":");
  out_.pad(x.minute, 2);
  out_.lit("Z\",\"draught\":");
  sc ? out_.tenths(x.draught) : out_.u(x.draught);
  out_.lit(",\"destination\":");
  out_.str(x.destination.view());
  out_.lit(",\"dte\":");
  out_.u(x.dte ? 1 : 0);
}

void App::printPositionB(const ais::PositionReportB& x, unsigned type) {
  const bool sc = !unscaled_;
  out_.lit(",\"reserved\":");
  out_.u(x.reserved);
  out_.lit(",\"speed\":");
  sc ? out_.tenths(x.speed) : out_.u(x.speed);
  out_.lit(",\"accuracy\":");
  out_.b(x.accuracy);
  out_.lit(",\"lon\":");
  sc ? out_.latlon(x.lon) : out_.i(x.lon);
  out_.lit(",\"lat\":");
  sc ? out_.latlon(x.lat) : out_.i(x.lat);
  out_.lit(",\"course\":");
  sc ? out_.tenths(x.course) : out_.u(x.course);
  out_.lit(",\"heading\":");
  out_.u(x.heading);
  out_.lit(",\"second\":");
  out_.u(x.second);
  out_.lit(",\"regional\":");
  out_.u(x.regional);
  if (type == 18) {
    out_.lit(",\"cs\":");
    out_.b(x.cs);
    out_.lit(",\"display\":");
    out_.b(x.display);
    out_.lit(",\"dsc\":");
    out_.b(x.dsc);
    out_.lit(",\"band\":");
    out_.b(x.band);
    out_.lit(",\"msg22\":");
    out_.b(x.msg22);
    out_.lit(",\"raim\":");
    out_.b(x.raim);
    out_.lit(",\"radio\":");
    out_.u(x.radio);
  } else {
    out_.lit(",\"shipname\":");
    out_.str(x.shipname.view());
    out_.lit(",\"shiptype\":");
    out_.u(x.shiptype);
    out_.lit(",\"shiptype_text\":\"");
    out_.raw(ais::shipTypeText(x.shiptype));
    out_.lit("\"");
    dims(x.to_bow, x.to_stern, x.to_port, x.to_starboard);
    out_.lit(",\"epfd\":");
    out_.u(x.epfd);
    out_.lit(",\"epfd_text\":\"");
    out_.raw(ais::epfdText(x.epfd));
    out_.lit("\",\"raim\":");
    out_.b(x.raim);
    out_.lit(",\"dte\":");
    out_.u(x.dte ? 1 : 0);
    out_.lit(",\"assigned\":");
    out_.b(x.assigned);
  }
}

void App::printAidToNavigation(const ais::AidToNavigation& x) {
  const bool sc = !unscaled_;
  out_.lit(",\"aid_type\":");
  out_.u(x.aid_type);
  out_.lit(",\"aid_type_text\":\"");
  out_.raw(ais::aidTypeText(x.aid_type));
  out_.lit("\",\"name\":");
  out_.str(x.name.view());
  // gpsd orders these differently in its two modes.
  if (sc) {
    out_.lit(",\"lon\":");
    out_.latlon(x.lon);
    out_.lit(",\"lat\":");
    out_.latlon(x.lat);
    out_.lit(",\"accuracy\":");
    out_.b(x.accuracy);
  } else {
    out_.lit(",\"accuracy\":");
    out_.b(x.accuracy);
    out_.lit(",\"lon\":");
    out_.i(x.lon);
    out_.lit(",\"lat\":");
    out_.i(x.lat);
  }
  dims(x.to_bow, x.to_stern, x.to_port, x.to_starboard);
  out_.lit(",\"epfd\":");
  out_.u(x.epfd);
  out_.lit(",\"epfd_text\":\"");
  out_.raw(ais::epfdText(x.epfd));
  out_.lit("\",\"second\":");
  out_.u(x.second);
  out_.lit(",\"regional\":");
  out_.u(x.regional);
  out_.lit(",\"off_position\":");
  out_.b(x.off_position);
  out_.lit(",\"raim\":");
  out_.b(x.raim);
  out_.lit(",\"virtual_aid\":");
  out_.b(x.virtual_aid);
}

void App::printStaticData24(const ais::StaticDataReport& x, std::uint32_t mmsi,
                            const ais::Text20* merged_name) {
  if (merged_name) {
    out_.lit(",\"shipname\":");
    out_.str(merged_name->view());
  } else {
    out_.lit(",\"part\":\"B\"");
  }
  out_.lit(",\"shiptype\":");
  out_.u(x.shiptype);
  out_.lit(",\"shiptype_text\":\"");
  out_.raw(ais::shipTypeText(x.shiptype));
  out_.lit("\",\"vendorid\":");
  out_.str(x.vendorid.view());
  out_.lit(",\"model\":");
  out_.u(x.model);
  out_.lit(",\"serial\":");
  out_.u(x.serial);
  out_.lit(",\"callsign\":");
  out_.str(x.callsign.view());
  if (mmsi / 10000000u == 98u) {
    out_.lit(",\"mothership_mmsi\":");
    out_.u(x.mothership_mmsi);
  } else {
    dims(x.to_bow, x.to_stern, x.to_port, x.to_starboard);
  }
}

void App::printLongRange(const ais::LongRangeReport& x) {
  const bool sc = !unscaled_;
  out_.lit(",\"status\":");
  if (sc) {
    out_.lit("\"");
    out_.raw(ais::navStatusText(x.status));
    out_.lit("\"");
  } else {
    out_.u(x.status);
  }
  out_.lit(",\"accuracy\":");
  out_.b(x.accuracy);
  out_.lit(",\"lon\":");
  sc ? out_.printf1("%.1f", x.lon / 600.0) : out_.i(x.lon);
  out_.lit(",\"lat\":");
  sc ? out_.printf1("%.1f", x.lat / 600.0) : out_.i(x.lat);
  out_.lit(",\"speed\":");
  out_.u(x.speed);
  out_.lit(",\"course\":");
  out_.u(x.course);
  out_.lit(",\"raim\":");
  out_.b(x.raim);
  out_.lit(",\"gnss\":");
  out_.b(x.gnss);
}

void App::finish(const char* prog) {
  out_.flush();
  std::fflush(stdout);
  const ais::Counters& c = decoder_.counters();
  std::string s;
  char tmp[128];
  auto add = [&s, &tmp](const char* what, std::uint64_t n) {
    if (n == 0)
      return;
    std::snprintf(tmp, sizeof(tmp), "%s%s %llu", s.empty() ? "" : ", ", what,
                  static_cast<unsigned long long>(n));
    s += tmp;
  };
  std::uint64_t rejected = stats_.garbage;
  for (auto n : stats_.reject)
    rejected += n;
  std::snprintf(
      tmp, sizeof(tmp), "%s: %llu lines, %llu sentences (%llu not AIS), %llu messages printed, %llu rejected",
      prog, static_cast<unsigned long long>(stats_.lines), static_cast<unsigned long long>(stats_.sentences),
      static_cast<unsigned long long>(stats_.other_sentences),
      static_cast<unsigned long long>(stats_.printed), static_cast<unsigned long long>(rejected));
  std::string line = tmp;
  add("garbage", stats_.garbage);
  for (int r = 1; r < static_cast<int>(nmea::Reject::kCount); ++r)
    add(nmea::rejectText(static_cast<nmea::Reject>(r)), stats_.reject[r]);
  add("orphan fragments", c.orphans);
  add("out-of-order fragments", c.out_of_order);
  add("restarted messages", c.restarted);
  add("timed-out messages", c.timeouts);
  add("evicted messages", c.evicted);
  add("bad AIVDM fields", c.bad_fields);
  add("bad fill bits", c.bad_fill);
  add("bad armour", c.bad_armour);
  add("empty payloads", c.empty_payload);
  add("too short", c.too_short);
  add("bad type 24 part", c.bad_part);
  add("too long", c.too_long);
  add("unsupported types", c.unsupported);
  const std::size_t incomplete = decoder_.pendingCount();
  add("incomplete at end", incomplete);
  add("type 24A held", stats_.type24_held);
  add("type 24B without 24A dropped", stats_.type24_dropped);
  if (!s.empty())
    line += " (" + s + ")";
  std::fprintf(stderr, "%s\n", line.c_str());
}

// Splits a file descriptor into lines with one big buffer; a line longer than the buffer is cut
// (it is rejected as too long anyway).
bool processFd(int fd, App& app) {
  std::vector<char> buf(kReadChunk * 2);
  std::size_t have = 0;
  for (;;) {
    const ssize_t got = ::read(fd, buf.data() + have, buf.size() - have);
    if (got < 0)
      return false;
    if (got == 0)
      break;
    have += static_cast<std::size_t>(got);
    std::size_t begin = 0;
    for (;;) {
      const void* nl = std::memchr(buf.data() + begin, '\n', have - begin);
      if (!nl)
        break;
      const std::size_t end = static_cast<std::size_t>(static_cast<const char*>(nl) - buf.data());
      app.processLine(std::string_view(buf.data() + begin, end - begin));
      begin = end + 1;
    }
    if (begin == 0 && have == buf.size()) {  // no newline in a full buffer: cut the line
      app.processLine(std::string_view(buf.data(), have));
      have = 0;
      continue;
    }
    std::memmove(buf.data(), buf.data() + begin, have - begin);
    have -= begin;
  }
  if (have > 0)
    app.processLine(std::string_view(buf.data(), have));
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  bool unscaled = false;
  bool split24 = false;
  std::vector<const char*> files;
  bool options_done = false;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (!options_done && a[0] == '-' && a[1] != '\0') {
      if (std::strcmp(a, "--") == 0) {
        options_done = true;
        continue;
      }
      for (const char* p = a + 1; *p; ++p) {
        if (*p == 'u') {
          unscaled = true;
        } else if (*p == 's') {
          split24 = true;
        } else if (*p == 'h') {
          std::fputs(kUsage, stdout);
          return 0;
        } else if (*p == 'j') {
          // gpsdecode's JSON switch: JSON is the only output here, accepted for drop-in use.
        } else {
          std::fprintf(stderr, "asv_ais_decode: unknown option -%c\n%s", *p, kUsage);
          return 2;
        }
      }
      continue;
    }
    files.push_back(a);
  }

  App app(unscaled, split24);
  int status = 0;
  if (files.empty())
    files.push_back("-");
  for (const char* f : files) {
    if (std::strcmp(f, "-") == 0) {
      app.setDevice("stdin");
      if (!processFd(0, app))
        status = 1;
      continue;
    }
    const int fd = ::open(f, O_RDONLY);
    if (fd < 0) {
      std::fprintf(stderr, "asv_ais_decode: cannot open %s: %s\n", f, std::strerror(errno));
      status = 1;
      continue;
    }
    app.setDevice(f);
    if (!processFd(fd, app)) {
      std::fprintf(stderr, "asv_ais_decode: read error on %s\n", f);
      status = 1;
    }
    ::close(fd);
  }
  app.finish("asv_ais_decode");
  return status;
}
